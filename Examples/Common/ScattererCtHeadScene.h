// The benchmark scene "ct-head" (shared/scenes/ct-head.json): the real CT head
// from Debian's invesalius-examples, a fixed camera, one directional scene
// light, and skin + bone transfer functions. VTK's own modes were measured on
// exactly this scene, so every example and benchmark sets it up through here.
#ifndef ScattererCtHeadScene_h
#define ScattererCtHeadScene_h

#include "ScattererTransferPresets.h"
#include "vtkSmartPointer.h"

#include <string>

class vtkGPUVolumeRayCastMapper;
class vtkImageData;
class vtkRenderer;
class vtkRenderWindow;
class vtkVolumeProperty;

namespace scatterer_examples
{
/** The data cache: $SCATTERER_DATA_DIR, else $XDG_CACHE_HOME/scatterer-template, else ~/.cache/...
 */
std::string DataDirectory();

/** The prepared CT head (scripts/prepare-data.sh writes it). */
std::string CtHeadPath();

/**
 * Reads @p input, or the prepared CT head when @p input is empty. On failure
 * returns nullptr with @p error saying why (for the CT head, how to prepare it).
 */
vtkSmartPointer<vtkImageData> ReadVolumeOrCtHead(const std::string& input, std::string& error);

/** The scene's transfer functions: skin and bone, in Hounsfield units. */
TransferPoints CtHeadTransferPoints();

/** Transfer functions and material (ambient/diffuse/specular) of the scene; shading off. */
void ApplyCtHeadProperty(vtkVolumeProperty* property);

/** Camera of the scene. */
void ApplyCtHeadCamera(vtkRenderer* renderer);

/** One directional scene light, no automatic headlight, two-sided lighting. */
void ApplyCtHeadLight(vtkRenderer* renderer);

/** Sample distance 0.5 mm, no auto-adjust, no jittering, image sample distance 1. */
void ApplyCtHeadMapperSettings(vtkGPUVolumeRayCastMapper* mapper);

/** The still-render update rate of the scene (renderer AllocatedRenderTime 10000 s). */
void ApplyCtHeadWindowSettings(vtkRenderWindow* window);

/**
 * For volumes other than the CT head: the transfer function DefaultTransferPreset
 * picks from the histogram (the scene's for CT in HU, else "auto"), the camera reset
 * to fit, a headlight.
 */
void ApplyAutoScene(vtkImageData* image, vtkVolumeProperty* property, vtkRenderer* renderer);
}

#endif
