// The medium and material tables of the light transport volume and their upload: what
// the passes look up per sample (the medium over the normalised scalar, each scalar's
// material, each material's scatterer kernel) and the per-material uniforms of the
// gather (colours, speed and opacity ratios).
#ifndef ScattererTransportTables_h
#define ScattererTransportTables_h

#include "ScattererSceneMaterials.h"     // for kMaxMaterials
#include "vtkScattererTransportVolume.h" // for Inputs
#include "vtkSmartPointer.h"

#include <scatterer/Transport.h> // for KernelPhoton

#include <vector>

class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace scatterer_gpu
{
struct TransportGrid;

/** The table textures, uploaded again whenever the medium changes (not on a light change). */
struct TransportTables
{
  /// RGBA32F, one row per medium (MediumRows): albedo rgb and sigma_t over the scalar.
  vtkSmartPointer<vtkTextureObject> Medium;
  /// R32F 1D: Medium's sigma_t of row 0 alone, which the sweeps read (st_attenuationAt).
  vtkSmartPointer<vtkTextureObject> Extinction;
  vtkSmartPointer<vtkTextureObject> Materials; ///< R32F: material index over the scalar, -1: none
  vtkSmartPointer<vtkTextureObject>
    Kernel; ///< RGBA32F, materials rows of (photons, centroid): offset, weight

  /** Uploads the tables of @p inputs in @p window's context. */
  void Upload(vtkOpenGLRenderWindow* window, const vtkScattererTransportVolume::Inputs& inputs);

  void ReleaseGraphicsResources(vtkWindow* window);
};

/** Material @p m's photons in @p inputs (Inputs::Kernels' row m, padding included). */
std::vector<scatterer::KernelPhoton> MaterialKernel(
  const vtkScattererTransportVolume::Inputs& inputs, int m);

/** st_atCentroid of the gather (scatterer_transport_gather.glsl): per material, whether
 * its kernel spreads little enough on @p grid to be read at its centroid alone
 * (scatterer::readsAtCentroid). */
void SetKernelReadUniforms(vtkShaderProgram* program, const TransportGrid& grid,
  const vtkScattererTransportVolume::Inputs& inputs);

/** The gather's per-material uniforms: colours, the speed and opacity ratio tables
 * (scatterer_scene::kMaxMaterials^2, row = the sample's material), the kernel width and the
 * switches. */
void SetMaterialUniforms(
  vtkShaderProgram* program, const vtkScattererTransportVolume::Inputs& inputs);
}

#endif
