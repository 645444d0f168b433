// The conformance cases through the npm package's wasm API in Node (pkg/full: the math with
// files, export and the comparison methods, as `screwbender/full` ships it).
import { createHash } from 'node:crypto';

import { CASES, poseSummary, presetDocument } from './cases.mjs';

/** Runs every case; returns {options, compare, export}: case id → result. */
export async function runNode() {
  const sb = await import(new URL('../../../pkg/full/node.js', import.meta.url).href);
  const { Motion } = sb;
  const out = { options: {}, compare: {}, export: {} };
  const attempt = (f) => {
    try {
      return f();
    } catch (e) {
      return { error: e.message };
    }
  };
  for (const c of CASES.options) {
    out.options[c.id] = attempt(() => {
      const m = new Motion(JSON.parse(presetDocument(c.preset)), c.options);
      return { ...m.options(), ...poseSummary(m.subdivide()) };
    });
  }
  for (const c of CASES.compare) {
    out.compare[c.id] = attempt(() => new Motion(JSON.parse(presetDocument(c.preset))).compareMethods(c.methods ?? undefined));
  }
  for (const c of CASES.export) {
    out.export[c.id] = attempt(() => {
      const f = new Motion(JSON.parse(presetDocument(c.preset))).exportFile({ format: c.format });
      return { sha256: createHash('sha256').update(f.data).digest('hex'), bytes: f.data.length };
    });
  }
  return out;
}
