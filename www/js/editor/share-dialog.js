// The Share & embed dialog (File → Share & embed…): the motion as it is in the playground, with its
// options, camera and layers, in four forms for a course:
//   * a link to the playground (the share payload after #s=, editor/session.js);
//   * a <screw-bender> snippet for a web page: the element's script tag and the element with the
//     motion document inline (a <script type="application/json"> child) and the options as
//     attributes;
//   * an <iframe> snippet for LMS editors that accept nothing else, pointing at embed.html (the
//     figure alone; share payload in the hash, options in the query);
//   * one self-contained .html file: the template built by scripts/serve.d/60-offline.mjs (the
//     element's code and the wasm inlined) with the figure filled in, which works from file://.
// A native <dialog> (showModal): focus stays inside, Esc closes it, the focus goes back to the
// control that opened it. Built node by node (no HTML strings), like the rest of the page.
import { LAYERS, LAYER_FIELD, DEFAULT_SHOW } from '../element/options.js';
import { encodeHash } from '../share-link.js';
import { download } from './files.js';
import { fileBase } from './media.js';
import { presetName } from './presets.js';

/** The offline template and its size (scripts/serve.d/60-offline.mjs), relative to the page. */
const OFFLINE_TEMPLATE = 'pkg-offline/figure.html';
const OFFLINE_INFO = 'pkg-offline/figure.json';
/** The template's places for the figure, the title and the bunny's mesh. */
const SLOT_FIGURE = '<!--screwbender:figure-->';
const SLOT_TITLE = '<!--screwbender:title-->';
const SLOT_BUNNY = '<!--screwbender:bunny-->';
/** The preset whose object is the Stanford bunny (figure/drawing.js), and where its mesh is. */
const BUNNY_PRESET = 'bunny6';
const BUNNY_URL = 'vendor/bunny.obj';
/** What the Web page form gives (more is said when the object shown is not the bar). */
const ELEMENT_NOTE = 'A <screw-bender> element with the motion inline: paste it into any HTML page.';
/** Largest pitch the element's `camera` attribute takes, in degrees (element/options.js). */
const MAX_PITCH_DEG = 89.9;

/** Escapes text for an HTML attribute value or element content. */
export function escapeHtml(s) {
  return String(s).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);
}

/** A number in few characters (the attributes are for people to read): at most `digits` decimals. */
const short = (x, digits = 2) => String(Number(x.toFixed(digits)));

/**
 * The <screw-bender> options that show the playground's figure as it is now: subdivision
 * options, strobe, layers, camera (yaw, pitch, distance and the point looked at, in degrees and
 * scene units), speed, loop, theme. Returns [name, value] pairs in a stable order; defaults are
 * left out.
 */
export function figureOptions(app) {
  const o = app.motion.options();
  const out = [['scheme', o.scheme]];
  if (o.scheme === 'j') out.push(['s', short(o.s, 4)]);
  out.push(['rules', o.rules], ['levels', String(o.levels)]);
  const strobe = app.parts.responsive?.fullStrobe() ?? app.view.strobe;
  out.push(['strobe', String(strobe)]);
  const show = LAYERS.filter((l) => app.view[LAYER_FIELD[l]]).join(' ');
  if (show !== DEFAULT_SHOW) out.push(['show', show || 'grid']);
  const c = app.viewer.camera;
  const deg = (r) => (r * 180) / Math.PI;
  // The attribute has no straight-down view: a top view is given as the steepest it takes.
  const pitch = Math.max(-MAX_PITCH_DEG, Math.min(MAX_PITCH_DEG, deg(c.pitch)));
  // To 10 decimals (trailing zeros dropped), target included: the figure, whatever its size,
  // is framed as the playground is, not merely turned alike.
  const exact = (x) => short(x, 10);
  out.push(['camera', [deg(c.yaw), pitch, c.distance, ...c.target].map(exact).join(' ')]);
  if (app.anim.speed !== 1) out.push(['speed', short(app.anim.speed)]);
  if (!app.anim.loop) out.push(['loop', 'false']);
  const theme = document.documentElement.dataset.theme === 'dark' ? 'dark' : 'light';
  if (theme !== 'light') out.push(['theme', theme]);
  return out;
}

/** The figure choices of the dialog: controls ('minimal' | 'full' | 'none') and autoplay. */
function choiceOptions({ controls, autoplay }) {
  const out = [];
  if (controls !== 'minimal') out.push(['controls', controls]);
  if (autoplay) out.push(['autoplay', '']);
  return out;
}

/** The figure options that a share payload does not carry (it has the options, strobe and camera). */
const notCarried = (app) => figureOptions(app).filter(([k]) => ['show', 'speed', 'loop', 'theme'].includes(k));

const attrs = (pairs) => pairs.map(([k, v]) => (v === '' ? ` ${k}` : ` ${k}="${escapeHtml(v)}"`)).join('');

/** The title of the figure: the motion's name, else its preset's. */
function titleOf(app) {
  // A preset's document is named by its id: the preset's own name reads better.
  const info = app.scenes?.find((s) => s.id === app.view.scene);
  const name = app.motion?.name;
  if (name && name !== info?.id) return name;
  return info ? presetName(info) : name || 'ScrewBender figure';
}

/**
 * The <screw-bender> snippet: the element's module and the element with the motion document
 * inline. `</` in the JSON is written `<\/` so that no string in it ends the script early.
 */
export function elementSnippet(app, choices, scriptUrl) {
  const doc = JSON.stringify(app.motion.toDocument()).replace(/</g, '\\u003c');
  const pairs = [...figureOptions(app), ...choiceOptions(choices)];
  return [
    `<script type="module" src="${escapeHtml(scriptUrl)}"></script>`,
    `<screw-bender${attrs(pairs)}>`,
    `  <script type="application/json">${doc}</script>`,
    `  ${escapeHtml(titleOf(app))}`,
    '</screw-bender>',
  ].join('\n');
}

/**
 * The URL of embed.html for the figure: the options that a share payload does not carry in the
 * query (layers, controls, autoplay, speed, loop, theme), the session after #s=.
 */
export function embedUrl(app, choices, pageUrl) {
  const q = new URLSearchParams([...notCarried(app), ...choiceOptions(choices)]);
  const url = new URL('embed.html', pageUrl);
  const query = q.toString().replace(/=(?=&|$)/g, '');
  return `${url.href}${query ? `?${query}` : ''}#s=${encodeHash(app.parts.session.session())}`;
}

/** The <iframe> snippet (a 16:10 frame as wide as the column, up to 800 px). */
export function iframeSnippet(app, choices, pageUrl) {
  return `<iframe src="${escapeHtml(embedUrl(app, choices, pageUrl))}" title="${escapeHtml(`${titleOf(app)} (3-D figure)`)}" width="800" height="500" style="border:0;max-width:100%;aspect-ratio:16/10;height:auto" loading="lazy" allow="fullscreen"></iframe>`;
}

/**
 * The offline file: the template with the figure (a <screw-bender> with the session as its
 * share payload), the title and, when the figure shows it, the bunny's mesh. Resolves to the
 * HTML text; rejects with an Error saying what could not be read.
 */
export async function offlineHtml(app, choices, base = document.baseURI) {
  const get = async (path) => {
    const res = await fetch(new URL(path, base));
    if (!res.ok) throw new Error(`${path}: HTTP ${res.status}`);
    return res.text();
  };
  const bunny = app.view.object === 'scene' && app.view.scene === BUNNY_PRESET;
  const [template, mesh] = await Promise.all([get(OFFLINE_TEMPLATE), bunny ? get(BUNNY_URL) : '']);
  for (const slot of [SLOT_FIGURE, SLOT_TITLE, SLOT_BUNNY]) {
    if (!template.includes(slot)) throw new Error(`${OFFLINE_TEMPLATE} has no ${slot} (rebuild it: scripts/serve.sh)`);
  }
  const title = titleOf(app);
  const pairs = [['share', encodeHash(app.parts.session.session())], ...notCarried(app), ...choiceOptions(choices)];
  const figure = `<screw-bender${attrs(pairs)}>${escapeHtml(title)}</screw-bender>`;
  // An OBJ file is plain text without '<'; anything else is refused rather than cut short.
  if (mesh.includes('<')) throw new Error(`${BUNNY_URL} holds '<', which cannot be inlined`);
  const meshScript = bunny ? `<script type="text/plain" id="screwbender-bunny">${mesh}</script>` : '';
  return template.replace(SLOT_TITLE, escapeHtml(title)).replace(SLOT_FIGURE, figure).replace(SLOT_BUNNY, meshScript);
}

/** "3.2 MB" / "850 KB". */
export function formatBytes(n) {
  return n >= 1e6 ? `${(n / 1e6).toFixed(1)} MB` : `${Math.max(1, Math.round(n / 1e3))} KB`;
}

/** Builds the dialog (once) and returns its parts. */
function build() {
  const node = (tag, props = {}, ...children) => {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(props)) {
      if (k === 'text') e.textContent = v;
      else e.setAttribute(k, v);
    }
    e.append(...children);
    return e;
  };
  const section = (id, heading, note, field, button) =>
    node('section', { class: 'share-item', 'aria-labelledby': `${id}-h` },
      node('h3', { id: `${id}-h`, text: heading }),
      node('p', { class: 'note', id: `${id}-note`, text: note }),
      field,
      node('div', { class: 'row' }, button));
  const dlg = node('dialog', { id: 'share', class: 'share', 'aria-labelledby': 'share-title' });
  const link = node('input', { id: 'share-link', type: 'text', readonly: '', 'aria-labelledby': 'share-link-h', 'aria-describedby': 'share-link-note', spellcheck: 'false' });
  const element = node('textarea', { id: 'share-element', readonly: '', rows: '4', 'aria-labelledby': 'share-element-h', 'aria-describedby': 'share-element-note', spellcheck: 'false' });
  const iframe = node('textarea', { id: 'share-iframe', readonly: '', rows: '3', 'aria-labelledby': 'share-iframe-h', 'aria-describedby': 'share-iframe-note', spellcheck: 'false' });
  const controls = node('select', { id: 'share-controls' },
    node('option', { value: 'minimal', text: 'play and time' }),
    node('option', { value: 'full', text: 'play, time, scheme, levels' }),
    node('option', { value: 'none', text: 'none' }));
  const autoplay = node('input', { id: 'share-autoplay', type: 'checkbox' });
  dlg.append(
    node('form', { method: 'dialog', class: 'share-head' },
      node('h2', { id: 'share-title', text: 'Share & embed' }),
      node('button', { type: 'submit', class: 'close', id: 'share-close', 'aria-label': 'Close', text: '×' })),
    node('p', { class: 'note', text: 'Each form below carries this motion with its options, camera and layers.' }),
    node('div', { class: 'row share-choices' },
      node('label', {}, 'Controls ', controls),
      node('label', {}, autoplay, ' play on load')),
    section('share-link', 'Link', 'Opens the playground with this session.', link,
      node('button', { type: 'button', id: 'share-copy-link', text: 'Copy link' })),
    section('share-element', 'Web page', ELEMENT_NOTE, element,
      node('button', { type: 'button', id: 'share-copy-element', text: 'Copy code' })),
    section('share-iframe', 'LMS page (iframe)', 'For Canvas, Moodle and editors that accept only an <iframe>: the figure alone.', iframe,
      node('button', { type: 'button', id: 'share-copy-iframe', text: 'Copy iframe' })),
    section('share-file', 'Offline file', 'One .html file with everything inside: opens from a disk, an e-mail or an LMS file area, with no network.',
      node('span'),
      node('button', { type: 'button', id: 'share-download', text: 'Download .html' })),
    node('p', { id: 'share-status', class: 'note', role: 'status' }),
  );
  document.body.append(dlg);
  return { dlg, link, element, iframe, controls, autoplay, status: dlg.querySelector('#share-status'), download: dlg.querySelector('#share-download') };
}

/** Copies `field`'s text; where the clipboard is refused, selects it and says how to copy. */
async function copyField(field, what, status) {
  try {
    await navigator.clipboard.writeText(field.value);
    status.textContent = `${what} copied to the clipboard.`;
  } catch {
    field.focus();
    field.select();
    status.textContent = `The clipboard is not available here: ${what.toLowerCase()} is selected, press Ctrl+C (⌘C) to copy it.`;
  }
}

let ui = null;
let templateBytes = null;

/**
 * Opens the dialog for the app's current motion; `opener` gets the focus back when it closes.
 * The offline file's size comes from the template's info file when the dialog opens.
 */
export function openShareDialog(app, opener = document.activeElement) {
  if (!ui) {
    ui = build();
    const refresh = () => fill(app);
    ui.controls.addEventListener('change', refresh);
    ui.autoplay.addEventListener('change', refresh);
    ui.dlg.querySelector('#share-copy-link').addEventListener('click', () => copyField(ui.link, 'The link', ui.status));
    ui.dlg.querySelector('#share-copy-element').addEventListener('click', () => copyField(ui.element, 'The code', ui.status));
    ui.dlg.querySelector('#share-copy-iframe').addEventListener('click', () => copyField(ui.iframe, 'The iframe code', ui.status));
    ui.download.addEventListener('click', () => saveOffline(app));
    ui.dlg.addEventListener('close', () => ui.opener?.focus?.());
    // Tab wraps inside the dialog (a modal <dialog> alone lets it leave for the browser's chrome).
    ui.dlg.addEventListener('keydown', (e) => {
      if (e.key !== 'Tab') return;
      const all = [...ui.dlg.querySelectorAll('button, select, input, textarea')].filter((el) => !el.disabled && el.offsetParent !== null);
      const [first, last] = [all[0], all.at(-1)];
      if (e.shiftKey && document.activeElement === first) last.focus();
      else if (!e.shiftKey && document.activeElement === last) first.focus();
      else return;
      e.preventDefault();
    });
  }
  ui.app = app;
  ui.opener = opener;
  ui.status.textContent = '';
  fill(app);
  ui.dlg.showModal();
  ui.dlg.querySelector('#share-copy-link').focus();
  if (templateBytes === null) {
    fetch(OFFLINE_INFO)
      .then((r) => (r.ok ? r.json() : null))
      .then((info) => {
        if (Number.isFinite(info?.bytes)) templateBytes = info.bytes;
        fill(app);
      })
      .catch(() => {});
  }
  return ui.dlg;
}

const choicesOf = () => ({ controls: ui.controls.value, autoplay: ui.autoplay.checked });

/** Writes the link and the snippets of the current motion into the dialog. */
function fill(app) {
  const choices = choicesOf();
  const page = new URL(location.pathname, location.href).href;
  ui.link.value = app.parts.session.shareLink();
  ui.element.value = elementSnippet(app, choices, new URL('js/element/screw-bender.js', page).href);
  ui.iframe.value = iframeSnippet(app, choices, page);
  // The element draws an inline motion with the bar: say so when the playground shows another object.
  ui.dlg.querySelector('#share-element-note').textContent =
    ELEMENT_NOTE + (app.view.object === 'bar' ? '' : ' It shows the motion with a bar; the iframe and the offline file keep the object shown here.');
  ui.download.textContent = templateBytes ? `Download .html (${formatBytes(templateBytes)})` : 'Download .html';
}

/** Builds the offline file and downloads it; the status line says its size or what failed. */
async function saveOffline(app) {
  ui.download.disabled = true;
  ui.status.textContent = 'Building the file…';
  try {
    const html = await offlineHtml(app, choicesOf());
    const name = `${fileBase(titleOf(app))}.html`;
    const blob = new Blob([html], { type: 'text/html' });
    download(name, html, 'text/html');
    ui.status.textContent = `Saved ${name} (${formatBytes(blob.size)}): open it in any browser, no network needed.`;
    return { name, bytes: blob.size };
  } catch (e) {
    ui.status.textContent = `The file could not be made: ${e.message}`;
    app.parts.notices.show(`The offline file could not be made: ${e.message}`);
    return null;
  } finally {
    ui.download.disabled = false;
  }
}
