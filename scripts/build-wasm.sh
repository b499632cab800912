#!/usr/bin/env bash
# WebAssembly build of the core + embind bindings → dist/kergen.mjs + dist/kergen.wasm, and
# dist/constants.js (the core's constants the package exports, from the module's wireFormat())
# (the files the npm package `kergen-wasm` ships; dist/ is gitignored).
set -euo pipefail
cd "$(dirname "$0")/.."
# Debian's emscripten needs its acorn from here for every optimized link (see ../shared/TOOLCHAIN.md).
export NODE_PATH=/usr/share/nodejs
command -v emcmake >/dev/null || { echo "build-wasm: emcmake not found (apt-get install emscripten, or bash scripts/setup.sh)" >&2; exit 1; }
emcmake cmake -S . -B build-wasm -DCMAKE_BUILD_TYPE=Release ${KERGEN_WASM_CMAKE_ARGS:-} >/dev/null
cmake --build build-wasm -j2
mkdir -p dist
cp build-wasm/wasm/kergen.mjs build-wasm/wasm/kergen.wasm dist/
# The core's constants the package exports, from the module just built (its wireFormat()).
node scripts/write-constants.mjs
# This build's sizes, printed only: the build never edits a tracked file (the package README's
# table is checked against the build by tests/node/readme-examples.test.mjs).
echo "build-wasm: dist/kergen.mjs and dist/kergen.wasm written; sizes:"
node scripts/size-table.mjs
