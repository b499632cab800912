// Vite 7 config for the demo page: `npm run build:web` → web/dist (relative asset URLs, so the
// folder can be served from any path). 'kergen-wasm' and 'kergen-wasm/worker' resolve to this
// repository's own package entry points, read from the root package.json `exports` map when it
// has one (default: wasm/index.js and wasm/worker.js).

import { defineConfig } from 'vite';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const webDir = path.dirname(fileURLToPath(import.meta.url));
const repoDir = path.resolve(webDir, '..');

function pick(target) {
  if (typeof target === 'string') return target;
  if (target && typeof target === 'object') {
    for (const cond of ['browser', 'import', 'module', 'default']) {
      const t = pick(target[cond]);
      if (t) return t;
    }
  }
  return null;
}

function entry(subpath, fallback) {
  let exp;
  try {
    exp = JSON.parse(fs.readFileSync(path.join(repoDir, 'package.json'), 'utf8')).exports;
  } catch {
    // unreadable package.json: use the default layout
  }
  let target = null;
  if (typeof exp === 'string') target = subpath === '.' ? exp : null;
  else if (exp && typeof exp === 'object') {
    const conditionsOnly = !Object.keys(exp).some((k) => k.startsWith('.'));
    target = pick(conditionsOnly ? (subpath === '.' ? exp : null) : exp[subpath]);
  }
  return path.resolve(repoDir, target ?? fallback);
}

export default defineConfig({
  root: webDir,
  base: './',
  build: {
    outDir: path.join(webDir, 'dist'),
    emptyOutDir: true,
    chunkSizeWarningLimit: 2000,
    // Two pages: the surface demo and the volume-mesh page (cells.html).
    rollupOptions: { input: { main: path.join(webDir, 'index.html'), cells: path.join(webDir, 'cells.html') } },
  },
  worker: { format: 'es' },
  resolve: {
    alias: [
      { find: /^kergen-wasm\/worker$/, replacement: entry('./worker', 'wasm/worker.js') },
      { find: /^kergen-wasm$/, replacement: entry('.', 'wasm/index.js') },
    ],
  },
  optimizeDeps: { exclude: ['kergen-wasm'] },
  server: { host: '127.0.0.1', fs: { allow: [repoDir] } },
  preview: { host: '127.0.0.1' },
});
