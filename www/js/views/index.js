// The analysis views of the dock, in tab order (see dock.js for the view contract).
import plots from './plots.js';
import metrics from './metrics.js';
import timing from './timing.js';
import methods from './methods.js';

export const VIEWS = [plots, metrics, timing, methods];
