#!/usr/bin/env bash
# The package's API reference, generated from its declarations (wasm/index.d.ts, worker.d.ts,
# three.d.ts) by TypeDoc (a devDependency), written to web/public/api/ (gitignored): Vite copies
# web/public/ into the demo's build, so `bash scripts/start.sh` serves it at /api/.
#   bash scripts/build-api-docs.sh [OUT_DIR]     (npm run docs:api)
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-web/public/api}"
[ -x node_modules/.bin/typedoc ] || { echo "build-api-docs: node_modules missing (npm ci)" >&2; exit 1; }
npx --no-install typedoc \
  --tsconfig scripts/typedoc.tsconfig.json \
  --entryPoints wasm/index.d.ts --entryPoints wasm/worker.d.ts --entryPoints wasm/three.d.ts \
  --name "kergen-wasm $(node -p "require('./package.json').version")" \
  --readme wasm/README.md \
  --excludeExternals --excludePrivate \
  --disableSources --githubPages false \
  --treatWarningsAsErrors \
  --logLevel Warn \
  --out "$out"
echo "build-api-docs: API reference written to $out/"
