// The conformance cases through the command line (`screwbender subdivide`, `compare --json`,
// `export`), run as a user runs it: the preset's document on standard input.
import { createHash } from 'node:crypto';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';

import { CASES, cli, optionFlags, presetDocument } from './cases.mjs';

const failure = (r) => ({ error: r.stderr.replace(/^screwbender: /, '').trimEnd() });

/** Runs every case; returns {options, compare, export}: case id → result. */
export function runCli() {
  const out = { options: {}, compare: {}, export: {} };
  for (const c of CASES.options) {
    const r = cli(['subdivide', ...optionFlags(c.options)], presetDocument(c.preset));
    if (r.code !== 0) {
      out.options[c.id] = failure(r);
      continue;
    }
    const poses = JSON.parse(r.stdout.toString()).poses;
    const row = (p) => [...p.origin, ...p.rotation];
    out.options[c.id] = { count: poses.length, first: row(poses[0]), last: row(poses.at(-1)) };
  }
  for (const c of CASES.compare) {
    const flags = c.methods ? ['--methods', c.methods.join(',')] : [];
    const r = cli(['compare', '--json', ...flags], presetDocument(c.preset));
    out.compare[c.id] = r.code === 0 ? JSON.parse(r.stdout.toString()) : failure(r);
  }
  const dir = mkdtempSync(path.join(tmpdir(), 'sb-conformance-'));
  try {
    for (const c of CASES.export) {
      const file = path.join(dir, `${c.id}.${c.format}`);
      const r = cli(['export', '--format', c.format, '-o', file], presetDocument(c.preset));
      if (r.code !== 0) {
        out.export[c.id] = failure(r);
        continue;
      }
      const data = readFileSync(file);
      out.export[c.id] = { sha256: createHash('sha256').update(data).digest('hex'), bytes: data.length };
    }
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
  return out;
}
