// The built npm package's `screwbender/full` entry (pkg/full/node.js: the math plus files,
// comparison methods, three.js keyframe tracks and teaching functions; scripts/build-pkg.sh),
// ready on import, for the JS tests of those parts. Not a test file itself.
export const sb = await import(new URL('../../pkg/full/node.js', import.meta.url).href);
