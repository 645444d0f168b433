// The way into the lessons before the lesson player is fetched. The player (js/lessons/player.js)
// brings KaTeX and its stylesheet (css/lessons.css) with it, about a sixth of what a first visit
// downloads, so a visit fetches it only when a lesson, the tour or the Lessons menu is to be
// shown: a ?lesson= or ?tour=1 link, a first visit's tour, a press of the Lessons button or of L,
// or a script asking for window.screwbender.lessons. Until then the toolbar holds a stand-in
// Lessons button; the player's own button takes its place once the player has started.
import { lazy, stylesheet } from './modules.js';
import { tourSeen } from '../lessons/progress.js';
import { el } from '../dom.js';

/**
 * Sets up the lessons of `app`, whose first frame `ready` resolves to. Returns `player()`: a
 * promise of the started player (null if it could not load, with a message in the banner; the
 * next call tries again), which fetches the player the first time it is called.
 * @param {import('../app.js').App} app
 * @param {Promise<void>} ready
 * @returns {() => Promise<any>}
 */
export function setUpLessons(app, ready) {
  const load = lazy('the lessons', async (a) => {
    const [m] = await Promise.all([
      import(a ? `../lessons/player.js?retry=${a}` : '../lessons/player.js'),
      stylesheet(new URL('../../css/lessons.css', import.meta.url)),
    ]);
    return m;
  });
  let started = null;
  let standIn = null;

  function player() {
    started ??= ready.then(
      async () => {
        try {
          const { startLessons } = await load();
          // The player makes its own button: it goes where the stand-in was.
          if (standIn) {
            standIn.id = '';
            window.removeEventListener('keydown', onKey);
          }
          const p = startLessons(app);
          standIn?.replaceWith(document.getElementById('t-lessons') ?? '');
          standIn = null;
          return p;
        } catch (e) {
          started = null;
          app.parts.notices.show(`Lessons unavailable: ${e.message}`);
          return null;
        }
      },
      () => null,
    );
    return started;
  }

  /** Fetches the player and shows its Lessons menu (what the stand-in button and L do). */
  async function openMenu() {
    (await player())?.openMenu();
  }

  // The same keys as the player's menu (lessons/menu.js): L with the focus on the 3-D view or the
  // page, not inside a control.
  function onKey(e) {
    const t = e.target;
    const onPage = !t || t === app.viewer.canvas || t === document.body || t === document.documentElement;
    if (!onPage || !(e.key === 'l' || e.key === 'L') || e.ctrlKey || e.metaKey || e.altKey) return;
    e.preventDefault();
    openMenu();
  }

  const params = new URLSearchParams(location.search);
  // The player's own test (lessons/player.js) decides whether the tour shows: this one only
  // decides whether to fetch the player for it.
  const tourDue = params.get('tour') === '1' || (!tourSeen() && !navigator.webdriver && params.get('tour') !== '0');
  if (params.has('lesson') || tourDue) {
    player();
  } else {
    ready.then(
      () => {
        if (started) return;
        standIn = el('button', { id: 't-lessons', title: 'Lessons and the tour (L)', onclick: openMenu }, el('b', { class: 'icon' }, '∑'), el('span', {}, 'Lessons'));
        document.getElementById('toolbar')?.append(standIn);
        window.addEventListener('keydown', onKey);
      },
      () => {},
    );
  }
  return player;
}
