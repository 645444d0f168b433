// The analysis dock's loading and opening: the first view opened fetches the dock (editor/dock.js),
// its views and the analysis module, with "loading…" in the dock meanwhile; a failed fetch is a
// message and the editor goes on without the dock. Opening or closing the dock changes the 3-D
// view's size: the panel folds beside it on screens narrower than 1700 px and the scene is
// framed again. The dock itself, once there, is app.dock.
import { lazy, stylesheet } from './modules.js';

// A retry asks for the modules under another URL (see editor/modules.js).
const loadDockModule = lazy('the analysis dock', (a) => import(a ? `./dock.js?retry=${a}` : './dock.js'));
// The views' charts are uPlot's: its stylesheet comes with them.
const loadViewModules = lazy('the analysis views', async (a) => {
  const [views] = await Promise.all([
    import(a ? `../dock/index.js?retry=${a}` : '../dock/index.js').then((m) => m.loadViews(a)),
    stylesheet(new URL('../../vendor/uPlot.min.css', import.meta.url)),
  ]);
  return views;
});

/** @type {import('../app.js').Part} */
export default {
  id: 'dockHost',
  create(app) {
    /** The view asked for while the dock loads ('' : closed). */
    let wanted = '';
    /** @type {Promise<void> | null} */
    let loading = null;
    /** Whether the panel was open before the dock folded it. */
    let panelWasOpen = false;

    /**
     * Up to 1700 px wide, the settings panel would cover the right part of the 3-D view that the
     * open dock leaves: fold it while the dock is open, and unfold it again when it closes (if it
     * was open).
     */
    function foldPanel(open) {
      const gui = app.ui?.gui;
      if (!gui || window.innerWidth >= 1700) return;
      if (open) {
        panelWasOpen = !gui._closed;
        gui.close();
      } else if (panelWasOpen) gui.open();
    }

    /** Fetches the dock, its views and the analysis module, showing "loading…" in the dock. */
    async function load() {
      const root = document.getElementById('dock');
      const body = root.querySelector('.body');
      const note = document.createElement('p');
      note.className = 'note loading';
      note.setAttribute('role', 'status');
      note.textContent = 'Loading the analysis views…';
      body.append(note);
      root.classList.add('open');
      try {
        const [{ Dock }, views, analysis] = await Promise.all([loadDockModule(), loadViewModules(), app.analysis()]);
        app.dock = new Dock(app, views, analysis);
      } catch (e) {
        app.parts.notices.show(`${e.message}. The editor works on without the analysis views.`);
        app.updateView({ dock: '' });
        wanted = '';
        app.ui?.refresh();
      } finally {
        note.remove();
        if (!app.dock) root.classList.remove('open');
        loading = null;
      }
    }

    function openNow(id) {
      const dock = app.dock;
      let inst = null;
      const wasOpen = !!dock.active;
      try {
        inst = dock.open(id || null);
        // The 3-D view changes size when the dock opens or closes (wide screens): re-frame.
        if (wasOpen !== !!dock.active) {
          foldPanel(!!dock.active);
          app.viewer.invalidateSize();
          app.parts.viewpoint.fit();
        }
        app.updateView({ dock: id || '' });
      } catch (e) {
        app.updateView({ dock: '' });
        app.parts.notices.show(e.message);
      }
      app.parts.session.autosave();
      app.ui?.refresh();
      return inst;
    }

    return {
      /** A promise while the dock and its modules are fetched, else null. */
      get loading() {
        return loading;
      },
      /**
       * Opens analysis view `id` ('' or null closes the dock); resolves to its instance (null
       * when closed, or when the dock could not be fetched).
       */
      async open(id) {
        if (!app.dock) {
          wanted = id || '';
          if (!id) {
            // Closed while it loads (V, the toolbar button): closed at once, and it stays
            // closed when the load ends.
            if (loading) {
              document.getElementById('dock').classList.remove('open');
              app.updateView({ dock: '' });
              app.ui?.refresh();
            }
            return null;
          }
          if (loading) document.getElementById('dock').classList.add('open');
          loading ??= load();
          await loading;
          if (!app.dock) return null;
          // Meanwhile another view may have been asked for (its own call opens it), or the dock
          // closed.
          if (wanted !== id) return wanted ? app.dock.current : openNow('');
        }
        return openNow(id);
      },
    };
  },
};
