#!/usr/bin/env bash
# AddressSanitizer + UndefinedBehaviorSanitizer run of the unit tests that do not render
# (ScattererPhysicsTests and ScattererUnitTests, CTest label "unit"):
#   bash scripts/sanitize.sh
# Configures ${ASAN_BUILD_DIR:-build-asan} with -DSCATTERER_SANITIZE=ON, builds only those
# test programs (and what they link; no rendering tests, examples or benchmarks), and runs
# them under CTest with leak detection on and every sanitizer report fatal. Extra arguments
# go to ctest (e.g. -R Generator). Timing: about 1.5-2.5 min on 2 cores, nearly all build.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${ASAN_BUILD_DIR:-build-asan}"
start=$(date +%s)
bash scripts/install-deps.sh
cmake -S . -B "$build" -DSCATTERER_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DSCATTERER_BUILD_BENCHMARKS=OFF ${CMAKE_ARGS:-} > "$build.configure.log" 2>&1 ||
  { cat "$build.configure.log"; exit 1; }
# The test programs behind the "unit" label; ScattererReferenceTests (VTK-free) also carries
# it once Testing/Reference is part of the build, and a label test whose program was not
# built would fail, so it is built when the target exists.
targets=(ScattererPhysicsTests ScattererUnitTests)
known="$(cmake --build "$build" --target help 2>/dev/null || true)"
for optional in ScattererReferenceTests; do
  if grep -qw -- "$optional" <<< "$known"; then
    targets+=("$optional")
  fi
done
cmake --build "$build" --target "${targets[@]}" -j 2 \
  > "$build/build.log" 2>&1 || { tail -n 60 "$build/build.log"; exit 1; }
echo "sanitize: built ${targets[*]} in $(( $(date +%s) - start )) s"

# ASan: leaks on (LeakSanitizer), abort on the first report. UBSan: halt on the first
# report (the code is also built with -fno-sanitize-recover=undefined).
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$PWD/Testing/Sanitizers/lsan.supp:print_suppressions=1}"
ctest --test-dir "$build" -L '^unit$' --output-on-failure -j 2 "$@"
echo "sanitize: finished in $(( $(date +%s) - start )) s"
