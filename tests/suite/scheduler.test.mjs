// The test suite's scheduler (scripts/test.sh) on made-up stage tables: lanes select their stages
// and what those need, `beside` stages run while the next ones start, `after` and `alone` wait,
// and a failure anywhere stops the run with the count line. Each stage appends to a shared log.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

/** Runs test.sh on `table` (lines: name lane runs after command) with `args`; returns its output and log. */
function run(table, args = [], { skipSetup = true } = {}) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'stages-'));
  const file = path.join(dir, 'stages.txt');
  const log = path.join(dir, 'log');
  fs.writeFileSync(file, table.map((l) => l.replaceAll('LOG', log)).join('\n') + '\n');
  const r = spawnSync('bash', ['scripts/test.sh', ...args], {
    cwd: ROOT,
    env: { ...process.env, STAGES: file, SKIP_SETUP: skipSetup ? '1' : '0' },
    encoding: 'utf8',
  });
  const lines = fs.existsSync(log) ? fs.readFileSync(log, 'utf8').trim().split('\n') : [];
  fs.rmSync(dir, { recursive: true, force: true });
  return { status: r.status, out: r.stdout, err: r.stderr, lines };
}

const mark = (word) => `echo ${word} >> LOG`;

test('a lane runs its stages and what they need, transitively, and no other', () => {
  const table = [
    'setup-x setup cpu - true',
    'a rust cpu setup-x true',
    'b web cpu a true',
    'c web cpu - true',
    'd python cpu - true',
    'e e2e cpu b true',
  ];
  const names = (args, o) => run(table, ['--list', ...args], o).out.trim().split('\n').map((l) => l.split(/\s+/)[0]);
  assert.deepEqual(names(['e2e'], { skipSetup: false }), ['setup-x', 'a', 'b', 'e']);
  assert.deepEqual(names(['python']), ['d']);
  assert.deepEqual(names(['web', 'python'], { skipSetup: false }), ['setup-x', 'a', 'b', 'c', 'd']);
  assert.deepEqual(names([], { skipSetup: false }), ['setup-x', 'a', 'b', 'c', 'd', 'e']);
  assert.deepEqual(names([]), ['a', 'b', 'c', 'd', 'e'], 'SKIP_SETUP=1 leaves the installs out');
  assert.notEqual(run(table, ['nosuchlane']).status, 0);
});

test('a beside stage runs while the next start; after and alone wait for it', () => {
  const r = run([
    `slow rust beside - ${mark('slow-start')}; sleep 2; ${mark('slow-end')}`,
    `quick rust cpu - ${mark('quick')}`,
    `needs-slow rust cpu slow ${mark('needs-slow')}`,
    `other rust beside - sleep 1; ${mark('other-end')}`,
    `last e2e alone - ${mark('last')}`,
  ]);
  assert.equal(r.status, 0, r.err);
  const at = (w) => r.lines.indexOf(w);
  assert.ok(at('quick') < at('slow-end'), `quick ran beside slow: ${r.lines}`);
  assert.ok(at('slow-end') < at('needs-slow'), `after waited: ${r.lines}`);
  assert.ok(at('other-end') < at('last') && at('slow-end') < at('last'), `alone waited: ${r.lines}`);
  assert.match(r.out, /stages: 5 passed, 0 failed/);
  assert.match(r.err, /\d+ s +\d+ cpu s +\d+ % busy +slow +passed/);
});

test('a beside stage starts once what it needs has passed, during a foreground stage before it', () => {
  const r = run([
    `need rust beside - ${mark('need')}`,
    `long rust cpu - sleep 3; ${mark('long-end')}`,
    `early rust beside need ${mark('early')}`,
    `last e2e alone - ${mark('last')}`,
    `after-alone rust beside long ${mark('after-alone')}`,
  ]);
  assert.equal(r.status, 0, r.err);
  const at = (w) => r.lines.indexOf(w);
  assert.ok(at('early') < at('long-end'), `early started during long: ${r.lines}`);
  assert.ok(at('early') < at('last') && at('last') < at('after-alone'), `nothing beside the alone stage: ${r.lines}`);
});

test('a failing foreground stage stops the run: no later stage, the count line says so', () => {
  const r = run([`one rust cpu - ${mark('one')}`, 'two rust cpu - exit 3', `three rust cpu - ${mark('three')}`]);
  assert.equal(r.status, 3);
  assert.deepEqual(r.lines, ['one']);
  assert.match(r.out, /stages: 1 passed, 1 failed/);
  assert.match(r.err, /stage 'two' FAILED \(exit 3\)/);
});

test('a failing beside stage stops the run when it ends, and its output is shown', () => {
  const r = run([
    'bad rust beside - echo "what went wrong"; exit 4',
    `waits rust cpu - sleep 2; ${mark('waits')}`,
    `never rust cpu - ${mark('never')}`,
  ]);
  assert.equal(r.status, 4);
  assert.ok(!r.lines.includes('never'), `no stage after the failure was seen: ${r.lines}`);
  assert.match(r.err, /what went wrong/);
  assert.match(r.out, /stages: \d+ passed, 1 failed/);
});
