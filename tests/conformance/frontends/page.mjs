// The conformance cases through the playground page in Chromium: its own wasm modules (the
// first-frame module's Motion for options; the analysis module, fetched as the page fetches it,
// for the comparison and the file export), called in the page as its code calls them.
import { launch, openPage, serveWww } from '../../e2e/lib.mjs';
import { CASES, presetDocument } from './cases.mjs';

/** Runs every case in one page; returns {options, compare, export}: case id → result. */
export async function runPage() {
  const { url, stop } = await serveWww();
  const browser = await launch('webgpu');
  try {
    const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
    const { page, problems } = await openPage(context, url, 'webgpu');
    const presets = new Set([...CASES.options, ...CASES.compare, ...CASES.export].map((c) => c.preset));
    const documents = Object.fromEntries([...presets].map((id) => [id, presetDocument(id)]));
    const out = await page.evaluate(
      async ({ cases, documents }) => {
        const { app, openView } = window.screwbender;
        const Motion = app.motion.constructor;
        // The analysis module forwards its methods (compareMethods, exportFile) to this class.
        await openView('methods');
        await openView('');
        const attempt = (f) => {
          try {
            return f();
          } catch (e) {
            return { error: e.message };
          }
        };
        const summary = (flat) => ({ count: flat.length / 7, first: Array.from(flat.slice(0, 7)), last: Array.from(flat.slice(flat.length - 7)) });
        const hex = async (data) => Array.from(new Uint8Array(await crypto.subtle.digest('SHA-256', data)), (b) => b.toString(16).padStart(2, '0')).join('');
        const out = { options: {}, compare: {}, export: {} };
        for (const c of cases.options) {
          out.options[c.id] = attempt(() => {
            const m = new Motion(JSON.parse(documents[c.preset]), c.options);
            return { ...m.options(), ...summary(m.subdivide()) };
          });
        }
        for (const c of cases.compare) {
          out.compare[c.id] = attempt(() => new Motion(JSON.parse(documents[c.preset])).compareMethods(c.methods ?? undefined));
        }
        for (const c of cases.export) {
          const f = attempt(() => new Motion(JSON.parse(documents[c.preset])).exportFile({ format: c.format }));
          out.export[c.id] = f.error ? f : { sha256: await hex(f.data), bytes: f.data.length };
        }
        return out;
      },
      { cases: CASES, documents },
    );
    if (problems.length) throw new Error(`the page reported: ${problems.join('; ')}`);
    return out;
  } finally {
    await browser.close();
    stop();
  }
}
