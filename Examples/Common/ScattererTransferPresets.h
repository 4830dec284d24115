// Transfer functions a user can start from: named presets for CT (in Hounsfield
// units) and MRI, and an automatic one for unknown data chosen from the volume's
// histogram. The viewer switches between them by key or --preset, and shifts and
// scales them (window/level); scatterer-render's automatic scene uses the automatic one.
#ifndef ScattererTransferPresets_h
#define ScattererTransferPresets_h

#include <array>
#include <string>
#include <vector>

class vtkImageData;
class vtkVolumeProperty;

namespace scatterer_examples
{
/** Opacity (value, opacity per voxel) and colour (value, r, g, b) points of one transfer function.
 */
struct TransferPoints
{
  std::string Name;
  std::vector<std::array<double, 2>> Opacity;
  std::vector<std::array<double, 4>> Color;
};

/** Histogram of the finite values of a volume's first scalar component. */
class VolumeHistogram
{
public:
  /** Counts @p image's finite values into @p bins bins over their range. */
  VolumeHistogram(vtkImageData* image, int bins = 1024);

  double Minimum() const { return this->Low; }
  double Maximum() const { return this->High; }
  /** The value below which a share @p q (0..1) of the voxels at or above @p from lies. */
  double Quantile(double q, double from = -1e300) const;
  /**
   * Otsu's threshold (N. Otsu, IEEE Trans. SMC 9(1), 1979): the value that splits the
   * voxels in [@p from, @p to] into two classes with the largest between-class variance.
   */
  double OtsuThreshold(double from, double to) const;
  /** Share of the voxels below @p value. */
  double ShareBelow(double value) const;

private:
  double BinValue(int bin) const;
  int BinOf(double value) const;
  double Low = 0.0;
  double High = 1.0;
  std::vector<double> Counts;
  double Total = 0.0;
};

/** The preset names, in the order the viewer's p key cycles through them. */
const std::vector<std::string>& TransferPresetNames();

/** One line per preset for --help: "  name  what it shows", no final line end. */
std::string TransferPresetHelp();

/**
 * The preset @p name for @p image ("auto" is the histogram-chosen one); false with
 * @p why naming the known presets when @p name is not one.
 */
bool MakeTransferPreset(const std::string& name, const VolumeHistogram& histogram,
  TransferPoints& points, std::string& why);

/**
 * The preset the viewer opens unknown data with: "ct-head" (the benchmark scene's
 * skin and bone) when the histogram looks like CT in Hounsfield units (air at about
 * -1000 HU), else "auto".
 */
std::string DefaultTransferPreset(const VolumeHistogram& histogram);

/**
 * Writes @p points into @p property's scalar opacity and colour, every value x moved
 * to center + (x - center) * scale + shift, where center is the middle of the points'
 * opacity ramp: window/level on the whole transfer function, colours following opacity.
 */
void ApplyTransferPoints(
  const TransferPoints& points, double shift, double scale, vtkVolumeProperty* property);

/** The middle of the opacity ramp of @p points (where window/level scales about). */
double TransferCenter(const TransferPoints& points);
}

#endif
