// Pictures out of the 3-D view, for slides and handouts: a PNG screenshot and a WebM video of
// one cycle of the motion, from the toolbar's View menu (editor/viewpoint.js).
//
// PNG: the view drawn again at 1× or 2× its drawing buffer (2× is drawn at twice the size, lines
// twice as wide, not scaled up) and copied in the same task (Viewer.snapshot: a WebGPU canvas is
// readable only until its frame is presented). A transparent background comes from two frames,
// on black and on white: where they differ the background shows through (alpha = 1 − the
// difference), and the colour is the black frame's divided by alpha.
//
// Video: one cycle of the motion at FPS frames per second of the motion's own time (the
// timeline's seconds): frame i shows time i / FPS, is drawn, and goes to a WebCodecs
// VideoEncoder (VP8, else VP9) stamped i / FPS; editor/webm.js writes the WebM file. Every frame
// is in the video, however long the machine takes to draw and encode it (a progress bar and a
// Cancel button meanwhile). MediaRecorder on canvas.captureStream(0) was the first choice, but
// it stamps frames by the wall clock, and headless Chromium's canvas track delivered none of 60
// requested frames of the WebGL canvas (a 2-D copy: 43 frames spread over 7.4 s for 2 s of
// motion). cycle() is the one place this part touches the playback.
//
// Both leave out the selected pose's gizmo and highlight unless the View menu keeps them, and
// draw the pose numbers (page elements over the view, not part of its frames) when they are
// shown.
import { download } from './files.js';
import { webmFile } from './webm.js';

/** Frames per second of the video. */
export const FPS = 30;
/** Bit rate asked of the encoder (bits per second). */
const VIDEO_BITS = 6e6;
/** WebCodecs codecs tried in order (the first the encoder takes is used): VP8, VP9 profile 0. */
const VIDEO_CODECS = ['vp8', 'vp09.00.10.08'];
/** A key frame every this many frames (seeking in the video). */
const KEY_EVERY = 2 * FPS;
/** Frames waiting in the encoder before the next one is drawn (bounds the memory held). */
const MAX_QUEUE = 4;
/** Background of the transparent picture's two frames (sRGB). */
const BLACK = [0, 0, 0];
const WHITE = [1, 1, 1];

/** A file name from a title: lower case, words joined by '-', nothing a file system refuses. */
export function fileBase(title) {
  const s = String(title ?? '')
    .normalize('NFKD')
    .replace(/[\u0300-\u036f]/g, '')
    .toLowerCase()
    .replace(/[^a-z0-9]+/g, '-')
    .replace(/^-+|-+$/g, '')
    .slice(0, 80);
  return s || 'screwbender';
}

/**
 * The motion's playback for the recorder: its duration in seconds (the timeline's interval) and
 * show(t), the object at t seconds from the start (app.seekTime, view/viewer.js).
 */
function cycle(app) {
  const { start, end } = app.viewer.playhead();
  return { duration: end - start, show: (t) => app.seekTime(start + t) };
}

/** A 2-D canvas holding a copy of `source` (drawn in the same task as the frame). */
function copyOf(source) {
  const c = document.createElement('canvas');
  c.width = source.width;
  c.height = source.height;
  c.getContext('2d', { willReadFrequently: true }).drawImage(source, 0, 0);
  return c;
}

/** The picture of the two frames on black and on white with the background made transparent. */
function unmatte(onBlack, onWhite) {
  const { width: w, height: h } = onBlack;
  const ctx = onBlack.getContext('2d', { willReadFrequently: true });
  const black = ctx.getImageData(0, 0, w, h);
  const white = onWhite.getContext('2d', { willReadFrequently: true }).getImageData(0, 0, w, h).data;
  const d = black.data;
  for (let i = 0; i < d.length; i += 4) {
    // Per channel white − black = 255 (1 − alpha); the mean of the three is the least noisy.
    const diff = (white[i] - d[i] + white[i + 1] - d[i + 1] + white[i + 2] - d[i + 2]) / 3;
    const a = Math.max(0, Math.min(255, 255 - diff));
    if (a > 0) {
      const k = 255 / a;
      d[i] = Math.min(255, d[i] * k);
      d[i + 1] = Math.min(255, d[i + 1] * k);
      d[i + 2] = Math.min(255, d[i + 2] * k);
    }
    d[i + 3] = a;
  }
  ctx.putImageData(black, 0, 0);
  return onBlack;
}

/**
 * Draws the pose numbers shown over the view (editor/labels.js: #pose-labels) onto `canvas`, a
 * picture of the whole view at its own size: the labels are page elements, not part of the 3-D
 * frame, so a picture would lose them.
 */
function drawPoseNumbers(app, canvas) {
  const layer = document.getElementById('pose-labels');
  if (!layer || layer.hidden) return;
  const view = app.canvas.getBoundingClientRect();
  const k = canvas.width / Math.max(1, view.width);
  const ctx = canvas.getContext('2d');
  for (const e of layer.querySelectorAll('.pose-label')) {
    if (e.hidden) continue;
    const r = e.getBoundingClientRect();
    if (r.width === 0) continue;
    const st = getComputedStyle(e);
    const x = (r.left - view.left) * k;
    const y = (r.top - view.top) * k;
    ctx.fillStyle = st.backgroundColor;
    ctx.beginPath();
    ctx.roundRect(x, y, r.width * k, r.height * k, 4 * k);
    ctx.fill();
    ctx.fillStyle = st.color;
    ctx.font = `${st.fontWeight} ${parseFloat(st.fontSize) * k}px ${st.fontFamily}`;
    ctx.textAlign = 'center';
    ctx.textBaseline = 'middle';
    ctx.fillText(e.textContent, x + (r.width * k) / 2, y + (r.height * k) / 2);
  }
}

/**
 * Leaves out the gizmo and the selection highlight while pictures are taken, unless the View
 * menu's "gizmo & selection" is ticked: returns the function that selects the pose again.
 */
function hideSelection(app) {
  const keep = document.getElementById('m-png-selection')?.checked;
  const selected = app.selected;
  if (keep || selected < 0) return () => {};
  app.select(-1);
  // The pose numbers drop their "selected" colour too.
  app.parts.labels?.place();
  return () => {
    app.select(selected);
    app.parts.labels?.place();
  };
}

export default {
  id: 'media',
  create(app) {
    const $ = (id) => document.getElementById(id);
    /** The recording in progress: { cancel() }, else null. */
    let recording = null;

    const title = () => app.motion?.name || app.view.scene || 'screwbender';

    /**
     * Saves the view as a PNG: `scale` 1 or 2 (times the drawing buffer), `transparent` for no
     * background. Resolves to { name, width, height }, or null after a message when it failed
     * (nothing changed).
     */
    async function savePng({ scale = 1, transparent = false } = {}) {
      if (scale !== 1 && scale !== 2) {
        app.showError(`PNG scale: ${scale} is not 1 or 2`);
        return null;
      }
      let out;
      const reselect = hideSelection(app);
      try {
        const frames = [];
        app.viewer.snapshot(scale, transparent ? [BLACK, WHITE] : [null], (canvas) => frames.push(copyOf(canvas)));
        out = transparent ? unmatte(frames[0], frames[1]) : frames[0];
        drawPoseNumbers(app, out);
      } catch (e) {
        app.showError(`The picture could not be made: ${e.message}`);
        return null;
      } finally {
        reselect();
      }
      const blob = await new Promise((resolve) => out.toBlob(resolve, 'image/png'));
      if (!blob) {
        app.showError('The picture could not be encoded as PNG.');
        return null;
      }
      const name = `${fileBase(title())}${scale === 2 ? '@2x' : ''}.png`;
      download(name, blob, 'image/png');
      return { name, width: out.width, height: out.height };
    }

    /**
     * The encoder settings for a `width` × `height` video: { config } with the first codec of
     * VIDEO_CODECS the browser encodes, or { why } when there is none.
     */
    async function videoConfig(width, height) {
      if (typeof window.VideoEncoder !== 'function' || typeof window.VideoFrame !== 'function') {
        return { why: 'this browser has no video encoder (WebCodecs VideoEncoder)' };
      }
      for (const codec of VIDEO_CODECS) {
        const config = { codec, width, height, bitrate: VIDEO_BITS, framerate: FPS };
        try {
          if ((await VideoEncoder.isConfigSupported(config)).supported) return { config };
        } catch {
          // Not this codec: the next one.
        }
      }
      return { why: 'this browser encodes neither VP8 nor VP9 video' };
    }

    function showProgress(on, fraction = 0) {
      $('rec').hidden = !on;
      $('rec-progress').value = fraction;
      $('rec-label').textContent = `Recording one cycle… ${Math.round(fraction * 100)} %`;
      $('m-video').disabled = on;
    }

    /**
     * Records one cycle of the motion as a WebM video at FPS frames per second and downloads it.
     * Resolves to { name, frames, duration, bytes }, or null when it could not start (a message
     * says why; nothing changed), failed (a message) or was cancelled (nothing downloaded).
     */
    async function recordVideo() {
      if (recording) return null;
      const c = cycle(app);
      if (!(c.duration > 0 && Number.isFinite(c.duration))) {
        app.showError('No video: the motion has no duration.', 'warn');
        return null;
      }
      // Even sides (what the VP8 and VP9 encoders take).
      const { w, h } = app.pixelSize();
      const width = w & ~1;
      const height = h & ~1;
      let cancelled = false;
      recording = { cancel: () => (cancelled = true) };
      const { config, why } = await videoConfig(width, height);
      if (!config) {
        recording = null;
        app.showError(`No video: ${why}. Try a recent Chrome, Edge or Firefox.`, 'warn');
        return null;
      }
      // A cycle ends where it began: its last frame is the one before the first again; an open
      // motion shows its end pose too.
      const steps = Math.max(1, Math.round(c.duration * FPS));
      const count = app.motion.closed ? steps : steps + 1;
      const chunks = [];
      let error = null;
      const encoder = new VideoEncoder({
        output: (chunk) => {
          const data = new Uint8Array(chunk.byteLength);
          chunk.copyTo(data);
          chunks.push({ data, timestamp: chunk.timestamp, key: chunk.type === 'key' });
        },
        error: (e) => (error ??= e),
      });
      // The playback as it was, given back afterwards.
      const { playing, u, visible } = app.anim;
      if (playing) app.setPlaying(false);
      showProgress(true, 0);
      const reselect = hideSelection(app);
      // Each frame: the 3-D view copied with the pose numbers drawn on it.
      const still = document.createElement('canvas');
      still.width = width;
      still.height = height;
      try {
        encoder.configure(config);
        for (let i = 0; i < count && !cancelled && !error; i++) {
          c.show(Math.min(i / FPS, c.duration));
          app.viewer.draw();
          still.getContext('2d').drawImage(app.canvas, 0, 0);
          drawPoseNumbers(app, still);
          const frame = new VideoFrame(still, {
            timestamp: Math.round((i * 1e6) / FPS),
            duration: Math.round(1e6 / FPS),
            visibleRect: { x: 0, y: 0, width, height },
          });
          encoder.encode(frame, { keyFrame: i % KEY_EVERY === 0 });
          frame.close();
          showProgress(true, (i + 1) / count);
          // The page stays responsive (Cancel) and the encoder's queue short.
          do await new Promise((resolve) => setTimeout(resolve, 0));
          while (encoder.encodeQueueSize > MAX_QUEUE && !cancelled && !error);
        }
        if (!cancelled && !error) await encoder.flush();
      } catch (e) {
        error ??= e;
      } finally {
        if (encoder.state !== 'closed') encoder.close();
        reselect();
        recording = null;
        showProgress(false);
        app.anim.u = u;
        app.anim.visible = visible;
        app.updateAnim();
        if (playing) app.setPlaying(true);
        app.requestDraw();
        app.ui?.refresh();
      }
      if (cancelled) {
        app.ui?.toast('Recording cancelled: no video saved.');
        return null;
      }
      let bytes;
      try {
        if (error) throw error;
        chunks.sort((a, b) => a.timestamp - b.timestamp);
        bytes = webmFile({ codec: config.codec, width, height, durationMs: (count * 1000) / FPS, frames: chunks });
      } catch (e) {
        app.showError(`The video could not be recorded: ${e.message ?? e}`);
        return null;
      }
      const name = `${fileBase(title())}.webm`;
      download(name, bytes, 'video/webm');
      const duration = count / FPS;
      app.ui?.toast(`Saved ${name}: ${duration.toFixed(2)} s, ${count} frames at ${FPS} fps`);
      return { name, frames: count, duration, bytes: bytes.length };
    }

    /** Stops the recording in progress without saving it. */
    function cancelVideo() {
      recording?.cancel();
    }

    return {
      savePng,
      recordVideo,
      cancelVideo,
      get recording() {
        return !!recording;
      },
      bind() {
        const m = app.parts.viewpoint.menu;
        const scale = () => ($('m-png-2x').checked ? 2 : 1);
        $('m-png').addEventListener('click', () => {
          m.close();
          savePng({ scale: scale(), transparent: $('m-png-transparent').checked });
        });
        $('m-video').addEventListener('click', () => {
          m.close();
          recordVideo();
        });
        $('rec-cancel').addEventListener('click', cancelVideo);
      },
    };
  },
};
