// What the light transport volume takes from the physics: extinction in VTK's
// opacity convention and the scatterer templates as an in-scattering kernel.
// Plain C++17 + GLM (no VTK, no OpenGL); the GPU passes that use these live in
// Module/Transport/scatterer_transport_*.glsl.
#pragma once

#include <scatterer/Material.h>
#include <scatterer/Template.h>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace scatterer {

// Extinction coefficient per world unit of an opacity alpha given per
// `unitDistance` world units, VTK's convention (vtkVolumeProperty's
// ScalarOpacityUnitDistance): d world units of constant alpha let through
// (1 - alpha)^(d / u) = exp(-sigma_t d), so
//   sigma_t = -ln(1 - alpha) / u.
// alpha is clamped to [0, 1 - 1e-6] (alpha = 1 is "opaque": about 13.8 / u).
// Throws std::invalid_argument for a non-positive or non-finite unitDistance.
double extinctionFromOpacity(double alpha, double unitDistance);

// One photon of an in-scattering kernel: offset in world units, weight > 0.
struct KernelPhoton {
  glm::vec3 offset;
  float weight;
};

// World length of one template radius for `material` when its extinction in the
// scene is sigmaT per world unit. The generator measures paths in template radii,
// with the mean free path lambda_r = meanFreePath(material) radii (paper Eq. 2);
// in the scene the mean free path is 1 / sigmaT. Equating the two:
//   radius = (1 / sigmaT) / lambda_r.
// So photons sit where the paper's random walk puts them, in mean free paths of
// the real medium. Clamped to [minRadius, maxRadius]; sigmaT <= 0 gives maxRadius.
double kernelRadius(const Material& material, double sigmaT, double minRadius, double maxRadius);

// The in-scattering kernel of one material: every photon of every template
// (each template weighted 1 / templates.size(), so the kernel is their mean: the
// expected photon distribution), the `cap` most intense kept, offsets scaled by
// `radius` world units. Sorted by weight, descending; weights sum to 1 (empty if
// there is no photon). Throws std::invalid_argument for cap < 1 or a
// non-positive radius.
std::vector<KernelPhoton> mergedKernel(
  const std::vector<Template>& templates, int cap, double radius);

// The kernel's centroid c = sum_j w_j r_j / sum_j w_j (world units); zero for a kernel
// without weight.
glm::vec3 kernelCentroid(const std::vector<KernelPhoton>& kernel);

// How far the kernel's photons spread about its centroid c on the transport grid:
// the largest |worldToGrid (r_j - c)| along any grid axis, in grid texels (0 for a
// kernel without weight; infinite for a non-finite worldToGrid). worldToGrid maps a
// world vector to grid texels.
double kernelSpread(const std::vector<KernelPhoton>& kernel, const glm::mat3& worldToGrid);

// Reading a kernel at its centroid alone. The gather takes
//   R(p) = sum_j w_j A(p + r_j) / sum_j w_j
// of the stored light A, which is trilinear between texel centres: linear along each
// axis between them, with a slope of at most G there (G: the largest change of A
// between neighbouring texels). A linear field's weighted mean is its value at the
// centroid, A(p + c), exactly; A's slope changes only at texel centres (p itself is
// one), so with every photon within s texels of c along each axis
//   |R(p) - A(p + c)| <= 3 s G.
// The templates' brightest photons lie within a few hundredths of a template radius of
// their centre, and a template radius is one mean free path of the real medium or
// less (kernelRadius): on the CT head both materials' kernels spread under 1/20 of a
// transport texel (docs/model.md, step 2). Up to this spread a texel inside its
// material reads A once, at p + c, instead of once per photon (the gather's cost:
// docs/rendering.md); photons that may land in another material (colour bleeding, the
// boundary rescale) are always gathered one by one.
inline constexpr double kCentroidReadSpread = 1.0 / 16.0;
bool readsAtCentroid(const std::vector<KernelPhoton>& kernel, const glm::mat3& worldToGrid);

} // namespace scatterer
