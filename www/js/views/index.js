// The analysis views of the dock, in tab order (see ../editor/dock.js for the view contract).
import plots from './plots.js';
import metrics from './metrics.js';
import timing from './timing.js';
import axes from './axes.js';
import steps from './steps.js';
import polygon from './polygon.js';
import frame from './frame.js';
import methods from './methods.js';

export const VIEWS = [plots, metrics, timing, axes, steps, polygon, frame, methods];
