// The Custom Elements Manifest (npm/custom-elements.json) against the element and its typings:
// every attribute the element watches (www/js/element/options.js) and every attribute, property
// and event of npm/element-types.d.ts is in the manifest, and the manifest names nothing else;
// the package.json "customElements" field points at it and the package ships it.
//
//   node --test tests/frameworks/manifest.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { ROOT } from '../e2e/lib.mjs';

const manifest = JSON.parse(fs.readFileSync(path.join(ROOT, 'npm/custom-elements.json'), 'utf8'));
const types = fs.readFileSync(path.join(ROOT, 'npm/element-types.d.ts'), 'utf8');
const pkg = JSON.parse(fs.readFileSync(path.join(ROOT, 'npm/package.json'), 'utf8'));

/** The member names of `interface name { … }` in element-types.d.ts (one level deep). */
function keysOf(name) {
  const m = types.match(new RegExp(`interface ${name} \\{([\\s\\S]*?)\\n\\}`));
  assert.ok(m, `interface ${name} in element-types.d.ts`);
  return [...m[1].matchAll(/^ {2}'?([\w-]+)'?\??:/gm)].map((x) => x[1]);
}

const element = manifest.modules.flatMap((m) => m.declarations).find((d) => d.customElement);

test('the manifest follows the schema version 2 layout and declares <screw-bender>', () => {
  assert.match(manifest.schemaVersion, /^2\.\d+\.\d+$/);
  assert.equal(element.tagName, 'screw-bender');
  assert.equal(element.name, 'ScrewBenderElement');
  const definition = manifest.modules.flatMap((m) => m.exports).find((e) => e.kind === 'custom-element-definition');
  assert.deepEqual(definition, { kind: 'custom-element-definition', name: 'screw-bender', declaration: { name: 'ScrewBenderElement', module: 'viewer.js' } });
  for (const a of element.attributes) assert.ok(a.type?.text && a.description, `attribute ${a.name} has a type and a description`);
  for (const e of element.events) assert.ok(e.type?.text && e.description, `event ${e.name} has a type and a description`);
});

/** The element's ATTRIBUTES list, read from its source (a module of the browser's, not Node's). */
function watchedAttributes() {
  const src = fs.readFileSync(path.join(ROOT, 'www/js/element/options.js'), 'utf8');
  const m = src.match(/export const ATTRIBUTES = \[([^\]]*)\]/);
  assert.ok(m, 'ATTRIBUTES in options.js');
  return [...m[1].matchAll(/'([\w-]+)'/g)].map((x) => x[1]);
}

test('every attribute the element watches is in the manifest, and the manifest names the typings\' attributes exactly', () => {
  const ATTRIBUTES = watchedAttributes();
  assert.ok(ATTRIBUTES.length >= 17);
  const listed = element.attributes.map((a) => a.name);
  for (const a of ATTRIBUTES) assert.ok(listed.includes(a), `attribute ${a} is in the manifest`);
  assert.deepEqual([...listed].sort(), keysOf('ScrewBenderAttributes').sort());
});

test('the manifest names the typings\' properties and events exactly', () => {
  const fields = element.members.filter((m) => m.kind === 'field').map((m) => m.name);
  for (const p of keysOf('ScrewBenderProperties')) assert.ok(fields.includes(p), `property ${p} is in the manifest`);
  assert.deepEqual(element.events.map((e) => e.name).sort(), keysOf('ScrewBenderEvents').sort());
});

test('package.json points at the manifest and ships it with the framework typings', () => {
  assert.equal(pkg.customElements, './custom-elements.json');
  for (const f of ['custom-elements.json', 'element-types.d.ts', 'react.d.ts', 'vue.d.ts', 'svelte.d.ts']) {
    assert.ok(pkg.files.includes(f), `${f} is in "files"`);
  }
  for (const entry of ['./react', './vue', './svelte']) {
    assert.equal(pkg.exports[entry].types, `${entry}.d.ts`);
    assert.equal(pkg.exports[entry].default, './viewer.js', `${entry} defines the element`);
  }
});
