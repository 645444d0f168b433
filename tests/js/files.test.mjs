// Motion.exportFile and importMotionFile (cargo feature `files`: the npm package's
// `screwbender/full` entry, not its light main module): glTF / CSV export, round trips through
// every import format, and bad settings and files (clear Error, motion unchanged).
import assert from 'node:assert/strict';
import { describe, it } from 'node:test';
import { sb } from './full-package.mjs';

const { Motion, importMotionFile } = sb;

function samePoses(a, b, tol) {
  assert.equal(a.length, b.length);
  for (let i = 0; i < a.length; i += 7) {
    for (let k = 0; k < 3; k++) assert.ok(Math.abs(a[i + k] - b[i + k]) <= tol, `pose ${i / 7} origin`);
    const dot = a[i + 3] * b[i + 3] + a[i + 4] * b[i + 4] + a[i + 5] * b[i + 5] + a[i + 6] * b[i + 6];
    assert.ok(1 - Math.abs(dot) <= tol, `pose ${i / 7} rotation`);
  }
}

describe('Motion.exportFile', () => {
  it('writes a GLB with the adaptive keyframe count, and importMotionFile reads the control poses back', () => {
    const m = Motion.fromPreset('l_cycle_rotated');
    const f = m.exportFile({ format: 'glb' });
    assert.equal(f.fileName, 'l_cycle_rotated-motion.glb');
    assert.equal(f.mimeType, 'model/gltf-binary');
    assert.ok(f.data instanceof Uint8Array);
    assert.equal(new TextDecoder().decode(f.data.subarray(0, 4)), 'glTF');
    assert.ok(f.sampleCount > 6 * 32, `${f.sampleCount} keyframes`);
    // A tighter tolerance needs more keyframes (the deviation bound scales with Δθ²).
    const fine = m.exportFile({ format: 'glb', tolerance: 1e-6 });
    assert.ok(fine.sampleCount > f.sampleCount);
    const doc = importMotionFile('l_cycle_rotated.glb', f.data);
    const back = new Motion(doc);
    samePoses(back.poses(), m.poses(), 1e-6);
    assert.equal(back.closed, true);
  });

  it('writes .gltf + .bin that import together (the JSON names the buffer)', () => {
    const m = Motion.fromPreset('helix_open');
    const f = m.exportFile({ format: 'gltf', name: 'walk' });
    assert.equal(f.fileName, 'walk-motion.gltf');
    assert.equal(f.binName, 'walk-motion.bin');
    const json = JSON.parse(new TextDecoder().decode(f.data));
    assert.equal(json.buffers[0].uri, 'walk-motion.bin');
    assert.equal(json.buffers[0].byteLength, f.bin.length);
    assert.throws(() => importMotionFile('walk-motion.gltf', f.data), /walk-motion\.gltf: .*walk-motion\.bin/);
    const doc = importMotionFile('walk-motion.gltf', f.data, { 'walk-motion.bin': f.bin });
    samePoses(new Motion(doc).poses(), m.poses(), 1e-6);
    assert.equal(doc.closed, false);
  });

  it('writes CSV poses (finite rows) and a body-point trajectory; fixed rate gives fps × duration + 1 rows', () => {
    const m = Motion.fromPreset('circle4');
    const f = m.exportFile({ format: 'csv', fps: 10 });
    const lines = new TextDecoder().decode(f.data).trim().split('\n');
    assert.equal(lines.length - 1, f.sampleCount);
    assert.equal(f.sampleCount, 41); // 4 spans of 1 s at 10 fps, both ends
    const rows = lines.slice(1).map((l) => l.split(',').map(Number));
    for (const r of rows) assert.ok(r.every(Number.isFinite));
    const t = m.exportFile({ format: 'csv', point: [1, 0, 0] });
    assert.match(new TextDecoder().decode(t.data).split('\n')[0], /x,y,z/);
    // A pose CSV imports as the same number of control poses (the CSV importer takes x..qz).
    const csv = 'x,y,z,qw,qx,qy,qz\n' + m.poses().reduce((s, v, i) => s + v + ((i + 1) % 7 ? ',' : '\n'), '');
    const doc = importMotionFile('poses.csv', csv);
    samePoses(new Motion(doc).poses(), m.poses(), 1e-12);
  });

  it('uses the given times (the last one is the cycle time back at pose 0)', () => {
    const m = Motion.fromPreset('circle4');
    const f = m.exportFile({ format: 'csv', fps: 2, times: [0, 1, 3, 4, 8] });
    assert.equal(f.sampleCount, 17);
    assert.throws(() => m.exportFile({ format: 'csv', times: [0, 1, 2] }), /times: 3 times given, expected 5/);
    assert.throws(() => m.exportFile({ format: 'csv', times: [0, 2, 1, 3, 4] }), /times/);
  });

  it('rejects bad settings with a message naming the setting, and the motion keeps working', () => {
    const m = Motion.fromPreset('circle4');
    const json = m.toJson();
    const bad = [
      [{ format: 'fbx' }, /format: unknown value 'fbx'/],
      [{ format: 'glb', tolerance: 0 }, /tolerance/],
      [{ format: 'glb', tolerance: NaN }, /tolerance/],
      [{ format: 'glb', fps: -1 }, /fps/],
      [{ format: 'glb', fps: 30, tolerance: 1e-3 }, /either tolerance .* or fps/],
      [{ format: 'glb', point: [0, 0, 0] }, /point: .*csv/],
      [{ format: 'glb', object: 'teapot' }, /object.mesh: unknown value 'teapot'/],
      [{ format: 'glb', mesh: { kind: 'obj', data: 'v 0 0 0\n', size: 1 } }, /mesh/],
      [{ format: 'glb', mesh: { kind: 'stl', data: '', size: 1 } }, /mesh.kind: unknown value 'stl'/],
      [{ format: 'glb', colour: 'red' }, /unknown field `colour`/],
      [null, /settings/],
    ];
    for (const [settings, re] of bad) {
      assert.throws(() => m.exportFile(settings), (e) => e instanceof Error && re.test(e.message), JSON.stringify(settings));
      assert.equal(m.toJson(), json);
    }
    assert.ok(m.exportFile({ format: 'glb', object: 'cone' }).sampleCount > 0);
  });
});

describe('importMotionFile', () => {
  it('names the file and the line, column or part at fault', () => {
    const cases = [
      ['a.csv', 'x,y,z,qw,qx,qy,qz\n0,0,0,1,0,0,0\n1,2,abc,1,0,0,0\n', /a\.csv: line 3, column z: 'abc' is not a number/],
      ['b.csv', '0,0,0,1,0,0\n', /b\.csv: .*line 1/],
      ['c.csv', '', /c\.csv: /],
      ['d.glb', new Uint8Array([0x67, 0x6c, 0x54, 0x46, 2, 0, 0, 0, 12, 0, 0, 0]), /d\.glb: /],
      ['e.gltf', '{"asset":{"version":"2.0"}}', /e\.gltf: .*anim/i],
      ['f.gltf', '{"asset":', /f\.gltf: gltf: invalid glTF JSON/],
      ['g.json', '{"poses":[]}', /g\.json: /],
      ['h.txt', 'x', /h\.txt: unknown file type/],
    ];
    for (const [name, data, re] of cases) assert.throws(() => importMotionFile(name, data), re, name);
    assert.throws(() => importMotionFile(7, 'x'), /fileName/);
    assert.throws(() => importMotionFile('a.csv', 42), /data: expected a Uint8Array or a string/);
  });

  it('refuses files over the 64 MiB limit before parsing', () => {
    const big = new Uint8Array((64 << 20) + 1);
    assert.throws(() => importMotionFile('big.glb', big), /big\.glb: .*at most 67108864 bytes/);
  });
});
