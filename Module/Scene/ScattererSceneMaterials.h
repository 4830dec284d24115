// Materials of a scene, as the template generator and the illumination shader
// need them: physical parameters for the generator (scatterer::Material) and
// the scalar range in the transfer-function table's coordinates for the shader.
//
// Without user materials they are derived from the scalar opacity transfer
// function: every interval of the data range where the opacity is above zero
// becomes one material (the CT head scene: skin and bone). So a scene with one
// visible interval gets one material and no boundary code.
#ifndef ScattererSceneMaterials_h
#define ScattererSceneMaterials_h

#include <scatterer/Material.h>

#include <string>
#include <vector>

class vtkDataArray;
class vtkPiecewiseFunction;
class vtkVolumeProperty;

namespace scatterer_scene
{
/** A material a user asked for (by scalar range or label id). */
struct RequestedMaterial
{
  bool IsLabel = false;
  double Lo = 0.0, Hi = 0.0; ///< scalar range (inclusive) when !IsLabel
  int Label = 0;             ///< label id when IsLabel
  double RefractiveIndex = 1.4;
  double Color[3] = { 1.0, 1.0, 1.0 };
};

struct SceneMaterial
{
  scatterer::Material Physics; ///< opacity (the TF's, the paper's 1 - T), n, colour, selector
  float Range[2] = { 0, 0 };   ///< normalized to the TF table (0 = data min, 1 = data max)
  double OpacityPerUnit = 0;   ///< the TF's largest opacity over the range (per unit distance)
};

struct MaterialSet
{
  std::vector<SceneMaterial> Materials;
  int Dropped = 0; ///< derived intervals beyond the material limit (left unlit)
};

/** Materials a volume is split into at most: the one home of the limit, which the shaders
 * get as ST_MAX_MATERIALS (ScattererShaderComposer, ScattererTransportPrograms). */
constexpr int kMaxMaterials = 8;

/**
 * Materials for one volume. @p dataRange is the finite range of the rendered
 * scalars (what VTK maps its transfer-function tables over); @p property
 * supplies the opacity transfer function and (for derived materials) colours.
 * Without requested materials, they are derived from the opacity transfer
 * function over @p derivationRange (the data range, or the whole volume's range
 * for a piece of a split volume, so that every piece derives the same ones).
 */
MaterialSet BuildMaterials(const std::vector<RequestedMaterial>& requested,
  vtkVolumeProperty* property, const double dataRange[2], const double derivationRange[2]);

/**
 * The material of each entry of a table over the scalar range [range[0], range[1]]
 * (entry i covers the normalised scalar [i, i + 1) / size and holds the material of
 * its centre value; -1 for none; labels match within 0.5 of their id). The
 * transport volume looks materials up here, in the volume texture's own
 * normalisation, so a degenerate range (one value) still finds its material.
 */
std::vector<float> MaterialTable(const MaterialSet& set, const double range[2], int size);

/** Visible voxels (opacity above zero) that belong to no material, and one such value. */
struct Unassigned
{
  long long Count = 0;
  double Example = 0.0;
};

/**
 * Scans @p scalars (component @p component) for visible values that none of @p set's
 * materials selects; visibility from @p property's opacity transfer function,
 * tabulated over @p dataRange. Read-only: no copy of the volume is made.
 */
Unassigned CountUnassigned(vtkDataArray* scalars, const MaterialSet& set,
  vtkVolumeProperty* property, const double dataRange[2], int component);

/** The largest value of @p opacity over [lo, hi] (its ends and the nodes between). */
double MaxOpacity(vtkPiecewiseFunction* opacity, double lo, double hi);

/** Speed ratios n_m / n_k (row m = sample material) for the shader, row-major. */
std::vector<float> SpeedRatios(const MaterialSet& set);

/** Intensity factors min(1, opacity_m / opacity_k) for the shader, row-major. */
std::vector<float> OpacityRatios(const MaterialSet& set);
}

#endif
