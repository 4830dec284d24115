"""ScattererTemplate: scatterer-template global illumination for VTK volume rendering.

    from scatterertemplate import vtkScattererTemplateVolumeMapper
    mapper = vtkScattererTemplateVolumeMapper()   # instead of vtkOpenGLGPUVolumeRayCastMapper

Classes: vtkScattererTemplateVolumeMapper, vtkScattererTemplateSource,
vtkScattererMaterial, vtkScattererVolumeReader, vtkScattererTemplateVersion
(``__version__``), and the mapper's parts vtkScattererTransportVolume (its light
transport volume, GetTransportVolume) and vtkScattererLightExchange (a distributed
volume's light exchange). Rendering needs VTK's OpenGL
factories, so import ``vtkmodules.vtkRenderingOpenGL2`` and
``vtkmodules.vtkRenderingVolumeOpenGL2`` (done here) before making a render window.
"""

# The OpenGL implementations of VTK's rendering classes (factory overrides).
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401

from .ScattererTemplate import (  # noqa: F401
    vtkScattererLightExchange,
    vtkScattererMaterial,
    vtkScattererTemplateSource,
    vtkScattererTemplateVersion,
    vtkScattererTemplateVolumeMapper,
    vtkScattererTransportVolume,
    vtkScattererVolumeReader,
)

# The library's own version (one number: CMake/ScattererTemplateVersion.cmake).
__version__ = vtkScattererTemplateVersion.GetVersion()

__all__ = [
    "vtkScattererLightExchange",
    "vtkScattererMaterial",
    "vtkScattererTemplateSource",
    "vtkScattererTemplateVersion",
    "vtkScattererTemplateVolumeMapper",
    "vtkScattererTransportVolume",
    "vtkScattererVolumeReader",
]
