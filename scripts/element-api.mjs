// The <screw-bender> element's API, written from its features' declarations
// (www/js/element/features.js and the feature files it names), which are the only place an
// option, property, method or event is declared:
//
//   npm/element-types.d.ts         the attributes, properties and events for the framework typings
//                                  (npm/react.d.ts, vue.d.ts, svelte.d.ts build on it)
//   npm/custom-elements.json       the Custom Elements Manifest
//   python/screwbender/_figure_options.py   the notebook figure's traitlets (python/widget/figure.js
//                                  imports the same list from the declarations when bundled)
//
// The generated files are committed: the Python package builds from its sources without Node,
// and the typings and manifest are read in the repository (README, the framework apps). The
// builds run this script (build-pkg.sh into the package, python/build-figure.sh for the
// traitlets), and the type-check stage runs it with --check, which fails while a committed
// file differs from what the declarations give.
//
//   node scripts/element-api.mjs               # write the three files
//   node scripts/element-api.mjs --check       # exit 1 naming each stale file
//   node scripts/element-api.mjs --npm-out DIR # write the two npm files into DIR only
//   node scripts/element-api.mjs --python      # write the Python file only
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { FEATURES, OPTIONS } from '../www/js/element/features.js';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const SOURCE = 'www/js/element/features.js';

const attributes = OPTIONS.filter((o) => o.attribute !== false);
const properties = FEATURES.flatMap((f) => f.properties ?? []);
const methods = FEATURES.flatMap((f) => f.methods ?? []);
const events = FEATURES.flatMap((f) => f.events ?? []);

/** The TypeScript type of a list of words. */
const union = (words) => words.map((w) => `'${w}'`).join(' | ');

/** An option's type in the typings (attributes carry strings; frameworks may pass values). */
function tsType(o) {
  if (o.ts) return o.ts;
  if (Array.isArray(o.type)) return union(o.type);
  return { boolean: 'BooleanAttribute', number: 'NumberAttribute', integer: 'NumberAttribute', string: 'string' }[o.type];
}

/** An option's type in the manifest (what the attribute's value means). */
function manifestType(o) {
  if (Array.isArray(o.type)) return union(o.type);
  return o.type === 'integer' ? 'number' : o.type;
}

/** `{ a: T; b?: U }` of an event detail's fields. */
const fieldsText = (fields) => `{ ${Object.entries(fields).map(([k, t]) => `${k}: ${t}`).join('; ')} }`;

/** The event's type: CustomEvent of its detail, or a plain Event. */
const eventType = (e, inline) => (e.detail ? `CustomEvent<${inline ? fieldsText(e.detail.fields) : e.detail.type}>` : 'Event');

/** A doc comment at `indent`. */
const doc = (text, indent = '') => `${indent}/** ${text} */\n`;

function elementTypes() {
  let out = `// The <screw-bender> element's attributes, properties and events: what the framework typings
// (react.d.ts, vue.d.ts, svelte.d.ts) build their element entries from. Written by
// scripts/element-api.mjs from the element's declarations (${SOURCE} and
// the files it names): edit those, not this file. Names follow HTMLMediaElement where they
// apply. Every member is optional here: a framework may set any of them.
import type { Motion, MotionDocumentInput, SubdivisionOptions } from './screwbender.js';
import type { CameraState, PictureOptions, ScrewBenderElement } from './viewer.js';

/** A boolean attribute: present (\`true\`, \`''\`, any string but \`'false'\`) or absent. */
export type BooleanAttribute = boolean | '' | 'true' | 'false';
/** A number attribute: a number, or its decimal text as attributes carry it. */
export type NumberAttribute = number | \`\${number}\`;

/**
 * The attributes of <screw-bender> (strings in HTML; a framework may pass numbers and booleans,
 * which the element reads the same way). Sources: the first present of \`src\`, \`share\`, an inline
 * \`<script type="application/json">\` child, \`preset\`.
 */
export interface ScrewBenderAttributes {
`;
  for (const o of attributes) {
    out += doc(o.deprecated ? `@deprecated ${o.deprecated}` : o.doc, '  ');
    out += `  ${/^[\w]+$/.test(o.name) ? o.name : `'${o.name}'`}?: ${tsType(o)};\n`;
  }
  out += `}

/** Options of play(): how many times an open motion plays before it ends. */
export interface PlayOptions {
  repetitions?: number;
}

/**
 * The properties a framework sets on the element besides the attributes (those of an
 * attribute's name are typed there).
 */
export interface ScrewBenderProperties {
`;
  const names = new Set(attributes.map((o) => o.name));
  for (const p of properties.filter((p) => p.set && !names.has(p.name))) {
    out += doc(p.doc, '  ');
    out += `  ${p.name}?: ${p.ts};\n`;
  }
  out += '}\n';
  // One interface per detail type (time and timeupdate share theirs).
  const details = [...new Map(events.filter((e) => e.detail).map((e) => [e.detail.type, e])).values()];
  for (const e of details) {
    out += `${doc(e.detail.doc)}export interface ${e.detail.type} {\n`;
    for (const [k, t] of Object.entries(e.detail.fields)) out += `  ${k}: ${t};\n`;
    out += '}\n';
  }
  out += `
/** The events of <screw-bender>, by type (none of them bubbles out of the figure as an exception). */
export interface ScrewBenderEvents {
`;
  for (const e of events) {
    out += doc(e.doc, '  ');
    out += `  ${/^[\w]+$/.test(e.name) ? e.name : `'${e.name}'`}: ${eventType(e, false)};\n`;
  }
  out += `}

/** An event's handler, \`this\` being the element. */
export type ScrewBenderHandler<K extends keyof ScrewBenderEvents> = (this: ScrewBenderElement, event: ScrewBenderEvents[K]) => void;

/**
 * The handlers as \`on<type>\` props, the spelling React 19 and Svelte 5 attach to a custom
 * element's event of that type (\`ontime\`, \`oncamera-change\`).
 */
export type ScrewBenderEventProps = {
  [K in keyof ScrewBenderEvents as \`on\${K}\`]?: (event: ScrewBenderEvents[K]) => void;
};

/** The options of mount(): the attributes (by their names) and those a script alone gives. */
export interface ScrewBenderOptions extends ScrewBenderAttributes {
${OPTIONS.filter((o) => o.attribute === false).map((o) => `${doc(o.doc, '  ')}  ${o.name}?: ${tsType(o)};\n`).join('')}}

/**
 * A figure's script API: what mount() returns and what <screw-bender> has (its properties and
 * methods). Playback follows HTMLMediaElement: times are seconds of the motion's own timing.
 */
export interface ScrewBenderHandle {
${properties.map((p) => `${doc(p.doc, '  ')}  ${p.set ? '' : 'readonly '}${p.name}: ${p.ts};\n`).join('')}${methods
  .map((m) => `${doc(m.doc, '  ')}  ${m.name}(${m.params.map((a) => `${a.name}${a.optional ? '?' : ''}: ${a.ts}`).join(', ')}): ${m.returns};\n`)
  .join('')}}

/** Everything a framework may set on <screw-bender>: attributes, properties and handlers. */
export type ScrewBenderProps = ScrewBenderAttributes & ScrewBenderProperties & ScrewBenderEventProps;

export type { ScrewBenderElement };
`;
  return out;
}

function manifest() {
  const fields = new Set(properties.map((p) => p.name));
  const attr = (o) => ({
    name: o.name,
    type: { text: manifestType(o) },
    description: o.doc,
    ...(o.default !== undefined && { default: JSON.stringify(o.default) }),
    ...(o.deprecated && { deprecated: o.deprecated }),
    ...(fields.has(o.name) && { fieldName: o.name }),
  });
  const members = [
    ...properties.map((p) => ({ kind: 'field', name: p.name, type: { text: p.ts }, description: p.doc, ...(!p.set && { readonly: true }) })),
    ...methods.map((m) => ({
      kind: 'method',
      name: m.name,
      parameters: m.params.map((a) => ({ name: a.name, type: { text: a.ts }, ...(a.optional && { optional: true }) })),
      return: { type: { text: m.returns } },
      description: m.doc,
    })),
  ];
  const element = {
    kind: 'class',
    name: 'ScrewBenderElement',
    tagName: 'screw-bender',
    customElement: true,
    summary: 'A live 3-D figure of a smooth rigid-body motion by screw subdivision.',
    description: 'Draws a motion (a preset, a file, a share link or an inline JSON document) on WebGPU or WebGL2; orbit, play and scrub, and with `editable` drag its poses. Failures show inside the figure and fire `error`; nothing is thrown into the host page.',
    superclass: { name: 'HTMLElement', package: 'global:' },
    attributes: attributes.map(attr),
    members,
    events: events.map((e) => ({ name: e.name, type: { text: eventType(e, true) }, description: e.doc })),
    slots: FEATURES.flatMap((f) => f.slots ?? []).map((s) => ({ name: s.name, description: s.doc })),
    cssParts: FEATURES.flatMap((f) => f.parts ?? []).map((s) => ({ name: s.name, description: s.doc })),
  };
  const declaration = { name: 'ScrewBenderElement', module: 'viewer.js' };
  return `${JSON.stringify({
    schemaVersion: '2.1.0',
    readme: 'README.md',
    modules: [{
      kind: 'javascript-module',
      path: 'viewer.js',
      description: 'The screwbender/viewer entry: importing it defines <screw-bender>.',
      declarations: [element],
      exports: [
        { kind: 'js', name: 'ScrewBenderElement', declaration },
        { kind: 'js', name: 'mount', declaration: { name: 'mount', module: 'viewer.js' } },
        { kind: 'custom-element-definition', name: 'screw-bender', declaration },
      ],
    }],
  }, null, 2)}\n`;
}

/** A Python literal of a JSON value. */
const py = (v) => (v === true ? 'True' : v === false ? 'False' : v === null ? 'None' : JSON.stringify(v));

/** `text` as `#:` comment lines of at most `width` characters. */
function pyComment(text, indent, width = 100) {
  const lines = [];
  let line = `${indent}#:`;
  for (const word of text.split(/\s+/)) {
    if (line.length + 1 + word.length > width && line.length > indent.length + 2) {
      lines.push(line);
      line = `${indent}#:`;
    }
    line += ` ${word}`;
  }
  lines.push(line);
  return lines.join('\n');
}

function pythonTraits() {
  let out = `"""The options the notebook figure shares with the \`\`<screw-bender>\`\` element, as traitlets
synchronised with its front end (which reads the same list, python/widget/figure.js).

Written by scripts/element-api.mjs from the element's declarations
(${SOURCE} and the files it names): edit those, not this file.
"""

from __future__ import annotations

import anywidget
import traitlets


class FigureOptions(anywidget.AnyWidget):
    """The element's options that :class:\`~screwbender.Figure\` synchronises (checked by the figure)."""
`;
  for (const o of OPTIONS.filter((x) => x.python)) {
    const spec = typeof o.python === 'object' ? o.python : {};
    let trait = spec.trait;
    if (!trait) {
      const kind = Array.isArray(o.type) ? 'Unicode' : { string: 'Unicode', number: 'Float', integer: 'Int', boolean: 'Bool' }[o.type];
      trait = 'default' in spec ? `traitlets.${kind}(${py(spec.default)})` : `traitlets.${kind}(None, allow_none=True)`;
    }
    out += `\n${pyComment(o.doc.replace(/`/g, '``'), '    ')}\n    ${o.name} = ${trait}.tag(sync=True)\n`;
  }
  return out;
}

const FILES = {
  'npm/element-types.d.ts': elementTypes,
  'npm/custom-elements.json': manifest,
  'python/screwbender/_figure_options.py': pythonTraits,
};

const args = process.argv.slice(2);
const at = args.indexOf('--npm-out');
if (args.includes('--check')) {
  const stale = Object.entries(FILES).filter(([file, make]) => {
    const full = path.join(ROOT, file);
    return !fs.existsSync(full) || fs.readFileSync(full, 'utf8') !== make();
  });
  for (const [file] of stale) console.error(`${file} differs from the element's declarations: run node scripts/element-api.mjs`);
  if (stale.length) process.exit(1);
  console.log(`element API: ${Object.keys(FILES).join(', ')} match the declarations`);
} else if (at >= 0) {
  const dir = path.resolve(args[at + 1]);
  for (const file of ['npm/element-types.d.ts', 'npm/custom-elements.json']) {
    fs.writeFileSync(path.join(dir, path.basename(file)), FILES[file]());
  }
} else {
  for (const [file, make] of Object.entries(FILES)) {
    if (args.includes('--python') && !file.startsWith('python/')) continue;
    fs.writeFileSync(path.join(ROOT, file), make());
    console.log(`wrote ${file}`);
  }
}
