#!/usr/bin/env bash
# Idempotent set-up for a fresh Debian (bookworm) machine, run as root (or with sudo available):
# system packages for the native build, tests, wasm build and browser tests, then npm packages.
set -euo pipefail
cd "$(dirname "$0")/.."

need=()
for p in build-essential cmake clang libgtest-dev libbenchmark-dev libcgal-dev libgmp-dev libmpfr-dev libqhull-dev \
         emscripten chromium valgrind clang-format voro++ tetgen python3-meshio python3-vtk9; do
  dpkg -s "$p" >/dev/null 2>&1 || need+=("$p")
done
# Node may come from Debian (nodejs + npm packages) or from elsewhere (a nodejs package that
# bundles npm): ask for the commands, not the package names.
command -v node >/dev/null 2>&1 || need+=(nodejs)
command -v npm >/dev/null 2>&1 || need+=(npm)
if [ ${#need[@]} -gt 0 ]; then
  echo "setup: installing ${need[*]}"
  SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${need[@]}" >/dev/null
fi

if [ -L node_modules ]; then
  # A link to another checkout's packages (a git worktree): npm ci would empty the folder it
  # points to, under the other checkout's feet. That checkout's own set-up keeps it current.
  echo "setup: node_modules links to $(readlink node_modules): left as it is"
elif [ -f package-lock.json ]; then
  if [ ! -d node_modules ] || [ package-lock.json -nt node_modules/.package-lock.json ]; then
    echo "setup: npm ci"
    npm ci --no-audit --no-fund --loglevel=error
  fi
fi
echo "setup: ok"
