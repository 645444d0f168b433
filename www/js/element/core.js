// What every figure has whatever its features: its options as one object, the renderer's
// backend (and the mount() option that asks for WebGL2), the viewer for tests and advanced
// use, and the `error` event by which every failure reaches the page.

/** @type {import('./options.js').Feature} */
export const coreFeature = {
  name: 'core',
  doc: 'Options as one object, the backend, errors.',
  options: [
    {
      name: 'backend', type: ['webgl2'], attribute: false, python: { trait: 'traitlets.Enum([None, "webgl2"], None, allow_none=True)' },
      doc: '`webgl2` skips WebGPU (mount() only; without it WebGPU where the browser has a usable adapter, else WebGL2).',
    },
  ],
  properties: [
    {
      name: 'options', ts: 'Partial<Record<keyof ScrewBenderAttributes, unknown>> & Partial<SubdivisionOptions>',
      doc: 'The options given, with the motion\'s subdivision options; set a partial object to change some.',
      get: (fig) => ({ ...fig.opts, ...(fig.model.motion ? fig.model.motion.options() : {}) }),
      set: (fig, patch) => fig.setOptions(patch ?? {}),
    },
    {
      name: 'backend', ts: '\'WebGPU\' | \'WebGL2\' | null', doc: 'The renderer\'s backend, null before the start or without graphics.',
      get: (fig) => fig.viewer?.backend ?? null,
    },
    { name: 'viewer', ts: 'unknown', doc: 'The viewer (for tests and advanced use): camera, picking, renderer.', get: (fig) => fig.viewer },
  ],
  events: [
    {
      name: 'error', doc: 'An attribute, source or call failed; the figure shows the message.',
      detail: {
        type: 'ErrorDetail', doc: 'The detail of `error`: the attribute and value at fault (null when none) and the message.',
        fields: { attribute: 'string | null', value: 'unknown', message: 'string' },
      },
    },
  ],
};
