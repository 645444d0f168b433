import { svelte } from '@sveltejs/vite-plugin-svelte';
import { defineConfig } from 'vite';

export default defineConfig({
  plugins: [svelte()],
  // The figure's sources find their WebAssembly modules by import.meta.url: not pre-bundled.
  optimizeDeps: { exclude: ['screwbender'] },
});
