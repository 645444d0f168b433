// The analysis charts' series colours against the chart card (www/js/dock/ink.js seriesInk,
// WCAG 2.1 SC 1.4.11: graphical objects at least 3:1): every colour the chart views give their
// series passes in both themes once drawn; colours that pass are drawn as they are, failing ones
// keep their hue; other notations pass through; CHART_BG follows the dock's colours in
// style.css. ink.js touches `document` only inside functions, so it loads in Node as it is.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { describe, it } from 'node:test';
import { fileURLToPath } from 'node:url';
import { CHART_BG, CHART_INK, MIN_CONTRAST, PALETTE, contrast, seriesInk, seriesInkFor } from '../../www/js/dock/ink.js';

const ROOT = path.join(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const read = (p) => fs.readFileSync(path.join(ROOT, p), 'utf8');

/**
 * Every series colour the chart views write (`color: '#rrggbb'` in their series lists, and the
 * Okabe–Ito PALETTE), read from the sources so a colour added later is checked too.
 */
function seriesColours() {
  const out = new Set(PALETTE.map((c) => c.toLowerCase()));
  for (const f of ['plots.js', 'methods.js', 'timing.js']) {
    for (const m of read(`www/js/dock/${f}`).matchAll(/color: '(#[0-9a-fA-F]{6})'/g)) out.add(m[1].toLowerCase());
  }
  // methods.js's optimised Ramamoorthi–Barr curve takes a slot colour.
  const slots = /const SLOT_COLORS = \[([^\]]*)\]/.exec(read('www/js/dock/methods.js'));
  for (const m of slots[1].matchAll(/'(#[0-9a-fA-F]{6})'/g)) out.add(m[1].toLowerCase());
  return [...out];
}

/** HSL hue in degrees of a #rrggbb colour (null for greys). */
function hue(c) {
  const [r, g, b] = [1, 3, 5].map((k) => parseInt(c.slice(k, k + 2), 16) / 255);
  const max = Math.max(r, g, b);
  const d = max - Math.min(r, g, b);
  if (d === 0) return null;
  const h = max === r ? ((g - b) / d) % 6 : max === g ? (b - r) / d + 2 : (r - g) / d + 4;
  return (h * 60 + 360) % 360;
}

/** `rgba(r, g, b, a)` composited over the opaque `under` ([r, g, b]), as #rrggbb. */
function over(rgba, under) {
  const [r, g, b, a] = rgba.split(',').map(Number);
  return `#${[r, g, b].map((v, i) => Math.round(v * a + under[i] * (1 - a)).toString(16).padStart(2, '0')).join('')}`;
}

describe('chart series contrast (seriesInk)', () => {
  const colours = seriesColours();

  it('finds the series colours of the chart views', () => {
    for (const c of ['#d1202f', '#2f9e44', '#1f5fd1', '#8a8f9c', '#d55e00', '#009e73', '#0072b2', '#999999', '#1d2230']) {
      assert.ok(colours.includes(c), `${c} in ${colours}`);
    }
  });

  for (const theme of ['light', 'dark']) {
    it(`${theme}: every series colour is drawn with at least 3:1 against the card`, () => {
      for (const c of colours) {
        const drawn = seriesInkFor(c, theme);
        assert.match(drawn, /^#[0-9a-f]{6}$/i);
        assert.ok(contrast(drawn, CHART_BG[theme]) >= MIN_CONTRAST, `${c} → ${drawn}: ${contrast(drawn, CHART_BG[theme]).toFixed(2)}:1 on ${CHART_BG[theme]}`);
      }
    });

    it(`${theme}: colours that pass are unchanged; failing ones keep their hue and change little`, () => {
      for (const c of colours) {
        const drawn = seriesInkFor(c, theme);
        if (contrast(c, CHART_BG[theme]) >= MIN_CONTRAST) {
          assert.equal(drawn, c);
          continue;
        }
        if (theme === 'dark' && drawn === CHART_INK.dark.series) continue; // near-black: the light ink (below)
        assert.notEqual(drawn, c);
        if (hue(c) !== null) {
          const dh = Math.abs(hue(drawn) - hue(c));
          assert.ok(Math.min(dh, 360 - dh) < 2, `${c} (${hue(c).toFixed(1)}°) → ${drawn} (${hue(drawn).toFixed(1)}°)`);
        }
        // The first step that passes: one step less would not.
        assert.ok(contrast(drawn, CHART_BG[theme]) < MIN_CONTRAST + 0.35, `${c} → ${drawn} went further than needed`);
      }
    });
  }

  it('dark: the blue and red of the paper now pass (they measured 2.4–3:1 before)', () => {
    for (const c of ['#1f5fd1', '#d1202f', '#0072b2']) {
      assert.ok(contrast(c, CHART_BG.dark) < MIN_CONTRAST, `${c} failed before`);
      const drawn = seriesInkFor(c, 'dark');
      assert.ok(contrast(drawn, CHART_BG.dark) >= MIN_CONTRAST, `${c} → ${drawn}`);
    }
  });

  it('dark: near-black series take the light ink, as before', () => {
    assert.equal(seriesInkFor('#000000', 'dark'), '#e6e9ef');
    assert.equal(seriesInkFor('#1d2230', 'dark'), '#e6e9ef');
    assert.equal(seriesInkFor('#1d2230', 'light'), '#1d2230');
  });

  it('other notations pass through unchanged; the result is deterministic', () => {
    for (const c of ['red', '#fff', 'rgba(0,0,0,0.5)', '', undefined, null]) {
      for (const theme of ['light', 'dark']) assert.equal(seriesInkFor(c, theme), c);
    }
    assert.equal(seriesInkFor('#1f5fd1', 'dark'), seriesInkFor('#1f5fd1', 'dark'));
    assert.equal(seriesInkFor('#1F5FD1', 'dark'), seriesInkFor('#1f5fd1', 'dark'));
  });

  it('seriesInk follows <html data-theme>', () => {
    const saved = globalThis.document;
    try {
      globalThis.document = { documentElement: { dataset: { theme: 'dark' } } };
      assert.equal(seriesInk('#1f5fd1'), seriesInkFor('#1f5fd1', 'dark'));
      globalThis.document.documentElement.dataset.theme = 'light';
      assert.equal(seriesInk('#1f5fd1'), '#1f5fd1');
      assert.equal(seriesInk('#999999'), seriesInkFor('#999999', 'light'));
    } finally {
      if (saved === undefined) delete globalThis.document;
      else globalThis.document = saved;
    }
  });

  it('CHART_BG is the dock of style.css over the backdrop nearest the series (black in light, white in dark)', () => {
    const css = read('www/css/style.css');
    const light = /\n#dock \{[^}]*background: rgba\(([^)]*)\)/.exec(css);
    const dark = /html\[data-theme="dark"\] #dock \{ background: rgba\(([^)]*)\)/.exec(css);
    assert.ok(light && dark, 'the #dock backgrounds in style.css');
    assert.equal(CHART_BG.light, over(light[1], [0, 0, 0]));
    assert.equal(CHART_BG.dark, over(dark[1], [255, 255, 255]));
  });
});

// The point-rules figure (www/js/dock/polygon.js) draws on its own white canvas in both themes:
// its lines, arrows, outlines and label are checked against that white.
describe('point-rules figure contrast (polygon.js)', () => {
  const src = read('www/js/dock/polygon.js');

  it('paints its canvas white before drawing', () => {
    assert.match(src, /g\.fillStyle = '#fff';\s*g\.fillRect\(0, 0, w, h\);/);
  });

  it('every line, mark and label colour has at least 3:1 against the white canvas', () => {
    const inks = new Set();
    for (const re of [/color: '(#[0-9a-fA-F]{6})'/g, /const CONTROL = '(#[0-9a-fA-F]{3,6})'/g, /strokeStyle = '(#[0-9a-fA-F]{3,6})'/g]) {
      for (const m of src.matchAll(re)) inks.add(m[1].toLowerCase());
    }
    // The label's fillStyle, set just before its fillText.
    const label = /fillStyle = '(#[0-9a-fA-F]{3,6})';\s*g\.font/.exec(src);
    assert.ok(label, 'the level label colour');
    inks.add(label[1].toLowerCase());
    const six = (c) => (c.length === 4 ? `#${[...c.slice(1)].map((d) => d + d).join('')}` : c);
    for (const c of ['#d1202f', '#1f5fd1', '#1f9d3a', '#8a8f9c', '#333', '#444', '#555']) assert.ok(inks.has(c), `${c} in ${[...inks]}`);
    for (const c of inks) {
      assert.ok(contrast(six(c), '#ffffff') >= MIN_CONTRAST, `${c}: ${contrast(six(c), '#ffffff').toFixed(2)}:1 on white`);
    }
  });
});
