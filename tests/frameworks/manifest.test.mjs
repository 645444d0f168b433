// The Custom Elements Manifest (npm/custom-elements.json) and the typings (npm/element-types.d.ts)
// against the element's declarations (www/js/element/features.js), from which
// scripts/element-api.mjs writes both: each names exactly the declared attributes, properties
// and events (`ratechange` among them), and both are what the declarations give now (not
// stale); the package.json "customElements" field points at the manifest and the package
// ships it. (tests/e2e/element-media.test.mjs compares the declarations with the element's real
// observed attributes, members and events.)
//
//   node --test tests/frameworks/manifest.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { execFileSync } from 'node:child_process';
import { ROOT } from '../e2e/lib.mjs';
import { ATTRIBUTES, EVENTS, FEATURES } from '../../www/js/element/features.js';

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

test('the manifest names exactly the declared attributes, properties, methods and events', () => {
  assert.deepEqual(element.attributes.map((a) => a.name).sort(), [...ATTRIBUTES].sort());
  const declared = FEATURES.flatMap((f) => [...(f.properties ?? []), ...(f.methods ?? [])]).map((m) => m.name);
  assert.deepEqual(element.members.map((m) => m.name).sort(), declared.sort());
  assert.deepEqual(element.events.map((e) => e.name).sort(), [...EVENTS].sort());
  assert.ok(EVENTS.includes('ratechange'), 'ratechange is declared');
});

test('the typings name exactly the declared attributes and events; settable properties are typed', () => {
  assert.deepEqual(keysOf('ScrewBenderAttributes').sort(), [...ATTRIBUTES].sort());
  assert.deepEqual(keysOf('ScrewBenderEvents').sort(), [...EVENTS].sort());
  const settable = FEATURES.flatMap((f) => f.properties ?? []).filter((p) => p.set && !ATTRIBUTES.includes(p.name)).map((p) => p.name);
  assert.deepEqual(keysOf('ScrewBenderProperties').sort(), settable.sort());
  for (const p of keysOf('ScrewBenderProperties')) assert.ok(element.members.some((m) => m.kind === 'field' && m.name === p), `property ${p} is in the manifest`);
});

test('the committed typings, manifest and Python traitlets are what the declarations give', () => {
  execFileSync(process.execPath, [path.join(ROOT, 'scripts/element-api.mjs'), '--check'], { stdio: 'pipe' });
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
