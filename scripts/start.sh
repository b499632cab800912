#!/usr/bin/env bash
# `npm start`: set up the machine, build the wasm package, its API reference and the demo page,
# and serve the page on 127.0.0.1 (port 5173, or $PORT; the API reference at /api/). Ctrl-C stops
# the server. Everything it writes is gitignored (dist/, build-wasm/, web/public/api/, web/dist/):
# the work tree stays clean.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh
if [ -f scripts/build-wasm.sh ]; then
  echo "start: building the wasm package (scripts/build-wasm.sh)"
  bash scripts/build-wasm.sh
elif [ ! -f dist/kergen.wasm ]; then
  echo "start: scripts/build-wasm.sh is missing and dist/kergen.wasm does not exist" >&2
  exit 1
fi
echo "start: building the API reference (scripts/build-api-docs.sh → web/public/api/, served at /api/)"
bash scripts/build-api-docs.sh
echo "start: building the page (vite build --config web/vite.config.js)"
node node_modules/vite/bin/vite.js build --config web/vite.config.js --logLevel warn

PORT="${PORT:-5173}"
echo
echo "kergen-wasm demo: http://127.0.0.1:${PORT}/   (API reference: http://127.0.0.1:${PORT}/api/)"
echo
exec node node_modules/vite/bin/vite.js preview --config web/vite.config.js --host 127.0.0.1 --port "$PORT" --strictPort
