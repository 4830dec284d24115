// Warnings about a scene (an unsupported input, lights or materials beyond a limit), and
// errors that would repeat at every frame, said once per mapper: a scene renders many
// frames, and the same message every frame would bury everything else. Raised on the
// mapper (its WarningEvent and ErrorEvent observers, or the output window), as the
// mapper's own vtkWarningMacro and vtkErrorMacro would.
#ifndef ScattererWarnOnce_h
#define ScattererWarnOnce_h

#include "vtkObject.h"
#include "vtkSetGet.h"

#include <set>
#include <string>

namespace scatterer_render
{
/** Raises each distinct warning or error once on its owner. */
class WarnOnce
{
public:
  /** @p owner: the object the warnings are raised on (the mapper). */
  explicit WarnOnce(vtkObject* owner)
    : Owner(owner)
  {
  }

  /** Raises @p what on the owner, unless it was said before. */
  void operator()(const std::string& what)
  {
    if (this->Said.insert(what).second)
    {
      vtkWarningWithObjectMacro(this->Owner, << what);
    }
  }

  /**
   * Raises @p what on the owner once per @p topic: for a warning whose text carries
   * numbers that change from frame to frame (a count of voxels in each time step), which
   * would otherwise be said again at every change.
   */
  void operator()(const std::string& what, const std::string& topic)
  {
    if (this->Said.insert("topic:" + topic).second)
    {
      vtkWarningWithObjectMacro(this->Owner, << what);
    }
  }

  /** Raises @p what on the owner as an error (vtkErrorMacro's), unless it was said
   * before: a failure that repeats at every frame (a transport volume that cannot be
   * built) is said once too. */
  void Error(const std::string& what)
  {
    if (this->Said.insert("error:" + what).second)
    {
      vtkErrorWithObjectMacro(this->Owner, << what);
    }
  }

private:
  vtkObject* Owner;
  std::set<std::string> Said;
};
}

#endif
