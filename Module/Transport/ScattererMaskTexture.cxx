#include "ScattererMaskTexture.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkTextureObject.h"
#include "vtkTimeStamp.h"

namespace scatterer_gpu
{
vtkTextureObject* MaskTexture::Update(
  vtkOpenGLRenderWindow* window, vtkImageData* mask, const int volumeDims[3], std::string& why)
{
  vtkDataArray* scalars = mask ? mask->GetPointData()->GetScalars() : nullptr;
  if (!scalars)
  {
    why = "the mask has no scalars";
    return nullptr;
  }
  int dims[3];
  mask->GetDimensions(dims);
  if (dims[0] != volumeDims[0] || dims[1] != volumeDims[1] || dims[2] != volumeDims[2])
  {
    why = "the mask's grid (" + std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + "x" +
      std::to_string(dims[2]) + ") is not the volume's (" + std::to_string(volumeDims[0]) + "x" +
      std::to_string(volumeDims[1]) + "x" + std::to_string(volumeDims[2]) + ")";
    return nullptr;
  }
  if (scalars->GetDataType() != VTK_UNSIGNED_CHAR || scalars->GetNumberOfComponents() != 1)
  {
    why = "the mask is not one 8-bit component (as vtkGPUVolumeRayCastMapper expects)";
    return nullptr;
  }
  if (this->Texture && this->Texture->GetContext() == window && this->UploadedFrom == mask &&
    this->UploadedMTime == mask->GetMTime())
  {
    return this->Texture;
  }
  this->Texture = vtkSmartPointer<vtkTextureObject>::New();
  this->Texture->SetContext(window);
  this->Texture->SetWrapS(vtkTextureObject::ClampToEdge);
  this->Texture->SetWrapT(vtkTextureObject::ClampToEdge);
  this->Texture->SetWrapR(vtkTextureObject::ClampToEdge);
  // Nearest, as the ray caster samples its own mask: a voxel is in or out.
  this->Texture->SetMinificationFilter(vtkTextureObject::Nearest);
  this->Texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  if (!this->Texture->Create3DFromRaw(
        dims[0], dims[1], dims[2], 1, VTK_UNSIGNED_CHAR, scalars->GetVoidPointer(0)))
  {
    this->Texture = nullptr;
    why = "the mask texture could not be uploaded";
    return nullptr;
  }
  this->UploadedFrom = mask;
  this->UploadedMTime = mask->GetMTime();
  vtkTimeStamp now;
  now.Modified();
  this->UploadTime = now.GetMTime();
  return this->Texture;
}

void MaskTexture::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Texture)
  {
    this->Texture->ReleaseGraphicsResources(window);
    this->Texture = nullptr;
  }
  this->UploadedFrom = nullptr;
}
}
