#include "vtkScattererTemplateVolumeMapper.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkScattererTemplateVolumeMapper);

vtkScattererTemplateVolumeMapper::vtkScattererTemplateVolumeMapper() = default;
vtkScattererTemplateVolumeMapper::~vtkScattererTemplateVolumeMapper() = default;

void vtkScattererTemplateVolumeMapper::GPURender(vtkRenderer* ren, vtkVolume* vol)
{
  this->Superclass::GPURender(ren, vol);
}

void vtkScattererTemplateVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IlluminationEnabled: " << (this->IlluminationEnabled ? "On" : "Off") << "\n";
}
