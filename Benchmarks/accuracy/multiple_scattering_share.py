#!/usr/bin/python3
"""How much of the light is multiply scattered: the Monte Carlo reference against the
mapper, from a finished accuracy benchmark run (docs/accuracy.md, "Multiple scattering
against a single-scattering reference").

    build/bin/scatterer-reference --scene ct-head --size 256x256 --spp 2048 \\
      --max-order 1 --output OUT/single-ct-head
    /usr/bin/python3 Benchmarks/accuracy/multiple_scattering_share.py OUT ct-head \\
      OUT/single-ct-head.vti

OUT is the benchmark's output folder (run_accuracy_benchmark.sh). The reference's
multiple scattering is its full image less its single-scattering image (the same scene
rendered with --max-order 1). The mapper's is transport_default less
transport_single_scattering (MultipleScattering 0), both as displayed (knee, clamp),
taken back from the benchmark's PNGs (which it wrote times exposure_scale x the
reference's PNG exposure; the latter cancels in every ratio below) and put on the
reference's scale by the least-squares fit of the single-scattering images.

Prints, over all pixels and per quintile of the reference's single scattering
(darkest first): multiple / single scattering energy of the reference and of the mapper,
and the mapper's single scattering over the reference's.
"""
import csv
import sys

import imageio
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLImageDataReader


def read_radiance(path):
    reader = vtkXMLImageDataReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    if image.GetNumberOfPoints() == 0:
        sys.exit("cannot read a reference image from " + path)
    width, height, _ = image.GetDimensions()
    values = vtk_to_numpy(image.GetPointData().GetArray("Radiance"))
    # VTK images start at the bottom row, PNGs at the top.
    return values.reshape(height, width, -1)[::-1, :, :3].astype(float)


def read_displayed(folder, scene, config, scale):
    png = np.asarray(imageio.imread("%s/%s-%s.png" % (folder, scene, config)))
    return png[:, :, :3].astype(float) / 255.0 / scale


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    folder, scene, single_path = sys.argv[1:]
    rows = {r["config"]: r for r in csv.DictReader(open(folder + "/accuracy.csv")) if r["scene"] == scene}
    for config in ("transport_default", "transport_single_scattering"):
        if config not in rows:
            sys.exit("%s/accuracy.csv has no %s row for %s" % (folder, config, scene))
    spp = rows["transport_default"]["reference_spp"]
    width, height = imageio.imread("%s/%s-transport_default.png" % (folder, scene)).shape[1::-1]
    full = read_radiance("%s/reference-%s-%dx%d-%sspp.vti" % (folder, scene, width, height, spp))
    single = read_radiance(single_path)
    if single.shape != full.shape:
        sys.exit("the single-scattering reference is %s, the benchmark's %s" % (single.shape, full.shape))
    mapper = read_displayed(folder, scene, "transport_default", float(rows["transport_default"]["exposure_scale"]))
    mapper_single = read_displayed(
        folder, scene, "transport_single_scattering", float(rows["transport_single_scattering"]["exposure_scale"]))
    fit = (mapper_single * single).sum() / (mapper_single * mapper_single).sum()
    mapper *= fit
    mapper_single *= fit
    ms_reference = full - single
    ms_mapper = mapper - mapper_single

    def line(label, sel):
        print("%-22s %9.2f %9.2f %9.2f" % (label, ms_reference[sel].sum() / single[sel].sum(),
            ms_mapper[sel].sum() / mapper_single[sel].sum(), mapper_single[sel].sum() / single[sel].sum()))

    print("%s: multiple / single scattering energy; the mapper's single / the reference's" % scene)
    print("%-22s %9s %9s %9s" % ("pixels", "reference", "mapper", "single"))
    drawn = full.mean(axis=2) > 1e-3 * full.max()
    line("all drawn", drawn)
    luminance = single.mean(axis=2)
    edges = np.quantile(luminance[drawn], np.linspace(0.0, 1.0, 6))
    for q in range(5):
        line("single quintile %d" % (q + 1), drawn & (luminance >= edges[q]) & (luminance <= edges[q + 1]))
    print("RMSE of the multiple scattering alone: %.5f (the reference's mean %.5f)" % (
        np.sqrt(((ms_mapper - ms_reference) ** 2).mean()), ms_reference.mean()))


if __name__ == "__main__":
    main()
