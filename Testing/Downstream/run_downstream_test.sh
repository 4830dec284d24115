#!/usr/bin/env bash
# CTest ScattererDownstreamProject: installs the build tree into a fresh prefix, then
# configures, builds and runs Testing/Downstream against that prefix only.
# With PYTHON and PYTHON_DEST (the package's folder relative to the prefix) it also imports
# the installed Python package from the prefix and makes a mapper there.
#   run_downstream_test.sh BUILD_DIR WORK_DIR [CMAKE] [BUILD_TYPE] [PYTHON PYTHON_DEST]
set -euo pipefail
build="$1"
work="$2"
cmake="${3:-cmake}"
type="${4:-Release}"
python="${5:-}"
python_dest="${6:-}"
src="$(cd "$(dirname "$0")" && pwd)"
rm -rf "$work"
mkdir -p "$work"
prefix="$work/prefix"
"$cmake" --install "$build" --prefix "$prefix" > "$work/install.log" ||
  { cat "$work/install.log"; exit 1; }
for f in lib/cmake/ScattererTemplate/ScattererTemplateConfig.cmake \
         include/ScattererTemplate/vtkScattererTemplateVolumeMapper.h \
         include/scatterer/Material.h; do
  [ -e "$prefix/$f" ] || { echo "missing from the install tree: $f"; exit 1; }
done
ls "$prefix"/lib/libScattererTemplate*.so* > /dev/null
# Only the install tree: not the build tree's package registry, not the source tree.
"$cmake" -S "$src" -B "$work/build" -DCMAKE_BUILD_TYPE="$type" \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF > "$work/configure.log" 2>&1 ||
  { cat "$work/configure.log"; exit 1; }
grep "ScattererTemplate .* from $prefix" "$work/configure.log" ||
  { echo "ScattererTemplate was not found in $prefix"; cat "$work/configure.log"; exit 1; }
"$cmake" --build "$work/build" -j 2 > "$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
out="$("$work/build/downstream")"
echo "$out"
case "$out" in
  vtkScattererTemplateVolumeMapper*) ;;
  *) echo "unexpected output"; exit 1 ;;
esac
# The library the program loaded is the installed one.
if command -v ldd > /dev/null; then
  ldd "$work/build/downstream" | grep "libScattererTemplate" | grep -q "$prefix" ||
    { echo "downstream does not load the installed library:"; ldd "$work/build/downstream"; exit 1; }
fi
if [ -n "$python" ]; then
  # Only the install tree's package: run from an empty folder, no build tree on the path.
  (cd "$work" && PYTHONPATH="$prefix/$python_dest" "$python" -c '
import scatterertemplate, sys
m = scatterertemplate.vtkScattererTemplateVolumeMapper()
m.SetOcclusionStrength(0.5)
assert m.GetOcclusionStrength() == 0.5
assert scatterertemplate.__file__.startswith(sys.argv[1]), scatterertemplate.__file__
print("python:", m.GetClassName(), "from", scatterertemplate.__file__)
' "$prefix/") || { echo "the installed Python package does not import"; exit 1; }
fi
echo "downstream project OK"
