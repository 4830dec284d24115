#!/usr/bin/env bash
# Prepares the real CT head ("ProMED CT 0051", Debian package invesalius-examples)
# in the data cache the examples and benchmarks read by default:
#   ${SCATTERER_DATA_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/scatterer-template}/ct-head.mhd
# The raw int16 volume is extracted from the package's archive, checked against
# the checksum of the benchmark scene, and given a MetaImage header.
# Also the CT angiography "stent" (python3-imageio's stent.npz) as stent.mhd, for
# the automatic transfer function's tests; the MRI (mricron-data's ch2.nii.gz) is
# read where the package puts it.
set -euo pipefail

archive=/usr/share/doc/invesalius-examples/examples/Cranium.inv3
sha256=d87fd5e6aaf2c4fdf4f3fe28ee3335192fc2464ed8e9682fc78530cb837938da
cache="${SCATTERER_DATA_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/scatterer-template}"

prepare_stent() {
  local npz=/usr/lib/python3/dist-packages/imageio/resources/images/stent.npz
  [ -f "$cache/stent.mhd" ] && [ -f "$cache/stent.raw" ] && return 0
  if [ ! -f "$npz" ]; then
    echo "note: $npz is missing (apt-get install -y python3-imageio); the stent tests will be skipped" >&2
    return 0
  fi
  mkdir -p "$cache"
  # stent.npz holds one int16 array in (z, y, x) order, 256 x 128 x 128.
  /usr/bin/python3 - "$npz" "$cache" <<'PY'
import sys, numpy
npz, cache = sys.argv[1], sys.argv[2]
volume = numpy.load(npz)["arr_0"].astype("<i2", copy=False)
numpy.ascontiguousarray(volume).tofile(cache + "/stent.raw.tmp")
z, y, x = volume.shape
with open(cache + "/stent.mhd", "w") as header:
    header.write("ObjectType = Image\nNDims = 3\nDimSize = %d %d %d\nElementType = MET_SHORT\n"
                 "ElementByteOrderMSB = False\nElementSpacing = 1 1 1\nOffset = 0 0 0\n"
                 "ElementDataFile = stent.raw\n" % (x, y, z))
PY
  mv "$cache/stent.raw.tmp" "$cache/stent.raw"
  echo "CT angiography ready: $cache/stent.mhd"
}
prepare_stent

if [ -f "$cache/ct-head.mhd" ] && [ -f "$cache/ct-head.raw" ] &&
  echo "$sha256  $cache/ct-head.raw" | sha256sum --check --status; then
  echo "CT head ready: $cache/ct-head.mhd"
  exit 0
fi
if [ ! -f "$archive" ]; then
  echo "error: $archive is missing; install it with: apt-get install -y invesalius-examples" >&2
  exit 1
fi
mkdir -p "$cache"
member=$(tar -tzf "$archive" | grep '/matrix.dat$' | head -n 1)
tar -xzf "$archive" -O "$member" > "$cache/ct-head.raw.tmp"
if ! echo "$sha256  $cache/ct-head.raw.tmp" | sha256sum --check --status; then
  rm -f "$cache/ct-head.raw.tmp"
  echo "error: $archive/$member does not have the expected checksum $sha256" >&2
  exit 1
fi
mv "$cache/ct-head.raw.tmp" "$cache/ct-head.raw"
cat > "$cache/ct-head.mhd" <<MHD
ObjectType = Image
NDims = 3
DimSize = 256 256 108
ElementType = MET_SHORT
ElementByteOrderMSB = False
ElementSpacing = 0.9570312 0.9570312 1.5
Offset = 0 0 0
ElementNumberOfChannels = 1
ElementDataFile = ct-head.raw
MHD
echo "CT head ready: $cache/ct-head.mhd"
