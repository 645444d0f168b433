// Node entry of the `screwbender` package (the "node" export condition); scripts/build-pkg.sh
// also copies it to full/node.js, the Node entry of `screwbender/full`.
//
// It instantiates the same WebAssembly file as the browser entry, synchronously from disk, so
// `import { Motion } from 'screwbender'` is ready at once in Node. Calling the default export
// `init()` as in browsers is harmless here: the module is already initialised.
import { readFileSync } from 'node:fs';
import { initSync } from './screwbender.js';

initSync({ module: readFileSync(new URL('./screwbender_bg.wasm', import.meta.url)) });

export * from './screwbender.js';
export { default } from './screwbender.js';
