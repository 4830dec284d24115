#!/usr/bin/env bash
# AddressSanitizer + UndefinedBehaviorSanitizer run of the unit tests that do not render
# (ScattererPhysicsTests and ScattererUnitTests, CTest label "unit"):
#   bash scripts/sanitize.sh
# Configures ${ASAN_BUILD_DIR:-build-asan} with -DSCATTERER_SANITIZE=ON, builds those test
# programs (and what they link), and runs them under CTest with leak detection on and every
# sanitizer report fatal. Extra arguments go to ctest (e.g. -R Generator). Then a few
# rendering runs under Xvfb with the same build: the CT head in both illumination modes
# (scatterer-render), the bad-input tests and one hard case. Leak detection is off for those
# runs only: Mesa's GL driver leaks 112 bytes at exit in every run, stock mode included,
# with no usable stack. Timing: about 4-6 min on 2 cores, most of it the build.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${ASAN_BUILD_DIR:-build-asan}"
start=$(date +%s)
bash scripts/install-deps.sh
cmake -S . -B "$build" -DSCATTERER_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DSCATTERER_BUILD_BENCHMARKS=OFF ${CMAKE_ARGS:-} > "$build.configure.log" 2>&1 ||
  { cat "$build.configure.log"; exit 1; }
# The test programs behind the "unit" label, and the programs of the rendering runs below.
targets=(ScattererPhysicsTests ScattererReferenceTests ScattererUnitTests ScattererHardCaseTests
  scatterer-render)
cmake --build "$build" --target "${targets[@]}" -j 2 \
  > "$build/build.log" 2>&1 || { tail -n 60 "$build/build.log"; exit 1; }
echo "sanitize: built ${targets[*]} in $(( $(date +%s) - start )) s"

# ASan: leaks on (LeakSanitizer), abort on the first report. UBSan: halt on the first
# report (the code is also built with -fno-sanitize-recover=undefined).
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$PWD/Testing/Sanitizers/lsan.supp:print_suppressions=1}"
ctest --test-dir "$build" -L '^unit$' --output-on-failure -j 2 "$@"

# Rendering under the sanitizers (leak detection off: see above). The CT head is prepared
# by scripts/prepare-data.sh (scripts/test.sh runs it first).
echo "sanitize: rendering runs"
export ASAN_OPTIONS="${ASAN_RENDER_OPTIONS:-detect_leaks=0:abort_on_error=1}"
out="$(mktemp -d "${TMPDIR:-/tmp}/scatterer-sanitize.XXXXXX")"
trap 'rm -rf "$out"' EXIT
for illumination in transport per-sample; do
  bash scripts/xvfb.sh "$build/bin/scatterer-render" --illumination "$illumination" \
    --size 96x96 --output "$out/ct-head-$illumination.png"
done
bash scripts/xvfb.sh "$build/bin/ScattererHardCaseTests" \
  --gtest_filter='BadInput.*:HardCases.RefractiveIndexRatioOneThousandAndTotalInternalReflection'
echo "sanitize: finished in $(( $(date +%s) - start )) s"
