#!/usr/bin/env bash
# JS lint and layout for every .js/.mjs/.ts file of the tree: ESLint (eslint.config.js) and
# Prettier (.prettierrc.json), both from npm (devDependencies). --fix applies what they can;
# without it (what .ci/run runs) any finding fails.
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x node_modules/.bin/eslint ] || { echo "lint: node_modules missing (bash scripts/setup.sh runs npm ci)" >&2; exit 1; }
if [ "${1:-}" = "--fix" ]; then
  npx --no-install prettier --write --log-level warn .
  npx --no-install eslint --fix .
  echo "lint: fixed what ESLint and Prettier can"
else
  npx --no-install eslint --max-warnings 0 .
  npx --no-install prettier --check --log-level warn . || {
    echo "lint: the files above do not follow Prettier's layout (run bash scripts/lint.sh --fix)" >&2
    exit 1
  }
  echo "lint: $(git ls-files '*.js' '*.mjs' '*.ts' | wc -l) JS/TS files pass ESLint and Prettier"
fi
