/**
 * @class   vtkScattererTemplateVolumeMapper
 * @brief   GPU ray-cast volume mapper with scatterer-template global illumination.
 *
 * A drop-in replacement for vtkOpenGLGPUVolumeRayCastMapper: swap the class and
 * the picture stays the same until illumination is switched on. The mapper adds
 * its work by injecting GLSL replacement snippets into the stock ray caster in
 * GPURender(), so everything the stock mapper supports (blend modes, cropping,
 * clipping planes, opaque geometry, multiple volumes) keeps working.
 *
 * With IlluminationEnabled off the mapper renders pixel-identically to
 * vtkOpenGLGPUVolumeRayCastMapper (this is tested).
 *
 * @sa vtkOpenGLGPUVolumeRayCastMapper
 */
#ifndef vtkScattererTemplateVolumeMapper_h
#define vtkScattererTemplateVolumeMapper_h

#include "ScattererTemplateModule.h" // for export macro
#include "vtkOpenGLGPUVolumeRayCastMapper.h"

class SCATTERERTEMPLATE_EXPORT vtkScattererTemplateVolumeMapper
  : public vtkOpenGLGPUVolumeRayCastMapper
{
public:
  static vtkScattererTemplateVolumeMapper* New();
  vtkTypeMacro(vtkScattererTemplateVolumeMapper, vtkOpenGLGPUVolumeRayCastMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Master switch for scatterer-template illumination. Off: the mapper renders
   * exactly as vtkOpenGLGPUVolumeRayCastMapper. Default: on.
   */
  vtkSetMacro(IlluminationEnabled, bool);
  vtkGetMacro(IlluminationEnabled, bool);
  vtkBooleanMacro(IlluminationEnabled, bool);
  ///@}

protected:
  vtkScattererTemplateVolumeMapper();
  ~vtkScattererTemplateVolumeMapper() override;

  /**
   * The injection point: prepares the illumination shader code and resources
   * for this volume, then lets the stock ray caster render.
   */
  void GPURender(vtkRenderer* ren, vtkVolume* vol) override;

  bool IlluminationEnabled = true;

private:
  vtkScattererTemplateVolumeMapper(const vtkScattererTemplateVolumeMapper&) = delete;
  void operator=(const vtkScattererTemplateVolumeMapper&) = delete;
};

#endif
