# Renders an image volume (.vti, .mhd, NIfTI, ...) with the "Scatterer Volume"
# representation and saves a PNG. Run with the plugin and ParaView's Python on the
# paths (scripts/paraview-env.sh sets them; docs/paraview.md):
#   bash scripts/paraview-env.sh pvbatch Examples/paraview/render_volume_pvbatch.py head.vti head.png
import sys

from paraview.simple import (ColorBy, GetColorTransferFunction, GetOpacityTransferFunction,
                             GetActiveViewOrCreate, OpenDataFile, Render, SaveScreenshot, Show)

volume_file, png_file = sys.argv[1], sys.argv[2]
reader = OpenDataFile(volume_file)
if reader is None:
    sys.exit("ParaView has no reader for %s" % volume_file)
reader.UpdatePipeline()

# Colour by the volume's first single-component point array, whatever its name
# ("ImageFile", "scalars", "MetaImage", ...): a name that is not there renders nothing.
arrays = [name for name in reader.PointData.keys()
          if reader.PointData[name].GetNumberOfComponents() == 1
          and name not in ("vtkGhostType", "vtkValidPointMask")]
if not arrays:
    sys.exit("%s has no single-component point array to render" % volume_file)
array = arrays[0]
low, high = reader.PointData[array].GetRange()

view = GetActiveViewOrCreate("RenderView")
display = Show(reader, view)
if "Scatterer Volume" not in display.GetProperty("Representation").Available:
    sys.exit("No 'Scatterer Volume' representation: load the plugin "
             "(PV_PLUGIN_PATH, or run through scripts/paraview-env.sh)")
display.SetRepresentationType("Scatterer Volume")
ColorBy(display, ("POINTS", array))
display.SetScalarBarVisibility(view, False)

# A transfer function that shows something on any data: the lowest fifth of the range
# (air, background) transparent, then opacity rising to 0.8; colours from dark red
# to white over the data range.
colors = GetColorTransferFunction(array)
colors.RGBPoints = [low, 0.5, 0.1, 0.05, 0.5 * (low + high), 0.9, 0.6, 0.4, high, 1.0, 1.0, 1.0]
opacity = GetOpacityTransferFunction(array)
opacity.Points = [low, 0.0, 0.5, 0.0, low + 0.2 * (high - low), 0.0, 0.5, 0.0,
                  high, 0.8, 0.5, 0.0]

display.ScattererShadows = 1          # illumination properties: docs/paraview.md
display.ScattererTemplateRadius = 0   # 0: 10 x the mean voxel spacing
view.ResetCamera(False)
Render(view)
SaveScreenshot(png_file, view, ImageResolution=[512, 512])
print("rendered %s (point array %r, range %g..%g) to %s" % (volume_file, array, low, high,
                                                            png_file))
