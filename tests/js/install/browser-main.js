// Browser smoke entry shared by the Vite app and the plain ES-module page: loads the package,
// runs the checks and publishes the result for the Playwright driver (window.__smoke).
import init, * as sb from 'screwbender';
import { runSmoke } from './smoke.mjs';

async function main() {
  try {
    await init();
    window.__smoke = runSmoke(sb);
  } catch (e) {
    window.__smoke = { ok: false, checks: [{ name: 'load', ok: false, detail: String(e && e.stack ? e.stack : e) }] };
  }
  document.body.textContent = JSON.stringify(window.__smoke, null, 2);
}
main();
