// The SCORM runtime adapter: finds the API an LMS gives a package's page (SCORM 1.2
// `window.API`, SCORM 2004 `window.API_1484_11`) and speaks one vocabulary to both versions.
// Written here rather than taken from npm: the runtime libraries there (scorm-again, pipwerks)
// are the LMS side or wrap only the calls; what the page needs is the mapping of its few facts
// (score, status, interactions, suspend data, time spent) onto each version's data model,
// which is this file.
//
// The API search follows the standard's algorithm (ADL's "API discovery"): the window's parent
// chain (at most 7 levels for 1.2, 500 for 2004), then the opener's chain. A window of another
// origin cannot be read; the search then stops on that branch.
//
// connectLms(win, format) returns null when no API is found (the page runs as a plain lesson),
// else an Lms:
//   version                   '1.2' | '2004'
//   learnerId, learnerName    from cmi.core.student_id / cmi.learner_id ('' when not given)
//   resumed                   the LMS says this launch resumes an earlier one (entry = resume)
//   suspendData               the suspend data kept from the last launch ('' when none)
//   masteryScore              the LMS's own mastery (0…1) from the manifest, or null
//   save({suspendData, scaled, completed, passed})   writes status and score
//   interaction(n, record)    writes interaction record n (see record below)
//   commit()                  LMSCommit / Commit, with the time spent so far (session_time)
//   terminate()               LMSFinish / Terminate (once; later calls do nothing)
//   errors                    the LMS calls that failed, as "call: code message" lines

import { fnv1a } from './variants.js';

/** How far up a parent chain each version's search goes (the standard's limits). */
const MAX_DEPTH = { '1.2': 7, 2004: 500 };
/** The API object's name in each version. */
const API_NAME = { '1.2': 'API', 2004: 'API_1484_11' };

/** The API of `version` in `win` or one of its parents, or null. */
function scan(win, version) {
  const name = API_NAME[version];
  let w = win;
  for (let depth = 0; w && depth <= MAX_DEPTH[version]; depth++) {
    try {
      if (w[name]) return w[name];
      if (!w.parent || w.parent === w) return null;
      w = w.parent;
    } catch {
      // Another origin: nothing readable further up this chain.
      return null;
    }
  }
  return null;
}

/** The API of `version` for `win`: its parent chain, then its opener's. */
export function findApi(win, version) {
  const api = scan(win, version);
  if (api) return api;
  try {
    return win.opener ? scan(win.opener, version) : null;
  } catch {
    return null;
  }
}

/** `ms` milliseconds as SCORM 1.2 CMITimespan (HHHH:MM:SS.SS). */
export function timespan12(ms) {
  const cs = Math.max(0, Math.round(ms / 10));
  const h = Math.floor(cs / 360000);
  const m = Math.floor((cs % 360000) / 6000);
  const s = (cs % 6000) / 100;
  return `${String(h).padStart(4, '0')}:${String(m).padStart(2, '0')}:${s.toFixed(2).padStart(5, '0')}`;
}

/** `ms` milliseconds as an ISO 8601 duration (SCORM 2004 timeinterval, PT…H…M…S). */
export function duration2004(ms) {
  const cs = Math.max(0, Math.round(ms / 10));
  const h = Math.floor(cs / 360000);
  const m = Math.floor((cs % 360000) / 6000);
  const s = (cs % 6000) / 100;
  return `PT${h}H${m}M${s.toFixed(2)}S`;
}

const pad = (n) => String(n).padStart(2, '0');

/**
 * The seed of a randomised step's variant (variants.js) in an LMS: the same for the same learner
 * and lesson at every launch, so a resumed lesson shows the variant the learner saw without
 * storing it (FNV-1a of both ids, 32 bits).
 */
export function variantSeed(learnerId, lessonId) {
  return fnv1a(`${learnerId}\u0000${lessonId}`);
}

/**
 * One exercise's interaction record: `id` (letters, digits, `_`), `choice` (the exercise is a
 * multiple choice), `response` (the chosen answer's index for a choice, else what the checks
 * measured, as text), `correct`, `answer` (the right choice's index, for a choice) and `time`
 * (a Date).
 * @typedef {{id: string, choice: boolean, response: number | string, correct: boolean, answer?: number, time: Date}} InteractionRecord
 */

/**
 * Connects to the LMS API for `win` (format 'scorm12' or 'scorm2004': that version's API is
 * looked for first, then the other's) and initialises it. Null when there is none, or when the
 * LMS refuses to initialise.
 */
export function connectLms(win, format) {
  const order = format === 'scorm12' ? ['1.2', '2004'] : ['2004', '1.2'];
  for (const version of order) {
    const api = findApi(win, version);
    if (api) return open(api, version);
  }
  return null;
}

function open(api, version) {
  const v12 = version === '1.2';
  const errors = [];
  const started = Date.now();
  let live = false;

  /** Runs API call `name` (with the version's argument convention); records a failure. */
  const call = (name, ...args) => {
    let r;
    try {
      r = api[name](...args);
    } catch (e) {
      errors.push(`${name}: ${e?.message ?? e}`);
      return '';
    }
    if (name.endsWith('GetValue') && r !== '') return String(r);
    const code = String(api[v12 ? 'LMSGetLastError' : 'GetLastError']?.() ?? '0');
    if (code !== '0') {
      const msg = api[v12 ? 'LMSGetErrorString' : 'GetErrorString']?.(code) ?? '';
      errors.push(`${name}(${args[0] ?? ''}): ${code} ${msg}`);
      return name.endsWith('GetValue') ? '' : 'false';
    }
    return r === undefined || r === null ? '' : String(r);
  };
  const get = (el) => call(v12 ? 'LMSGetValue' : 'GetValue', el);
  const set = (el, value) => call(v12 ? 'LMSSetValue' : 'SetValue', el, String(value));

  if (String(call(v12 ? 'LMSInitialize' : 'Initialize', '')) !== 'true') return null;
  live = true;

  const masteryText = get(v12 ? 'cmi.student_data.mastery_score' : 'cmi.scaled_passing_score');
  const mastery = Number(masteryText);
  const lms = {
    version,
    learnerId: get(v12 ? 'cmi.core.student_id' : 'cmi.learner_id'),
    learnerName: get(v12 ? 'cmi.core.student_name' : 'cmi.learner_name'),
    resumed: get(v12 ? 'cmi.core.entry' : 'cmi.entry') === 'resume',
    suspendData: get('cmi.suspend_data'),
    // 1.2 gives a percentage (0–100), 2004 a scaled score (−1…1).
    masteryScore: masteryText === '' || !Number.isFinite(mastery) ? null : v12 ? mastery / 100 : mastery,
    errors,

    /**
     * Writes the learner's state: suspend data, the score `scaled` (0…1, the share of the
     * exercises solved), completion and, once completed, pass or fail (`passed` null: no mastery
     * score, so no pass/fail). The raw score is that share in percent (min 0, max 100): SCORM
     * 1.2 LMSs compare the raw score with the mastery score, a percentage, and most gradebooks
     * read the raw score as points out of 100.
     */
    save({ suspendData, scaled, completed, passed }) {
      set('cmi.suspend_data', suspendData);
      // Exit "suspend": the next launch resumes with this data (also after completion, so a
      // learner who comes back sees their answers and the summary).
      set(v12 ? 'cmi.core.exit' : 'cmi.exit', 'suspend');
      const score = v12 ? 'cmi.core.score' : 'cmi.score';
      set(`${score}.min`, 0);
      set(`${score}.max`, 100);
      set(`${score}.raw`, Math.round(scaled * 10000) / 100);
      if (!v12) set('cmi.score.scaled', scaled.toFixed(4));
      if (v12) {
        // 1.2 has one status: passed / failed say completed too.
        set('cmi.core.lesson_status', !completed ? 'incomplete' : passed === null ? 'completed' : passed ? 'passed' : 'failed');
      } else {
        set('cmi.completion_status', completed ? 'completed' : 'incomplete');
        set('cmi.progress_measure', scaled.toFixed(4));
        set('cmi.success_status', !completed || passed === null ? 'unknown' : passed ? 'passed' : 'failed');
      }
    },

    /** Writes interaction record `n` (see InteractionRecord). */
    interaction(n, r) {
      const at = `cmi.interactions.${n}`;
      set(`${at}.id`, r.id);
      set(`${at}.type`, r.choice ? 'choice' : v12 ? 'performance' : 'other');
      const t = r.time;
      if (v12) {
        set(`${at}.time`, `${pad(t.getHours())}:${pad(t.getMinutes())}:${pad(t.getSeconds())}`);
        // 1.2 choice responses are single letters or digits (a–z, 0–9).
        set(`${at}.student_response`, r.choice ? (r.response === '' ? '' : Number(r.response).toString(36)) : String(r.response).slice(0, 255));
        set(`${at}.result`, r.correct ? 'correct' : 'wrong');
        if (r.choice && r.answer !== undefined) set(`${at}.correct_responses.0.pattern`, r.answer.toString(36));
      } else {
        set(`${at}.timestamp`, `${t.getFullYear()}-${pad(t.getMonth() + 1)}-${pad(t.getDate())}T${pad(t.getHours())}:${pad(t.getMinutes())}:${pad(t.getSeconds())}`);
        set(`${at}.learner_response`, r.choice ? (r.response === '' ? '' : `answer_${r.response}`) : String(r.response).slice(0, 4000));
        set(`${at}.result`, r.correct ? 'correct' : 'incorrect');
        if (r.choice && r.answer !== undefined) set(`${at}.correct_responses.0.pattern`, `answer_${r.answer}`);
      }
    },

    /** Commits what was written, with the time spent so far (session_time). */
    commit() {
      if (!live) return;
      const ms = Date.now() - started;
      set(v12 ? 'cmi.core.session_time' : 'cmi.session_time', v12 ? timespan12(ms) : duration2004(ms));
      call(v12 ? 'LMSCommit' : 'Commit', '');
    },

    /** Ends the communication (the page is going away); later calls do nothing. */
    terminate() {
      if (!live) return;
      lms.commit();
      live = false;
      call(v12 ? 'LMSFinish' : 'Terminate', '');
    },
  };
  return lms;
}
