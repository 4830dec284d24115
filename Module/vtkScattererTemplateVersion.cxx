#include "vtkScattererTemplateVersion.h"

#include "vtkObjectFactory.h"

// SCATTERER_TEMPLATE_VERSION{,_MAJOR,_MINOR,_PATCH} come from PROJECT_VERSION
// (Module/CMakeLists.txt), which is CMake/ScattererTemplateVersion.cmake: one place.
vtkStandardNewMacro(vtkScattererTemplateVersion);

const char* vtkScattererTemplateVersion::GetVersion()
{
  return SCATTERER_TEMPLATE_VERSION;
}

int vtkScattererTemplateVersion::GetMajorVersion()
{
  return SCATTERER_TEMPLATE_VERSION_MAJOR;
}

int vtkScattererTemplateVersion::GetMinorVersion()
{
  return SCATTERER_TEMPLATE_VERSION_MINOR;
}

int vtkScattererTemplateVersion::GetPatchVersion()
{
  return SCATTERER_TEMPLATE_VERSION_PATCH;
}

void vtkScattererTemplateVersion::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Version: " << GetVersion() << "\n";
}
