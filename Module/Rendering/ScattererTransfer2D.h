// A 2D transfer function (vtkVolumeProperty::SetTransferFunction2D: RGBA over the
// scalar and the gradient magnitude) as the illumination reads it.
//
// VTK 9.1's ray caster looks the table up per ray step, with no opacity correction:
// its alpha is the opacity of one step of SampleDistance world units. The transport
// turns that into an extinction per world unit, sigma_t = -ln(1 - alpha) / SampleDistance,
// and the materials are derived from the most any gradient row shows of a scalar.
#ifndef ScattererTransfer2D_h
#define ScattererTransfer2D_h

#include <string>
#include <vector>

class vtkColorTransferFunction;
class vtkImageData;
class vtkPiecewiseFunction;

namespace scatterer_render
{
/** Why @p table cannot be read as a 2D transfer function, or "" if it can. */
std::string Transfer2DProblem(vtkImageData* table);

/**
 * The medium over (normalised scalar, gradient magnitude): @p rows rows of entries of
 * 4 floats (albedo rgb, sigma_t per world unit), the table's own texels (at most 4096 x
 * 1024; larger tables are sampled at the nearest texel).
 */
void TabulateTransfer2D(
  vtkImageData* table, double sampleDistance, std::vector<float>& medium, int& rows);

/**
 * What a scalar shows at its most visible gradient, over the scalar range [lo, hi]:
 * @p opacity per @p unit distance (the 1D convention materials are derived in) and
 * @p color there.
 */
void Transfer2DVisibility(vtkImageData* table, double lo, double hi, double sampleDistance,
  double unit, vtkPiecewiseFunction* opacity, vtkColorTransferFunction* color);
}

#endif
