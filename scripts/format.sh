#!/usr/bin/env bash
# Applies .clang-format to every C++ file of the tree (--check: only reports, exit 1 if a file
# would change; what .ci/run runs).
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null || { echo "format: clang-format not found (bash scripts/setup.sh installs it)" >&2; exit 1; }
mapfile -t files < <(git ls-files '*.cpp' '*.h')
if [ "${1:-}" = "--check" ]; then
  if clang-format --dry-run --Werror "${files[@]}" 2>/tmp/kergen-format.$$; then
    echo "format: ${#files[@]} C++ files follow .clang-format"
    rm -f /tmp/kergen-format.$$
  else
    grep -o '^[^:]*:' /tmp/kergen-format.$$ | sort -u | sed 's/:$//' | head -20 >&2
    rm -f /tmp/kergen-format.$$
    echo "format: the files above do not follow .clang-format (run bash scripts/format.sh)" >&2
    exit 1
  fi
else
  clang-format -i "${files[@]}"
  echo "format: ${#files[@]} C++ files formatted"
fi
