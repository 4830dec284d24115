// The renderer's lights as the illumination shader sees them: world-space
// directions toward each light (or positions), colours scaled by the volume
// property's diffuse coefficient and the light's intensity, and the summed
// ambient term. Covers VTK's headlight, camera lights and scene lights,
// directional and positional, up to VTK's limit of 6 lights in its volume shader.
#ifndef ScattererSceneLights_h
#define ScattererSceneLights_h

#include <vector>

class vtkRenderer;
class vtkVolumeProperty;

namespace scatterer_scene
{
struct LightSet
{
  std::vector<float> Direction;      ///< 3 per light: unit vector toward a directional light
  std::vector<float> Position;       ///< 3 per light: world position of a positional light
  std::vector<int> Positional;       ///< 1 per light
  std::vector<float> Color;          ///< 3 per light: kd * diffuse colour * intensity
  std::vector<float> FocalDirection; ///< 3 per light: unit vector from the light to its focal point
  std::vector<float> Attenuation;    ///< 3 per light: VTK's (constant, linear, quadratic)
  std::vector<float> ConeCos;        ///< 1 per light: cos(cone angle) of a spot, -2 for none
  std::vector<float> Exponent;       ///< 1 per light: spot exponent
  std::vector<float> AmbientColor;   ///< 3 per light: ka * ambient colour * intensity
  float Ambient[3] = { 0, 0, 0 };    ///< the sum of AmbientColor over the lights
  bool AnyPositional = false;
  int Skipped = 0;   ///< switched-on lights beyond the limit
  int NonFinite = 0; ///< switched-on lights left out for a NaN or infinite setting
  /// switched-on lights left out for a direction they do not define (a directional light
  /// or spot at its focal point) or an attenuation 1 / (a0 + a1 d + a2 d^2) that is not
  /// positive at every distance (a positional light)
  int Undefined = 0;
  int Count() const { return static_cast<int>(this->Positional.size()); }
};

constexpr int kMaxLights = 6;

/** The brightest light (the largest colour sum; the first of equals) and its share of all
 * the lights' colour, 0 < Share <= 1; index 0 and share 0 for no light. The light inside
 * a dense texel follows it alone (scatterer_illumination_dec.glsl, st_surfaceChange). */
struct BrightestLight
{
  int Index = 0;
  float Share = 0.0f;
};
BrightestLight FindBrightestLight(const LightSet& lights);

/**
 * Collects the switched-on lights of @p renderer (call during rendering). A light whose
 * intensity, colours, position, focal point, attenuation, cone angle or exponent (or the
 * property's diffuse or ambient coefficient) is NaN or infinite would light every sample
 * NaN, a black frame: it is left out and counted (NonFinite). So is one whose direction
 * or attenuation is undefined (Undefined), which VTK's own shading draws black.
 */
LightSet CollectLights(vtkRenderer* renderer, vtkVolumeProperty* property);
}

#endif
