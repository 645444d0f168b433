// Types of the vendored lil-gui, from its npm package (type checking only: `www/jsconfig.json`).
export * from 'lil-gui';
export { default } from 'lil-gui';
