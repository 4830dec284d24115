#include "ScattererTransportProgress.h"

#include "vtk_glew.h"

#include <algorithm>

namespace scatterer_gpu
{
void TransportProgress::BeginBuild(int lights, int iterations, bool medium)
{
  this->Done = 0;
  this->BeforeSweeps = medium ? 1 : 0;
  // + the source, the gather (with the multiply scattered and ambient light added)
  this->Total = this->BeforeSweeps + lights * (kSweepSteps + 1) + 2 + iterations;
  this->Building = true;
}

void TransportProgress::StepDone()
{
  ++this->Done;
  if (this->Waits())
  {
    glFinish();
    this->Callback(std::min(1.0, this->Done / static_cast<double>(this->Total)));
  }
}

void TransportProgress::SweepDone(int light)
{
  // A sweep of fewer than kSweepSteps slices reports fewer: count it as kSweepSteps.
  this->Done = this->BeforeSweeps + light * (kSweepSteps + 1) + kSweepSteps - 1;
  this->StepDone();
}

void TransportProgress::BuildDone()
{
  this->Done = this->Total - 1;
  this->StepDone();
}
}
