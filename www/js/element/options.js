// The options of a <screw-bender> figure (its attributes, or mount()'s options): their names, the
// checks of their values, and the error that names the option and the value at fault.

/** Attributes the element watches (each maps onto an option of mount()). */
/**
 * The most subdivision levels: the core's `frontend::MAX_LEVELS`, which every front end shares
 * (one level more never fits the memory limit, whatever the poses; `limits().maxLevels` of the
 * wasm API, compared with this in tests/js/api.test.mjs). Here as a constant because attributes
 * are checked before the figure's module is fetched.
 */
export const MAX_LEVELS = 19;

export const ATTRIBUTES = [
  'preset', 'src', 'share', 'scheme', 'levels', 's', 'rules', 'strobe', 'show', 'autoplay', 'loop',
  'speed', 'editable', 'controls', 'camera', 'theme', 'persist', 'alt', 'loading', 'poster', 'touch-action',
  'scene', 'j',
];
/** Former names of options, kept for one release: former name → name. */
export const ALIASES = { scene: 'preset', j: 's' };

/**
 * `patch` with the former option names replaced by the current ones. A former name given with a
 * different value beside the current one stays, so that the checks can name both.
 */
export function canonical(patch) {
  const out = { ...patch };
  for (const [old, now] of Object.entries(ALIASES)) {
    if (old in out) {
      if (!(now in out)) out[now] = out[old];
      if (String(out[now]) === String(out[old])) delete out[old];
    }
  }
  return out;
}
/** Layers of the `show` option, and those shown by default. */
export const LAYERS = ['strobe', 'control', 'trajectories', 'polyscrew', 'polygon', 'triads', 'grid'];
export const DEFAULT_SHOW = 'strobe control trajectories polygon triads grid';
export const LAYER_FIELD = {
  strobe: 'showStrobe', control: 'showControl', trajectories: 'showTrajectories', polyscrew: 'showPolyscrew',
  polygon: 'showPolygon', triads: 'showTriads', grid: 'showGrid',
};
const SCHEMES = ['bspline', 'fourpoint', 'jarek', 'j'];
const RULES = ['direct', 'split-then-tweak', 'split'];
export const CONTROLS = ['none', 'minimal', 'full'];
export const THEMES = ['light', 'dark'];
/** What a touch on a figure without the focus leaves to the page (`touch-action`). */
export const TOUCH = ['pan-y', 'pan-x', 'none'];
/** Named camera views: yaw and pitch in degrees. */
const VIEWS = { iso: [-60, 34], front: [-90, 5], side: [0, 5], top: [-90, 89] };
/** Most strobe copies a figure draws. */
export const MAX_STROBE = 20000;
/** An error naming the option (attribute) and the value that caused it. */
export class OptionError extends Error {
  constructor(attribute, value, message) {
    super(`${attribute}="${String(value).slice(0, 120)}": ${message}`);
    this.attribute = attribute;
    this.value = value;
  }
}

/** An option's boolean: present and not false / "false". */
export const bool = (v) => v !== undefined && v !== null && v !== false && v !== 'false';

/** Reads and checks one option; throws an OptionError on a bad value. */
export function number(name, value, lo, hi, integer = false) {
  const x = typeof value === 'number' ? value : Number(String(value).trim());
  if (String(value).trim() === '' || !Number.isFinite(x)) throw new OptionError(name, value, 'not a number');
  if (integer && !Number.isInteger(x)) throw new OptionError(name, value, 'not a whole number');
  if (x < lo || x > hi) throw new OptionError(name, value, `out of range (${lo} to ${hi})`);
  return x;
}

/** Checks that `value` is one of `list`. */
export function oneOf(name, value, list) {
  if (!list.includes(value)) throw new OptionError(name, value, `expected one of ${list.join(', ')}`);
  return value;
}

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

/** The subdivision options among `o` (checked), for Motion.setOptions. */
export function subdivisionOptions(o) {
  const out = {};
  if (o.scheme != null && o.scheme !== '') out.scheme = oneOf('scheme', o.scheme, SCHEMES);
  if (o.s != null && o.s !== '') {
    out.s = number('s', o.s, -4, 4);
    out.scheme ??= 'j';
  }
  if (o.j != null && o.j !== '' && number('j', o.j, -4, 4) !== out.s) {
    throw new OptionError('s', o.s, `s and j disagree (j="${o.j}"; j is the former name of s)`);
  }
  if (o.rules != null && o.rules !== '') out.rules = oneOf('rules', o.rules, RULES);
  if (o.levels != null && o.levels !== '') out.levels = number('levels', o.levels, 0, MAX_LEVELS, true);
  return out;
}

/** Options from an element's attributes (and its inline JSON child). */
export function optionsOf(el) {
  const o = {};
  for (const a of ATTRIBUTES) if (el.hasAttribute(a)) o[a] = el.getAttribute(a);
  for (const b of ['autoplay', 'editable']) if (o[b] === '') o[b] = true;
  const script = el.querySelector(':scope > script[type="application/json"]');
  if (script) o.inline = script.textContent;
  return canonical(o);
}
