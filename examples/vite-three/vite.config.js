// `vite build` needs no configuration (three.js makes the page's chunk larger than Vite's 500 kB
// warning: the limit is raised). Vite 7's dev server (`vite`) pre-bundles dependencies into
// node_modules/.vite/deps/, where the package's worker and .wasm are not: excluded (Vite 8's
// works either way).
export default { optimizeDeps: { exclude: ['kergen-wasm'] }, build: { chunkSizeWarningLimit: 1000 } };
