// Conversions between vtkScattererMaterial / vtkScattererTemplateSource and the
// VTK-free physics core (scatterer::Material, scatterer::GeneratorSettings).
//
// Private to the module: the public headers are installed without the core's
// include directory, so only sources include this.
#ifndef ScattererMaterialConversion_h
#define ScattererMaterialConversion_h

#include <scatterer/GeneratorSettings.h>
#include <scatterer/Material.h>

class vtkScattererMaterial;

namespace scatterer_vtk
{
/**
 * The core's view of @p material: every field copied as is (the diffuse colour
 * rounded to float). Does not validate; scatterer::Material::validate() does.
 */
scatterer::Material ToPhysics(vtkScattererMaterial* material);

/**
 * Sets @p material to @p physics (a material the core validated, e.g. read from
 * a template file), so that ToPhysics(material) == physics field by field.
 */
void FromPhysics(const scatterer::Material& physics, vtkScattererMaterial* material);

/** Field-by-field equality (exact, bit for bit on finite values). */
bool SamePhysics(const scatterer::Material& a, const scatterer::Material& b);
bool SameSettings(const scatterer::GeneratorSettings& a, const scatterer::GeneratorSettings& b);
}

#endif
