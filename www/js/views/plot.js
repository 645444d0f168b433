// Small line charts for the analysis views, on uPlot (vendored in www/vendor/).
import uPlot from '../../vendor/uPlot.esm.js';

/** Distinct colours (colour-blind safe, Okabe–Ito) for series that are not the paper's schemes. */
export const PALETTE = ['#0072b2', '#d55e00', '#009e73', '#cc79a7', '#e69f00', '#56b4e9', '#000000'];

/**
 * A chart in `parent`: `series` = [{label, color, width?, dash?}], `x` the x-axis label.
 * `marks` (x values, e.g. control-pose times) are drawn as thin vertical lines; `legend: false`
 * leaves the legend to the caller (one legend for several charts).
 * Returns {set(x, ys, marks?), setTitle(text), resize(width), destroy(), plot}.
 */
export function lineChart(parent, { title, x = 'u', series, height = 150, log = false, legend = true }) {
  const box = document.createElement('div');
  box.className = 'chart';
  parent.append(box);
  let marks = [];
  const opts = {
    title,
    width: Math.max(200, parent.clientWidth || 480),
    height,
    scales: { x: { time: false }, y: log ? { distr: 3 } : {} },
    legend: { show: legend, live: false },
    cursor: { drag: { x: true, y: false } },
    axes: [
      { label: x, size: 34, labelSize: 14, font: '11px system-ui', labelFont: '11px system-ui' },
      { size: 52, font: '11px system-ui' },
    ],
    series: [
      {},
      ...series.map((s) => ({
        label: s.label,
        stroke: s.color,
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
          ctx.strokeStyle = 'rgba(29,34,48,0.28)';
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
        },
      ],
    },
  };
  const plot = new uPlot(opts, [[], ...series.map(() => [])], box);
  return {
    plot,
    set(xs, ys, newMarks = marks) {
      marks = newMarks;
      plot.setData([Array.from(xs), ...ys.map((y) => Array.from(y))]);
    },
    setTitle(text) {
      const t = plot.root.querySelector('.u-title');
      if (t) t.textContent = text;
    },
    resize(width) {
      plot.setSize({ width: Math.max(200, width), height });
    },
    destroy() {
      plot.destroy();
      box.remove();
    },
  };
}

/** A number for tables: 0, fixed for moderate magnitudes, else exponential. */
export function fmt(v, digits = 3) {
  if (v === null || v === undefined) return '–';
  if (!Number.isFinite(v)) return String(v);
  if (v === 0) return '0';
  const a = Math.abs(v);
  return a >= 1e-2 && a < 1e4 ? v.toPrecision(digits) : v.toExponential(digits - 1);
}

/** Builds an element with text content (never HTML from strings: names may come from files). */
export function el(tag, props = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(props)) {
    if (k === 'class') e.className = v;
    else if (k === 'style') e.style.cssText = v;
    else if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
    else if (k in e) e[k] = v;
    else e.setAttribute(k, v);
  }
  for (const c of children) if (c !== null && c !== undefined) e.append(c instanceof Node ? c : String(c));
  return e;
}
