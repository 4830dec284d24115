#include "ScattererMapperSetup.h"

#include "vtkNew.h"
#include "vtkOpenGLGPUVolumeRayCastMapper.h"
#include "vtkRenderer.h"
#include "vtkScattererTemplateVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <sstream>

namespace scatterer_examples
{
vtkSmartPointer<vtkGPUVolumeRayCastMapper> MakeMapper(const RenderOptions& o)
{
  if (o.Mode != "template")
  {
    return vtkSmartPointer<vtkOpenGLGPUVolumeRayCastMapper>::New();
  }
  auto mapper = vtkSmartPointer<vtkScattererTemplateVolumeMapper>::New();
  mapper->IlluminationEnabledOn();
  mapper->SetShadowsEnabled(o.Shadows);
  mapper->SetColorBleedingEnabled(o.Bleeding);
  mapper->SetThinPartCheckEnabled(o.Thin);
  mapper->SetBoundaryRefractionEnabled(o.Boundary);
  mapper->SetTemplateBlendingEnabled(o.Blend);
  mapper->SetShaderPathSelection(o.RequestedPaths ? vtkScattererTemplateVolumeMapper::AS_REQUESTED
                                                  : vtkScattererTemplateVolumeMapper::AUTOMATIC);
  mapper->SetIlluminationMode(o.Illumination == "per-sample"
      ? vtkScattererTemplateVolumeMapper::PER_SAMPLE
      : vtkScattererTemplateVolumeMapper::TRANSPORT);
  if (o.TransportScale > 0)
    mapper->SetTransportScale(o.TransportScale);
  if (o.MaxTransportVoxels >= 0)
    mapper->SetMaximumTransportVoxels(o.MaxTransportVoxels);
  if (o.Photons > 0)
    mapper->SetPhotonCap(o.Photons);
  if (o.Templates > 0)
    mapper->SetTemplatesPerMaterial(o.Templates);
  if (o.Interval > 0)
    mapper->SetIlluminationInterval(o.Interval);
  if (o.Radius > 0)
    mapper->SetTemplateRadius(o.Radius);
  if (o.Threshold >= 0)
    mapper->SetPhotonThreshold(o.Threshold);
  if (o.Strength >= 0)
    mapper->SetOcclusionStrength(o.Strength);
  if (o.LongRange >= 1)
    mapper->SetLongRangeMultiple(o.LongRange);
  if (o.MultipleScattering >= 0)
    mapper->SetMultipleScattering(o.MultipleScattering);
  return mapper;
}

std::string DescribeSettings(vtkGPUVolumeRayCastMapper* mapper)
{
  auto* m = vtkScattererTemplateVolumeMapper::SafeDownCast(mapper);
  if (!m)
  {
    return "";
  }
  std::ostringstream out;
  out << "illumination="
      << (m->GetIlluminationMode() == vtkScattererTemplateVolumeMapper::TRANSPORT ? "transport"
                                                                                  : "per-sample")
      << " transport_scale=" << m->GetTransportScale()
      << " max_transport_voxels=" << m->GetMaximumTransportVoxels()
      << " multiple_scattering=" << m->GetMultipleScattering() << " radius="
      << (m->GetTemplateRadius() > 0 ? std::to_string(m->GetTemplateRadius()) : "auto")
      << " templates=" << m->GetTemplatesPerMaterial() << " photons=" << m->GetPhotonCap()
      << " interval=" << m->GetIlluminationInterval() << " threshold=" << m->GetPhotonThreshold()
      << " strength=" << m->GetOcclusionStrength() << " long_range=" << m->GetLongRangeMultiple()
      << " blend=" << (m->GetTemplateBlendingEnabled() ? "on" : "off");
  return out.str();
}

vtkVolume* AddVolume(
  vtkRenderer* renderer, vtkAbstractVolumeMapper* mapper, vtkVolumeProperty* property)
{
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  renderer->AddVolume(volume);
  return volume;
}
}
