// The analysis views of the dock, in tab order (see dock.js for the view contract).
import methods from './methods.js';

export const VIEWS = [methods];
