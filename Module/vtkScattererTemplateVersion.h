/**
 * @class   vtkScattererTemplateVersion
 * @brief   The ScattererTemplate version this library was built as.
 *
 * One number, set once in CMake/ScattererTemplateVersion.cmake (the projects take it):
 * CMake's `ScattererTemplate_VERSION` (find_package), this class, Python's
 * `scatterertemplate.__version__` and every program's `--version` all report it.
 * Like vtkVersion, for applications that log or check what they run with.
 */
#ifndef vtkScattererTemplateVersion_h
#define vtkScattererTemplateVersion_h

#include "ScattererTemplateModule.h" // for export macro
#include "vtkObject.h"

class SCATTERERTEMPLATE_EXPORT vtkScattererTemplateVersion : public vtkObject
{
public:
  static vtkScattererTemplateVersion* New();
  vtkTypeMacro(vtkScattererTemplateVersion, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** "major.minor.patch", e.g. "0.1.0". */
  static const char* GetVersion();
  static int GetMajorVersion();
  static int GetMinorVersion();
  static int GetPatchVersion();

protected:
  vtkScattererTemplateVersion() = default;
  ~vtkScattererTemplateVersion() override = default;

private:
  vtkScattererTemplateVersion(const vtkScattererTemplateVersion&) = delete;
  void operator=(const vtkScattererTemplateVersion&) = delete;
};

#endif
