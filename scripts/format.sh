#!/usr/bin/env bash
# Formats every C++ file in git with its layer's .clang-format (the nearest one up the tree:
# the top-level file for the VTK layer, Module/Physics/.clang-format for the VTK-free physics
# and its tests). --check changes nothing and fails on the first file that is not formatted
# (the test ScattererCodeFormat runs that; it exits 77, "skipped", outside a git checkout or
# without clang-format). clang-format 14 (Debian's clang-format-14): other versions format
# some constructs differently.
set -euo pipefail
cd "$(dirname "$0")/.."
check=0
args=(-i)
if [[ "${1:-}" == "--check" ]]; then
  check=1
  args=(--dry-run -Werror)
fi
unavailable() {
  echo "format.sh: $1" >&2
  if (( check )); then exit 77; fi
  exit 1
}
clang_format="${CLANG_FORMAT:-clang-format-14}"
command -v "$clang_format" > /dev/null ||
  unavailable "$clang_format not found (apt-get install clang-format-14)"
git rev-parse --is-inside-work-tree > /dev/null 2>&1 ||
  unavailable "not a git checkout: the files to format are the ones git tracks"
git ls-files -z '*.h' '*.cxx' '*.cpp' | xargs -0 "$clang_format" "${args[@]}"
