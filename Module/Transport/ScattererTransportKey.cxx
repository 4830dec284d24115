#include "ScattererTransportKey.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

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

// The volume's placement (texture -> world, row-major 4x4) split into what moves the
// medium relative to itself and its translation t, which only moves it in the world.
// An affine placement x = A u + t: a world plane n.x + d = 0 is, in texture
// coordinates, (A^T n).u + (n.t + d) = 0 (the row vector (n, d) times the matrix), and
// a world point p lies at p - t from the volume's translated origin. A projective
// placement (a user matrix with a perspective row) keeps its translation in the key.
struct PlacementWithoutTranslation
{
  double Matrix[16];
  double Translation[3] = { 0, 0, 0 };
  std::vector<double> ClipPlanes;

  explicit PlacementWithoutTranslation(const vtkScattererTransportVolume::Inputs& in)
  {
    std::copy(in.TexToWorld, in.TexToWorld + 16, this->Matrix);
    const bool affine = in.TexToWorld[12] == 0.0 && in.TexToWorld[13] == 0.0 &&
      in.TexToWorld[14] == 0.0 && in.TexToWorld[15] == 1.0;
    if (affine)
    {
      for (int r = 0; r < 3; ++r)
      {
        this->Translation[r] = in.TexToWorld[4 * r + 3];
        this->Matrix[4 * r + 3] = 0.0;
      }
    }
    for (size_t p = 0; p + 3 < in.ClipPlanes.size(); p += 4)
    {
      for (int c = 0; c < 4; ++c)
      {
        double sum = 0.0;
        for (int r = 0; r < 4; ++r)
        {
          sum += static_cast<double>(in.ClipPlanes[p + r]) * in.TexToWorld[4 * r + c];
        }
        this->ClipPlanes.push_back(sum);
      }
    }
  }

  std::array<double, 3> FromVolume(const float position[3]) const
  {
    return { position[0] - this->Translation[0], position[1] - this->Translation[1],
      position[2] - this->Translation[2] };
  }
};
}

namespace
{
// The medium's fingerprint with the placement already split (TransportKey needs it for
// its positional lights too: split once a frame, not twice).
std::uint64_t MediumKeyWith(
  const vtkScattererTransportVolume::Inputs& in, const PlacementWithoutTranslation& placement)
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
  // The placement without its translation: a volume moved (vtkVolume::SetPosition, a
  // widget dragging it) carries its medium along, grid and all. What a move does change
  // is keyed where it acts: the clipping planes, which stay in the world, as planes in
  // texture coordinates; positional lights by where they lie from the volume
  // (TransportKey).
  f.Add(placement.Matrix, 16);
  f.Add(in.TexToDataset, 16);
  f.Add(in.TexToIndex, 16);
  f.Add(placement.ClipPlanes);
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
}

std::uint64_t MediumKey(const vtkScattererTransportVolume::Inputs& in)
{
  return MediumKeyWith(in, PlacementWithoutTranslation(in));
}

std::uint64_t TransportKey(const vtkScattererTransportVolume::Inputs& in)
{
  const PlacementWithoutTranslation placement(in);
  Fingerprint f;
  f.Add(MediumKeyWith(in, placement));
  f.Add(in.MultipleScattering);
  f.Add(in.DiffusionIterations);
  f.Add(in.CoarseDimLights);
  for (const auto& l : in.Lights)
  {
    f.Add(l.Positional);
    f.Add(l.Color, 3);
    f.Add(l.Ambient, 3);
    f.Add(l.Entering.get());
    if (!l.Positional)
    {
      // A directional light is its direction alone: VTK's headlight and camera lights
      // also move their position with the camera, so zooming or panning under them
      // must not rebuild.
      f.Add(l.Toward, 3);
      continue;
    }
    const std::array<double, 3> fromVolume = placement.FromVolume(l.Position);
    f.Add(fromVolume.data(), 3);
    f.Add(l.FocalDirection, 3);
    f.Add(l.Attenuation, 3);
    f.Add(l.ConeCos);
    f.Add(l.Exponent);
  }
  return f.Value();
}
}
