// The charts' colours and their contrast checks: the series palette, the ink of each theme, the
// card the charts are drawn on, and the WCAG contrast that keeps every series line readable on
// it (seriesInk). Touches `document` only inside functions, so it loads in Node as it is.

/** Distinct colours (colour-blind safe, Okabe–Ito) for series that are not the paper's schemes. */
export const PALETTE = ['#0072b2', '#d55e00', '#009e73', '#cc79a7', '#e69f00', '#56b4e9', '#000000'];

/**
 * The charts' ink per theme (the page's <html data-theme>, set by editor/theme.js): tick labels
 * and axis titles, grid and tick lines, the control-pose marks, and the colour near-black series
 * take in the dark theme (black has no hue to keep, so it takes the light text ink rather than a
 * grey; see seriesInk). Light is uPlot's own default look.
 */
export const CHART_INK = {
  light: { axis: '#000000', grid: 'rgba(0,0,0,0.07)', marks: 'rgba(29,34,48,0.28)', series: null },
  dark: { axis: '#d5dae3', grid: 'rgba(230,233,239,0.13)', marks: 'rgba(230,233,239,0.32)', series: '#e6e9ef' },
};

/**
 * The card the charts are drawn on, per theme, for the series' contrast (seriesInk). The charts
 * are transparent on the analysis dock, whose background is translucent: style.css `#dock`
 * (light, rgba(250, 251, 253, 0.96)) and `html[data-theme="dark"] #dock` (dark,
 * rgba(30, 34, 43, 0.96)). What shows through the 4 % (the page, or the 3-D view when it lies
 * under the dock) is unknown here, so each value is the dock composited over the backdrop that
 * brings it closest to the series: black under the light dock (#f0f1f3), white under the dark
 * one (#272b33). A series that passes on these passes on any backdrop. Keep in step with
 * style.css (the e2e test analysis.test.mjs reads the dock's colour and checks the lines).
 */
export const CHART_BG = { light: '#f0f1f3', dark: '#272b33' };

/** WCAG 2.1 SC 1.4.11: graphical objects needed to understand content want 3:1 against what is next to them. */
export const MIN_CONTRAST = 3;

/**
 * How far each step of seriesInk mixes a failing colour toward white or black (a fraction of
 * the way): small enough that the result stays close to the colour it was, at most 20 steps.
 */
const MIX_STEP = 0.05;

/** The name of the theme shown now: 'light' or 'dark'. */
function themeShown() {
  return document.documentElement.dataset.theme === 'dark' ? 'dark' : 'light';
}

/** The ink of the theme shown now. */
export function chartInk() {
  return CHART_INK[themeShown()];
}

/** Relative luminance (0..1, WCAG 2.1) of a #rrggbb colour; null for other notations. */
function luminance(color) {
  const m = /^#([0-9a-f]{6})$/i.exec(color ?? '');
  if (!m) return null;
  const n = parseInt(m[1], 16);
  const lin = (c) => (c <= 0.03928 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4);
  return 0.2126 * lin(((n >> 16) & 255) / 255) + 0.7152 * lin(((n >> 8) & 255) / 255) + 0.0722 * lin((n & 255) / 255);
}

/** WCAG contrast ratio (1..21) of two #rrggbb colours; null when either is in another notation. */
export function contrast(a, b) {
  const la = luminance(a);
  const lb = luminance(b);
  if (la === null || lb === null) return null;
  return (Math.max(la, lb) + 0.05) / (Math.min(la, lb) + 0.05);
}

/**
 * `color` (#rrggbb) moved fraction `f` of the way toward white (`to` 255) or black (0) in sRGB,
 * as #rrggbb. Each channel's distance from the others scales by (1 − f), so the hue (HSL/HSV)
 * stays the one of `color` up to the rounding to bytes.
 */
function mix(color, to, f) {
  const n = parseInt(color.slice(1), 16);
  return `#${[16, 8, 0].map((s) => Math.round(((n >> s) & 255) + (to - ((n >> s) & 255)) * f).toString(16).padStart(2, '0')).join('')}`;
}

/**
 * A series colour as drawn in theme `theme` ('light' or 'dark'): unchanged when it has at least
 * MIN_CONTRAST against the theme's card (CHART_BG); else mixed toward white (dark theme) or
 * black (light theme) in steps of MIX_STEP until it has, so the hue stays and a line reads as
 * the same series in both themes (white and black themselves pass, so the loop ends).
 * Near-black series in the dark theme take the light ink instead (they have no hue to keep,
 * and a grey just over 3:1 would read as disabled). Other notations than #rrggbb are returned
 * as they are.
 */
export function seriesInkFor(color, theme) {
  const bg = CHART_BG[theme] ?? CHART_BG.light;
  const l = luminance(color);
  if (l === null || contrast(color, bg) >= MIN_CONTRAST) return color;
  const ink = CHART_INK[theme]?.series;
  if (ink && l < 0.05) return ink;
  const to = theme === 'dark' ? 255 : 0;
  for (let k = 1; ; k++) {
    const c = mix(color, to, Math.min(1, k * MIX_STEP));
    if (contrast(c, bg) >= MIN_CONTRAST || k * MIX_STEP >= 1) return c;
  }
}

/**
 * A series colour as drawn in the theme shown now (seriesInkFor): series strokes, uPlot's
 * legend markers and the views' own legend swatches all take it, read at every draw so the
 * theme switch recolours them.
 */
export function seriesInk(color) {
  return seriesInkFor(color, themeShown());
}
