// The binary mask as the light transport volume reads it: a 3D texture of the mask
// image's first component (R8, nearest), uploaded again only when the image changes.
// VTK 9.1 keeps the ray caster's own mask texture private, so the transport volume
// gets this copy (one byte per voxel of GPU memory).
#ifndef ScattererMaskTexture_h
#define ScattererMaskTexture_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <string>

class vtkImageData;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

namespace scatterer_gpu
{
class MaskTexture
{
public:
  /**
   * The texture of @p mask in @p window's context, uploaded if the mask changed since
   * the last call; nullptr with @p why set when the mask cannot be used (not on the
   * volume's grid @p volumeDims, not 8-bit, no scalars, or the upload failed).
   */
  vtkTextureObject* Update(
    vtkOpenGLRenderWindow* window, vtkImageData* mask, const int volumeDims[3], std::string& why);

  /** Changes whenever the texture's content does. */
  vtkMTimeType GetUploadTime() const { return this->UploadTime; }

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkSmartPointer<vtkTextureObject> Texture;
  vtkImageData* UploadedFrom = nullptr; // compared by address and MTime only
  vtkMTimeType UploadedMTime = 0;
  vtkMTimeType UploadTime = 0;
};
}

#endif
