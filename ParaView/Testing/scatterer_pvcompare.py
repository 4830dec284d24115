"""Image comparisons for the pvbatch tests (numpy + ParaView's VTK)."""
import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkTestingRendering import vtkTesting


def read_rgb(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    nx, ny, _ = image.GetDimensions()
    if nx * ny == 0:
        raise SystemExit("could not read %s" % path)
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(ny, nx, -1)
    return pixels[:, :, :3].astype(numpy.int32)


def difference(path_a, path_b):
    """Per-pixel difference statistics of two PNGs of the same size (0..255 levels)."""
    a, b = read_rgb(path_a), read_rgb(path_b)
    if a.shape != b.shape:
        raise SystemExit("%s and %s differ in size: %s vs %s" % (path_a, path_b, a.shape, b.shape))
    worst = numpy.abs(a - b).max(axis=2)
    return {"mean": float(numpy.abs(a - b).mean()), "max": int(worst.max()),
            "fraction_over_16": float((worst > 16).mean()),
            "fraction_over_32": float((worst > 32).mean())}


def worst_column(path_a, path_b, columns):
    """The largest mean difference (0..255 levels) down one image column among `columns`,
    over the rows where the image at path_b draws anything: a seam one pixel wide, which
    the per-pixel statistics above average away."""
    a, b = read_rgb(path_a), read_rgb(path_b)
    drawn = b.max(axis=2) > 0
    d = (a - b).mean(axis=2)
    worst = 0.0
    for c in columns:
        rows = drawn[:, c]
        if rows.any():
            worst = max(worst, abs(float(d[rows, c].mean())))
    return worst


def baseline_error(image_path, baseline_path, temp_dir):
    """VTK's regression-image comparison (what vtkRegressionTestImage does in the
    C++ tests): the error of the best match with the baseline. Difference images go
    to temp_dir."""
    testing = vtkTesting()
    for arg in ("-V", baseline_path, "-T", temp_dir):
        testing.AddArgument(arg)
    reader = vtkPNGReader()
    reader.SetFileName(image_path)
    reader.Update()
    testing.SetVerbose(0)
    # RegressionTest returns PASSED/FAILED for a threshold; ask with a huge one and
    # read back the error it measured, so the caller states its own tolerance.
    testing.RegressionTest(reader, 1.0e9)
    return testing.GetImageDifference()
