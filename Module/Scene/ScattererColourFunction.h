// The colour transfer function a volume's samples are coloured with, as VTK 9.1's GPU
// ray caster decides it; the lighting takes the same, so the colour it carries is the one
// on screen.
//
// vtkOpenGLGPUVolumeRayCastMapper (vtkVolumeInputHelper::UpdateColorTransferFunction)
// reads vtkVolumeProperty::GetRGBTransferFunction(c) only. When no RGB function is set,
// that getter creates VTK's default ramp (black at 0, white at 1024) and switches the
// component to 3 colour channels, so a grey function set with
// SetColor(vtkPiecewiseFunction*) is never read. Asking for the grey function instead
// gave the lighting other colours than the picture and, on the first frame only (before
// the ray caster had switched the channels), other tables than on the next.
#ifndef ScattererColourFunction_h
#define ScattererColourFunction_h

#include "vtkColorTransferFunction.h"
#include "vtkVolumeProperty.h"

namespace scatterer_scene
{
/** The colour function VTK 9.1's ray caster reads for component @p c of @p property. */
inline vtkColorTransferFunction* RayCasterColour(vtkVolumeProperty* property, int c)
{
  return property->GetRGBTransferFunction(c);
}
}

#endif
