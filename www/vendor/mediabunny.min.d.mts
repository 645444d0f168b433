// Types of the vendored mediabunny, from its npm package (type checking only: `www/jsconfig.json`).
export * from 'mediabunny';
