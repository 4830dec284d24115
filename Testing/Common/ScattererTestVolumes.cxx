#include "ScattererTestVolumes.h"

#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkVolumeProperty.h"

#include <cmath>

namespace scatterer_testing
{
vtkSmartPointer<vtkImageData> MakeShellBallPlate(int dims, int scalarType, bool inverted)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(dims, dims, dims);
  image->SetSpacing(1.0, 1.0, 1.0);
  image->SetOrigin(0.0, 0.0, 0.0);
  image->AllocateScalars(scalarType, 1);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  const double c = 0.5 * (dims - 1);
  const double shellOuter = 0.40 * dims, shellInner = 0.34 * dims;
  const double ballRadius = 0.16 * dims;
  vtkIdType id = 0;
  for (int k = 0; k < dims; ++k)
  {
    for (int j = 0; j < dims; ++j)
    {
      for (int i = 0; i < dims; ++i, ++id)
      {
        const double x = i - c, y = j - c, z = k - c;
        const double r = std::sqrt(x * x + y * y + z * z);
        const double bx = x - 0.08 * dims, by = y + 0.05 * dims, bz = z;
        double value = 0.0;
        if (r <= shellOuter && r >= shellInner)
        {
          value = 100.0;
        }
        if (std::sqrt(bx * bx + by * by + bz * bz) <= ballRadius)
        {
          value = 200.0;
        }
        // A thin plate (2 voxels) outside the shell, facing the camera's +x side.
        if (i >= dims - 6 && i < dims - 4 && std::abs(y) < 0.3 * dims && std::abs(z) < 0.3 * dims)
        {
          value = 150.0;
        }
        scalars->SetTuple1(id, inverted ? 250.0 - value : value);
      }
    }
  }
  return image;
}

void ApplyShellBallPlateProperty(vtkVolumeProperty* property)
{
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(50.0, 0.0);
  opacity->AddPoint(100.0, 0.08);
  opacity->AddPoint(125.0, 0.5);
  opacity->AddPoint(150.0, 0.9);
  opacity->AddPoint(200.0, 0.95);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.0, 0.0, 0.0);
  color->AddRGBPoint(100.0, 0.9, 0.6, 0.5);
  color->AddRGBPoint(150.0, 0.5, 0.7, 0.9);
  color->AddRGBPoint(200.0, 1.0, 1.0, 0.9);
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetInterpolationTypeToLinear();
  property->SetAmbient(0.2);
  property->SetDiffuse(0.8);
  property->SetSpecular(0.3);
  property->SetSpecularPower(20.0);
}

vtkSmartPointer<vtkImageData> MakeComponentVolume(
  int dims, int components, const ComponentFill& fill)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(dims, dims, dims);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, components);
  auto* p = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int k = 0; k < dims; ++k)
    for (int j = 0; j < dims; ++j)
      for (int i = 0; i < dims; ++i)
        for (int c = 0; c < components; ++c)
          *p++ = fill(i, j, k, c);
  return image;
}

vtkSmartPointer<vtkImageData> MakeMaskBeyond(int dims, double cut, bool labels)
{
  return MakeComponentVolume(dims, 1,
    [cut, labels](int i, int, int, int) -> unsigned char
    { return labels ? (i > cut ? 2 : 1) : (i > cut ? 0 : 255); });
}

void HideLabelTwo(vtkGPUVolumeRayCastMapper* mapper, vtkVolumeProperty* property,
  vtkImageData* labels, vtkColorTransferFunction* color, vtkPiecewiseFunction* opacity)
{
  vtkNew<vtkPiecewiseFunction> transparent;
  transparent->AddPoint(0, 0.0);
  transparent->AddPoint(255, 0.0);
  mapper->SetMaskInput(labels);
  mapper->SetMaskTypeToLabelMap();
  property->SetLabelColor(1, color);
  property->SetLabelScalarOpacity(1, opacity);
  property->SetLabelColor(2, color);
  property->SetLabelScalarOpacity(2, transparent);
}
}
