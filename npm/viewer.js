// The `screwbender/viewer` entry: the custom element <screw-bender> (defined on import) and
// mount(element, options) for frameworks. The figure's sources are bundled in
// viewer/js/screw-bender.js (the same modules as the playground's view), which finds its
// stylesheet and the bunny mesh beside it (viewer/css/, viewer/vendor/). This entry tells it
// where the package keeps the WebAssembly modules (viewer/pkg/: WebGPU only; viewer/pkg-gl/:
// WebGL2, imported only where WebGPU has no usable adapter; full/: to read a glTF or CSV `src`),
// with import paths that bundlers follow; a figure imports them only after it has started,
// after this module has run.
import { configure } from './viewer/js/screw-bender.js';

configure({
  modules: {
    main: () => import('./viewer/pkg/screwbender.js'),
    gl: () => import('./viewer/pkg-gl/screwbender.js'),
    files: () => import('./full/screwbender.js'),
  },
});

export { mount, ScrewBenderElement, ATTRIBUTES, LAYERS, configure } from './viewer/js/screw-bender.js';
