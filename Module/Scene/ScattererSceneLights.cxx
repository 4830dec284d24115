#include "ScattererSceneLights.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkRenderer.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <initializer_list>

namespace scatterer_scene
{
namespace
{
bool AllFinite(std::initializer_list<double> values)
{
  for (const double v : values)
  {
    if (!std::isfinite(v))
    {
      return false;
    }
  }
  return true;
}

// Every setting of @p light that reaches the illumination besides its placement, and the
// property's coefficients @p kd and @p ka, are finite.
bool SettingsFinite(vtkLight* light, double kd, double ka)
{
  const double* d = light->GetDiffuseColor();
  const double* a = light->GetAmbientColor();
  const double* att = light->GetAttenuationValues();
  return AllFinite({ light->GetIntensity(), kd, ka, d[0], d[1], d[2], a[0], a[1], a[2], att[0],
    att[1], att[2], light->GetConeAngle(), light->GetExponent() });
}
}

LightSet CollectLights(vtkRenderer* renderer, vtkVolumeProperty* property)
{
  LightSet set;
  const double kd = property->GetDiffuse(0);
  const double ka = property->GetAmbient(0);
  vtkLightCollection* lights = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  vtkLight* light;
  for (lights->InitTraversal(it); (light = lights->GetNextLight(it));)
  {
    if (!light->GetSwitch() || light->GetIntensity() <= 0.0)
    {
      continue;
    }
    // The renderer has already placed camera lights for this frame
    // (vtkRenderer::UpdateLightsGeometryToFollowCamera), so the transformed position and
    // focal point are in world coordinates. A headlight sits at the camera (vtkLight)
    // whether or not the renderer moved it there: it does only while LightFollowCamera
    // is on, and VTK 9.1's ray caster lights a lone headlight from the camera either way.
    double position[3], focal[3];
    vtkCamera* camera = renderer->GetActiveCamera();
    if (light->LightTypeIsHeadlight() && camera)
    {
      camera->GetPosition(position);
      camera->GetFocalPoint(focal);
    }
    else
    {
      light->GetTransformedPosition(position);
      light->GetTransformedFocalPoint(focal);
    }
    if (!SettingsFinite(light, kd, ka) ||
      !AllFinite({ position[0], position[1], position[2], focal[0], focal[1], focal[2] }))
    {
      ++set.NonFinite;
      continue;
    }
    if (set.Count() >= kMaxLights)
    {
      ++set.Skipped;
      continue;
    }
    // A direction is needed by a directional light and by a spot (cone up to 90 degrees,
    // below); a positional light's attenuation must be positive at every distance.
    const double cone = light->GetConeAngle();
    const bool spot = light->GetPositional() && cone <= 90.0;
    const double* attenuation = light->GetAttenuationValues();
    double toLight[3] = { position[0] - focal[0], position[1] - focal[1], position[2] - focal[2] };
    const bool noDirection = vtkMath::Normalize(toLight) == 0.0;
    const bool badAttenuation = light->GetPositional() &&
      (attenuation[0] < 0.0 || attenuation[1] < 0.0 || attenuation[2] < 0.0 ||
        attenuation[0] + attenuation[1] + attenuation[2] <= 0.0);
    if ((noDirection && (!light->GetPositional() || spot)) || badAttenuation)
    {
      ++set.Undefined;
      continue;
    }
    if (noDirection)
    {
      toLight[2] = 1.0; // a point light: its direction is not read
    }
    const double intensity = light->GetIntensity();
    const double* diffuse = light->GetDiffuseColor();
    const double* ambient = light->GetAmbientColor();
    for (int c = 0; c < 3; ++c)
    {
      set.FocalDirection.push_back(static_cast<float>(-toLight[c]));
      set.Attenuation.push_back(static_cast<float>(attenuation[c]));
      set.Direction.push_back(static_cast<float>(toLight[c]));
      set.Position.push_back(static_cast<float>(position[c]));
      set.Color.push_back(static_cast<float>(kd * diffuse[c] * intensity));
      set.AmbientColor.push_back(static_cast<float>(ka * ambient[c] * intensity));
      set.Ambient[c] += set.AmbientColor.back();
    }
    set.Positional.push_back(light->GetPositional() ? 1 : 0);
    // VTK lights a positional light as a spot up to a cone of 90 degrees, its cone and
    // exponent applied (vtkVolumeShaderComposer: in_lightConeAngle <= 90), and above as a
    // point light.
    set.ConeCos.push_back(
      spot ? static_cast<float>(std::cos(vtkMath::RadiansFromDegrees(cone))) : -2.0f);
    set.Exponent.push_back(static_cast<float>(light->GetExponent()));
    set.AnyPositional = set.AnyPositional || light->GetPositional();
  }
  return set;
}

BrightestLight FindBrightestLight(const LightSet& lights)
{
  BrightestLight brightest;
  float best = -1.0f, total = 0.0f;
  for (int l = 0; l < lights.Count(); ++l)
  {
    const float sum = lights.Color[3 * l] + lights.Color[3 * l + 1] + lights.Color[3 * l + 2];
    total += sum;
    if (sum > best)
    {
      best = sum;
      brightest.Index = l;
    }
  }
  brightest.Share = total > 0.0f ? best / total : 0.0f;
  return brightest;
}
}
