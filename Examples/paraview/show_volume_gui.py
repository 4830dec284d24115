# Shows an image volume as "Scatterer Volume" in the ParaView GUI, coloured by its
# point array whatever that is called, with a transfer function that shows something.
# The volume: the file named by $SCATTERER_VOLUME, else the active source (open one
# and press Apply first). Either from the command line (docs/paraview.md):
#   SCATTERER_VOLUME=head.vti bash scripts/paraview-env.sh paraview --script=Examples/paraview/show_volume_gui.py
# or in the GUI: View > Python Shell > Run Script, and pick this file.
import os

from paraview.simple import (ColorBy, GetActiveSource, GetActiveViewOrCreate,
                             GetColorTransferFunction, GetOpacityTransferFunction,
                             OpenDataFile, Render, SetActiveSource, Show)

if os.environ.get("SCATTERER_VOLUME"):
    source = OpenDataFile(os.environ["SCATTERER_VOLUME"])
    SetActiveSource(source)
else:
    source = GetActiveSource()
if source is None:
    raise RuntimeError("Open an image volume first, or set SCATTERER_VOLUME")
source.UpdatePipeline()

# The first single-component point array, whatever its name.
arrays = [name for name in source.PointData.keys()
          if source.PointData[name].GetNumberOfComponents() == 1
          and name not in ("vtkGhostType", "vtkValidPointMask")]
if not arrays:
    raise RuntimeError("The active source has no single-component point array")
array = arrays[0]
low, high = source.PointData[array].GetRange()

view = GetActiveViewOrCreate("RenderView")
display = Show(source, view)
if "Scatterer Volume" not in display.GetProperty("Representation").Available:
    raise RuntimeError("No 'Scatterer Volume' representation: load the plugin (Tools > "
                       "Manage Plugins, or start ParaView through scripts/paraview-env.sh)")
display.SetRepresentationType("Scatterer Volume")
ColorBy(display, ("POINTS", array))

# As in render_volume_pvbatch.py: the lowest fifth of the range transparent, opacity
# rising to 0.8 above it; dark red to white. Edit them in the Color Map Editor.
colors = GetColorTransferFunction(array)
colors.RGBPoints = [low, 0.5, 0.1, 0.05, 0.5 * (low + high), 0.9, 0.6, 0.4, high, 1.0, 1.0, 1.0]
opacity = GetOpacityTransferFunction(array)
opacity.Points = [low, 0.0, 0.5, 0.0, low + 0.2 * (high - low), 0.0, 0.5, 0.0,
                  high, 0.8, 0.5, 0.0]
view.ResetCamera(False)
Render(view)
