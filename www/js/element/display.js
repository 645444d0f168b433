// What the 3-D view draws: the layers (`show`) and the copies of the object along the motion
// (`strobe`).
import { DEFAULT_SHOW, LAYERS, LAYER_FIELD, OptionError, number } from './options.js';

/** Most strobe copies a figure draws. */
export const MAX_STROBE = 20000;

/** The layers of a `show` value (checked). */
function layersOf(value) {
  const show = String(value).trim().split(/\s+/).filter(Boolean);
  for (const s of show) if (!LAYERS.includes(s)) throw new OptionError('show', value, `unknown layer ${s} (layers: ${LAYERS.join(', ')})`);
  return show;
}

/** @type {import('./options.js').Feature} */
export const displayFeature = {
  name: 'display',
  doc: 'The layers drawn and the strobe copies.',
  options: [
    {
      name: 'strobe', type: 'integer', parse: (v) => number('strobe', v, 0, MAX_STROBE, true), python: true,
      doc: `Copies of the object drawn along the motion, 0 to ${MAX_STROBE}.`,
    },
    {
      // An empty value is a value: no layer shown.
      name: 'show', type: 'string', default: DEFAULT_SHOW, empty: true, parse: layersOf, python: true,
      doc: `Layers shown, space separated: ${LAYERS.join(' ')}.`,
    },
  ],
  apply(fig, v) {
    const { view } = fig.model;
    if (v.strobe !== undefined) view.strobe = v.strobe;
    for (const l of LAYERS) view[LAYER_FIELD[l]] = v.show.includes(l);
    if (view.strobe === 0) view.showStrobe = false;
  },
};
