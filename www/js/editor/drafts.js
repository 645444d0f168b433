// Work kept across tabs, reloads and browsers without storage. Each tab autosaves into a draft
// of its own (localStorage `screwbender.draft.<tab id>`, the tab id kept in sessionStorage, so
// a reload finds its own tab's draft again); a new tab starts from the newest draft. A tab
// therefore never overwrites the work of another: when the page starts, the drafts of closed
// tabs that hold other work are listed, each to open (an undoable edit: the work shown before
// stays in Undo) or to discard. Where storage runs full, the oldest closed drafts give way.
// Where the browser gives the page no storage (a sandboxed frame, storage turned off) it says
// so once, in words, and offers Share and Export instead; nothing is written and no raw
// exception text reaches the user.

/** Where the page kept its one autosave before tabs had drafts: read when no draft is there. */
export const STORAGE_KEY = 'screwbender.playground.v1';
/** Prefix of each tab's own draft: {tab, savedAt (ms since 1970), open, session}. */
export const DRAFT_PREFIX = 'screwbender.draft.';
/** sessionStorage key of this tab's id. */
const TAB_KEY = 'screwbender.tab';
/** Drafts kept at most; the oldest closed ones go first beyond it. */
export const MAX_DRAFTS = 12;
/** Drafts listed at most when the page starts (the newest). */
const MAX_LISTED = 3;

/** The page's localStorage where it works (a write and a read), else null. */
function probe() {
  try {
    const s = window.localStorage;
    const k = 'screwbender.probe';
    s.setItem(k, '1');
    s.removeItem(k);
    return s;
  } catch {
    return null;
  }
}

/** A new tab id. */
const newId = () => (crypto.randomUUID?.() ?? `${Date.now().toString(36)}-${Math.random().toString(36).slice(2)}`);

/** @type {import('../app.js').Part} */
export default {
  id: 'drafts',
  create(app) {
    const store = probe();
    let tab = null;
    let told = false;
    /** The last message of a failed save (each shown once). */
    let failed = '';
    /** The key of a closed tab's draft this tab started from (its work goes on here). */
    let adopted = null;

    /** A parsed draft, or null. */
    function read(key) {
      try {
        const d = JSON.parse(store.getItem(key) ?? 'null');
        return d && typeof d === 'object' && d.session ? d : null;
      } catch {
        return null;
      }
    }

    /** Every draft: [{key, tab, savedAt, open, session}], newest first. */
    function all() {
      if (!store) return [];
      const out = [];
      for (let i = 0; i < store.length; i++) {
        const key = store.key(i);
        if (!key?.startsWith(DRAFT_PREFIX)) continue;
        const d = read(key);
        if (d) out.push({ ...d, key, savedAt: Number(d.savedAt) || 0 });
      }
      return out.sort((a, b) => b.savedAt - a.savedAt);
    }

    /**
     * This tab's id: the one kept in sessionStorage when its draft is closed (a reload), else a
     * new one (a first visit, or a duplicated tab whose original is still open).
     */
    function tabId() {
      if (tab) return tab;
      let kept = null;
      try {
        kept = sessionStorage.getItem(TAB_KEY);
      } catch {
        kept = null;
      }
      const own = kept && store ? read(DRAFT_PREFIX + kept) : null;
      tab = kept && (!own || !own.open) ? kept : newId();
      try {
        sessionStorage.setItem(TAB_KEY, tab);
      } catch {
        // No sessionStorage: a reload starts from the newest draft instead.
      }
      return tab;
    }

    /** Marks this tab's draft open or closed (pagehide / pageshow). */
    function mark(open) {
      if (!store || !tab) return;
      const d = read(DRAFT_PREFIX + tab);
      if (!d) return;
      try {
        store.setItem(DRAFT_PREFIX + tab, JSON.stringify({ ...d, open }));
      } catch {
        // Full: the draft keeps its last state.
      }
    }

    /** Drops the oldest closed drafts beyond MAX_DRAFTS. */
    function prune() {
      const list = all().filter((d) => !d.open && d.tab !== tab);
      const open = all().length - list.length;
      for (const d of list.slice(Math.max(0, MAX_DRAFTS - open))) store.removeItem(d.key);
    }

    /** The notice bar (#drafts), made on first use. */
    function bar() {
      let el = document.getElementById('drafts');
      if (!el) {
        el = document.createElement('aside');
        el.id = 'drafts';
        el.setAttribute('aria-label', 'Kept work');
        el.setAttribute('role', 'status');
        document.body.append(el);
      }
      el.hidden = false;
      return el;
    }

    const button = (text, onClick, cls = '') => {
      const b = document.createElement('button');
      b.type = 'button';
      b.textContent = text;
      if (cls) b.className = cls;
      b.addEventListener('click', onClick);
      return b;
    };

    function closeButton(el) {
      const x = button('×', () => (el.hidden = true), 'close');
      x.setAttribute('aria-label', 'Dismiss');
      return x;
    }

    /** Says once that this page cannot keep work, with Share and Export at hand. */
    function tellNoStorage() {
      if (told) return;
      told = true;
      const el = bar();
      el.className = 'warn';
      const p = document.createElement('p');
      p.textContent = 'This page cannot keep your work: the browser gives it no storage here (a sandboxed frame, or storage turned off). Share a link or export the motion to keep it.';
      const share = button('Share link…', () => document.getElementById('m-share')?.click());
      const exp = button('Export JSON', () => app.parts.files.exportJson());
      el.replaceChildren(p, share, exp, closeButton(el));
      app.errors.push(p.textContent);
    }

    /** How a draft reads in the list: when it was saved and what it holds. */
    function describe(d) {
      const when = new Date(d.savedAt).toLocaleString([], { dateStyle: 'short', timeStyle: 'short' });
      const n = d.session.document?.poses?.length ?? 0;
      const name = d.session.document?.name || d.session.view?.scene || 'a motion';
      return `${name}, ${n} poses, saved ${when}`;
    }

    /**
     * Lists the drafts of closed tabs that hold other work than the page shows (a tab still
     * open keeps its work itself).
     */
    function offer() {
      if (!store) return;
      const mine = JSON.stringify(app.parts.session.session(false).document);
      const others = all().filter((d) => d.tab !== tab && !d.open && JSON.stringify(d.session.document) !== mine).slice(0, MAX_LISTED);
      if (!others.length) return;
      const el = bar();
      el.className = 'info';
      const p = document.createElement('p');
      p.textContent = others.length === 1 ? 'Work of another tab is kept:' : `Work of ${others.length} other tabs is kept:`;
      const list = document.createElement('ul');
      for (const d of others) {
        const li = document.createElement('li');
        const what = document.createElement('span');
        what.textContent = describe(d);
        const open = button('Open', () => {
          // One undoable edit: what the page showed stays in Undo.
          app.run('openSession', d.session, `the work of another tab (${describe(d)})`);
          store.removeItem(d.key);
          app.parts.session.autosave();
          li.remove();
          if (!list.children.length) el.hidden = true;
        });
        open.setAttribute('aria-label', `Open ${describe(d)}`);
        const drop = button('Discard', () => {
          store.removeItem(d.key);
          li.remove();
          if (!list.children.length) el.hidden = true;
        });
        drop.setAttribute('aria-label', `Discard ${describe(d)}`);
        li.append(what, open, drop);
        list.append(li);
      }
      el.replaceChildren(p, list, closeButton(el));
    }

    return {
      /** Whether the page can keep work (localStorage works). */
      get available() {
        return !!store;
      },
      /** This tab's id (the key of its draft). */
      get tab() {
        return tabId();
      },
      /** The session to start from: this tab's own draft after a reload, else the newest of any tab. */
      latest() {
        if (!store) return null;
        const own = read(DRAFT_PREFIX + tabId());
        const d = own ?? all()[0];
        // A closed tab's work that this tab goes on with: this tab's draft takes it over (bind).
        if (!own && d && !d.open) adopted = d.key;
        if (d) return d.session;
        try {
          const text = store.getItem(STORAGE_KEY);
          return text ? JSON.parse(text) : null;
        } catch {
          return null;
        }
      },
      /** The drafts of every tab, newest first ({key, tab, savedAt, open, session}). */
      list: all,
      /**
       * Keeps `session` as this tab's draft; where storage is full, the oldest drafts of closed
       * tabs give way first. Without storage it only says once that work is not kept; a failure
       * is said once per message.
       */
      save(session) {
        if (!store) return tellNoStorage();
        const text = JSON.stringify({ tab: tabId(), savedAt: Date.now(), open: true, session });
        for (;;) {
          try {
            store.setItem(DRAFT_PREFIX + tabId(), text);
            failed = '';
            return;
          } catch (e) {
            const full = /quota/i.test(`${e?.name} ${e?.message}`);
            const oldest = full ? all().filter((d) => !d.open && d.tab !== tab).at(-1) : null;
            if (oldest) {
              store.removeItem(oldest.key);
              continue;
            }
            const msg = full
              ? "Autosave failed: the browser's storage for this page is full. Share a link or export the motion to keep it."
              : 'Autosave failed: the browser refused to store the work. Share a link or export the motion to keep it.';
            if (msg !== failed) app.parts.notices.show(msg, 'warn');
            failed = msg;
            return;
          }
        }
      },
      bind() {
        if (!store) return tellNoStorage();
        tabId();
        if (adopted) {
          // Once this tab's own draft holds the work, the one it came from goes.
          app.parts.session.autosave();
          const mine = read(DRAFT_PREFIX + tabId());
          const from = read(adopted);
          if (mine && from && JSON.stringify(mine.session.document) === JSON.stringify(from.session.document)) store.removeItem(adopted);
          adopted = null;
        }
        prune();
        offer();
        window.addEventListener('pagehide', () => mark(false));
        window.addEventListener('pageshow', (e) => e.persisted && mark(true));
      },
    };
  },
};
