#include "ScattererTemplatePoints.h"

#include "vtkCellArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

namespace scatterer_vtk
{
vtkIdType CountPhotons(const scatterer::TemplateSet& set)
{
  vtkIdType n = 0;
  for (const auto& entry : set.materials)
  {
    for (const auto& t : entry.templates)
    {
      n += static_cast<vtkIdType>(t.photons.size());
    }
  }
  return n;
}

void TemplatePhotonsToPolyData(
  const scatterer::TemplateSet& set, double radius, vtkPolyData* output)
{
  const vtkIdType count = CountPhotons(set);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(count);
  vtkNew<vtkFloatArray> intensity;
  intensity->SetName("Intensity");
  intensity->SetNumberOfTuples(count);
  vtkNew<vtkIntArray> templateId;
  templateId->SetName("TemplateId");
  templateId->SetNumberOfTuples(count);
  vtkNew<vtkIntArray> materialId;
  materialId->SetName("MaterialId");
  materialId->SetNumberOfTuples(count);
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfTuples(count + 1);
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfTuples(count);
  vtkNew<vtkStringArray> names;
  names->SetName("MaterialName");
  names->SetNumberOfValues(static_cast<vtkIdType>(set.materials.size()));

  vtkIdType id = 0;
  for (std::size_t m = 0; m < set.materials.size(); ++m)
  {
    names->SetValue(static_cast<vtkIdType>(m), set.materials[m].material.name);
    const auto& templates = set.materials[m].templates;
    for (std::size_t t = 0; t < templates.size(); ++t)
    {
      for (const scatterer::Photon& photon : templates[t].photons)
      {
        const float p[3] = { static_cast<float>(photon.position.x * radius),
          static_cast<float>(photon.position.y * radius),
          static_cast<float>(photon.position.z * radius) };
        points->SetPoint(id, p);
        intensity->SetValue(id, photon.intensity);
        templateId->SetValue(id, static_cast<int>(t));
        materialId->SetValue(id, static_cast<int>(m));
        offsets->SetValue(id, id);
        connectivity->SetValue(id, id);
        ++id;
      }
    }
  }
  offsets->SetValue(count, count);

  vtkNew<vtkCellArray> verts;
  verts->SetData(offsets, connectivity);
  output->SetPoints(points);
  output->SetVerts(verts);
  output->GetPointData()->SetScalars(intensity);
  output->GetPointData()->AddArray(templateId);
  output->GetPointData()->AddArray(materialId);
  output->GetFieldData()->AddArray(names);
}
}
