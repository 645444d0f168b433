// The launch page of a lesson package (lesson.html, made by package.js): the playground with its
// lesson player, tied to the LMS that launched it. Reads the package's course (lessons/course.json,
// package.js), connects to the LMS (lms.js), restores the learner's place from suspend data
// (resume.js) and reports what the learner does: a record per checked exercise, the score, the
// status and the place, committed after each check. Opened outside an LMS it runs as a plain
// lesson with its progress in this browser, and says so once.
//
// The course is read before the player starts (its start waits for the first frame), so the
// first-visit tour never covers the lesson, and the LMS's place is in the player's progress
// before the Lessons menu first shows it.
import { connectLms, variantSeed } from './lms.js';
import { decodePlace, emptyPlace, encodePlace } from './resume.js';
import { markTourSeen, readProgress, writeProgress } from './progress.js';

/**
 * The course of a package (lessons/course.json): its format and mastery score (0…1 or null),
 * and per lesson its id, file, title, number of steps and the steps holding an exercise.
 * @typedef {{format: string, mastery: number | null, title: string, lessons: {id: string, file: string, title: string, steps: number, exercises: number[]}[]}} Course
 */

markTourSeen();
// The Lessons menu offers no package of a package (menu.js).
document.documentElement.dataset.lessonPackage = '1';

const page = /** @type {any} */ (window).screwbender;
/** @type {Course} */
const course = await fetch(new URL('../../lessons/course.json', import.meta.url))
  .then((r) => (r.ok ? r.json() : Promise.reject(new Error(`HTTP ${r.status}`))))
  .catch((e) => {
    // A package whose course file is missing or broken: the page runs as the playground.
    page.ready.then(() => page.app.parts.notices.show(`This lesson package cannot read its lessons/course.json (${e.message}): make it again. The page runs without its lessons.`), () => {});
    return null;
  });
if (course) await launch(course);

/** Connects the player of the page to the LMS for `course` and opens the course. */
async function launch(course) {
  const lms = connectLms(window, course.format);
  const stepCounts = course.lessons.map((l) => l.steps);
  // Course-wide exercise numbers: lesson k's exercises start at offsets[k].
  const offsets = course.lessons.map((_, k) => course.lessons.slice(0, k).reduce((n, l) => n + l.exercises.length, 0));
  const total = offsets.at(-1) + course.lessons.at(-1).exercises.length;
  const restored = lms ? decodePlace(lms.suspendData, stepCounts, total) : null;
  const place = restored ?? emptyPlace(course.lessons.length);
  if (lms) {
    // The LMS's place is the learner's: it replaces whatever this browser kept (another learner
    // may have used it), so the Lessons menu shows the same.
    // With the learner's variant seed: randomised steps show the numbers they showed at the
    // last launch, whichever browser this is.
    course.lessons.forEach((l, k) => writeProgress(l.id, { ...toProgress(place.lessons[k]), seed: variantSeed(lms.learnerId ?? '', l.id) }));
  } else {
    course.lessons.forEach((l, k) => Object.assign(place.lessons[k], readProgress(l.id)));
  }

  /** The lms.js connection (null outside an LMS), the course's place and the learner's seed. */
  page.lms = {
    connected: !!lms,
    version: lms?.version ?? null,
    learnerId: lms?.learnerId ?? '',
    /** The seed of lesson `id`'s randomised variants (lms.js variantSeed) for this learner. */
    seed: (id) => variantSeed(lms?.learnerId ?? '', id),
    place,
    errors: () => [...(lms?.errors ?? [])],
  };

  /** The player's progress object for a lesson's place. */
  function toProgress(p) {
    return { step: p.step, solved: [...p.solved], answers: { ...p.answers } };
  }

  /** The score and status the LMS is told: solved of all exercises, and pass / fail at the end. */
  function report() {
    const solved = course.lessons.reduce((n, l, k) => n + l.exercises.filter((s) => place.lessons[k].solved.includes(s)).length, 0);
    const scaled = total ? solved / total : 1;
    const completed = place.lessons.every((l) => l.finished);
    const mastery = lms?.masteryScore ?? course.mastery;
    const passed = mastery === null || mastery === undefined ? null : scaled >= mastery - 1e-9;
    lms?.save({ suspendData: encodePlace(place), scaled, completed, passed });
  }

  const player = await page.lessons;
  if (player) {
    const index = (id) => course.lessons.findIndex((l) => l.id === id);
    const follow = (e) => {
      const k = index(e.detail.id);
      if (k < 0) return -1;
      const p = place.lessons[k];
      Object.assign(p, toProgress(e.detail.progress), { finished: p.finished });
      place.current = k;
      return k;
    };
    player.events.addEventListener('open', follow);
    player.events.addEventListener('step', (e) => {
      if (follow(e) >= 0) report();
    });
    player.events.addEventListener('check', (e) => {
      const k = follow(e);
      if (k < 0 || !lms) return;
      const { step, ok, answer } = e.detail;
      const g = offsets[k] + course.lessons[k].exercises.indexOf(step);
      if (!place.order.includes(g)) place.order.push(g);
      const x = player.lesson?.steps[step]?.exercise;
      const choice = !!x?.choices;
      const measured = e.detail.results.filter((c) => c.kind !== 'choice' && c.got).map((c) => c.got).join('; ');
      lms.interaction(place.order.indexOf(g), {
        id: `${course.lessons[k].id.replace(/[^\w]/g, '_')}_step${step + 1}`,
        choice,
        response: choice ? (answer ?? '') : measured || (ok ? 'solved' : 'not solved'),
        correct: ok,
        answer: x?.checks.find((c) => c.kind === 'choice')?.answer,
        time: new Date(),
      });
      report();
      lms.commit();
    });
    player.events.addEventListener('finish', (e) => {
      const k = follow(e);
      if (k < 0) return;
      place.lessons[k].finished = true;
      report();
      lms?.commit();
    });

    if (lms) {
      report();
      lms.commit();
      window.addEventListener('pagehide', () => lms.terminate());
    } else {
      page.app.parts.notices.show('Not launched from an LMS: this lesson runs on its own, and its progress stays in this browser.', 'info');
    }
    const l = course.lessons[place.current];
    // A course starts at its menu; a single lesson, or a course resumed, at the lesson shown last.
    if (course.lessons.length > 1 && !restored && !place.lessons.some((p) => p.step > 0 || p.solved.length)) player.openMenu();
    else await player.open(l.file, { progress: { ...toProgress(place.lessons[place.current]), ...(lms ? { seed: page.lms.seed(l.id) } : {}) } });
  }
}
