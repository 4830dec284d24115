// Downstream program: creates the mapper and a material from the installed module.
#include "vtkNew.h"
#include "vtkScattererMaterial.h"
#include "vtkScattererTemplateVolumeMapper.h"

#include <iostream>

int main()
{
  vtkNew<vtkScattererTemplateVolumeMapper> mapper;
  mapper->SetOcclusionStrength(0.5);
  vtkNew<vtkScattererMaterial> material;
  material->SetRefractiveIndex(1.5);
  std::cout << mapper->GetClassName() << " OcclusionStrength=" << mapper->GetOcclusionStrength()
            << " " << material->GetClassName() << "\n";
  const bool ok = mapper->IsA("vtkOpenGLGPUVolumeRayCastMapper") &&
    mapper->GetOcclusionStrength() == 0.5 && material->GetRefractiveIndex() == 1.5;
  return ok ? 0 : 1;
}
