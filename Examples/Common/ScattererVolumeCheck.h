// Checks, before anything is rendered, that a volume read from a file can give a
// meaningful picture, so that scatterer-render and scatterer-viewer refuse bad input
// with a message instead of drawing a black (or solid white) frame without a word.
// Every rule lives here; both programs call CheckVolume and nothing else.
#ifndef ScattererVolumeCheck_h
#define ScattererVolumeCheck_h

#include <string>

class vtkImageData;

namespace scatterer_examples
{
/**
 * The range of the finite values (NaN and +-Inf ignored) of the first component of
 * the point scalars. False, with @p range untouched, when there are no scalars or
 * no finite value. The automatic transfer function is laid over this range:
 * vtkDataSet::GetScalarRange would include an infinity and stretch the ramp over
 * nothing.
 */
bool FiniteScalarRange(vtkImageData* image, double range[2]);

/**
 * Empty when @p image can be rendered; otherwise one sentence that names @p path,
 * says what is wrong with the volume and why that cannot give a picture. Refused:
 * no scalars or no finite value; fewer than 2 points along an axis; a spacing that
 * is not a finite number > 0; an origin or bounds that are not finite; and, when
 * @p autoScene (the automatic transfer function, a ramp over the finite range), a
 * constant volume.
 *
 * The numeric limits on placement (how small a spacing, how far an origin single
 * precision can still resolve) belong to vtkScattererVolumeReader, which refuses a
 * file beyond them; they are not repeated here. Anything between those limits and
 * a picture is caught after rendering by the blank-frame check (ScattererFrameCheck.h).
 */
std::string CheckVolume(vtkImageData* image, const std::string& path, bool autoScene);
}

#endif
