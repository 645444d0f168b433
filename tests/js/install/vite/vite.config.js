// Vite config of the install test app. The dev server's dependency pre-bundling would move the
// module away from its .wasm file, so the package is excluded from it (as the README says);
// `vite build` does not need this.
import { defineConfig } from 'vite';

export default defineConfig({
  optimizeDeps: { exclude: ['screwbender'] },
  logLevel: 'warn',
});
