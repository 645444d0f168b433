// React 19 without @vitejs/plugin-react: esbuild (Vite's own transform) compiles the JSX with
// React's automatic runtime. The plugin only adds Fast Refresh in the dev server.
import { defineConfig } from 'vite';

export default defineConfig({
  esbuild: { jsx: 'automatic', jsxImportSource: 'react' },
  // The figure's sources find their WebAssembly modules by import.meta.url: not pre-bundled.
  optimizeDeps: { exclude: ['screwbender'] },
});
