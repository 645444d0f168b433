// Types of the vendored uPlot, from its npm package (type checking only: `www/jsconfig.json`).
export { default } from 'uplot';
