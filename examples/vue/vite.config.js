import vue from '@vitejs/plugin-vue';
import { defineConfig } from 'vite';

export default defineConfig({
  // <screw-bender> is a custom element, not a Vue component: Vue leaves it to the browser.
  plugins: [vue({ template: { compilerOptions: { isCustomElement: (tag) => tag === 'screw-bender' } } })],
  // The figure's sources find their WebAssembly modules by import.meta.url: not pre-bundled.
  optimizeDeps: { exclude: ['screwbender'] },
});
