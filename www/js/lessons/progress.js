// Lesson progress in localStorage: per lesson the step last shown, the exercises solved, the
// multiple-choice answers given and the seed of its randomised steps' variant (variants.js); and
// whether the first-visit tour has been seen. Storage that is broken, full or disabled never
// throws: progress then lasts for this page only.

/**
 * Whether `v` is a seed: a whole number from 0 to 2³² − 1. Here, not in variants.js, as every
 * visit reads the progress (for the tour) and a plain visit fetches nothing else of the lessons.
 */
export const isSeed = (v) => Number.isInteger(v) && v >= 0 && v <= 0xffffffff;

const PROGRESS_PREFIX = 'screwbender.lesson.';
const TOUR_SEEN_KEY = 'screwbender.tour.seen';

/**
 * The saved progress of lesson `id`: {step, solved: [step…], answers: {step: choice}, seed?}
 * (`seed`: once the lesson has randomised steps and has been opened).
 */
export function readProgress(id) {
  try {
    const p = JSON.parse(localStorage.getItem(PROGRESS_PREFIX + id) ?? 'null');
    if (p && typeof p === 'object') {
      const out = { step: Number.isInteger(p.step) ? p.step : 0, solved: Array.isArray(p.solved) ? p.solved : [], answers: p.answers ?? {} };
      if (isSeed(p.seed)) out.seed = p.seed;
      return out;
    }
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
