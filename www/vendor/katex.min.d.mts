// Types of the vendored KaTeX, from its npm package (type checking only: `www/jsconfig.json`).
export * from 'katex';
export { default } from 'katex';
