/**
 * @class   vtkScattererLightExchange
 * @brief   Carries each light between the pieces of a distributed volume, so that a
 *          piece is shaded by the matter of every piece between it and the light.
 *
 * With MPI (ParaView's pvbatch or pvserver), each rank renders its piece of the
 * volume plus ghost layers. The ghost layers hold what is local to a sample (the
 * template in-scattering, interpolation); they cannot hold the shadow of matter
 * farther away. This class makes the light exact across pieces:
 *
 * 1. Each rank computes, per light, the optical depth of its own voxels along every
 *    line of the light (a light-space map; scatterer/LightSpace.h): orthographic for a
 *    directional light, octahedral around a positional one.
 * 2. The ranks exchange the maps through the controller ParaView already uses, each
 *    as the window of lines its piece crosses (an AllGather of the windows' corners,
 *    then an AllGatherV of their depths).
 * 3. Each rank adds the maps of the pieces in front of it along each line, less
 *    their part inside its ghost layers (it has those voxels, and its own sweep
 *    crosses them), and the mapper's transport sweep multiplies the transmittance
 *    through the piece and its ghosts by exp(-that depth).
 *
 * Exchange() is collective: every rank calls it once per frame before the volume
 * renders (vtkScattererVolumeRepresentation does, from its renderer's StartEvent,
 * which ParaView raises on every rank). It exchanges only when something it depends
 * on changed on some rank (a one-int AllGather says so), so a still scene costs one
 * small message per frame.
 *
 * Cost per light change: each rank receives (ranks - 1) x size^2 x 4 bytes per light
 * (size: the map's side in texels; docs/paraview.md) and marches size^2 lines
 * through its own piece and its ghost layers on the CPU.
 *
 * @sa vtkScattererTemplateVolumeMapper::SetLightExchange, scatterer/LightSpace.h
 */
#ifndef vtkScattererLightExchange_h
#define vtkScattererLightExchange_h

#include "ScattererTemplateModule.h" // for export macro
#include "vtkObject.h"
#include "vtkScattererTransportVolume.h" // for EnteringDepth

#include <memory> // for Internals
#include <vector> // for the maps

class vtkImageData;
class vtkMultiProcessController;
class vtkRenderer;
class vtkScattererTemplateVolumeMapper;
class vtkVolume;

class SCATTERERTEMPLATE_EXPORT vtkScattererLightExchange : public vtkObject
{
public:
  static vtkScattererLightExchange* New();
  vtkTypeMacro(vtkScattererLightExchange, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The ranks: ParaView's global controller. With fewer than 2 processes nothing is exchanged. */
  virtual void SetController(vtkMultiProcessController* controller);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

  ///@{
  /**
   * On (default): the light that enters a piece has crossed the pieces in front of
   * it. Off: each piece is lit as if only its own voxels and ghost layers stood in the
   * light's way (the control of the tests). Must be the same on every rank.
   */
  vtkSetMacro(Enabled, bool);
  vtkGetMacro(Enabled, bool);
  vtkBooleanMacro(Enabled, bool);
  ///@}

  ///@{
  /**
   * Frames rendered while the user drags (the same on every rank): the maps' lines lie
   * the mapper's InteractiveTransportScale voxels apart instead of one, as the
   * transport volume does then, which makes an exchange about that factor cubed
   * cheaper. Default off.
   */
  vtkSetMacro(Interactive, bool);
  vtkGetMacro(Interactive, bool);
  ///@}

  /**
   * Collective: call on every rank, once per frame, before the volume renders.
   * @p piece is the image @p mapper renders on this rank (its voxels and ghost
   * layers; null if the rank holds none), @p owned the structured extent of the
   * voxels it owns, @p whole the whole volume's extent.
   */
  void Exchange(vtkRenderer* renderer, vtkVolume* volume, vtkScattererTemplateVolumeMapper* mapper,
    vtkImageData* piece, const int owned[6], const int whole[6]);

  /** What the mapper reads: the lights it was made for, and per light its map. */
  struct Result
  {
    bool Active = false; ///< false: light enters every piece unattenuated
    std::vector<vtkScattererTransportVolume::Light> Lights; ///< geometry only, world
  };
  const Result& GetResult() const { return this->Current; }

  /** Milliseconds the last exchange took on this rank (maps, messages, sums); frames
   * that exchange nothing leave it as it is. */
  vtkGetMacro(LastExchangeMilliseconds, double);
  /** Bytes this rank received in the last exchange. */
  vtkGetMacro(LastExchangeBytes, double);
  /** Exchanges so far (frames that found something changed). */
  vtkGetMacro(ExchangeCount, int);

protected:
  vtkScattererLightExchange();
  ~vtkScattererLightExchange() override;

  vtkMultiProcessController* Controller = nullptr;
  bool Enabled = true;
  bool Interactive = false;
  double LastExchangeMilliseconds = 0.0;
  double LastExchangeBytes = 0.0;
  int ExchangeCount = 0;

private:
  vtkScattererLightExchange(const vtkScattererLightExchange&) = delete;
  void operator=(const vtkScattererLightExchange&) = delete;

  Result Current;
  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
