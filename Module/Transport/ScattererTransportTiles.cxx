#include "ScattererTransportTiles.h"

#include "ScattererTransportFramebuffer.h"
#include "ScattererTransportPrograms.h"
#include "ScattererTransportTextures.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
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

void CoarseTiles::Update(vtkOpenGLRenderWindow* window, vtkOpenGLFramebufferObject* framebuffer,
  vtkTextureObject* coarseMedium, std::initializer_list<vtkTextureObject*> fluence, bool onTiles)
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
  const int rows = std::max(1, (this->Count + kRowRects - 1) / kRowRects);
  std::vector<float> texels(static_cast<size_t>(8 * kRowRects * rows), 0.0f);
  for (size_t r = 0; r < rects.size(); ++r)
  {
    const TexelRect& t = rects[r];
    const float values[8] = { static_cast<float>(t.X0), static_cast<float>(t.Y0),
      static_cast<float>(t.X1), static_cast<float>(t.Y1), static_cast<float>(t.Z), 0, 0, 0 };
    std::copy_n(values, 8, texels.data() + 8 * r);
  }
  this->Rects = NewTransportTexture(window, false, vtkTextureObject::ClampToEdge);
  this->Rects->Create2DFromRaw(2 * kRowRects, rows, 4, VTK_FLOAT, texels.data());

  // The texels the draws leave out read 0, what the Jacobi pass writes where there is no
  // medium.
  AttachLayeredTargets(framebuffer, fluence);
  vtkOpenGLState* state = window->GetState();
  state->vtkglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  DetachAll(framebuffer);
}

void CoarseTiles::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Rects)
  {
    this->Rects->ReleaseGraphicsResources(window);
    this->Rects = nullptr;
  }
  this->Count = 0;
}

void DrawTiles(vtkOpenGLFramebufferObject* framebuffer, vtkOpenGLQuadHelper* quad,
  vtkShaderProgram* program, std::initializer_list<vtkTextureObject*> targets,
  const CoarseTiles& tiles)
{
  AttachLayeredTargets(framebuffer, targets);
  if (tiles.Count > 0)
  {
    ScopedSampler rects(program, "st_tileRects", tiles.Rects);
    program->SetUniformi("st_firstLayer", 0);
    program->SetUniformi("st_rowRects", CoarseTiles::kRowRects);
    vtkTextureObject* first = *targets.begin();
    const float dims[2] = { static_cast<float>(first->GetWidth()),
      static_cast<float>(first->GetHeight()) };
    program->SetUniform2f("st_tileDims", dims);
    quad->VAO->Bind();
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, tiles.Count);
    quad->VAO->Release();
  }
  DetachAll(framebuffer);
}
}
