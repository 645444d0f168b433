// e2e-backends: webgpu (the file is computed on the CPU, the same on either backend: once)
// End-to-end: the playground's glTF export of a preset is the command line's, byte for byte.
// Each preset is picked in the preset chooser and exported with the panel's Export glTF (.glb)
// button, as a user does; the CLI (`screwbender preset ID | screwbender export --format glb`)
// gets the page's subdivision options and export tolerance as flags. The presets cover the
// three kinds of object a file can carry: bunny6 (the scanned Stanford bunny, which the page
// fetches and the CLI compiles in), pip_morph5 (five shapes morphing, one morph target each)
// and l_cycle_rotated (a plain shape).
//
// The CLI is the debug build of the workspace (what the native test stage builds, or
// `cargo build -p screwbender-cli`), or SCREWBENDER_BIN; it is built when missing.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { ROOT, BACKEND, playgroundPage, waitFrames } from './lib.mjs';

let play;
let page;
let problems;
let cli;
let work;

/** The debug CLI of this checkout (built if missing). */
function findCli() {
  if (process.env.SCREWBENDER_BIN) return process.env.SCREWBENDER_BIN;
  const meta = JSON.parse(execFileSync('cargo', ['metadata', '--format-version', '1', '--no-deps'], { cwd: ROOT, maxBuffer: 64 << 20 }));
  const bin = path.join(meta.target_directory, 'debug', 'screwbender');
  if (!fs.existsSync(bin)) execFileSync('cargo', ['build', '-q', '-p', 'screwbender-cli'], { cwd: ROOT, stdio: 'inherit' });
  return bin;
}

before(async () => {
  cli = findCli();
  work = fs.mkdtempSync(path.join(os.tmpdir(), 'screwbender-parity-'));
  ({ play, page, problems } = await playgroundPage({ acceptDownloads: true }));
  await page.evaluate(() => document.querySelector('#hint .close')?.click());
});

after(async () => {
  await play?.close();
  if (work) fs.rmSync(work, { recursive: true, force: true });
});

/** Picks preset `id` in the chooser (the panel's Preset button, then the preset's card). */
async function pickPreset(id) {
  await page.locator('#panel button', { hasText: 'Preset:' }).click();
  await page.locator(`#presets .preset[data-id=${id}]`).click();
  await page.waitForFunction((want) => window.screwbender.app.view.scene === want, id);
  await waitFrames(page, 1);
}

/** Clicks the File folder's Export glTF (.glb) button; returns the download's name and bytes. */
async function exportGlb() {
  await page.evaluate(() => window.screwbender.app.ui.gui.folders.find((f) => f._title === 'File').open());
  const download = page.waitForEvent('download', { timeout: 120000 });
  await page.locator('#panel').getByText('Export glTF (.glb)', { exact: true }).click();
  const d = await download;
  return { name: d.suggestedFilename(), bytes: fs.readFileSync(await d.path()) };
}

/** The CLI's .glb of preset `id` with the page's subdivision options and export tolerance. */
function cliGlb(id, options, tolerance) {
  const doc = execFileSync(cli, ['preset', id]);
  const flags = ['--levels', String(options.levels), '--rules', options.rules, '--tolerance', String(tolerance)];
  if (options.scheme === 'j') flags.push('--s', String(options.s ?? options.j));
  else flags.push('--scheme', options.scheme);
  const out = path.join(work, `${id}.glb`);
  execFileSync(cli, ['export', '--format', 'glb', ...flags, '-o', out], { input: doc });
  return fs.readFileSync(out);
}

/** The JSON chunk of a GLB (what the assertion messages show when the bytes differ). */
function gltfJson(glb) {
  const length = glb.readUInt32LE(12);
  return JSON.parse(glb.subarray(20, 20 + length).toString('utf8'));
}

/** Meshes (vertex counts, morph targets) and animation channels of a GLB: what a difference shows. */
function summary(glb) {
  const g = gltfJson(glb);
  return {
    meshes: g.meshes.map((m) => m.primitives.map((p) => ({ vertices: g.accessors[p.attributes.POSITION].count, targets: p.targets?.length ?? 0 }))),
    channels: (g.animations ?? []).flatMap((a) => a.channels.map((c) => `${c.target.node}.${c.target.path}`)),
  };
}

for (const id of ['bunny6', 'pip_morph5', 'l_cycle_rotated']) {
  test(`${BACKEND}: the page's .glb of ${id} is the CLI's`, async () => {
    await pickPreset(id);
    const { options, tolerance } = await page.evaluate(() => ({
      options: window.screwbender.options(),
      // The panel's export tolerance (the File folder's controller; 1e-4 unless changed).
      tolerance: window.screwbender.app.ui.gui.folders.find((f) => f._title === 'File').controllers.find((c) => c.property === 'tolerance').getValue(),
    }));
    const { name, bytes } = await exportGlb();
    assert.equal(name, `${id}-motion.glb`);
    const expected = cliGlb(id, options, tolerance);
    // The summaries first: a failure then says what differs, not merely that bytes do.
    assert.deepEqual(summary(bytes), summary(expected), `${id}: meshes, morph targets and animation channels`);
    // Byte for byte, pip_morph5 included: its convex pieces are hulls of points made with sine
    // and cosine, whose last bit on a hull's flat faces decides which triangulation the hull
    // takes; the core computes them with the same math library natively and in wasm.
    assert.ok(bytes.equals(expected), `${id}: ${bytes.length} bytes from the page, ${expected.length} from the CLI, not the same`);
    if (id === 'bunny6') {
      // The scanned bunny, not the wedge that stands in while its file is not there.
      assert.ok(summary(bytes).meshes[0][0].vertices > 10000, 'the Stanford bunny');
    }
    if (id === 'pip_morph5') {
      const s = summary(bytes);
      assert.equal(s.meshes.length, 5, 'one mesh per shape');
      assert.ok(s.meshes.every((m) => m.every((p) => p.targets === 1)), 'one morph target each');
      assert.ok(s.channels.some((c) => c.endsWith('.weights')) && s.channels.some((c) => c.endsWith('.scale')), 'weights and scale animated');
    }
    assert.deepEqual(problems, []);
  });
}
