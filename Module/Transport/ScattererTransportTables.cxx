#include "ScattererTransportTables.h"

#include "ScattererTransportGrid.h"
#include "ScattererTransportTextures.h"

#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <scatterer/Transport.h>

#include <glm/mat3x3.hpp>

#include <algorithm>
#include <initializer_list>
#include <vector>

namespace scatterer_gpu
{
void TransportTables::Upload(
  vtkOpenGLRenderWindow* window, const vtkScattererTransportVolume::Inputs& in)
{
  // Linear over the scalar, as the ray caster reads its transfer functions.
  this->Medium = NewTransportTexture(window, true, vtkTextureObject::ClampToEdge);
  const int rows = std::max(1, in.MediumRows);
  const size_t entries = in.Medium.size() / (4 * rows);
  this->Medium->Create2DFromRaw(static_cast<unsigned int>(entries), static_cast<unsigned int>(rows),
    4, VTK_FLOAT, const_cast<float*>(in.Medium.data()));
  // Row 0's sigma_t alone, as the sweeps read it (st_attenuationAt).
  std::vector<float> extinction(entries);
  for (size_t i = 0; i < entries; ++i)
  {
    extinction[i] = in.Medium[4 * i + 3];
  }
  this->Extinction = NewTransportTexture(window, true, vtkTextureObject::ClampToEdge);
  this->Extinction->Create1DFromRaw(
    static_cast<unsigned int>(entries), 1, VTK_FLOAT, extinction.data());

  // Nearest: a scalar belongs to one material or none.
  std::vector<float> table(in.MaterialTable);
  const int materialRows = std::max(1, in.MaterialRows);
  if (table.size() < static_cast<size_t>(materialRows))
  {
    table.assign(materialRows, -1.0f);
  }
  this->Materials = NewTransportTexture(window, false, vtkTextureObject::ClampToEdge);
  this->Materials->Create2DFromRaw(static_cast<unsigned int>(table.size() / materialRows),
    static_cast<unsigned int>(materialRows), 1, VTK_FLOAT, table.data());

  // Row m: material m's photons, then their centroid (weight 1), which the gather reads
  // alone where the kernel spreads little (SetKernelReadUniforms).
  const int materials = std::max<int>(1, static_cast<int>(in.MaterialColors.size() / 3));
  const int width = std::max(1, in.KernelWidth);
  std::vector<float> kernel(static_cast<size_t>(4 * (width + 1) * materials), 0.0f);
  for (int m = 0; m < materials; ++m)
  {
    const std::vector<scatterer::KernelPhoton> photons = MaterialKernel(in, m);
    float* row = kernel.data() + static_cast<size_t>(4 * (width + 1) * m);
    for (size_t k = 0; k < photons.size(); ++k)
    {
      std::copy_n(&photons[k].offset.x, 3, row + 4 * k);
      row[4 * k + 3] = photons[k].weight;
    }
    const glm::vec3 centroid = scatterer::kernelCentroid(photons);
    std::copy_n(&centroid.x, 3, row + 4 * width);
    row[4 * width + 3] = 1.0f;
  }
  this->Kernel = NewTransportTexture(window, false, vtkTextureObject::ClampToEdge);
  this->Kernel->Create2DFromRaw(width + 1, materials, 4, VTK_FLOAT, kernel.data());
}

std::vector<scatterer::KernelPhoton> MaterialKernel(
  const vtkScattererTransportVolume::Inputs& in, int m)
{
  std::vector<scatterer::KernelPhoton> photons;
  const size_t width = static_cast<size_t>(std::max(0, in.KernelWidth));
  for (size_t k = 0; k < width; ++k)
  {
    const size_t i = 4 * (width * static_cast<size_t>(m) + k);
    if (i + 3 < in.Kernels.size())
    {
      photons.push_back(
        { glm::vec3(in.Kernels[i], in.Kernels[i + 1], in.Kernels[i + 2]), in.Kernels[i + 3] });
    }
  }
  return photons;
}

void SetKernelReadUniforms(vtkShaderProgram* program, const TransportGrid& grid,
  const vtkScattererTransportVolume::Inputs& in)
{
  glm::mat3 worldToGrid;
  for (int i = 0; i < 9; ++i)
  {
    worldToGrid[i % 3][i / 3] = static_cast<float>(grid.WorldToGrid[i]); // row-major in
  }
  using scatterer_scene::kMaxMaterials;
  int atCentroid[kMaxMaterials] = {};
  const int materials = static_cast<int>(in.MaterialColors.size() / 3);
  for (int m = 0; m < materials && m < kMaxMaterials; ++m)
  {
    atCentroid[m] =
      in.GatherAtCentroid && scatterer::readsAtCentroid(MaterialKernel(in, m), worldToGrid) ? 1 : 0;
  }
  program->SetUniform1iv("st_atCentroid", kMaxMaterials, atCentroid);
}

void TransportTables::ReleaseGraphicsResources(vtkWindow* window)
{
  for (auto* t : { &this->Medium, &this->Materials, &this->Kernel })
  {
    if (*t)
    {
      (*t)->ReleaseGraphicsResources(window);
      *t = nullptr;
    }
  }
}

void SetMaterialUniforms(vtkShaderProgram* program, const vtkScattererTransportVolume::Inputs& in)
{
  const int materials = static_cast<int>(in.MaterialColors.size() / 3);
  program->SetUniformi("st_materialCount", materials);
  // The ratio tables of the inputs are materials x materials; the shader's have
  // kMaxMaterials columns.
  using scatterer_scene::kMaxMaterials;
  float colors[kMaxMaterials][3] = {};
  float speed[kMaxMaterials * kMaxMaterials] = {};
  float ratio[kMaxMaterials * kMaxMaterials] = {};
  for (int m = 0; m < materials && m < kMaxMaterials; ++m)
  {
    for (int c = 0; c < 3; ++c)
    {
      colors[m][c] = in.MaterialColors[3 * m + c];
    }
    for (int k = 0; k < materials && k < kMaxMaterials; ++k)
    {
      speed[kMaxMaterials * m + k] = in.SpeedRatios[materials * m + k];
      ratio[kMaxMaterials * m + k] = in.OpacityRatios[materials * m + k];
    }
  }
  program->SetUniform3fv("st_matColor", kMaxMaterials, colors);
  program->SetUniform1fv("st_speedRatio", kMaxMaterials * kMaxMaterials, speed);
  program->SetUniform1fv("st_opacityRatio", kMaxMaterials * kMaxMaterials, ratio);
  program->SetUniformi("st_kernelCount", in.KernelWidth);
  program->SetUniformi("st_bleed", in.Bleed ? 1 : 0);
  program->SetUniformi("st_boundary", in.Boundary ? 1 : 0);
}
}
