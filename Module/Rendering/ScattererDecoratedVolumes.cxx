#include "ScattererDecoratedVolumes.h"

#include "ScattererShaderInstaller.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkVolume.h"

namespace scatterer_render
{
DecoratedVolumes::DecoratedVolumes(vtkAbstractVolumeMapper* owner)
  : Owner(owner)
{
  this->Watcher->SetClientData(this);
  this->Watcher->SetCallback([](vtkObject* caller, unsigned long, void* client, void*)
    { static_cast<DecoratedVolumes*>(client)->Check(static_cast<vtkVolume*>(caller)); });
}

DecoratedVolumes::~DecoratedVolumes()
{
  for (auto& d : this->Volumes)
  {
    if (d.Volume)
    {
      d.Volume->RemoveObserver(d.Tag);
      scatterer_shader::RemoveIllumination(d.Volume);
    }
  }
}

void DecoratedVolumes::Watch(vtkVolume* volume)
{
  for (const auto& d : this->Volumes)
  {
    if (d.Volume == volume)
    {
      return;
    }
  }
  this->Volumes.push_back(
    { volume, volume->AddObserver(vtkCommand::ModifiedEvent, this->Watcher) });
}

void DecoratedVolumes::Check(vtkVolume* volume)
{
  if (volume->GetMapper() == this->Owner)
  {
    return;
  }
  scatterer_shader::RemoveIllumination(volume);
  for (auto it = this->Volumes.begin(); it != this->Volumes.end(); ++it)
  {
    if (it->Volume == volume)
    {
      volume->RemoveObserver(it->Tag);
      this->Volumes.erase(it);
      break;
    }
  }
}
}
