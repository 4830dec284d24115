#include "ScattererMirroredWinding.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiVolume.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtk_glew.h"

namespace scatterer_render
{
bool DirectionMirrors(vtkVolume* vol, vtkDataObject* input)
{
  auto* image = vtkImageData::SafeDownCast(input);
  return image && !vtkMultiVolume::SafeDownCast(vol) &&
    image->GetDirectionMatrix()->Determinant() < 0.0;
}

bool NearPlaneCutsVolume(vtkRenderer* ren, vtkVolume* vol, vtkDataObject* input)
{
  auto* image = vtkImageData::SafeDownCast(input);
  if (!image || !ren || !ren->GetActiveCamera())
  {
    return false;
  }
  double planes[24];
  ren->GetActiveCamera()->GetFrustumPlanes(ren->GetTiledAspectRatio(), planes);
  const double* nearPlane = planes + 16; // left, right, bottom, top, near, far
  const int* e = image->GetExtent();
  bool below = false, above = false, on = false;
  for (int corner = 0; corner < 8; ++corner)
  {
    const double index[3] = { static_cast<double>(e[corner & 1 ? 1 : 0]),
      static_cast<double>(e[corner & 2 ? 3 : 2]), static_cast<double>(e[corner & 4 ? 5 : 4]) };
    double dataset[4] = { 0.0, 0.0, 0.0, 1.0 };
    image->TransformContinuousIndexToPhysicalPoint(index, dataset);
    double world[4];
    vol->GetMatrix()->MultiplyPoint(dataset, world);
    const double side = nearPlane[0] * world[0] / world[3] + nearPlane[1] * world[1] / world[3] +
      nearPlane[2] * world[2] / world[3] + nearPlane[3];
    below = below || side < 0.0;
    above = above || side > 0.0;
    on = on || side == 0.0;
  }
  return on || (below && above);
}

float ImageSampleDistanceFor(bool mirrors, float requested)
{
  return mirrors ? 1.0f : requested;
}

ScopedMirroredWinding::ScopedMirroredWinding(bool mirrors)
  : Mirrors(mirrors)
{
  if (this->Mirrors)
  {
    glFrontFace(GL_CW);
  }
}

ScopedMirroredWinding::~ScopedMirroredWinding()
{
  if (this->Mirrors)
  {
    glFrontFace(GL_CCW); // OpenGL's default, which VTK never changes
  }
}
}
