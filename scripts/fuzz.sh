#!/usr/bin/env bash
# Builds the libFuzzer targets of Testing/Fuzz (clang, ASan + UBSan; only
# fuzz_volume_headers links VTK) into ${FUZZ_BUILD_DIR:-build-fuzz} and runs each for a
# bounded time:
#   bash scripts/fuzz.sh                        # 25 s per target (what CI runs)
#   bash scripts/fuzz.sh 3600                   # an hour per target
#   bash scripts/fuzz.sh 600 volume_headers     # one target only
# The seed corpus is copied to a temporary folder first, so the repository is not
# modified. Exits non-zero if a fuzzer finds a crash, a sanitizer report, a timeout
# (> 5 s for one input) or an input that needs more than 1 GiB; the failing inputs are
# kept in <build>/crashes/<target>/ with the command that reproduces them.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-25}"
all_targets=(template_generator template_reader volume_headers)
usage="usage: $0 [seconds-per-target (default 25)] [target: ${all_targets[*]}]"
if ! [[ "$seconds" =~ ^[1-9][0-9]*$ ]]; then
  echo "$usage" >&2
  exit 2
fi
if [ $# -ge 2 ]; then
  if ! [[ " ${all_targets[*]} " == *" $2 "* ]]; then
    echo "$usage" >&2
    exit 2
  fi
  targets=("$2")
else
  targets=("${all_targets[@]}")
fi
build="${FUZZ_BUILD_DIR:-build-fuzz}"

start=$(date +%s)
bash scripts/install-deps.sh # clang and libclang-rt-14-dev (libFuzzer)
CC="${FUZZ_CC:-clang}" CXX="${FUZZ_CXX:-clang++}" cmake -S Testing/Fuzz -B "$build" \
  > "$build.configure.log" 2>&1 ||
  { cat "$build.configure.log"; exit 1; }
cmake --build "$build" -j 2 --target "${targets[@]/#/fuzz_}" > "$build/build.log" 2>&1 ||
  { tail -n 60 "$build/build.log"; exit 1; }
echo "fuzz: built in $(( $(date +%s) - start )) s"

work="$(mktemp -d "${TMPDIR:-/tmp}/scatterer-fuzz.XXXXXX")"
trap 'rm -rf "$work"' EXIT
# UBSan findings abort (the targets are built with -fno-sanitize-recover=all); print
# where they happened.
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

failed=()
for target in "${targets[@]}"; do
  corpus="$work/corpus/$target"
  artifacts="$work/artifacts/$target"
  mkdir -p "$corpus" "$artifacts"
  cp Testing/Fuzz/corpus/"$target"/* "$corpus"/
  log="$work/$target.log"
  echo "fuzz: $target for $seconds s"
  # TMPDIR: fuzz_volume_headers writes its files in a folder there, which a crash (no
  # atexit) would otherwise leave behind.
  if TMPDIR="$work" "$build/fuzz_$target" "$corpus" -max_total_time="$seconds" -timeout=5 \
    -rss_limit_mb=1024 -artifact_prefix="$artifacts/" -print_final_stats=1 > "$log" 2>&1; then
    grep -E '^#[0-9]+[[:space:]]+DONE|^stat::(number_of_executed_units|average_exec_per_sec|peak_rss_mb)' \
      "$log" | sed "s/^/fuzz: $target: /" || true
  else
    echo "fuzz: $target FAILED; the end of its log:" >&2
    tail -n 80 "$log" >&2
    kept="$build/crashes/$target"
    mkdir -p "$kept"
    cp "$artifacts"/* "$kept"/ 2>/dev/null || true
    cp "$log" "$kept/"
    echo "fuzz: failing inputs kept in $kept/; reproduce with: $build/fuzz_$target $kept/<crash-file>" >&2
    failed+=("$target")
  fi
done

echo "fuzz: finished in $(( $(date +%s) - start )) s"
if [ ${#failed[@]} -ne 0 ]; then
  echo "fuzz: FAILED: ${failed[*]}" >&2
  exit 1
fi
