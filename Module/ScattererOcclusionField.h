// Builds the occlusion field of a volume (scatterer/Illumination.h): per voxel
// the extinction the opacity transfer function gives it and its material.
// Rebuilt only when the input, the transfer function or the materials change.
#ifndef ScattererOcclusionField_h
#define ScattererOcclusionField_h

#include "ScattererSceneMaterials.h"

#include <scatterer/Illumination.h>

class vtkDataArray;
class vtkVolumeProperty;

namespace scatterer_scene
{
/**
 * @p scalars hold one component per voxel, @p dims voxels (texels) per axis,
 * @p range the finite scalar range VTK maps its tables over. Non-finite
 * values get no extinction and no material.
 */
scatterer::OcclusionField BuildOcclusionField(vtkDataArray* scalars, const int dims[3],
  const double range[2], vtkVolumeProperty* property, const MaterialSet& materials);

/** Visible voxels (opacity > 0) that belong to no material, and one such value. */
struct Unassigned
{
  long long Count = 0;
  double Example = 0.0;
};
Unassigned CountUnassigned(vtkDataArray* scalars, const scatterer::OcclusionField& field);
}

#endif
