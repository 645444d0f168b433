// The glTF export of the morphing preset (A8, pip_morph5: cone, star, block, cylinder, sphere)
// played by the real three.js: GLTFLoader reads the .glb the CLI writes, an AnimationMixer plays
// its first clip, and at each control pose's time the one visible span mesh (scale keys), with
// its morph target weight applied, must be that pose's shape: at the star's time a ray from the
// axis toward a notch leaves the object at the star's inner radius (its convex hull would reach
// much farther) and a ray toward a point reaches the outer radius.
//
//   SCREWBENDER_BIN=path/to/screwbender node --test tests/gltf/morph.test.mjs
//
// Without SCREWBENDER_BIN the release binary of the cargo target directory is used.
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { describe, it } from 'node:test';

import * as THREE from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';

function binary() {
  if (process.env.SCREWBENDER_BIN) return process.env.SCREWBENDER_BIN;
  const meta = JSON.parse(execFileSync('cargo', ['metadata', '--format-version', '1', '--no-deps'], { encoding: 'utf8' }));
  return path.join(meta.target_directory, 'release', 'screwbender');
}

const bin = binary();
const work = fs.mkdtempSync(path.join(os.tmpdir(), 'screwbender-morph-'));
fs.writeFileSync(path.join(work, 'a8.json'), execFileSync(bin, ['preset', 'pip_morph5']));
const glbPath = path.join(work, 'a8.glb');
execFileSync(bin, ['export', '--format', 'glb', path.join(work, 'a8.json'), '-o', glbPath]);
const bytes = fs.readFileSync(glbPath);
const gltf = await new GLTFLoader().parseAsync(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.length), '');
fs.rmSync(work, { recursive: true, force: true });

/** The control poses' times: the keyframes of the control node's animation. */
const controlClip = gltf.animations.find((a) => a.name === 'control poses');
const knots = Array.from(controlClip.tracks[0].times);
const objectClip = gltf.animations.find((a) => a !== controlClip);

const root = gltf.scene;
const mixer = new THREE.AnimationMixer(root);
mixer.clipAction(objectClip).play();

/** The triangles of the visible span mesh at time `t`, in the object's frame, morph applied. */
function objectAt(t) {
  mixer.setTime(t);
  root.updateMatrixWorld(true);
  const spans = [];
  root.traverse((o) => {
    if (o.isMesh && o.morphTargetInfluences) spans.push(o);
  });
  const visible = spans.filter((o) => o.scale.x > 0.5);
  assert.equal(visible.length, 1, `one span visible at t = ${t} (scales ${spans.map((o) => o.scale.x)})`);
  assert.ok(spans.every((o) => o.scale.x === 0 || o.scale.x === 1));
  const mesh = visible[0];
  const g = mesh.geometry;
  const base = g.attributes.position;
  const delta = g.morphAttributes.position[0];
  assert.ok(g.morphTargetsRelative, 'glTF morph targets are displacements');
  const w = mesh.morphTargetInfluences[0];
  // The span node sits at the object's origin: its own transform is its scale only.
  assert.ok(mesh.position.length() < 1e-12 && mesh.quaternion.w === 1);
  const pts = [];
  for (let i = 0; i < base.count; i++) {
    pts.push(new THREE.Vector3(
      base.getX(i) + w * delta.getX(i),
      base.getY(i) + w * delta.getY(i),
      base.getZ(i) + w * delta.getZ(i),
    ));
  }
  return { pts, weight: w, name: mesh.name };
}

/** The farthest distance along `dir` (from the origin) at which the ray meets a triangle. */
function reach({ pts }, dir) {
  let far = 0;
  const e1 = new THREE.Vector3();
  const e2 = new THREE.Vector3();
  const p = new THREE.Vector3();
  const s = new THREE.Vector3();
  const q = new THREE.Vector3();
  for (let i = 0; i + 2 < pts.length; i += 3) {
    const [a, b, c] = [pts[i], pts[i + 1], pts[i + 2]];
    e1.subVectors(b, a);
    e2.subVectors(c, a);
    p.crossVectors(dir, e2);
    const det = e1.dot(p);
    if (Math.abs(det) < 1e-14) continue;
    s.copy(a).negate();
    const u = s.dot(p) / det;
    q.crossVectors(s, e1);
    const v = dir.dot(q) / det;
    const t = e2.dot(q) / det;
    if (u >= -1e-9 && v >= -1e-9 && u + v <= 1 + 1e-9 && t > 0) far = Math.max(far, t);
  }
  return far;
}

function bounds({ pts }) {
  const box = new THREE.Box3();
  for (const p of pts) box.expandByPoint(p);
  return box;
}

// The star of scene A8: outer radius 0.8, inner 0.35, first point along +y (f32 files).
const OUTER = 0.8;
const INNER = 0.35;
const F32 = 1e-5;
const angle = (k) => Math.PI / 2 + (Math.PI * k) / 5;
const along = (a) => new THREE.Vector3(Math.cos(a), Math.sin(a), 0);

describe('the morphing preset played by three.js', () => {
  it('has five control times and one span mesh per span', () => {
    assert.equal(knots.length, 6, 'a cycle of five poses: six knots');
    let spans = 0;
    root.traverse((o) => {
      if (o.isMesh && o.morphTargetInfluences) spans += 1;
    });
    assert.equal(spans, 5);
  });

  it("shows the star at the star's time, notches and points included", () => {
    const star = objectAt(knots[1]);
    assert.ok(star.weight < 1e-6, `the span starts at the star (weight ${star.weight})`);
    for (let k = 0; k < 5; k++) {
      const tip = reach(star, along(angle(2 * k)));
      assert.ok(Math.abs(tip - OUTER) < F32, `point ${k}: reach ${tip}`);
      const notch = reach(star, along(angle(2 * k + 1)));
      assert.ok(Math.abs(notch - INNER) < F32, `notch ${k}: reach ${notch} (the hull's would be ${OUTER * Math.cos(Math.PI / 5)})`);
    }
    const box = bounds(star);
    assert.ok(Math.abs(box.max.z - 0.2) < F32 && Math.abs(box.min.z + 0.2) < F32, 'thickness 0.4');
  });

  it('shows the block and the sphere at their times, and blends in between', () => {
    const block = bounds(objectAt(knots[2]));
    for (const [got, want] of [[block.max.x, 0.5], [block.max.y, 0.3], [block.max.z, 0.7], [block.min.x, -0.5]]) {
      assert.ok(Math.abs(got - want) < F32, `block bounds ${got} vs ${want}`);
    }
    const sphere = objectAt(knots[4]);
    for (const d of [[1, 0, 0], [0, 1, 0], [0, 0, 1], [-1, 0, 0]]) {
      const r = reach(sphere, new THREE.Vector3(...d));
      assert.ok(Math.abs(r - 0.7) < F32, `sphere radius ${r} along ${d}`);
    }
    // Halfway from the cone to the star the point reaches between the two.
    const mid = objectAt(0.5 * (knots[0] + knots[1]));
    assert.ok(mid.weight > 0.05 && mid.weight < 0.95, `weight ${mid.weight}`);
    const tip = reach(mid, along(angle(0)));
    assert.ok(tip > 0.3 + 1e-3 && tip < OUTER - 1e-3, `halfway reach ${tip}`);
  });
});
