// The timeline: play / pause, the scrubber over the playback interval in seconds (the motion's
// own key times), the key markers above it (editor/key-markers.js), speed and loop, and the
// time readout.
import { buildKeyMarkers } from './key-markers.js';

/**
 * Wires the timeline's controls; returns {refresh, setTime}.
 * @param {import('../app.js').App} app
 */
export function buildTimeline(app) {
  const $ = (id) => document.getElementById(id);
  $('play').onclick = () => app.viewer.setPlaying(!app.anim.playing);
  const scrub = /** @type {HTMLInputElement} */ ($('scrub'));
  scrub.addEventListener('input', () => {
    const [a, b] = app.motion.timeDomain();
    app.viewer.seekTime(a + (b - a) * (Number(scrub.value) / 1000));
  });
  const keyMarkers = buildKeyMarkers(app, $('keys'));
  const speed = /** @type {HTMLInputElement} */ ($('speed'));
  speed.addEventListener('input', () => app.setPlayback({ speed: Number(speed.value) }));
  const loop = /** @type {HTMLInputElement} */ ($('loop'));
  loop.addEventListener('change', () => app.setPlayback({ loop: loop.checked }));

  /** Shows playback (play button, speed, loop) and the key markers. */
  function refresh() {
    $('play').textContent = app.anim.playing ? '❚❚' : '▶';
    $('play').title = app.anim.playing ? 'Pause (Space)' : 'Play (Space)';
    $('play').setAttribute('aria-label', app.anim.playing ? 'Pause' : 'Play');
  }

  /** Shows speed, loop and the key markers (after the toolbar's pressed states). */
  function refreshControls() {
    speed.value = String(app.anim.speed);
    loop.checked = app.anim.loop;
    loop.disabled = app.motion.closed;
    keyMarkers.place();
  }

  /**
   * The playhead moved: u in [a, b], and `playhead` {t, start, end} in seconds.
   * @param {number} u
   * @param {number} a
   * @param {number} b
   * @param {{t: number, start: number, end: number}} playhead
   */
  function setTime(u, a, b, playhead) {
    const { t, start, end } = playhead;
    scrub.value = String(Math.round(((t - start) / (end - start)) * 1000));
    $('time').textContent = `t = ${t.toFixed(2)} s · u = ${u.toFixed(2)}`;
    $('time').title = `Time ${t.toFixed(3)} s of ${start.toFixed(2)}–${end.toFixed(2)} s; motion parameter u = ${u.toFixed(3)} of ${a}–${b}`;
    scrub.setAttribute('aria-valuetext', `${t.toFixed(2)} seconds, u = ${u.toFixed(2)}`);
    app.parts.pose.setTime(u);
  }

  return { refresh, refreshControls, setTime };
}
