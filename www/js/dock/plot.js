// Small line charts for the analysis views, on uPlot (vendored in www/vendor/): labelled ticks
// at 1-2-5 steps on both axes, a unit on the y axis, a playhead synced with playback and a hover
// callback (the dock shows that instant's pose in 3-D).
import uPlot from '../../vendor/uPlot.esm.js';
import { chartInk, seriesInk } from './ink.js';

/** Tick steps 1, 2, 5 × 10^e (the same numbers uPlot knows the decimals of). */
const NICE_STEPS = [];
for (let e = -16; e < 16; e++) for (const m of [1, 2, 5]) NICE_STEPS.push(+`${m}e${e}`);

/** Tick labels for tick values `splits` at step `step`: as many decimals as the step needs. */
export function tickLabels(splits, step) {
  const a = Math.max(...splits.map(Math.abs));
  if (a >= 1e5 || (a > 0 && a < 1e-3)) {
    // Mantissa × 10^e with the exponent of the largest tick and the step's digits: 2e-15, 2.5e-15.
    const e = Math.floor(Math.log10(a));
    const dec = Math.min(6, Math.max(0, e - Math.floor(Math.log10(step) + 1e-9)));
    return splits.map((v) => (Math.abs(v) < step * 1e-9 ? '0' : `${(v / 10 ** e).toFixed(dec)}e${e}`));
  }
  const dec = step > 0 ? Math.min(10, Math.max(0, -Math.floor(Math.log10(step) + 1e-9))) : 0;
  return splits.map((v) => (Math.abs(v) < step * 1e-9 ? 0 : v).toFixed(dec));
}

/** Every live chart (the theme switch redraws them). */
const allCharts = new Set();
/**
 * Legend swatches of the views' own legends (inkSwatch): the theme switch recolours them. Held
 * weakly, so that a view rebuilt many times does not keep its old legends alive here.
 */
const swatches = new Set();
let themeWatch = null;

/**
 * Gives element `e` (a legend swatch) the background of series colour `color` as drawn in the
 * theme shown (seriesInk), now and at every theme switch, so a legend the view builds itself
 * shows the same colour as the chart's line. Returns `e`.
 */
export function inkSwatch(e, color) {
  e.style.background = seriesInk(color);
  e.dataset.seriesColor = color;
  swatches.add(new WeakRef(e));
  watchTheme();
  return e;
}

/** Redraws every chart in the theme shown when <html data-theme> changes (zoom, data and playhead kept). */
function watchTheme() {
  if (themeWatch || typeof MutationObserver === 'undefined') return;
  let shown = document.documentElement.dataset.theme;
  themeWatch = new MutationObserver(() => {
    const now = document.documentElement.dataset.theme;
    if (now === shown) return;
    shown = now;
    for (const c of allCharts) c.restyle();
    for (const ref of swatches) {
      const e = ref.deref();
      if (e) e.style.background = seriesInk(e.dataset.seriesColor);
      else swatches.delete(ref);
    }
  });
  themeWatch.observe(document.documentElement, { attributes: true, attributeFilter: ['data-theme'] });
}

/** Where the playhead is: a function () => {t, u} (seconds and motion parameter), or null. */
let playheadSource = null;
/** Every live chart with a playhead (see sync()). */
const charts = new Set();
let polling = false;
/** How long (ms) the charts keep reading the playhead every frame after it last moved. */
const QUIET_MS = 1000;
/** When the playhead last moved or something may have moved it (performance.now()). */
let movedAt = 0;
/** The playhead last read. */
let lastT = NaN;
let lastU = NaN;

/**
 * Sets the playhead's source for every chart (the dock does, with the app's playback time).
 * Charts read it once per animation frame while it moves and for a second after, and move their
 * playhead only when it changed; then they rest until wakePlayheads (a loop reading it every
 * display frame would keep the processor busy for as long as the dock stays open).
 */
export function setPlayheadSource(source) {
  playheadSource = source;
  wakePlayheads();
}

/** Reads the playhead every frame again: the app's playback, motion or timing changed. */
export function wakePlayheads() {
  movedAt = performance.now();
  startPolling();
}

function startPolling() {
  if (polling || !playheadSource || charts.size === 0) return;
  polling = true;
  const tick = (now) => {
    if (charts.size === 0 || now - movedAt > QUIET_MS) {
      polling = false;
      return;
    }
    if (!document.hidden) syncPlayheads();
    requestAnimationFrame(tick);
  };
  requestAnimationFrame(tick);
}

/** Moves every chart's playhead to the source's time now (tests call it to skip a frame). */
export function syncPlayheads() {
  if (!playheadSource) return;
  const at = readPlayhead();
  if (!at) return;
  if (at.t !== lastT || at.u !== lastU) {
    lastT = at.t;
    lastU = at.u;
    movedAt = performance.now();
  }
  // Hidden charts (another view, the dock closed) catch up when drawn again.
  for (const c of charts) if (c.box.isConnected && c.box.offsetParent !== null) c.playheadAt(at);
}

/** The source's playhead, or null when there is none (no motion yet). */
function readPlayhead() {
  if (!playheadSource) return null;
  try {
    return playheadSource();
  } catch {
    return null;
  }
}

/**
 * A chart in `parent`: `series` = [{label, color, width?, dash?}], `x` the x-axis label, `y` the
 * y-axis label (with its unit). `marks` (x values, e.g. control-pose times) are drawn as thin
 * vertical lines; `legend: false` leaves the legend to the caller (one legend for several
 * charts). `playhead`: which playback coordinate the x axis is in ('t' seconds, 'u' the motion
 * parameter, false: none). `onHover(x | null)`: the pointer is over the plot at x (null: left).
 * `zeroBelow`: data whose every |y| is at most this is zero up to rounding (e.g. the angular
 * acceleration of a polyscrew, 1e-15 rad/s² of noise): the y axis then spans 0..1 instead of
 * magnifying the noise into spikes, and `chart.flat` is true (the data and hover are unchanged).
 * Returns {set(x, ys, marks?), setTitle(text), setYLabel(text), resize(width, height?), ticks(), playheadAt({t, u}),
 * playheadX, destroy(), plot, box}.
 * @param {HTMLElement} parent
 * @param {{title?: string, x?: string, y?: string, series?: {label: string, color?: string, width?: number, dash?: number[]}[], height?: number, log?: boolean, legend?: boolean, playhead?: string | false, onHover?: (x: number | null) => void, zeroBelow?: number | null}} [options]
 */
export function lineChart(parent, { title, x = 'u', y, series, height = 150, log = false, legend = true, playhead = 't', onHover, zeroBelow = null } = {}) {
  const box = document.createElement('div');
  box.className = 'chart';
  parent.append(box);
  let marks = [];
  /** Every |y| of the data is at most `zeroBelow`. */
  let flat = false;
  let h = height;
  let ready = false;
  /** The tick labels last drawn, per axis (0: x, 1: y). */
  const labels = [[], []];
  const values = (axis) => (u, splits, _idx, _space, step) => {
    const l = axis === 1 && log ? splits.map((v) => fmt(v, 2)) : tickLabels(splits, step);
    labels[axis] = l;
    return l;
  };
  // Axis, grid and tick colours are read at every draw, so a redraw shows the theme's ink.
  const inked = {
    stroke: () => chartInk().axis,
    grid: { stroke: () => chartInk().grid, width: 1 },
    ticks: { stroke: () => chartInk().grid, width: 1 },
  };
  const opts = {
    title,
    width: Math.max(200, parent.clientWidth || 480),
    height,
    scales: {
      x: { time: false },
      // uPlot's own y range (10 % padding, 0 kept in view) unless the data is rounding noise.
      y: log ? { distr: 3 } : { range: (_u, min, max) => (flat ? [0, 1] : min == null ? [null, null] : uPlot.rangeNum(min, max, 0.1, true)) },
    },
    legend: { show: legend, live: false },
    cursor: { drag: { x: true, y: false } },
    axes: [
      { label: x, size: 30, labelSize: 14, gap: 2, space: 36, incrs: NICE_STEPS, values: values(0), font: '11px system-ui', labelFont: '11px system-ui', ...inked },
      {
        label: y, labelSize: y ? 14 : 0, size: 44, gap: 2, space: 12, values: values(1), font: '11px system-ui', labelFont: '11px system-ui',
        ...(log ? {} : { incrs: NICE_STEPS }),
        ...inked,
      },
    ],
    series: [
      {},
      ...series.map((s) => ({
        label: s.label,
        stroke: () => seriesInk(s.color),
        width: s.width ?? 1.5,
        dash: s.dash,
        points: { show: false },
      })),
    ],
    hooks: {
      draw: [
        (u) => {
          const ctx = u.ctx;
          ctx.save();
          ctx.strokeStyle = chartInk().marks;
          ctx.lineWidth = 1;
          ctx.setLineDash([3, 3]);
          for (const m of marks) {
            const px = u.valToPos(m, 'x', true);
            if (px < u.bbox.left || px > u.bbox.left + u.bbox.width) continue;
            ctx.beginPath();
            ctx.moveTo(px, u.bbox.top);
            ctx.lineTo(px, u.bbox.top + u.bbox.height);
            ctx.stroke();
          }
          ctx.restore();
          if (ready) {
            // A redraw (new data, a resize, shown again) also catches up with the playhead.
            if (playhead && playheadSource) at = readPlayhead() ?? at;
            place();
          }
        },
      ],
    },
  };
  const plot = new uPlot(/** @type {import('../../vendor/uPlot.esm.js').default.Options} */ (opts), [[], ...series.map(() => [])], box);
  // The playhead: a line over the plotting area, moved without redrawing the chart.
  const line = document.createElement('div');
  line.className = 'playhead';
  line.hidden = true;
  plot.over.append(line);
  let at = null;
  function place() {
    const v = at === null ? null : at[/** @type {string} */ (playhead)];
    const px = v === null || v === undefined || !Number.isFinite(v) ? NaN : plot.valToPos(v, 'x');
    const inside = Number.isFinite(px) && px >= 0 && px <= plot.over.clientWidth;
    line.hidden = !inside;
    if (inside) line.style.transform = `translateX(${px.toFixed(1)}px)`;
    chart.playheadX = inside ? v : null;
  }
  if (onHover) {
    plot.over.addEventListener('pointermove', (e) => {
      const r = plot.over.getBoundingClientRect();
      const v = plot.posToVal(e.clientX - r.left, 'x');
      if (Number.isFinite(v)) onHover(v);
    });
    plot.over.addEventListener('pointerleave', () => onHover(null));
  }
  const chart = {
    plot,
    box,
    /** The x value the playhead shows (null: none or outside the plot). */
    playheadX: null,
    /** Every |y| of the data is at most `zeroBelow` (see above). */
    get flat() {
      return flat;
    },
    set(xs, ys, newMarks = marks) {
      marks = newMarks;
      // A zoom in x survives new data over the same x range (an edit, a view setting, the
      // theme): the y axis fits the new data in the zoomed window.
      const old = plot.data?.[0];
      const { min, max } = plot.scales.x;
      const n = xs.length;
      const sameX = old && old.length === n && n > 0 && old[0] === xs[0] && old[n - 1] === xs[n - 1];
      const zoomed = sameX && Number.isFinite(min) && Number.isFinite(max) && (min > old[0] || max < old[n - 1]);
      flat = zeroBelow !== null && n > 0 && ys.every((v) => Array.prototype.every.call(v, (y) => !(Math.abs(y) > zeroBelow)));
      plot.setData([Array.from(xs), ...ys.map((v) => Array.from(v))]);
      if (zoomed) plot.setScale('x', { min, max });
    },
    setTitle(text) {
      const t = plot.root.querySelector('.u-title');
      if (t) t.textContent = text;
    },
    /** Sets the y axis's label (drawn with the next data). */
    setYLabel(text) {
      if (plot.axes[1]) plot.axes[1].label = text;
    },
    resize(width, height = h) {
      h = height;
      plot.setSize({ width: Math.max(200, width), height: h });
    },
    /** The tick labels last drawn: {x: [...], y: [...]}. */
    ticks() {
      return { x: [...labels[0]], y: [...labels[1]] };
    },
    /** Moves the playhead to `{t, u}` (only when it changed). */
    playheadAt(next) {
      if (!playhead) return;
      if (at && next && at.t === next.t && at.u === next.u) return;
      at = next ? { t: next.t, u: next.u } : null;
      place();
    },
    /** Redraws in the theme shown now (the theme changed): the same data, zoom and playhead. */
    restyle() {
      // uPlot colours its legend's markers once, when it builds the legend. Its legend has a
      // row for the x values only when it is live (not here), so count the rows from the end.
      const rows = plot.root.querySelectorAll('.u-legend .u-series');
      const first = rows.length - series.length;
      rows.forEach((row, i) => {
        const marker = /** @type {HTMLElement | null} */ (row.querySelector('.u-marker'));
        const s = series[i - first];
        if (marker && s) marker.style.borderColor = seriesInk(s.color);
      });
      plot.redraw(true, false);
    },
    destroy() {
      allCharts.delete(chart);
      charts.delete(chart);
      plot.destroy();
      box.remove();
    },
  };
  ready = true;
  allCharts.add(chart);
  watchTheme();
  if (playhead) {
    charts.add(chart);
    wakePlayheads();
  }
  return chart;
}

/** A number for tables: 0, fixed for moderate magnitudes, else exponential. */
export function fmt(v, digits = 3) {
  if (v === null || v === undefined) return '–';
  if (!Number.isFinite(v)) return String(v);
  if (v === 0) return '0';
  const a = Math.abs(v);
  return a >= 1e-2 && a < 1e4 ? v.toPrecision(digits) : v.toExponential(digits - 1);
}

