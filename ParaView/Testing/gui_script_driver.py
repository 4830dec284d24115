"""Test driver (snippet_test.py): runs Examples/paraview/show_volume_gui.py as the GUI's
--script would ($SCATTERER_SNIPPET), saves the view to $SCATTERER_PNG and exits (the GUI
would otherwise stay open). Works in pvbatch too."""
import os
import runpy

runpy.run_path(os.environ["SCATTERER_SNIPPET"], run_name="__main__")
from paraview.simple import GetActiveView, SaveScreenshot  # noqa: E402

SaveScreenshot(os.environ["SCATTERER_PNG"], GetActiveView(), ImageResolution=[300, 300])
# The GUI sends Python's output to its own window, not to stdout: a file says it ran.
with open(os.environ["SCATTERER_PNG"] + ".done", "w") as done:
    done.write("SCATTERER_GUI_SNIPPET_DONE\n")
os._exit(0)  # the GUI has no other way out of --script; pvbatch would exit anyway
