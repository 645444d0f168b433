// The package smoke test shared by Node and the browser pages (no imports: the caller passes
// the loaded module). It subdivides presets and checks poses whose values are known exactly.
//
//   import * as sb from 'screwbender'; await sb.default(); const r = runSmoke(sb);
//   // r = { ok: boolean, checks: [{ name, ok, detail }] }

/** Runs the checks against the loaded `screwbender` module; never throws. */
export function runSmoke(sb) {
  const checks = [];
  const check = (name, fn) => {
    try {
      const detail = fn();
      checks.push({ name, ok: true, detail: detail ?? '' });
    } catch (e) {
      checks.push({ name, ok: false, detail: String(e && e.stack ? e.stack : e) });
    }
  };
  const near = (a, b, tol, what) => {
    for (let k = 0; k < b.length; k++) {
      if (!(Math.abs(a[k] - b[k]) <= tol)) {
        throw new Error(`${what}: got [${Array.from(a)}], expected [${b}] (tol ${tol})`);
      }
    }
  };
  // Quaternions q and -q are the same rotation.
  const nearQuat = (q, e, tol, what) => {
    const s = q[0] * e[0] + q[1] * e[1] + q[2] * e[2] + q[3] * e[3] < 0 ? -1 : 1;
    near(q.map((v) => s * v), e, tol, what);
  };

  check('version', () => {
    if (!/^\d+\.\d+\.\d+/.test(sb.version())) throw new Error(`version ${sb.version()}`);
    return sb.version();
  });

  check('circle4: subdivide + known pose', () => {
    const m = sb.Motion.fromPreset('circle4');
    try {
      const refined = m.subdivide();
      if (!(refined instanceof Float64Array) || refined.length !== 4 * 32 * 7) {
        throw new Error(`refined length ${refined.length}`);
      }
      // Every screw scheme keeps the circle: pose(u) = Rz(90°·u) at Rz(90°·u)·(3, 0, 0).
      for (const u of [0.5, 1.25, 3.7]) {
        const a = (Math.PI / 2) * u;
        const p = m.poseAt(u);
        near(p.origin, [3 * Math.cos(a), 3 * Math.sin(a), 0], 1e-12, `origin at u=${u}`);
        nearQuat(p.rotation, [Math.cos(a / 2), 0, 0, Math.sin(a / 2)], 1e-12, `rotation at u=${u}`);
      }
      return `${refined.length / 7} refined poses`;
    } finally {
      m.free();
    }
  });

  check('l_cycle_rotated: 4-point interpolates', () => {
    const m = sb.Motion.fromPreset('l_cycle_rotated');
    try {
      m.setLevels(6);
      const refined = m.subdivide();
      // Control pose 3 = refined pose 3·2^6, origin (2, 2, 0), Rz(45°).
      const j = 3 * 64 * 7;
      const c = Math.cos(Math.PI / 8);
      const s = Math.sin(Math.PI / 8);
      near(refined.subarray(j, j + 3), [2, 2, 0], 1e-12, 'refined origin');
      nearQuat(Array.from(refined.subarray(j + 3, j + 7)), [c, 0, 0, s], 1e-12, 'refined rotation');
      const m4 = m.refinedMatrices().subarray(3 * 64 * 16, 3 * 64 * 16 + 16);
      near(m4, [Math.SQRT1_2, Math.SQRT1_2, 0, 0, -Math.SQRT1_2, Math.SQRT1_2, 0, 0, 0, 0, 1, 0, 2, 2, 0, 1], 1e-6, 'matrix');
      return 'pose 3 reproduced';
    } finally {
      m.free();
    }
  });

  check('helix_open: every scheme reproduces the helix', () => {
    const m = sb.Motion.fromPreset('helix_open');
    try {
      for (const scheme of ['bspline', 'fourpoint', 'jarek']) {
        m.setScheme(scheme);
        const u = 2.5;
        const a = (Math.PI / 4) * u;
        const p = m.poseAt(u);
        near(p.origin, [3 * Math.cos(a), 3 * Math.sin(a), 0.6 * u], 1e-11, `${scheme} origin`);
        nearQuat(p.rotation, [Math.cos(a / 2), 0, 0, Math.sin(a / 2)], 1e-11, `${scheme} rotation`);
      }
      return 'bspline, fourpoint, jarek';
    } finally {
      m.free();
    }
  });

  check('bad input throws and leaves the motion unchanged', () => {
    const m = sb.Motion.fromPreset('pendulum');
    try {
      const before = m.toJson();
      let message = '';
      try {
        m.setPose(0, { origin: [0, 0, 0], rotation: [0, 0, 0, 0] });
      } catch (e) {
        message = e.message;
      }
      if (message !== 'pose.rotation: zero quaternion') throw new Error(`message '${message}'`);
      if (m.toJson() !== before) throw new Error('state changed');
      return message;
    } finally {
      m.free();
    }
  });

  return { ok: checks.every((c) => c.ok), checks };
}
