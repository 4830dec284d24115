// The progress of a light transport build, reported as the fraction of its stages the
// GPU has done: the medium passes when the medium changed, per light its sweep
// (kSweepSteps reports) and the light it brings, then the source, each diffusion
// iteration and the gather, which writes the whole light.
#ifndef ScattererTransportProgress_h
#define ScattererTransportProgress_h

#include <functional>
#include <utility>

namespace scatterer_gpu
{
/** Progress reports per light sweep: a sweep is most of a build's GPU time. */
constexpr int kSweepSteps = 4;

class TransportProgress
{
public:
  /** The callback (vtkScattererTransportVolume::SetProgressCallback); unset, nothing waits. */
  void SetCallback(std::function<void(double)> callback) { this->Callback = std::move(callback); }

  /** A build of @p lights lights and @p iterations diffusion iterations starts, with
   * the medium passes first if @p medium. */
  void BeginBuild(int lights, int iterations, bool medium);
  /** True while a build reports (and so waits for the GPU at each stage). */
  bool Waits() const { return this->Callback && this->Building; }
  /** The build is over (done or failed): later stages (a test's sweep) report nothing. */
  void EndBuild() { this->Building = false; }

  /**
   * One more stage is queued: with a callback, during a build, wait for the GPU
   * (glFinish) and report the fraction done, so that it says what the GPU has done,
   * not what was queued.
   */
  void StepDone();
  /** The sweep of light @p light is done (whatever its slices reported). */
  void SweepDone(int light);
  /** The build's last stage is done: reports 1. */
  void BuildDone();

private:
  std::function<void(double)> Callback;
  bool Building = false; // in a build (not a test's sweep alone)
  int Done = 0, Total = 1;
  int BeforeSweeps = 0; // stages before the first sweep
};
}

#endif
