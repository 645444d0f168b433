// The figure's camera: the `camera` option (a named view or angles in degrees), the camera as
// state (the `camera` property, radians and scene units) and `camera-change`, which says who
// moved it ('user' | 'api').
import { OptionError, number, oneOf } from './options.js';

/** Named camera views: yaw and pitch in degrees. */
const VIEWS = { iso: [-60, 34], front: [-90, 5], side: [0, 5], top: [-90, 89] };
const PROJECTIONS = ['perspective', 'orthographic'];
const FIELDS = ['yaw', 'pitch', 'distance', 'target', 'projection'];

/**
 * Camera option → {yaw, pitch, distance?, target?}, angles in radians: a named view, or
 * "yaw pitch [distance [tx ty tz]]" (degrees, scene units). With the target the figure is framed
 * exactly as given (the playground's Share & embed writes all six); without it the figure is
 * framed around the motion and then turned.
 */
export function cameraView(value) {
  const v = String(value).trim();
  if (VIEWS[v]) return { yaw: (VIEWS[v][0] * Math.PI) / 180, pitch: (VIEWS[v][1] * Math.PI) / 180 };
  const parts = v.split(/[\s,]+/).map(Number);
  if ([2, 3, 6].includes(parts.length) && parts.every(Number.isFinite) && Math.abs(parts[1]) <= 89.9 && !(parts[2] <= 0)) {
    const out = { yaw: (parts[0] * Math.PI) / 180, pitch: (parts[1] * Math.PI) / 180, distance: parts[2] };
    return parts.length === 6 ? { ...out, target: parts.slice(3) } : out;
  }
  throw new OptionError('camera', value, `expected ${Object.keys(VIEWS).join(', ')}, "yaw pitch [distance]" or "yaw pitch distance tx ty tz" (degrees, scene units; |pitch| < 90, distance > 0)`);
}

/** The viewer once the motion is loaded, else null. */
const viewerOf = (fig) => (fig.model.motion ? fig.viewer : null);

/** {yaw, pitch, distance, target, projection} (radians, scene units), or null before the start. */
export function cameraState(fig) {
  const c = viewerOf(fig)?.camera;
  if (!c) return fig.pendingCamera ? { ...fig.pendingCamera } : null;
  return { yaw: c.yaw, pitch: c.pitch, distance: c.distance, target: [...c.target], projection: c.ortho ? 'orthographic' : 'perspective' };
}

/**
 * Sets the fields given (checked first: a bad one changes nothing); fires camera-change 'api'.
 * A string is the `camera` option's value (a named view, "yaw pitch [distance]" or
 * "yaw pitch distance tx ty tz").
 */
export function setCamera(fig, s) {
  if (typeof s === 'string') {
    fig.setOptions({ camera: s });
    return;
  }
  if (!s || typeof s !== 'object') throw new OptionError('camera', s, 'expected an object {yaw, pitch, distance, target, projection}');
  const out = {};
  for (const key of Object.keys(s)) {
    if (!FIELDS.includes(key)) throw new OptionError('camera', key, 'unknown camera field (yaw, pitch, distance, target, projection)');
  }
  if (s.yaw !== undefined) out.yaw = number('camera.yaw', s.yaw, -1e6, 1e6);
  if (s.pitch !== undefined) out.pitch = number('camera.pitch', s.pitch, -Math.PI / 2, Math.PI / 2);
  if (s.distance !== undefined) out.distance = number('camera.distance', s.distance, 1e-6, 1e7);
  if (s.distance === 0) throw new OptionError('camera.distance', 0, 'must be more than 0');
  if (s.target !== undefined) {
    const t = /** @type {ArrayLike<number>} */ (s.target);
    if (!(Array.isArray(t) || ArrayBuffer.isView(t)) || t.length !== 3) throw new OptionError('camera.target', t, 'expected [x, y, z]');
    out.target = Array.from(t, (x, i) => number(`camera.target[${i}]`, x, -1e9, 1e9));
  }
  if (s.projection !== undefined) out.projection = oneOf('camera.projection', s.projection, PROJECTIONS);
  const v = viewerOf(fig);
  if (!v) {
    fig.pendingCamera = { ...fig.pendingCamera, ...out };
    return;
  }
  const { projection, ...rest } = out;
  Object.assign(v.camera, rest);
  if (projection) v.camera.ortho = projection === 'orthographic';
  v.cameraMoved('api');
}

/** @type {import('./options.js').Feature} */
export const cameraFeature = {
  name: 'camera',
  doc: 'The camera as an option, as state and as an event.',
  options: [
    {
      name: 'camera', type: 'string', parse: cameraView, ts: 'string | Partial<CameraState>',
      doc: '`iso`, `front`, `side`, `top`, `"yaw pitch [distance]"` or `"yaw pitch distance tx ty tz"` (degrees, scene units; the last three the point looked at) as an attribute; as a property, the camera as state (radians, scene units).',
      python: true,
    },
  ],
  properties: [
    {
      name: 'camera', ts: 'CameraState | null',
      doc: 'The camera; set any of its fields (fires `camera-change` with source `\'api\'`). Null before the start.',
      get: cameraState,
      set: (fig, c) => fig.guard(() => setCamera(fig, c)),
    },
  ],
  events: [
    {
      name: 'camera-change', doc: 'The camera moved, by the reader (`user`) or by code (`api`).',
      detail: {
        type: 'CameraChangeDetail', doc: 'The detail of `camera-change`: who moved the camera, and where it is now.',
        fields: { source: '\'user\' | \'api\'', camera: 'CameraState' },
      },
    },
  ],
  apply(fig, v, { patch, full }) {
    const cam = v.camera;
    if (!fig.model.motion || !cam || !('camera' in patch || full)) return;
    const viewer = fig.viewer;
    viewer.frameAll();
    viewer.camera.yaw = cam.yaw;
    viewer.camera.pitch = cam.pitch;
    if (cam.distance) viewer.camera.distance = cam.distance;
    if (cam.target) viewer.camera.target = [...cam.target];
    viewer.cameraMoved();
  },
  loaded(fig) {
    const c = fig.pendingCamera;
    fig.pendingCamera = null;
    if (c) setCamera(fig, c);
  },
};

/** The viewer's camera moved: `camera-change` with who moved it. */
export function cameraMoved(fig, source) {
  fig.emit('camera-change', { source, camera: cameraState(fig) });
}
