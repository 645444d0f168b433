// The analysis views of the dock, in tab order (see ../editor/dock.js for the view contract).
// Their modules (with uPlot) are fetched with the dock, not with the page: VIEW_IDS names them
// without fetching them (lesson files are checked against it).
export const VIEW_IDS = ['plots', 'metrics', 'timing', 'axes', 'steps', 'polygon', 'frame', 'methods'];

/**
 * Imports every view module; resolves to their descriptors in tab order. `attempt` > 0: a retry
 * after a failed fetch, which the browser would repeat under the same URL (editor/modules.js).
 */
export async function loadViews(attempt = 0) {
  const q = attempt ? `?retry=${attempt}` : '';
  const modules = await Promise.all([
    import(`./plots.js${q}`),
    import(`./metrics.js${q}`),
    import(`./timing.js${q}`),
    import(`./axes.js${q}`),
    import(`./steps.js${q}`),
    import(`./polygon.js${q}`),
    import(`./frame.js${q}`),
    import(`./methods.js${q}`),
  ]);
  const views = modules.map((m) => m.default);
  const ids = views.map((v) => v.id).join();
  if (ids !== VIEW_IDS.join()) throw new Error(`dock/index.js: VIEW_IDS (${VIEW_IDS}) and the modules (${ids}) differ`);
  return views;
}
