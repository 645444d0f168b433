// The subdivision of the motion shown: `scheme`, `s` (the J_s family; `j` is its former name),
// `rules` and `levels`, handed to the motion as one change (a refused one leaves the motion as
// it was) and said in the live region.
import { schemeName, say } from './description.js';
import { MAX_LEVELS, OptionError, number, oneOf } from './options.js';

const SCHEMES = ['bspline', 'fourpoint', 'jarek', 'j'];
const RULES = ['direct', 'split-then-tweak', 'split'];
const KEYS = ['scheme', 's', 'rules', 'levels'];

/** `s` of the options `o` (checked), undefined when absent. */
const sOf = (o) => (o.s != null && o.s !== '' ? number('s', o.s, -4, 4) : undefined);

/** The subdivision options among the checked values `v`, for Motion.setOptions. */
function subdivisionOf(v) {
  const out = {};
  for (const k of KEYS) if (v[k] !== undefined) out[k] = v[k];
  if (out.s !== undefined) out.scheme ??= 'j';
  return out;
}

/** @type {import('./options.js').Feature} */
export const subdivisionFeature = {
  name: 'subdivision',
  doc: 'The subdivision scheme, its parameter, rules and levels.',
  options: [
    {
      name: 'scheme', type: SCHEMES, parse: (v) => oneOf('scheme', v, SCHEMES), ts: 'SubdivisionOptions[\'scheme\']', python: true,
      doc: 'The subdivision scheme.',
    },
    {
      name: 's', type: 'number', parse: (v) => number('s', v, -4, 4), python: true,
      doc: 'The J_s parameter `s`, -4 to 4 (implies scheme `j`).',
    },
    {
      name: 'j', type: 'number', deprecated: 'Renamed to `s`.',
      doc: 'Former name of `s`, kept for one release (an error if it disagrees with `s`).',
      parse(v, o) {
        if (number('j', v, -4, 4) !== sOf(o)) throw new OptionError('s', o.s, `s and j disagree (j="${v}"; j is the former name of s)`);
        return undefined;
      },
    },
    {
      name: 'rules', type: RULES, parse: (v) => oneOf('rules', v, RULES), ts: 'SubdivisionOptions[\'rules\']', python: { default: 'direct' },
      doc: 'The rule set: `direct`, or the first version\'s split-then-tweak (`split`).',
    },
    {
      name: 'levels', type: 'integer', parse: (v) => number('levels', v, 0, MAX_LEVELS, true), python: true,
      doc: `Subdivision levels, 0 to ${MAX_LEVELS}.`,
    },
  ],
  apply(fig, v) {
    const { motion } = fig.model;
    const sub = subdivisionOf(v);
    if (!motion || !Object.keys(sub).length) return;
    const old = motion.options();
    try {
      motion.setOptions(sub);
    } catch (e) {
      motion.setOptions(old);
      const key = ['levels', 's', 'scheme', 'rules'].find((k) => k in sub) ?? 'levels';
      throw new OptionError(key, fig.opts[key], e.message);
    }
  },
  drawn(fig, v, { full }) {
    if (full || !Object.keys(subdivisionOf(v)).length) return;
    const m = fig.model.motion.options();
    say(fig, `${schemeName(m)}, ${m.levels} level${m.levels === 1 ? '' : 's'}`);
  },
};
