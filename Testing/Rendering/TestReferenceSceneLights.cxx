// The reference's scene conversion (Examples/reference, Convert) must light the Monte
// Carlo reference from where VTK's renderer puts each light. vtkLightKit's lights, the
// default lighting of a ParaView view, are camera lights: their position and focal point
// are given in the camera's frame (the camera at (0, 0, 1) looking at the origin, y up).
// Until 2026-12-06 the conversion took every light that is not a scene light for a
// headlight, so a light-kit reference was lit five times from the camera.
#include "ScattererReferenceScene.h"
#include "scatterer_reference/PathTracer.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkRenderer.h"
#include "vtkVolumeProperty.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <cmath>
#include <vector>

TEST(ReferenceSceneLights, LightKitLightsComeFromWhereTheCameraCarriesThem)
{
  scatterer_reference_vtk::VtkScene scene;
  scatterer_reference_vtk::MakeHardScene(scene, 8);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  const glm::dvec3 position(200.0, -50.0, 80.0), focal(10.0, 20.0, 30.0);
  camera->SetPosition(position.x, position.y, position.z);
  camera->SetFocalPoint(focal.x, focal.y, focal.z);
  camera->SetViewUp(0.0, 0.0, 1.0);
  scatterer_reference_vtk::ApplyLightKit(scene.Renderer);

  // The camera's frame in the world: x to its right, y its view up made orthogonal, z
  // back from the focal point toward the camera.
  const glm::dvec3 back = glm::normalize(position - focal);
  const glm::dvec3 right = glm::normalize(glm::cross(glm::dvec3(0.0, 0.0, 1.0), back));
  const glm::dvec3 up = glm::cross(back, right);
  std::vector<glm::dvec3> expected;
  vtkLightCollection* lights = scene.Renderer->GetLights();
  lights->InitTraversal();
  while (vtkLight* light = lights->GetNextItem())
  {
    ASSERT_FALSE(light->GetPositional());
    if (light->LightTypeIsHeadlight())
    {
      expected.push_back(back);
      continue;
    }
    ASSERT_TRUE(light->LightTypeIsCameraLight());
    double p[3], f[3];
    light->GetPosition(p);
    light->GetFocalPoint(f);
    const glm::dvec3 d(p[0] - f[0], p[1] - f[1], p[2] - f[2]);
    expected.push_back(glm::normalize(d.x * right + d.y * up + d.z * back));
  }
  ASSERT_EQ(expected.size(), 5u) << "vtkLightKit: key, fill, head and two back lights";

  const scatterer_reference::Scene converted =
    scatterer_reference_vtk::Convert(scene.Image, scene.Property, scene.Renderer, 16, 16);
  ASSERT_EQ(converted.directionalLights.size(), expected.size());
  ASSERT_TRUE(converted.pointLights.empty());
  int awayFromTheCamera = 0;
  for (size_t i = 0; i < expected.size(); ++i)
  {
    const glm::dvec3 got = converted.directionalLights[i].toLight;
    EXPECT_NEAR(glm::length(got - expected[i]), 0.0, 1e-9)
      << "light " << i << ": toward (" << got.x << ", " << got.y << ", " << got.z << "), expected ("
      << expected[i].x << ", " << expected[i].y << ", " << expected[i].z << ")";
    awayFromTheCamera += glm::dot(expected[i], back) < std::cos(glm::radians(30.0)) ? 1 : 0;
  }
  // The key, fill and back lights lie 40 degrees and more off the view direction.
  EXPECT_EQ(awayFromTheCamera, 4);
}
