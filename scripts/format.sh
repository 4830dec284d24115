#!/usr/bin/env bash
# Formats every C++ file in git with its layer's .clang-format (the nearest one up the tree:
# the top-level file for the VTK layer, Module/Physics/.clang-format for the VTK-free physics
# and its tests). --check changes nothing and fails on the first file that is not formatted
# (the test CodeFormat runs that). clang-format 14 (Debian's clang-format-14).
set -euo pipefail
cd "$(dirname "$0")/.."
clang_format="${CLANG_FORMAT:-clang-format-14}"
if ! command -v "$clang_format" > /dev/null; then
  echo "format.sh: $clang_format not found (apt-get install clang-format-14)" >&2
  exit 1
fi
args=(-i)
if [[ "${1:-}" == "--check" ]]; then
  args=(--dry-run -Werror)
fi
git ls-files -z '*.h' '*.cxx' '*.cpp' | xargs -0 "$clang_format" "${args[@]}"
