// The conformance cases through the Python package (python_runner.py in the project's venv).
import { spawnSync } from 'node:child_process';
import { existsSync } from 'node:fs';

import { CASES, presetDocument } from './cases.mjs';

/** The Python of the project's venv (scripts/python-env.sh), or SCREWBENDER_PYTHON. */
export const PYTHON = process.env.SCREWBENDER_PYTHON ?? new URL('../../../.venv/bin/python', import.meta.url).pathname;

/** Runs every case; returns {options, compare, export}: case id → result. */
export function runPython() {
  if (!existsSync(PYTHON)) throw new Error(`no Python at ${PYTHON}: run scripts/python-env.sh (or set SCREWBENDER_PYTHON)`);
  const presets = new Set([...CASES.options, ...CASES.compare, ...CASES.export].map((c) => c.preset));
  const documents = Object.fromEntries([...presets].map((id) => [id, presetDocument(id)]));
  const r = spawnSync(PYTHON, [new URL('./python_runner.py', import.meta.url).pathname], {
    input: JSON.stringify({ cases: CASES, documents }),
    maxBuffer: 1 << 28,
  });
  if (r.status !== 0) throw new Error(`python_runner.py failed (${r.status}): ${r.stderr}`);
  return JSON.parse(r.stdout.toString());
}
