// The analysis views of the dock, in tab order (see dock.js for the view contract).
import axes from './axes.js';
import steps from './steps.js';
import polygon from './polygon.js';
import frame from './frame.js';

export const VIEWS = [axes, steps, polygon, frame];
