// The notebook bundle's assets, inlined by build.mjs's loaders: the two renderer modules (their
// glue and their bytes: only the one the browser draws with is instantiated), the stylesheet's
// text and the bunny mesh as a data: URL, told to the figure with configure() (www/js/assets.js).
// figure.js imports this module first, so that the figure finds them from its first start: a
// notebook, JupyterLab, VS Code or an exported page needs no server, CDN or network.
import { configure } from '../../www/js/assets.js';
import init, * as glue from '../../www/pkg-webgpu/screwbender.js';
import initGl, * as glueGl from '../../www/pkg-gl/screwbender.js';
import bytes from '../../www/pkg-webgpu/screwbender_bg.wasm';
import bytesGl from '../../www/pkg-gl/screwbender_bg.wasm';
import css from '../../www/css/screw-bender.css';
import bunny from '../../crates/screwbender/assets/bunny.obj';

configure({
  modules: {
    main: async () => ({ ...glue, default: () => init({ module_or_path: bytes }) }),
    gl: async () => ({ ...glueGl, default: () => initGl({ module_or_path: bytesGl }) }),
    files: () => Promise.reject(new Error('the notebook figure reads no glTF or CSV file')),
  },
  css,
  bunny,
});
