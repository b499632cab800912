#!/usr/bin/env bash
# Every test: set-up, native build + ctest, wasm build, package tests in Node, browser e2e.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
echo "== format (clang-format)"; bash scripts/format.sh --check
echo "== lint (ESLint, Prettier)"; bash scripts/lint.sh
echo "== native build"; bash scripts/build-native.sh
echo "== native tests (ctest)"; ctest --test-dir build --output-on-failure -j2 -LE long
echo "== wasm build"; bash scripts/build-wasm.sh
echo "== package tests (node)"; npm run --silent test:node
echo "== package tests (oldest Node claimed)"; bash scripts/test-oldest-node.sh
echo "== browser e2e"; npm run --silent test:e2e
echo "all tests passed"
