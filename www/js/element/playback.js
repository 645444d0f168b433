// A figure's script API beyond its options, with the names and meanings of HTMLMediaElement
// where they apply: playback (play({repetitions}), pause, currentTime, duration, paused,
// playbackRate, loop and the events play, pause, ended, timeupdate, seeked, ratechange), the
// camera as state (the `camera` property, `camera-change` with detail.source 'user' | 'api'),
// pictures (toBlob, toDataURL), and the words the live region says about them. Times are the
// motion's own seconds (pose i at motion.times[i], else at i s), as seek(t) and `time` give them.
import { picture } from '../view/picture.js';
import { OptionError, number, oneOf } from './options.js';

const SCHEME_NAMES = { bspline: 'B-spline', fourpoint: '4-point', jarek: 'Jarek', j: 'J_s' };
const PROJECTIONS = ['perspective', 'orthographic'];
const TYPES = ['image/png', 'image/jpeg', 'image/webp'];
/** Largest picture scale (times the drawing buffer); the device's texture limit also applies. */
const MAX_SCALE = 8;

/** "4-point scheme" and the like, from a motion's options. */
export function schemeName(o) {
  return `${SCHEME_NAMES[o.scheme] ?? o.scheme} scheme${o.scheme === 'j' ? ` (s = ${o.s})` : ''}`;
}

const fmt = (v) => v.map((x) => (Math.abs(x) < 5e-3 ? 0 : x).toFixed(2)).join(', ');

/** "Pose 3 at (1.00, 2.00, 0.00)". */
export function describePose(motion, k) {
  return `Pose ${k} at (${fmt(motion.pose(k).origin)})`;
}

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

  // ---------------------------------------------------------------- playback

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

  /** The motion loaded: what was asked before takes effect. */
  loaded() {
    const { time, play, camera } = this.pending;
    this.pending = {};
    if (camera) this.setCamera(camera);
    if (time !== undefined) this.seek(time);
    if (play) this.play({ repetitions: play.passes ?? undefined });
  }

  // ---------------------------------------------------------------- camera

  /** {yaw, pitch, distance, target, projection} (radians, scene units), or null before the start. */
  get camera() {
    const c = this.viewer?.camera;
    if (!c) return this.pending.camera ? { ...this.pending.camera } : null;
    return { yaw: c.yaw, pitch: c.pitch, distance: c.distance, target: [...c.target], projection: c.ortho ? 'orthographic' : 'perspective' };
  }

  /**
   * Sets the fields given (checked first: a bad one changes nothing); fires camera-change 'api'.
   * A string is the `camera` attribute's value (a named view, "yaw pitch [distance]" or
   * "yaw pitch distance tx ty tz").
   */
  setCamera(s) {
    if (typeof s === 'string') {
      this.fig.setOptions({ camera: s });
      return;
    }
    if (!s || typeof s !== 'object') throw new OptionError('camera', s, 'expected an object {yaw, pitch, distance, target, projection}');
    const out = {};
    for (const key of Object.keys(s)) {
      if (!['yaw', 'pitch', 'distance', 'target', 'projection'].includes(key)) throw new OptionError('camera', key, 'unknown camera field (yaw, pitch, distance, target, projection)');
    }
    if (s.yaw !== undefined) out.yaw = number('camera.yaw', s.yaw, -1e6, 1e6);
    if (s.pitch !== undefined) out.pitch = number('camera.pitch', s.pitch, -Math.PI / 2, Math.PI / 2);
    if (s.distance !== undefined) out.distance = number('camera.distance', s.distance, 1e-6, 1e7);
    if (s.distance === 0) throw new OptionError('camera.distance', 0, 'must be more than 0');
    if (s.target !== undefined) {
      const t = /** @type {ArrayLike<number>} */ (s.target);
      if (!(Array.isArray(t) || ArrayBuffer.isView(t)) || t.length !== 3) throw new OptionError('camera.target', t, 'expected [x, y, z]');
      out.target = Array.from(t, (x, i) => number(`camera.target[${i}]`, x, -1e9, 1e9));
    }
    if (s.projection !== undefined) out.projection = oneOf('camera.projection', s.projection, PROJECTIONS);
    const v = this.viewer;
    if (!v) {
      this.pending.camera = { ...this.pending.camera, ...out };
      return;
    }
    const { projection, ...rest } = out;
    Object.assign(v.camera, rest);
    if (projection) v.camera.ortho = projection === 'orthographic';
    v.cameraMoved('api');
  }

  /** The viewer's camera moved. */
  cameraMoved(source) {
    this.fig.emit('camera-change', { source, camera: this.camera });
  }

  // ---------------------------------------------------------------- pictures

  /**
   * A 2-D canvas of the current view: `scale` times the drawing buffer (drawn at that size),
   * `transparent` background, `gizmo` to keep the selected pose's gizmo. Throws a RangeError
   * naming the option at fault, or when the figure has not started.
   */
  picture({ scale = 1, transparent = false, gizmo = false, type = 'image/png' } = {}) {
    if (!TYPES.includes(type)) throw new RangeError(`type: ${type} is not one of ${TYPES.join(', ')}`);
    if (!(typeof scale === 'number' && scale > 0 && scale <= MAX_SCALE)) throw new RangeError(`scale: ${scale} is not a number in (0, ${MAX_SCALE}]`);
    if (transparent && type === 'image/jpeg') throw new RangeError('transparent: image/jpeg has no transparency (use image/png or image/webp)');
    const v = this.viewer;
    if (!v?.renderer) {
      throw new RangeError(v?.suspended
        ? 'the figure rests while far from the viewport (it draws again when scrolled near)'
        : 'the figure has not started yet (a lazy figure starts near the viewport; await ready, or loading="eager")');
    }
    return picture(v, { scale, transparent: !!transparent, gizmo: !!gizmo });
  }

  /** The picture as a data: URL (see picture; `quality` 0 to 1 for JPEG and WebP). */
  toDataURL(opts = {}) {
    const q = quality(opts.quality);
    return this.picture(opts).toDataURL(opts.type ?? 'image/png', q);
  }

  /** The picture as a Blob (a promise; rejects with the error picture throws). */
  async toBlob(opts = {}) {
    const q = quality(opts.quality);
    const c = this.picture(opts);
    const blob = await new Promise((resolve) => c.toBlob(resolve, opts.type ?? 'image/png', q));
    if (!blob) throw new RangeError(`the picture could not be encoded as ${opts.type ?? 'image/png'}`);
    return blob;
  }
}

function quality(q) {
  if (q === undefined) return undefined;
  if (!(typeof q === 'number' && q >= 0 && q <= 1)) throw new RangeError(`quality: ${q} is not a number in [0, 1]`);
  return q;
}
