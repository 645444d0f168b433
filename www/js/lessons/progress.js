// Lesson progress in localStorage: per lesson the step last shown, the exercises solved and the
// multiple-choice answers given; and whether the first-visit tour has been seen. Storage that is
// broken, full or disabled never throws: progress then lasts for this page only.

const PROGRESS_PREFIX = 'screwbender.lesson.';
const TOUR_SEEN_KEY = 'screwbender.tour.seen';

/** The saved progress of lesson `id`: {step, solved: [step…], answers: {step: choice}}. */
export function readProgress(id) {
  try {
    const p = JSON.parse(localStorage.getItem(PROGRESS_PREFIX + id) ?? 'null');
    if (p && typeof p === 'object') return { step: Number.isInteger(p.step) ? p.step : 0, solved: Array.isArray(p.solved) ? p.solved : [], answers: p.answers ?? {} };
  } catch {
    // A broken entry counts as no progress.
  }
  return { step: 0, solved: [], answers: {} };
}

/** Saves progress `p` of lesson `id` (see readProgress). */
export function writeProgress(id, p) {
  try {
    localStorage.setItem(PROGRESS_PREFIX + id, JSON.stringify(p));
  } catch {
    // Storage full or disabled: progress is kept for this page only.
  }
}

/** Remembers that the tour has been shown. */
export function markTourSeen() {
  try {
    localStorage.setItem(TOUR_SEEN_KEY, '1');
  } catch {
    // Without storage the tour may show again next time.
  }
}

/** Whether the tour has been shown before (true when storage cannot be read). */
export function tourSeen() {
  try {
    return localStorage.getItem(TOUR_SEEN_KEY) !== null;
  } catch {
    return true;
  }
}
