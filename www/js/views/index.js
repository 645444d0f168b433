// The analysis views of the dock, in tab order (see dock.js for the view contract).
export const VIEWS = [];
