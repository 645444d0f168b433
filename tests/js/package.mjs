// The built npm package, imported and initialised once for the JS API tests: pkg/node.js, or
// the file named by SCREWBENDER_PKG (relative to the working directory). Not a test file itself.
/** The package's entry file (its neighbours are the package's other files). */
export const entry = process.env.SCREWBENDER_PKG
  ? new URL(process.env.SCREWBENDER_PKG, `file://${process.cwd()}/`)
  : new URL('../../pkg/node.js', import.meta.url);

/** The `screwbender` module, ready to use. */
export const sb = await import(entry.href);
await sb.default();
