#include "ScattererTransportTiles.h"

#include "ScattererTransportFramebuffer.h"

#include "vtkNew.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cstdint>

namespace scatterer_gpu
{
std::vector<TexelRect> CoverTexels(
  const int dims[3], int tile, const std::function<bool(int, int, int)>& has)
{
  std::vector<TexelRect> rects;
  tile = std::max(1, tile);
  const int columns = (dims[0] + tile - 1) / tile, rows = (dims[1] + tile - 1) / tile;
  std::vector<char> held(static_cast<size_t>(std::max(0, columns)));
  for (int z = 0; z < dims[2]; ++z)
  {
    const size_t layerStart = rects.size();
    for (int ty = 0; ty < rows; ++ty)
    {
      const int y0 = ty * tile, y1 = std::min(dims[1], y0 + tile);
      for (int tx = 0; tx < columns; ++tx)
      {
        const int x0 = tx * tile, x1 = std::min(dims[0], x0 + tile);
        bool any = false;
        for (int y = y0; y < y1 && !any; ++y)
        {
          for (int x = x0; x < x1 && !any; ++x)
          {
            any = has(x, y, z);
          }
        }
        held[static_cast<size_t>(tx)] = any ? 1 : 0;
      }
      const size_t rowStart = rects.size();
      for (int tx = 0; tx < columns;)
      {
        if (!held[static_cast<size_t>(tx)])
        {
          ++tx;
          continue;
        }
        int end = tx + 1;
        while (end < columns && held[static_cast<size_t>(end)])
        {
          ++end;
        }
        const int x0 = tx * tile, x1 = std::min(dims[0], end * tile);
        // A run with the columns of one that ends at this row of tiles extends it.
        bool extended = false;
        for (size_t r = layerStart; r < rowStart && !extended; ++r)
        {
          if (rects[r].X0 == x0 && rects[r].X1 == x1 && rects[r].Y1 == y0)
          {
            rects[r].Y1 = y1;
            extended = true;
          }
        }
        if (!extended)
        {
          rects.push_back({ x0, y0, x1, y1, z });
        }
        tx = end;
      }
    }
  }
  return rects;
}

void CoarseTiles::Update(vtkTextureObject* coarseMedium, bool onTiles)
{
  const int dims[3] = { static_cast<int>(coarseMedium->GetWidth()),
    static_cast<int>(coarseMedium->GetHeight()), static_cast<int>(coarseMedium->GetDepth()) };
  // Read back as the texture holds it (half floats, 8 bytes a texel): a nonzero sigma_t is
  // a nonzero half, however small, and the copy is half as large as in floats.
  std::vector<std::uint16_t> medium;
  if (onTiles)
  {
    medium.resize(4 * static_cast<size_t>(dims[0]) * dims[1] * dims[2]);
    coarseMedium->Activate();
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_HALF_FLOAT, medium.data());
    coarseMedium->Deactivate();
  }
  const std::vector<TexelRect> rects = CoverTexels(dims, kCoarseTile,
    [&](int x, int y, int z)
    {
      const size_t i = static_cast<size_t>(x) +
        static_cast<size_t>(dims[0]) * (static_cast<size_t>(y) + static_cast<size_t>(dims[1]) * z);
      return !onTiles || (medium[4 * i + 3] & 0x7fffu) != 0; // +-0: no medium
    });
  this->Count = static_cast<int>(rects.size());
  std::vector<float> corners;
  corners.reserve(18 * rects.size());
  for (const TexelRect& t : rects)
  {
    const float x0 = static_cast<float>(t.X0), y0 = static_cast<float>(t.Y0),
                x1 = static_cast<float>(t.X1), y1 = static_cast<float>(t.Y1),
                z = static_cast<float>(t.Z);
    for (const float corner : { x0, y0, z, x1, y0, z, x0, y1, z, x0, y1, z, x1, y0, z, x1, y1, z })
    {
      corners.push_back(corner);
    }
  }
  if (!this->Corners)
  {
    this->Corners = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    this->Corners->SetType(vtkOpenGLBufferObject::ArrayBuffer);
  }
  if (!corners.empty())
  {
    this->Corners->Upload(corners, vtkOpenGLBufferObject::ArrayBuffer);
  }
}

size_t CoarseTiles::GetGPUBytes() const
{
  return this->Corners ? 18 * sizeof(float) * static_cast<size_t>(this->Count) : 0;
}

void CoarseTiles::ReleaseGraphicsResources()
{
  if (this->Corners)
  {
    this->Corners->ReleaseGraphicsResources();
    this->Corners = nullptr;
  }
  this->Count = 0;
}

void DrawTiles(vtkOpenGLFramebufferObject* framebuffer, vtkShaderProgram* program,
  vtkTextureObject* target, const CoarseTiles& tiles)
{
  Attach2D(0, target);
  framebuffer->ActivateDrawBuffers(1);
  if (tiles.Count > 0)
  {
    const float size[2] = { static_cast<float>(target->GetWidth()),
      static_cast<float>(target->GetHeight()) };
    program->SetUniform2f("st_atlasSize", size);
    // The program's attributes, as the quad's arrays bind them, from the corners: a
    // corner's (x, y, z) as ndCoordIn, its (x, y) as texCoordIn.
    vtkNew<vtkOpenGLVertexArrayObject> corners;
    corners->Bind();
    constexpr size_t stride = 3 * sizeof(float);
    if (corners->AddAttributeArray(
          program, tiles.Corners, "ndCoordIn", 0, stride, VTK_FLOAT, 3, false) &&
      corners->AddAttributeArray(
        program, tiles.Corners, "texCoordIn", 0, stride, VTK_FLOAT, 2, false))
    {
      glDrawArrays(GL_TRIANGLES, 0, 6 * tiles.Count);
    }
    corners->Release();
    corners->ReleaseGraphicsResources();
  }
  DetachAll(framebuffer);
}
}
