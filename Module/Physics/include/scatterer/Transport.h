// What the light transport volume takes from the physics: extinction in VTK's
// opacity convention and the scatterer templates as an in-scattering kernel.
// Plain C++17 + GLM (no VTK, no OpenGL); the GPU passes that use these live in
// Module/Transport/scatterer_transport_*.glsl.
#pragma once

#include <scatterer/Material.h>
#include <scatterer/Template.h>

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

} // namespace scatterer
