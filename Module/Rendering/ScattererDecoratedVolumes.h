// The volumes that carry a mapper's illumination replacements.
//
// The replacements live on the vtkVolume's shader property, not on the mapper
// (Shaders/ScattererShaderInstaller.h), so a volume handed to another mapper would keep
// them. Each decorated volume is watched: when it stops using this mapper it is
// cleaned at once, and every one still decorated is cleaned when the mapper goes.
#ifndef ScattererDecoratedVolumes_h
#define ScattererDecoratedVolumes_h

#include "vtkNew.h"
#include "vtkWeakPointer.h"

#include <vector>

class vtkAbstractVolumeMapper;
class vtkCallbackCommand;
class vtkVolume;

namespace scatterer_render
{
/** The volumes a mapper put its replacements on, cleaned when they leave it or it goes. */
class DecoratedVolumes
{
public:
  /** @p owner: the mapper whose volumes these are (compared with vtkVolume::GetMapper). */
  explicit DecoratedVolumes(vtkAbstractVolumeMapper* owner);
  /** Removes the replacements from every volume still decorated. */
  ~DecoratedVolumes();
  DecoratedVolumes(const DecoratedVolumes&) = delete;
  DecoratedVolumes& operator=(const DecoratedVolumes&) = delete;

  /** Starts watching @p volume (once), which now carries the replacements. */
  void Watch(vtkVolume* volume);

private:
  /** @p volume changed: cleans and forgets it if it no longer uses the owner. */
  void Check(vtkVolume* volume);

  struct Entry
  {
    vtkWeakPointer<vtkVolume> Volume;
    unsigned long Tag = 0;
  };
  vtkAbstractVolumeMapper* Owner;
  std::vector<Entry> Volumes;
  vtkNew<vtkCallbackCommand> Watcher;
};
}

#endif
