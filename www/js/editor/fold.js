// Small screens keep the 3-D view in sight: the settings panel folds when a choice made in it
// is done (a preset picked, the tour ended), as it starts folded there (editor/panel.js).

/** Phones upright and on their side (the breakpoints the panel starts folded at). */
export function smallScreen() {
  return window.innerWidth < 760 || window.innerHeight < 500;
}

/** Folds the settings panel of `app` on a small screen; wider screens keep it as it is. */
export function foldPanelOnSmallScreens(app) {
  if (smallScreen()) app.ui?.gui.close();
}
