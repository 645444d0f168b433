// The `screwbender/viewer` entry: the custom element <screw-bender> (defined on import) and
// mount(element, options) for frameworks. The figure's sources live in viewer/ (the same modules
// as the playground's view, with the renderer's own WebAssembly module in viewer/pkg/).
export { mount, ScrewBenderElement, ATTRIBUTES, LAYERS } from './viewer/js/element/screw-bender.js';
