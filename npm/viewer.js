// The `screwbender/viewer` entry: the custom element <screw-bender> (defined on import) and
// mount(element, options) for frameworks. The figure's sources live in viewer/ (the same modules
// as the playground's view); this entry tells them where the package keeps the WebAssembly
// modules (viewer/pkg/: WebGPU only; viewer/pkg-gl/: WebGL2, imported only where WebGPU has no
// usable adapter; full/: to read a glTF or CSV `src`), with import paths that bundlers follow.
import { configure } from './viewer/js/assets.js';

configure({
  modules: {
    main: () => import('./viewer/pkg/screwbender.js'),
    gl: () => import('./viewer/pkg-gl/screwbender.js'),
    files: () => import('./full/screwbender.js'),
  },
});

export { mount, ScrewBenderElement, ATTRIBUTES, LAYERS, configure } from './viewer/js/element/screw-bender.js';
