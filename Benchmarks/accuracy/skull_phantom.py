#!/usr/bin/python3
"""A smooth skull under scalp in the CT head scene's frame: bands against the reference.

    /usr/bin/python3 Benchmarks/accuracy/skull_phantom.py write DIR
    SCATTERER_DATA_DIR=DIR build/bin/scatterer-reference --scene ct-head --size 256x256 \\
      --spp 1024 --output DIR/reference-ct-head-256x256-1024spp
    SCATTERER_DATA_DIR=DIR bash scripts/xvfb.sh build/bin/scatterer-bench-accuracy \\
      --size 256x256 --spp 1024 --frames 1 --scenes ct-head --configs transport_default \\
      --out DIR
    /usr/bin/python3 Benchmarks/accuracy/skull_phantom.py measure DIR \\
      DIR/ct-head-transport_default.png

`write` puts DIR/ct-head.mhd (and .raw), which the CT head scene reads in place of the
real head when SCATTERER_DATA_DIR is DIR: the CT head's grid (256 x 256 x 108 voxels of
0.957 x 0.957 x 1.5 mm), its transfer functions, camera and light. The phantom is a dome:
bone 8 mm thick (1000 HU) under 7 mm of scalp (-200 HU) over a brain of 30 HU (opacity 0),
every interface a logistic edge 0.7 mm wide, so the reference shows a smooth dome and
every band or ring a picture shows over it is the renderer's (the CT head's crown shows
the same bands over a real skull, docs/accuracy.md, "Bands on the crown"). The reference
at 1024 spp takes about 90 s on 2 cores.

`measure` prints, for each picture and for the reference, over the dome (away from its
rim) after the benchmark's exposure fit: the RMSE against the reference, and the bands:
the standard deviation of the luminance and of the green / red ratio less their local
means (a 13 px box), in % of their means. The reference's figures are its noise (the
dome has no bands); the reference is DIR/reference-ct-head-256x256-1024spp.vti.
"""
import os
import sys

import numpy as np

SIZE = (256, 256, 108)
SPACING = (0.9570312, 0.9570312, 1.5)
CENTRE = (122.0, 125.0, 30.0)  # mm: the dome's top lies in view of the scene's camera
INNER, BONE, SCALP = 70.0, 78.0, 85.0  # radii, mm


def write(directory):
    k, j, i = np.meshgrid(*(np.arange(n) for n in SIZE[::-1]), indexing="ij")
    r = np.sqrt((i * SPACING[0] - CENTRE[0]) ** 2 + (j * SPACING[1] - CENTRE[1]) ** 2 +
                (k * SPACING[2] - CENTRE[2]) ** 2)

    def inside(radius):
        return 1.0 / (1.0 + np.exp(np.clip((r - radius) / 0.7, -50.0, 50.0)))

    bone = inside(BONE) * (1.0 - inside(INNER))
    hu = -1000.0 + 800.0 * inside(SCALP) + 1200.0 * bone + 230.0 * inside(INNER)
    os.makedirs(directory, exist_ok=True)
    hu.astype("<i2").tofile(os.path.join(directory, "ct-head.raw"))
    with open(os.path.join(directory, "ct-head.mhd"), "w") as header:
        header.write("ObjectType = Image\nNDims = 3\nDimSize = %d %d %d\n" % SIZE +
                     "ElementType = MET_SHORT\nElementByteOrderMSB = False\n" +
                     "ElementSpacing = %.7f %.7f %.1f\n" % SPACING +
                     "Offset = 0 0 0\nElementNumberOfChannels = 1\n" +
                     "ElementDataFile = ct-head.raw\n")
    print("wrote %s" % os.path.join(directory, "ct-head.mhd"))


def read_rgb(path):
    """RGB, rows top down: a float .vti (the reference's radiance) or a PNG (0-1)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.vtkIOXML import vtkXMLImageDataReader
    reader = vtkXMLImageDataReader() if path.endswith(".vti") else vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    dims = image.GetDimensions()
    rgb = vtk_to_numpy(image.GetPointData().GetArray(0)).reshape(dims[1], dims[0], -1)
    rgb = rgb[::-1, :, :3].astype(float)
    return rgb if path.endswith(".vti") else rgb / 255.0


def box_mean(values, mask, half):
    """The mean of values over mask in a (2 half + 1)^2 box around each pixel."""
    def box(a):
        c = np.pad(a, (half + 1, half)).cumsum(0).cumsum(1)
        w = 2 * half + 1
        return c[w:, w:] - c[:-w, w:] - c[w:, :-w] + c[:-w, :-w]
    return box(np.where(mask, values, 0.0)) / np.maximum(box(mask.astype(float)), 1e-9)


def bands(rgb, mask):
    luminance = rgb.mean(axis=2)
    hue = rgb[..., 1] / np.maximum(rgb[..., 0], 1e-9)
    out = []
    for a in (luminance, hue):
        detail = (a - box_mean(a, mask, 6))[mask]
        out.append(100.0 * detail.std() / abs(a[mask].mean()))
    return out


def measure(directory, pictures):
    reference = read_rgb(os.path.join(directory, "reference-ct-head-256x256-1024spp.vti"))
    luminance = reference.mean(axis=2)
    dome = luminance > 0.15 * luminance.max()
    for _ in range(6):  # away from the rim, where the dome meets the black background
        dome[1:-1, 1:-1] &= dome[:-2, 1:-1] & dome[2:, 1:-1] & dome[1:-1, :-2] & dome[1:-1, 2:]
    print("picture,rmse_dome,bands_luminance_pct,bands_green_over_red_pct")
    print("reference (its noise),0,%.2f,%.2f" % tuple(bands(reference, dome)))
    for path in pictures:
        rgb = read_rgb(path)
        rgb *= (rgb * reference).sum() / max((rgb * rgb).sum(), 1e-12)  # the exposure fit
        rmse = np.sqrt(((rgb - reference)[dome] ** 2).mean())
        print("%s,%.5f,%.2f,%.2f" % ((path, rmse) + tuple(bands(rgb, dome))))


def main(argv):
    if len(argv) >= 2 and argv[0] == "write":
        write(argv[1])
    elif len(argv) >= 3 and argv[0] == "measure":
        measure(argv[1], argv[2:])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv[1:])
