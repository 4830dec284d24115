#include "ScattererTransportTextures.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <initializer_list>

namespace scatterer_gpu
{
namespace
{
bool HasSize(vtkTextureObject* texture, int width, int height, int depth)
{
  return texture && texture->GetWidth() == static_cast<unsigned int>(width) &&
    texture->GetHeight() == static_cast<unsigned int>(height) &&
    texture->GetDepth() == static_cast<unsigned int>(depth);
}

size_t Texels(vtkTextureObject* texture)
{
  return texture
    ? static_cast<size_t>(texture->GetWidth()) * texture->GetHeight() * texture->GetDepth()
    : 0;
}

// Allocates `texture` as a new 3D texture of `dims` (linear, clamped to edge) in
// `internalFormat`, e.g. GL_RGBA16F (format GL_RGBA, 4 components).
bool Allocate3D(vtkOpenGLRenderWindow* window, vtkSmartPointer<vtkTextureObject>& texture,
  const int dims[3], unsigned int internalFormat, unsigned int format, int components)
{
  texture = NewTransportTexture(window, true, vtkTextureObject::ClampToEdge);
  texture->SetInternalFormat(internalFormat);
  texture->SetFormat(format);
  if (!texture->Allocate3D(dims[0], dims[1], dims[2], components, VTK_FLOAT))
  {
    texture = nullptr; // allocated again next time
    return false;
  }
  return true;
}

// A new RGBA16F (4 components) or R16F (1) 3D texture.
bool Allocate16F(vtkOpenGLRenderWindow* window, vtkSmartPointer<vtkTextureObject>& texture,
  const int dims[3], int components = 4)
{
  return components == 1 ? Allocate3D(window, texture, dims, GL_R16F, GL_RED, 1)
                         : Allocate3D(window, texture, dims, GL_RGBA16F, GL_RGBA, 4);
}

// A new R16F 3D texture of `dims` (linear) whose border reads 0: outside the grid there
// is no matter.
bool AllocateExtinction(
  vtkOpenGLRenderWindow* window, vtkSmartPointer<vtkTextureObject>& texture, const int dims[3])
{
  float border[4] = { 0, 0, 0, 0 };
  texture = NewTransportTexture(window, true, vtkTextureObject::ClampToBorder);
  texture->SetBorderColor(border);
  texture->SetInternalFormat(GL_R16F);
  texture->SetFormat(GL_RED);
  if (!texture->Allocate3D(dims[0], dims[1], dims[2], 1, VTK_FLOAT))
  {
    texture = nullptr; // allocated again next time
    return false;
  }
  return true;
}

// A new texture (linear) of light whose border reads 1: outside the grid the light has
// crossed no matter.
vtkSmartPointer<vtkTextureObject> NewLightTexture(
  vtkOpenGLRenderWindow* window, unsigned int internalFormat, unsigned int format)
{
  float border[4] = { 1, 1, 1, 1 };
  auto texture = NewTransportTexture(window, true, vtkTextureObject::ClampToBorder);
  texture->SetBorderColor(border);
  texture->SetInternalFormat(internalFormat);
  texture->SetFormat(format);
  return texture;
}

// R16F: the light entering each texel (the transmittance).
vtkSmartPointer<vtkTextureObject> NewTransmittance(vtkOpenGLRenderWindow* window)
{
  return NewLightTexture(window, GL_R16F, GL_RED);
}

// RG16F: what a directional light's sweep keeps at its lines' points, T and the factor of
// the far half of the step that reaches the point (st_farFactor).
vtkSmartPointer<vtkTextureObject> NewCarriedLight(vtkOpenGLRenderWindow* window)
{
  return NewLightTexture(window, GL_RG16F, GL_RG);
}
}

vtkSmartPointer<vtkTextureObject> NewTransportTexture(
  vtkOpenGLRenderWindow* window, bool linear, int wrap)
{
  auto t = vtkSmartPointer<vtkTextureObject>::New();
  t->SetContext(window);
  t->SetMinificationFilter(linear ? vtkTextureObject::Linear : vtkTextureObject::Nearest);
  t->SetMagnificationFilter(linear ? vtkTextureObject::Linear : vtkTextureObject::Nearest);
  t->SetWrapS(wrap);
  t->SetWrapT(wrap);
  t->SetWrapR(wrap);
  return t;
}

std::vector<float> DownloadTexture3D(vtkTextureObject* texture, int components)
{
  std::vector<float> data(Texels(texture) * components);
  texture->Activate();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_3D, 0, components == 1 ? GL_RED : GL_RGBA, GL_FLOAT, data.data());
  texture->Deactivate();
  return data;
}

std::vector<float> DownloadAtlas(vtkTextureObject* atlas, const int dims[3], int columns)
{
  const size_t width = atlas->GetWidth(), height = atlas->GetHeight();
  std::vector<float> texels(4 * width * height);
  atlas->Activate();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, texels.data());
  atlas->Deactivate();
  std::vector<float> grid;
  grid.reserve(4 * static_cast<size_t>(dims[0]) * dims[1] * dims[2]);
  for (int z = 0; z < dims[2]; ++z)
  {
    const size_t x0 = static_cast<size_t>(z % columns) * dims[0];
    const size_t y0 = static_cast<size_t>(z / columns) * dims[1];
    for (int y = 0; y < dims[1]; ++y)
    {
      const float* row = texels.data() + 4 * ((y0 + y) * width + x0);
      grid.insert(grid.end(), row, row + 4 * static_cast<size_t>(dims[0]));
    }
  }
  return grid;
}

bool TransportTextures::AllocateFine(
  vtkOpenGLRenderWindow* window, const int dims[3], bool texelMeans, std::string& why)
{
  const int one[3] = { 1, 1, 1 };
  const int* meanDims = texelMeans ? dims : one;
  if (HasSize(this->Light, dims[0], dims[1], dims[2]) &&
    HasSize(this->FineScattering, dims[0], dims[1], dims[2]) &&
    HasSize(this->FineGather, dims[0], dims[1], dims[2]) &&
    HasSize(this->FineExtinction, meanDims[0], meanDims[1], meanDims[2]))
  {
    return true;
  }
  ++this->MediumAllocations;
  if (!Allocate16F(window, this->Light, dims) ||
    !Allocate3D(window, this->FineScattering, dims, GL_R11F_G11F_B10F, GL_RGB, 3) ||
    !Allocate3D(window, this->FineGather, dims, GL_R8, GL_RED, 1) ||
    !AllocateExtinction(window, this->FineExtinction, meanDims))
  {
    why = "the light textures could not be allocated";
    return false;
  }
  return true;
}

bool TransportTextures::AllocateArriving(
  vtkOpenGLRenderWindow* window, const int dims[3], std::string& why)
{
  // One texel more on each side (scatterer_transport_arrive.glsl).
  const int padded[3] = { dims[0] + 2, dims[1] + 2, dims[2] + 2 };
  if (HasSize(this->Arriving, padded[0], padded[1], padded[2]))
  {
    return true;
  }
  if (!Allocate16F(window, this->Arriving, padded))
  {
    why = "the arriving-light texture could not be allocated";
    return false;
  }
  return true;
}

void TransportTextures::ReleaseArriving(vtkWindow* window)
{
  if (this->Arriving)
  {
    this->Arriving->ReleaseGraphicsResources(window);
    this->Arriving = nullptr;
  }
}

bool TransportTextures::AllocateSweep(
  vtkOpenGLRenderWindow* window, const int sweepDims[3], bool slices, std::string& why)
{
  const int w = sweepDims[0], h = sweepDims[1], d = sweepDims[2];
  if (!HasSize(this->Transmittance, w, h, d))
  {
    this->Transmittance = NewTransmittance(window);
    if (!this->Transmittance->Allocate3D(w, h, d, 1, VTK_FLOAT))
    {
      this->Transmittance = nullptr; // allocated again next time
      why = "the transmittance texture could not be allocated";
      return false;
    }
  }
  if (slices && (!HasSize(this->Slices[0], w, h, 1) || !HasSize(this->Slices[1], w, h, 1)))
  {
    for (auto& slice : this->Slices)
    {
      slice = NewCarriedLight(window);
      if (!slice->Allocate2D(w, h, 2, VTK_FLOAT))
      {
        slice = nullptr;
        why = "the slice textures could not be allocated";
        return false;
      }
    }
  }
  return true;
}

bool TransportTextures::AllocateLines(
  vtkOpenGLRenderWindow* window, const int ringDims[3], const int lineDims[2], std::string& why)
{
  if (!HasSize(this->Lines, ringDims[0], ringDims[1], ringDims[2]))
  {
    this->Lines = NewCarriedLight(window);
    if (!this->Lines->Allocate3D(ringDims[0], ringDims[1], ringDims[2], 2, VTK_FLOAT))
    {
      this->Lines = nullptr;
      why = "the lines' texture could not be allocated";
      return false;
    }
  }
  for (auto& ends : this->LineEnds)
  {
    if (!HasSize(ends, lineDims[0], lineDims[1], 1))
    {
      ends = NewTransportTexture(window, false, vtkTextureObject::ClampToEdge);
      ends->SetInternalFormat(GL_RG32F);
      ends->SetFormat(GL_RG);
      if (!ends->Allocate2D(lineDims[0], lineDims[1], 2, VTK_FLOAT))
      {
        ends = nullptr;
        why = "the lines' texture could not be allocated";
        return false;
      }
    }
  }
  return true;
}

bool TransportTextures::AllocateCoarse(
  vtkOpenGLRenderWindow* window, const int dims[3], const int atlas[2], std::string& why)
{
  if (HasSize(this->Fluence[0], atlas[0], atlas[1], 1) &&
    HasSize(this->CoarseOcclusion, dims[0], dims[1], dims[2]))
  {
    return true;
  }
  ++this->MediumAllocations;
  bool allocated = Allocate16F(window, this->CoarseMedium, dims) &&
    Allocate16F(window, this->CoarseOcclusion, dims, 1);
  for (auto* grid : { &this->Fluence[0], &this->Fluence[1], &this->CoarseSource })
  {
    // The gather reads the fluence linearly, within a layer's tile (st_atlasLinear).
    *grid = NewTransportTexture(window, true, vtkTextureObject::ClampToEdge);
    (*grid)->SetInternalFormat(GL_RGBA16F);
    (*grid)->SetFormat(GL_RGBA);
    if (allocated && !(*grid)->Allocate2D(atlas[0], atlas[1], 4, VTK_FLOAT))
    {
      *grid = nullptr; // allocated again next time
      allocated = false;
    }
  }
  if (!allocated)
  {
    why = "the diffusion textures could not be allocated (atlas of " + std::to_string(atlas[0]) +
      " x " + std::to_string(atlas[1]) + " texels)";
    this->Fluence[0] = nullptr;
  }
  return allocated;
}

size_t TransportTextures::GetGPUBytes() const
{
  constexpr size_t rgba16f = 8, r11g11b10f = 4, r16f = 2, r8 = 1;
  return r11g11b10f * Texels(this->FineScattering) + r8 * Texels(this->FineGather) +
    rgba16f *
    (Texels(this->Light) + Texels(this->Arriving) + Texels(this->Fluence[0]) +
      Texels(this->Fluence[1]) + Texels(this->CoarseMedium) + Texels(this->CoarseSource)) +
    r16f *
    (Texels(this->Transmittance) + 2 * (Texels(this->Slices[0]) + Texels(this->Slices[1])) +
      2 * Texels(this->Lines) + 4 * (Texels(this->LineEnds[0]) + Texels(this->LineEnds[1])) +
      Texels(this->FineExtinction) + Texels(this->CoarseOcclusion)) +
    this->Tiles.GetGPUBytes();
}

void TransportTextures::ReleaseGraphicsResources(vtkWindow* window)
{
  for (auto* t : { &this->Light, &this->FineScattering, &this->FineGather, &this->FineExtinction,
         &this->Arriving, &this->Transmittance, &this->Slices[0], &this->Slices[1], &this->Lines,
         &this->LineEnds[0], &this->LineEnds[1], &this->Fluence[0], &this->Fluence[1],
         &this->CoarseMedium, &this->CoarseSource, &this->CoarseOcclusion })
  {
    if (*t)
    {
      (*t)->ReleaseGraphicsResources(window);
      *t = nullptr;
    }
  }
  this->Tiles.ReleaseGraphicsResources();
}
}
