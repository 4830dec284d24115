// VTK side of the reference renderer: turns a vtkImageData + vtkVolumeProperty +
// vtkRenderer (camera, lights) into a scatterer_reference::Scene, and writes its
// results (float .vti, PNG). Also builds the two scenes of the accuracy benchmark:
// the CT head (shared/scenes/ct-head.json, via Examples/Common) and the synthetic hard
// scene (a thin shell and a thin plate in front of a light, two materials).
//
// Conversion (docs/accuracy.md):
// - scalars: component 0 of the point scalars, as float; origin and spacing as given
//   (no direction matrix, no volume transform: identity assumed);
// - table: `tableSize` entries over the scalar range; sigma_t = -ln(1 - alpha) / u with
//   alpha the scalar opacity TF and u its ScalarOpacityUnitDistance; albedo = the colour
//   TF's colour (times `albedoScale`);
// - lights that are switched on, where VTK's renderer puts them before a frame
//   (vtkRenderer::UpdateLightsGeometryToFollowCamera, which this calls): directional
//   (toLight = position - focal point in world space) with irradiance intensity x diffuse
//   colour;
//   positional lights become point lights (VTK's default attenuation (1,0,0) means no
//   distance falloff, which is kept; spot cones are ignored).
// - camera: position, focal point, view up, view angle (perspective only).
#ifndef ScattererReferenceScene_h
#define ScattererReferenceScene_h

#include "scatterer_reference/PathTracer.h"

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkImageData;
class vtkRenderer;
class vtkVolumeProperty;

namespace scatterer_reference_vtk
{
struct VtkScene
{
  std::string Name;
  vtkSmartPointer<vtkImageData> Image;
  vtkSmartPointer<vtkVolumeProperty> Property;
  vtkSmartPointer<vtkRenderer> Renderer; // camera + lights (no window needed)
  double SampleDistance = 0.5;           // the GPU mapper's sample distance for this scene
};

/** The CT head scene (the prepared volume, ct-head.json). False with @p error if missing. */
bool MakeCtHeadScene(VtkScene& scene, std::string* error);

/** The CT head scene lit as ParaView lights a view by default: vtkLightKit's five lights
 * (key, fill, two back lights and a head light, at vtkLightKit's defaults, which are
 * ParaView's), all following the camera, instead of the one scene light. Its name is
 * "ct-head-light-kit". False with @p error if the CT head is missing. */
bool MakeCtHeadLightKitScene(VtkScene& scene, std::string* error);

/** Replaces @p renderer's lights by vtkLightKit's five, at its defaults (ParaView's). */
void ApplyLightKit(vtkRenderer* renderer);

/** The synthetic hard scene: 96^3, a thin shell (material A, red) behind a thin plate
 * (material B, white) that shadows it from a directional light. Another @p n samples
 * the same world-space scene (box [0, 95]^3, same camera and light) on an n^3 grid
 * (spacing 95 / (n - 1)); its name is then "shell-plate-<n>". */
void MakeHardScene(VtkScene& scene, int n = 96);

/** The hard scene lit by a point light (no cone, no attenuation) instead, outside the
 * box behind the plate: its name is "shell-plate-point" ("shell-plate-point-<n>"). */
void MakeHardPointLightScene(VtkScene& scene, int n = 96);

/** Dense, nearly white matter (a segmentation's labels as users colour them): a ball and
 * a plate beside it, 64^3, opaque at the voxel scale, the plate's red channel of albedo
 * exactly 1, under one directional light. Its name is "dense-ball". */
void MakeDenseScene(VtkScene& scene);

/** The named scenes MakeNamedScene knows, in words: "ct-head, ct-head-light-kit,
 * shell-plate, shell-plate-point or dense-ball". */
extern const char* const kNamedScenes;

/** True when @p name is one of kNamedScenes. */
bool IsNamedScene(const std::string& name);

/** True when @p name is a named scene of the prepared CT head, which scatterer-reference
 * also lays over another volume (--input); the others are built in (synthetic volumes). */
bool IsCtHeadScene(const std::string& name);

/**
 * One of kNamedScenes: fills @p scene. On failure returns false with @p error saying why
 * (a missing CT head names scripts/prepare-data.sh) and @p exitCode 1 (missing data) or 2
 * (unknown name).
 */
bool MakeNamedScene(const std::string& name, VtkScene& scene, std::string& error, int& exitCode);

/** Applies the scene's camera and lights to another renderer (for the GPU mappers). */
void ApplySceneView(const VtkScene& scene, vtkRenderer* renderer);

scatterer_reference::Scene Convert(vtkImageData* image, vtkVolumeProperty* property,
  vtkRenderer* renderer, int width, int height, int tableSize = 2048, double albedoScale = 1.0);

/** Float RGB ("Radiance") + "StandardError" point data, width x height x 1. */
vtkSmartPointer<vtkImageData> ToImageData(const scatterer_reference::RenderResult& result);

/** clamp(exposure * rgb) to 8 bits, no gamma (as VTK's composite colours). */
bool WritePng(
  const std::vector<float>& rgb, int width, int height, double exposure, const std::string& path);

/**
 * RGB bytes of a one-channel map as a black -> red -> yellow -> white heat map, scaled
 * so @p maxValue is white (the error maps of scatterer-reference and the accuracy benchmark).
 */
std::vector<unsigned char> HeatMapBytes(const std::vector<float>& map, double maxValue);

/** A PNG of a one-channel map: HeatMapBytes. */
bool WriteMapPng(
  const std::vector<float>& map, int width, int height, double maxValue, const std::string& path);

/** Exposure that maps the 99.5th percentile of luminance to 1. */
double AutoExposure(const std::vector<float>& rgb);

/** The RGB of a vtkImageData with unsigned char or float scalars (3 or 4 comps), to [0,1] floats.
 */
std::vector<float> ToFloatRgb(vtkImageData* image);

/** Writes .vti (XML) or .mha (MetaImage) by extension. */
bool WriteFloatImage(vtkImageData* image, const std::string& path);
}

#endif
