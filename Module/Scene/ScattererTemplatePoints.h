// The photons of a scatterer::TemplateSet as VTK points: the output of
// vtkScattererTemplateSource (its header documents the arrays). Kept apart from the
// source, which decides when templates are generated, saved or loaded; this only lays
// out what it has.
//
// Private to the module: the public headers are installed without the core's include
// directory, so only sources include this.
#ifndef ScattererTemplatePoints_h
#define ScattererTemplatePoints_h

#include "vtkType.h" // for vtkIdType

#include <scatterer/TemplateIO.h> // for scatterer::TemplateSet

class vtkPolyData;

namespace scatterer_vtk
{
/** Photons over every template of every material of @p set. */
vtkIdType CountPhotons(const scatterer::TemplateSet& set);

/**
 * Sets @p output to one point with a vertex cell per photon, in material, template and
 * photon order, at the photon's position times @p radius; point data Intensity (the
 * active scalars), TemplateId and MaterialId, field data MaterialName.
 */
void TemplatePhotonsToPolyData(
  const scatterer::TemplateSet& set, double radius, vtkPolyData* output);
}

#endif
