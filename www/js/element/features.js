// The figure's features, in the order their options are checked and applied: each declares its
// options, properties, methods, events, slots and parts once (options.js says how), and the
// element, mount()'s handle, the typings, the Custom Elements Manifest and the notebook figure
// are all made from these declarations (scripts/element-api.mjs writes the generated files).
import { cameraFeature } from './camera.js';
import { chromeFeature } from './chrome.js';
import { coreFeature } from './core.js';
import { descriptionFeature } from './description.js';
import { displayFeature } from './display.js';
import { editingFeature } from './editing.js';
import { labelsFeature } from './labels.js';
import { loadingFeature } from './loading.js';
import { picturesFeature } from './pictures.js';
import { playbackFeature } from './playback.js';
import { sourceFeature } from './source.js';
import { subdivisionFeature } from './subdivision.js';

/** @type {import('./options.js').Feature[]} */
export const FEATURES = [
  coreFeature, sourceFeature, subdivisionFeature, displayFeature, chromeFeature, descriptionFeature, editingFeature,
  cameraFeature, playbackFeature, picturesFeature, labelsFeature, loadingFeature,
];

/** Every declared option, in the features' order. */
export const OPTIONS = FEATURES.flatMap((f) => f.options ?? []);
/** The attributes the element watches: every option but those of mount() alone. */
export const ATTRIBUTES = OPTIONS.filter((o) => o.attribute !== false).map((o) => o.name);
/** Boolean options: present without a value (an attribute's '') means true. */
export const FLAGS = OPTIONS.filter((o) => o.type === 'boolean').map((o) => o.name);
/** The options of the notebook figure (python/widget/figure.js and its traitlets). */
export const WIDGET_OPTIONS = OPTIONS.filter((o) => o.python).map((o) => o.name);
/** Every declared event type. */
export const EVENTS = FEATURES.flatMap((f) => (f.events ?? []).map((e) => e.name));
