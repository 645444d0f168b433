// Pictures out of the 3-D view, for slides and handouts: a PNG screenshot and an MP4 or WebM video
// of one cycle of the motion, from the toolbar's View menu (editor/viewpoint.js).
//
// PNG: the view drawn again at 1× or 2× its drawing buffer (2× is drawn at twice the size, lines
// twice as wide, not scaled up) and copied in the same task (Viewer.snapshot: a WebGPU canvas is
// readable only until its frame is presented); a transparent background as figure/picture.js
// makes it.
//
// Video: one cycle of the motion at FPS frames per second of the motion's own time (the
// timeline's seconds): frame i shows time i / FPS, is drawn, and goes to a WebCodecs
// VideoEncoder stamped i / FPS; mediabunny (vendor/mediabunny.min.mjs, vendored from npm by
// scripts/serve.d/50-mediabunny.sh) muxes the encoded frames into the file. MP4 carries H.264 (what
// PowerPoint and Keynote play); WebM carries VP8 or VP9. A browser without an H.264 encoder gets
// WebM, with a message saying so. Every frame is in the video, however long the machine takes to
// draw and encode it (a progress bar and a Cancel button meanwhile). MediaRecorder on
// canvas.captureStream(0) stamps frames by the wall clock, and headless Chromium's canvas track
// drops frames of a canvas that takes long to draw (docs/speed/code-notes.md), so it is not
// used. cycle() is the one place this part
// touches the playback.
//
// Both leave out the selected pose's gizmo and highlight unless the View menu keeps them, and
// draw the pose numbers (page elements over the view, not part of its frames) when they are
// shown.
import { download } from './files.js';
import { picture } from '../figure/picture.js';

/** The muxer, fetched with the first video (it is not needed for the page's first frame). */
const loadMuxer = () => import('../../vendor/mediabunny.min.mjs');

/** Frames per second of the video. */
export const FPS = 30;
/** Bit rate asked of the encoder (bits per second). */
const VIDEO_BITS = 6e6;
/** The video containers: file extension and MIME type (videoCodecs below gives their codecs). */
export const VIDEO_FORMATS = {
  mp4: { ext: 'mp4', mime: 'video/mp4' },
  webm: { ext: 'webm', mime: 'video/webm' },
};
/**
 * H.264 levels (the codec string's last byte) by the most macroblocks (16 × 16 pixels) a frame may
 * have at that level: a decoder refuses a stream whose level is too low for its frame size.
 */
/** @type {[number, string][]} */
const AVC_LEVELS = [[3600, '1f'], [8192, '28'], [22080, '32'], [36864, '33'], [139264, '3c']];

/**
 * The WebCodecs codecs of `format` tried in order for a `width` × `height` video (the first the
 * encoder takes is used), each with mediabunny's name of it: for MP4, H.264 at the lowest level
 * that fits (Baseline, else High profile); for WebM, VP8, else VP9 profile 0.
 * @returns {{codec: string, mux: string, avc?: {format: string}}[]}
 */
export function videoCodecs(format, width, height) {
  if (format === 'webm') return [{ codec: 'vp8', mux: 'vp8' }, { codec: 'vp09.00.10.08', mux: 'vp9' }];
  const mbs = Math.ceil(width / 16) * Math.ceil(height / 16);
  const level = AVC_LEVELS.find(([most]) => mbs <= most)?.[1];
  if (!level) return [];
  return ['42', '64'].map((profile) => ({ codec: `avc1.${profile}00${level}`, mux: 'avc', avc: { format: 'avc' } }));
}
/** A key frame every this many frames (seeking in the video). */
const KEY_EVERY = 2 * FPS;
/** Frames waiting in the encoder before the next one is drawn (bounds the memory held). */
const MAX_QUEUE = 4;

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
 * show(t), the object at t seconds from the start (the viewer's seekTime, figure/viewer.js).
 */
function cycle(app) {
  const { start, end } = app.viewer.playhead();
  return { duration: end - start, show: (t) => app.viewer.seekTime(start + t) };
}

/**
 * Draws the pose numbers shown over the view (editor/labels.js: #pose-labels) onto `canvas`, a
 * picture of the whole view at its own size: the labels are page elements, not part of the 3-D
 * frame, so a picture would lose them.
 */
function drawPoseNumbers(app, canvas) {
  const layer = document.getElementById('pose-labels');
  if (!layer || layer.hidden) return;
  const view = app.viewer.canvas.getBoundingClientRect();
  const k = canvas.width / Math.max(1, view.width);
  const ctx = canvas.getContext('2d');
  for (const e of /** @type {NodeListOf<HTMLElement>} */ (layer.querySelectorAll('.pose-label'))) {
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
  const keep = /** @type {HTMLInputElement} */ (document.getElementById('m-png-selection'))?.checked;
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

/** @type {import('../app.js').Part} */
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
        app.parts.notices.show(`PNG scale: ${scale} is not 1 or 2`);
        return null;
      }
      let out;
      const reselect = hideSelection(app);
      try {
        out = picture(app.viewer, { scale, transparent, gizmo: true });
        drawPoseNumbers(app, out);
      } catch (e) {
        app.parts.notices.show(`The picture could not be made: ${e.message}`);
        return null;
      } finally {
        reselect();
      }
      const blob = await new Promise((resolve) => out.toBlob(resolve, 'image/png'));
      if (!blob) {
        app.parts.notices.show('The picture could not be encoded as PNG.');
        return null;
      }
      const name = `${fileBase(title())}${scale === 2 ? '@2x' : ''}.png`;
      download(name, blob, 'image/png');
      return { name, width: out.width, height: out.height };
    }

    /**
     * The encoder settings for a `width` × `height` video in `format` ('mp4' | 'webm'): { config,
     * mux, format } with the first codec the browser encodes (an MP4 without an H.264 encoder
     * becomes a WebM, and `fellBack` says why), or { why } when there is none.
     */
    async function videoConfig(format, width, height) {
      if (typeof window.VideoEncoder !== 'function' || typeof window.VideoFrame !== 'function') {
        return { why: 'this browser has no video encoder (WebCodecs VideoEncoder)' };
      }
      const first = async (f) => {
        for (const { codec, mux, avc } of videoCodecs(f, width, height)) {
          const config = /** @type {VideoEncoderConfig} */ ({ codec, width, height, bitrate: VIDEO_BITS, framerate: FPS, ...(avc ? { avc } : {}) });
          try {
            if ((await VideoEncoder.isConfigSupported(config)).supported) return { config, mux, format: f };
          } catch {
            // Not this codec: the next one.
          }
        }
        return null;
      };
      const got = await first(format);
      if (got) return got;
      if (format === 'mp4') {
        const webm = await first('webm');
        if (webm) return { ...webm, fellBack: `this browser has no H.264 encoder for ${width} × ${height} video, which MP4 needs` };
      }
      return { why: 'this browser encodes neither H.264 nor VP8 nor VP9 video' };
    }

    function showProgress(on, fraction = 0) {
      $('rec').hidden = !on;
      /** @type {HTMLProgressElement} */ ($('rec-progress')).value = fraction;
      $('rec-label').textContent = `Recording one cycle… ${Math.round(fraction * 100)} %`;
      /** @type {HTMLButtonElement} */ ($('m-video')).disabled = on;
    }

    /** The video format chosen in the View menu ('mp4' unless WebM is checked). */
    const chosenFormat = () => (/** @type {HTMLInputElement} */ ($('m-video-webm'))?.checked ? 'webm' : 'mp4');

    /**
     * Records one cycle of the motion as a video at FPS frames per second and downloads it:
     * `format` 'mp4' (H.264; WebM where the browser has no H.264 encoder, with a message) or
     * 'webm'. Resolves to { name, format, codec, frames, duration, bytes }, or null when it could
     * not start (a message says why; nothing changed), failed (a message) or was cancelled
     * (nothing downloaded).
     */
    async function recordVideo({ format = chosenFormat() } = {}) {
      if (recording) return null;
      if (!VIDEO_FORMATS[format]) {
        app.parts.notices.show(`Video format: ${JSON.stringify(format)} is not mp4 or webm`);
        return null;
      }
      const c = cycle(app);
      if (!(c.duration > 0 && Number.isFinite(c.duration))) {
        app.parts.notices.show('No video: the motion has no duration.', 'warn');
        return null;
      }
      // Even sides (what the H.264, VP8 and VP9 encoders take).
      const { w, h } = app.viewer.pixelSize();
      const width = w & ~1;
      const height = h & ~1;
      let cancelled = false;
      recording = { cancel: () => (cancelled = true) };
      const chosen = await videoConfig(format, width, height);
      if (!chosen.config) {
        recording = null;
        app.parts.notices.show(`No video: ${chosen.why}. Try a recent Chrome, Edge or Firefox.`, 'warn');
        return null;
      }
      const { config, mux } = chosen;
      const fmt = VIDEO_FORMATS[chosen.format];
      let muxer;
      try {
        muxer = await loadMuxer();
      } catch (e) {
        recording = null;
        app.parts.notices.show(`No video: the video writer could not load (${e.message}).`, 'warn');
        return null;
      }
      const { BufferTarget, EncodedPacket, EncodedVideoPacketSource, Mp4OutputFormat, Output, WebMOutputFormat } = muxer;
      // A cycle ends where it began: its last frame is the one before the first again; an open
      // motion shows its end pose too.
      const steps = Math.max(1, Math.round(c.duration * FPS));
      const count = app.motion.closed ? steps : steps + 1;
      const output = new Output({
        // MP4: the index first (a player starts without reading the whole file).
        format: chosen.format === 'mp4' ? new Mp4OutputFormat({ fastStart: 'in-memory' }) : new WebMOutputFormat(),
        target: new BufferTarget(),
      });
      const source = new EncodedVideoPacketSource(mux);
      output.addVideoTrack(source, { frameRate: FPS });
      let error = null;
      // The encoder hands out frames in decode order, which is the order the muxer takes them in.
      let muxed = Promise.resolve();
      const encoder = new VideoEncoder({
        output: (chunk, meta) => {
          const packet = EncodedPacket.fromEncodedChunk(chunk);
          muxed = muxed.then(() => source.add(packet, meta)).catch((e) => (error ??= e));
        },
        error: (e) => (error ??= e),
      });
      // The playback as it was, given back afterwards.
      const { playing, u, visible } = app.anim;
      if (playing) app.viewer.setPlaying(false);
      showProgress(true, 0);
      const reselect = hideSelection(app);
      // Each frame: the 3-D view copied with the pose numbers drawn on it.
      const still = document.createElement('canvas');
      still.width = width;
      still.height = height;
      try {
        await output.start();
        encoder.configure(config);
        for (let i = 0; i < count && !cancelled && !error; i++) {
          c.show(Math.min(i / FPS, c.duration));
          app.viewer.draw();
          still.getContext('2d').drawImage(app.viewer.canvas, 0, 0);
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
        if (!cancelled && !error) {
          await encoder.flush();
          await muxed;
        }
        if (!cancelled && !error) {
          source.close();
          await output.finalize();
        }
      } catch (e) {
        error ??= e;
      } finally {
        if (encoder.state !== 'closed') encoder.close();
        reselect();
        if (output.state !== 'finalized' && output.state !== 'canceled') await output.cancel().catch(() => {});
        recording = null;
        showProgress(false);
        app.setPlayback({ u, visible });
        app.viewer.updateAnim();
        if (playing) app.viewer.setPlaying(true);
        app.viewer.requestDraw();
        app.ui?.refresh();
      }
      if (cancelled) {
        app.ui?.toast('Recording cancelled: no video saved.');
        return null;
      }
      if (error) {
        app.parts.notices.show(`The video could not be recorded: ${error.message ?? error}`);
        return null;
      }
      const bytes = new Uint8Array(output.target.buffer);
      const name = `${fileBase(title())}.${fmt.ext}`;
      download(name, bytes, fmt.mime);
      const duration = count / FPS;
      const saved = `Saved ${name}: ${duration.toFixed(2)} s, ${count} frames at ${FPS} fps`;
      if (chosen.fellBack) app.parts.notices.show(`No MP4: ${chosen.fellBack}. ${saved} (WebM) instead.`, 'warn');
      else app.ui?.toast(saved);
      return { name, format: chosen.format, codec: config.codec, frames: count, duration, bytes: bytes.length };
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
        const scale = () => (/** @type {HTMLInputElement} */ ($('m-png-2x')).checked ? 2 : 1);
        $('m-png').addEventListener('click', () => {
          m.close();
          savePng({ scale: scale(), transparent: /** @type {HTMLInputElement} */ ($('m-png-transparent')).checked });
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
