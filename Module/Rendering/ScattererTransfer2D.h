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
 * The medium over (normalised scalar, gradient magnitude) of one scalar's 1D transfer
 * functions with a gradient opacity, as VTK 9.1's ray caster composites a step: the
 * scalar opacity corrected to the step, alpha = 1 - exp(-sigma_t step), times the
 * gradient opacity g at the magnitude, an extinction of
 *   sigma_t' = -ln(1 - min(g alpha, 1)) / step
 * (sigma_t where g = 1). @p row is the 1D medium (@p width entries of albedo rgb and
 * sigma_t per world unit); the magnitude axis gets @p rows rows of g over
 * [0, @p rangeWidth / 4], as VTK spans its gradient opacity table
 * (vtkOpenGLVolumeGradientOpacityTable; computeGradient normalises the magnitude by a
 * quarter of the scalar range), each at its texel's centre.
 */
void TabulateGradientOpacity(const float* row, int width, vtkPiecewiseFunction* gradientOpacity,
  double rangeWidth, double step, int rows, std::vector<float>& medium);

/**
 * What a scalar shows at its most visible gradient, over the scalar range [lo, hi]:
 * @p opacity per @p unit distance (the 1D convention materials are derived in) and
 * @p color there.
 */
void Transfer2DVisibility(vtkImageData* table, double lo, double hi, double sampleDistance,
  double unit, vtkPiecewiseFunction* opacity, vtkColorTransferFunction* color);
}

#endif
