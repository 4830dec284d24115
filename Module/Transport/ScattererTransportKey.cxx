#include "ScattererTransportKey.h"

#include <cstddef>

namespace scatterer_gpu
{
namespace
{
// FNV-1a over the inputs' bytes: cheap enough for every frame, unlike formatting
// them as text.
class Fingerprint
{
public:
  template <typename T>
  void Add(const T* values, size_t count)
  {
    const auto* bytes = reinterpret_cast<const unsigned char*>(values);
    for (size_t i = 0; i < count * sizeof(T); ++i)
    {
      this->Hash = (this->Hash ^ bytes[i]) * 1099511628211ull;
    }
  }
  template <typename T>
  void Add(const T& value)
  {
    this->Add(&value, 1);
  }
  template <typename T>
  void Add(const std::vector<T>& values)
  {
    this->Add(values.size());
    this->Add(values.data(), values.size());
  }
  std::uint64_t Value() const { return this->Hash; }

private:
  std::uint64_t Hash = 14695981039346656037ull;
};
}

std::uint64_t MediumKey(const vtkScattererTransportVolume::Inputs& in)
{
  Fingerprint f;
  f.Add(in.Volume);
  f.Add(in.VolumeUploadTime);
  f.Add(in.VolumeFilter);
  f.Add(in.Mask);
  f.Add(in.MaskUploadTime);
  f.Add(in.LabelMask);
  f.Add(in.MaskBlend);
  f.Add(in.MediumRows);
  f.Add(in.ScalarScale, 4);
  f.Add(in.ScalarBias, 4);
  f.Add(in.ComponentMode);
  f.Add(in.Components);
  f.Add(in.MaterialComponent);
  f.Add(in.ComponentWeights, 4);
  f.Add(in.VoxelStep, 3);
  f.Add(in.GradientAspect, 3);
  f.Add(in.OcclusionScale);
  f.Add(in.Downsample);
  f.Add(in.StillDownsample);
  f.Add(in.IndexOrigin, 3);
  f.Add(in.Cropping);
  f.Add(in.CropFlags);
  f.Add(in.CropMin, 3);
  f.Add(in.CropMax, 3);
  f.Add(in.Bleed);
  f.Add(in.Boundary);
  f.Add(in.GatherAtCentroid);
  f.Add(in.DiffuseOnTiles);
  f.Add(in.TablesVersion);
  f.Add(in.TexToWorld, 16);
  f.Add(in.TexToDataset, 16);
  f.Add(in.TexToIndex, 16);
  f.Add(in.ClipPlanes);
  f.Add(in.BoxTexels, 3);
  for (const auto& part : in.Parts)
  {
    f.Add(part.Volume);
    f.Add(part.UploadTime);
    f.Add(part.Filter);
    f.Add(part.ScalarScale);
    f.Add(part.ScalarBias);
    f.Add(part.BoxToTexture, 16);
  }
  return f.Value();
}

std::uint64_t TransportKey(const vtkScattererTransportVolume::Inputs& in)
{
  Fingerprint f;
  f.Add(MediumKey(in));
  f.Add(in.MultipleScattering);
  f.Add(in.DiffusionIterations);
  f.Add(in.CoarseDimLights);
  for (const auto& l : in.Lights)
  {
    f.Add(l.Toward, 3);
    f.Add(l.Position, 3);
    f.Add(l.Positional);
    f.Add(l.Color, 3);
    f.Add(l.Ambient, 3);
    f.Add(l.FocalDirection, 3);
    f.Add(l.Attenuation, 3);
    f.Add(l.ConeCos);
    f.Add(l.Exponent);
    f.Add(l.Entering.get());
  }
  return f.Value();
}
}
