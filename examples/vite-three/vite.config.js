// `vite build` needs no configuration. Vite 7's dev server (`vite`) pre-bundles dependencies into
// node_modules/.vite/deps/, where the package's worker and .wasm are not: exclude it.
export default { optimizeDeps: { exclude: ['kergen-wasm'] } };
