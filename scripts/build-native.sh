#!/usr/bin/env bash
# Native build: core library, CLI `kergen`, tests, benchmarks → build/
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release ${KERGEN_CMAKE_ARGS:-} >/dev/null
cmake --build build -j2
