// The figure as a media element: its options autoplay, loop and speed, and HTMLMediaElement's
// script API where it applies (play({repetitions}), pause, currentTime, duration, paused,
// playbackRate, loop; the events play, pause, ended, time / timeupdate, seeked, ratechange).
// Times are the motion's own seconds (pose i at motion.times[i], else at i s), as seek(t) and
// `time` give them.
import { describePose } from './description.js';
import { bool, number } from './options.js';

/** The detail of `time` and `timeupdate`. */
const TIME_DETAIL = {
  type: 'TimeDetail',
  doc: 'The detail of `time`: seconds `t` in [start, end] and the motion\'s parameter `u`.',
  fields: { t: 'number', u: 'number', start: 'number', end: 'number' },
};

/** @type {import('./options.js').Feature} */
export const playbackFeature = {
  name: 'playback',
  doc: 'Playback in the names and meanings of HTMLMediaElement.',
  options: [
    { name: 'autoplay', type: 'boolean', default: false, parse: bool, doc: 'Play from the start.', python: { default: false } },
    { name: 'loop', type: 'boolean', default: true, parse: bool, doc: 'Loop an open motion while playing.' },
    {
      name: 'speed', type: 'number', default: 1, parse: (v) => number('speed', v, 0, 100),
      doc: 'Control poses per second while playing, 0 to 100.',
    },
  ],
  properties: [
    {
      name: 'currentTime', ts: 'number', doc: 'The playhead in seconds; set it to seek (works while paused; fires `seeked`).',
      get: (fig) => fig.playback.currentTime,
      set: (fig, t) => fig.guard(() => fig.seek(t)),
    },
    { name: 'duration', ts: 'number', doc: 'The playback interval\'s length in seconds (NaN before the motion loads).', get: (fig) => fig.playback.duration },
    { name: 'paused', ts: 'boolean', doc: 'True unless playing.', get: (fig) => fig.playback.paused },
    {
      name: 'playbackRate', ts: 'number', doc: 'Motion seconds per real second, −100 to 100 (negative plays backwards); starts as `speed`.',
      get: (fig) => fig.playback.playbackRate,
      set: (fig, r) => fig.guard(() => (fig.playback.playbackRate = r)),
    },
    {
      name: 'loop', ts: 'boolean', doc: 'An open motion wraps at its end while playing (a cycle always does); the `loop` attribute.',
      get: (fig) => fig.playback.loop,
      set: (fig, on) => (fig.playback.loop = on),
    },
  ],
  methods: [
    {
      name: 'play', params: [{ name: 'options', ts: '{ repetitions?: number }', optional: true }], returns: 'void',
      doc: 'Plays; with `repetitions` (a whole number ≥ 1), that many passes and then `ended`.',
      call: (fig, opts) => fig.guard(() => fig.play(opts)),
    },
    { name: 'pause', params: [], returns: 'void', doc: 'Stops playback.', call: (fig) => fig.guard(() => fig.pause()) },
    {
      name: 'seek', params: [{ name: 't', ts: 'number' }], returns: 'void',
      doc: 'Shows the moving object at time `t` in seconds (the `currentTime` setter).',
      call: (fig, t) => fig.guard(() => fig.seek(t)),
    },
  ],
  events: [
    { name: 'time', doc: 'The playhead moved: seconds t in [start, end] and the motion\'s parameter u.', detail: TIME_DETAIL },
    { name: 'timeupdate', doc: 'The playhead moved (as `time`, in HTMLMediaElement\'s name).', detail: TIME_DETAIL },
    { name: 'play', doc: 'Playback started.' },
    { name: 'pause', doc: 'Playback stopped.' },
    { name: 'ended', doc: 'An open motion that does not loop reached its end.' },
    { name: 'seeked', doc: 'A seek (or a set of currentTime) finished.' },
    { name: 'ratechange', doc: 'playbackRate changed.' },
  ],
  // A full apply (a load) sets the rate and loop from the options; a patch only what it names
  // (playbackRate and loop set as properties stay).
  apply(fig, v, { patch, full }) {
    const { anim } = fig.model;
    if (full || 'speed' in patch) anim.speed = v.speed;
    if (full || 'loop' in patch) anim.loop = v.loop;
  },
  drawn(fig, v, { patch, full }) {
    if ('autoplay' in patch && !full) fig.viewer.setPlaying(v.autoplay);
  },
  loaded(fig) {
    fig.playback.loaded();
  },
};

export class Playback {
  constructor(fig) {
    this.fig = fig;
    this.wasPlaying = false;
    /** What was asked before the motion loaded (applied by loaded()). */
    this.pending = {};
  }

  get viewer() {
    return this.fig.model.motion ? this.fig.viewer : null;
  }

  /**
   * Plays `repetitions` passes (a whole number ≥ 1) and ends, or without it as loop says.
   * @param {{repetitions?: number}} [options]
   */
  play({ repetitions } = {}) {
    const passes = repetitions == null || repetitions === Infinity ? null : number('repetitions', repetitions, 1, 1e9, true);
    const v = this.viewer;
    if (!v) {
      this.pending.play = { passes };
      return;
    }
    const { anim, motion } = this.fig.model;
    const [a, b] = motion.timeDomain();
    const t = v.playTime();
    // Playing from the end it ran to starts over (as a media element that has ended).
    if (!motion.closed && (anim.speed >= 0 ? t >= b : t <= a)) v.showTime(anim.speed >= 0 ? a : b);
    anim.passes = passes;
    v.setPlaying(true);
  }

  pause() {
    delete this.pending.play;
    this.viewer?.setPlaying(false);
  }

  get paused() {
    return !this.fig.model.anim.playing;
  }

  /** The viewer started or stopped playing: play / pause events on a change. */
  playing(on) {
    this.fig.refreshChrome();
    if (on === this.wasPlaying) return;
    this.wasPlaying = on;
    if (!on) this.fig.model.anim.passes = null;
    this.fig.say(on ? 'Playing' : `Paused at ${this.currentTime.toFixed(2)} s`);
    this.fig.emit(on ? 'play' : 'pause', {});
  }

  /** Playback ran to an end by itself. */
  ended() {
    this.fig.say(`Ended at ${this.currentTime.toFixed(2)} s`);
    this.fig.emit('ended', {});
  }

  seek(t) {
    const x = number('currentTime', t, -1e9, 1e9);
    const v = this.viewer;
    if (!v) {
      this.pending.time = x;
      return;
    }
    v.seekTime(x);
    this.fig.emit('seeked', {});
  }

  get currentTime() {
    return this.viewer ? this.viewer.playTime() : (this.pending.time ?? 0);
  }

  /** The playback interval's length in seconds (NaN before the motion loads). */
  get duration() {
    const m = this.fig.model.motion;
    if (!m) return NaN;
    const [a, b] = m.timeDomain();
    return b - a;
  }

  get playbackRate() {
    return this.fig.model.anim.speed;
  }

  set playbackRate(r) {
    const x = number('playbackRate', r, -100, 100);
    if (x === this.fig.model.anim.speed) return;
    this.fig.model.anim.speed = x;
    this.fig.emit('ratechange', {});
  }

  get loop() {
    return this.fig.model.anim.loop;
  }

  /** A boolean, or an attribute's string ("false" is false), as frameworks may pass either. */
  set loop(on) {
    const b = typeof on === 'string' ? on !== 'false' : !!on;
    this.fig.opts.loop = b;
    this.fig.model.anim.loop = b;
  }

  /** Steps to the next (1) or previous (-1) key pose's time, wrapping on a cycle. */
  stepKey(dir) {
    const v = this.viewer;
    if (!v) return;
    const { motion } = this.fig.model;
    const n = motion.poseCount;
    const keys = Array.from({ length: n }, (_, k) => motion.timeAt(k));
    const [a, b] = motion.timeDomain();
    if (motion.closed) keys.push(b);
    const t = v.playTime();
    const eps = 1e-9 * Math.max(1, Math.abs(b - a));
    let i = dir > 0 ? keys.findIndex((x) => x > t + eps) : keys.findLastIndex((x) => x < t - eps);
    // Past the last key a cycle goes round (its end is its start), an open motion stays.
    if (i < 0 && motion.closed) i = dir > 0 ? Math.min(1, n - 1) : n - 1;
    if (i < 0) return;
    this.seek(keys[i]);
    this.fig.say(`${describePose(motion, i % n)}, ${keys[i].toFixed(2)} s`);
  }

  /** The motion loaded: the time and play asked before take effect. */
  loaded() {
    const { time, play } = this.pending;
    this.pending = {};
    if (time !== undefined) this.seek(time);
    if (play) this.play({ repetitions: play.passes ?? undefined });
  }
}
