// Types of the vendored fflate, from its npm package (type checking only: `www/jsconfig.json`).
export * from 'fflate';
