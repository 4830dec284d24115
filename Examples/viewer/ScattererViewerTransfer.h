// The viewer's transfer function: which preset is shown, and the window/level
// applied to it (keys [ ] { } o, ctrl + left drag). Values move about the preset's
// ramp centre, so the ramp keeps its shape while the user shifts and scales it.
#ifndef ScattererViewerTransfer_h
#define ScattererViewerTransfer_h

#include "Common/ScattererTransferPresets.h"

#include <string>

class vtkImageData;
class vtkVolumeProperty;

namespace scatterer_viewer
{
class ViewerTransfer
{
public:
  ViewerTransfer(vtkImageData* image, vtkVolumeProperty* property);

  /** Shows preset @p name with the window/level reset; false with @p why if unknown. */
  bool Select(const std::string& name, std::string& why);
  /** The next preset in TransferPresetNames() order. */
  void Next();
  /** Moves the ramp by @p fraction of the data range (level). */
  void Shift(double fraction);
  /** Widens (> 1) or narrows (< 1) the ramp about its centre (window). */
  void Scale(double factor);
  /** Back to the preset as defined. */
  void Reset();

  const std::string& PresetName() const { return this->Points.Name; }
  /** "ct-bone  level +120  window x0.80" for the status line. */
  std::string Describe() const;

  /** The window's limits: 1/20 .. 20 times the preset's width. */
  static constexpr double MinimumScale = 0.05;
  static constexpr double MaximumScale = 20.0;

private:
  void Apply();
  scatterer_examples::VolumeHistogram Histogram;
  vtkVolumeProperty* Property;
  scatterer_examples::TransferPoints Points;
  double Offset = 0.0;
  double Width = 1.0;
};
}

#endif
