// The vocabulary of a <screw-bender> figure's options (its attributes, or mount()'s options): the
// shape of a feature's declarations, the checks that read a value, and the error that names the
// option and the value at fault. The options themselves are declared by the features that own
// them (features.js lists them); this file knows none of them but the former names.

/**
 * An option a feature declares: an attribute of the element and an option of mount(), unless
 * `attribute` is false (mount() only). `type` is what the value means ('string', 'number',
 * 'integer', 'boolean', or the list of allowed words); `parse` reads a given value (a string
 * from an attribute, or a number or boolean from script) into the checked value, throwing an
 * OptionError; `default` is the value (as given, read by `parse` too) when the option is absent
 * or empty (an empty string is a value for a boolean, where it means present, and where `empty`
 * says so). `ts` is the
 * TypeScript type of the typings when richer than `type`; `python` puts the option into the
 * notebook figure (with its default there, or its trait's text).
 * @typedef {object} OptionDecl
 * @property {string} name
 * @property {'string' | 'number' | 'integer' | 'boolean' | string[]} type
 * @property {string} doc
 * @property {(value: any, options: Record<string, any>) => any} [parse]
 * @property {any} [default]
 * @property {boolean} [empty]
 * @property {boolean} [early] applies before the figure starts (checked then too)
 * @property {string} [ts]
 * @property {string} [deprecated]
 * @property {boolean} [attribute]
 * @property {boolean | {default?: any, trait?: string}} [python]
 */
/**
 * A property a feature declares: `get` (and `set`, else it is read-only) on the figure.
 * @typedef {object} PropertyDecl
 * @property {string} name
 * @property {string} ts
 * @property {string} doc
 * @property {(fig: any) => any} get
 * @property {(fig: any, value: any) => void} [set]
 */
/**
 * A method a feature declares: `call` with the figure and the arguments.
 * @typedef {object} MethodDecl
 * @property {string} name
 * @property {{name: string, ts: string, optional?: boolean}[]} params
 * @property {string} returns
 * @property {string} doc
 * @property {(fig: any, ...args: any[]) => any} call
 */
/**
 * An event a feature fires: its detail's type name and fields (none: a plain `Event` in the
 * typings).
 * @typedef {object} EventDecl
 * @property {string} name
 * @property {string} doc
 * @property {{type: string, doc: string, fields: Record<string, string>}} [detail]
 */
/**
 * One feature of the figure: what it declares, and how it applies its options. `check` hands
 * `apply` the checked values of its options (all features are checked before any applies);
 * `apply` runs on every change of options and on each load (`full`), `drawn` after the figure
 * rebuilt its drawing; `early` applies the options marked `early`, which take effect before
 * the figure starts (and are checked alone then);
 * `changed` sees every change of options first (also before the start); `loaded` runs when a
 * motion has loaded (what was asked before it takes effect).
 * @typedef {object} Feature
 * @property {string} name
 * @property {string} doc
 * @property {OptionDecl[]} [options]
 * @property {PropertyDecl[]} [properties]
 * @property {MethodDecl[]} [methods]
 * @property {EventDecl[]} [events]
 * @property {{name: string, doc: string}[]} [slots]
 * @property {{name: string, doc: string}[]} [parts]
 * @property {(fig: any, values: Record<string, any>, change: {patch: Record<string, any>, full: boolean}) => void} [apply]
 * @property {(fig: any, values: Record<string, any>, change: {patch: Record<string, any>, full: boolean}) => void} [drawn]
 * @property {(fig: any, values: Record<string, any>) => void} [early]
 * @property {(fig: any, patch: Record<string, any>) => void} [changed]
 * @property {(fig: any) => void} [loaded]
 */

/**
 * The most subdivision levels: the core's `frontend::MAX_LEVELS`, which every front end shares
 * (one level more never fits the memory limit, whatever the poses; `limits().maxLevels` of the
 * wasm API, compared with this in tests/js/api.test.mjs). Here as a constant because attributes
 * are checked before the figure's module is fetched.
 */
export const MAX_LEVELS = 19;

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
 * The checked values of `feature`'s options in `o` (with `early`, of its early options alone):
 * each option's `parse` of its value, or its default when it is absent or empty. Throws the
 * first option's OptionError.
 * @param {Feature} feature
 * @param {Record<string, any>} o
 * @param {boolean} [early]
 */
export function check(feature, o, early = false) {
  const out = {};
  for (const d of feature.options ?? []) {
    if (early && !d.early) continue;
    let v = o[d.name];
    if (v === undefined || v === null || (v === '' && d.type !== 'boolean' && !d.empty)) v = d.default;
    out[d.name] = v !== undefined && d.parse ? d.parse(v, o) : v;
  }
  return out;
}
