"""Runs Examples/python/render_ct_head.py on the prepared CT head at a small size and checks
the PNG it writes is not blank. Skipped (exit 77) when scripts/prepare-data.sh has not run."""
import os
import subprocess
import sys

from vtkmodules.vtkIOImage import vtkPNGReader

here = os.path.dirname(os.path.abspath(__file__))
example = os.path.join(here, "..", "..", "Examples", "python", "render_ct_head.py")
out_dir = sys.argv[1] if len(sys.argv) > 1 else "."
os.makedirs(out_dir, exist_ok=True)
if os.environ.get("SCATTERER_DATA_DIR"):
    data = os.environ["SCATTERER_DATA_DIR"]
elif os.environ.get("XDG_CACHE_HOME"):
    data = os.path.join(os.environ["XDG_CACHE_HOME"], "scatterer-template")
else:
    data = os.path.join(os.path.expanduser("~"), ".cache", "scatterer-template")
if not os.path.exists(os.path.join(data, "ct-head.mhd")):
    print("skipped: no CT head in %s (run bash scripts/prepare-data.sh)" % data)
    sys.exit(77)

png = os.path.join(out_dir, "TestScattererPythonExample.png")
if os.path.exists(png):
    os.remove(png)
run = subprocess.run([sys.executable, example, "--size", "160x160", "--output", png],
                     capture_output=True, text=True)
print(run.stdout, run.stderr)
if run.returncode != 0:
    sys.exit("the example failed (%d)" % run.returncode)
if "shadow" not in run.stdout:
    sys.exit("the example did not render with template illumination")
reader = vtkPNGReader()
reader.SetFileName(png)
reader.Update()
arr = reader.GetOutput().GetPointData().GetScalars()
if arr is None:
    sys.exit("no PNG written")
lit = sum(1 for k in range(arr.GetNumberOfValues()) if arr.GetValue(k) > 8)
print("non-black values: %d of %d" % (lit, arr.GetNumberOfValues()))
sys.exit(0 if lit > arr.GetNumberOfValues() // 20 else "the image is blank")
