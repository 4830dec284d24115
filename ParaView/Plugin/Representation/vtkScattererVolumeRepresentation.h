/**
 * @class   vtkScattererVolumeRepresentation
 * @brief   ParaView's image volume representation, rendered with scatterer-template
 *          global illumination.
 *
 * What ParaView's "Volume" representation of image data does (transfer functions,
 * blend modes, cropping, LOD outline, ordered compositing over MPI), with
 * vtkScattererTemplateVolumeMapper in place of the stock mapper and its illumination
 * settings forwarded as server-manager properties ("Scatterer Volume" in the
 * representation list; see ScattererVolumeRepresentation.xml and docs/paraview.md).
 *
 * Distributed rendering (pvbatch/pvserver with several ranks): occlusion near a
 * piece border must see the voxels of the neighbouring piece. When the data is split
 * into pieces, the representation asks upstream for ghost layers at least as wide as
 * the mapper's illumination reach (vtkScattererTemplateVolumeMapper::
 * GetIlluminationReach), lets the mapper light the piece with its ghosts, and renders
 * only the piece's own extent (cropping planes on its owned bounds), so the pieces
 * stay non-overlapping for ParaView's ordered compositing. Readers that cannot deliver
 * sub-extents (e.g. MetaImage) put the whole volume on one rank: that renders
 * correctly, just not in parallel.
 *
 * Shadows across pieces: ghost layers hold only what is local to a sample. Before
 * each frame renders (its renderer's StartEvent, raised on every rank), the ranks
 * exchange the optical depth of their pieces along each light
 * (vtkScattererLightExchange, through ParaView's global controller), and each piece's
 * transport sweep starts with the light that the pieces in front of it let through.
 *
 * Progress: the mapper's ProgressEvent while it rebuilds its illumination (templates,
 * then the GPU stages of the light transport volume) is re-sent as this
 * representation's own, which ParaView's progress handler observes: the progress bar
 * moves during a long first frame instead of jumping from 0 to 1.
 *
 * Interaction: as ParaView's "Volume" (vtkSmartVolumeMapper with
 * InteractiveAdjustSampleDistances), frames the view renders interactively (desired
 * update rate >= 1) use the mapper's AutoAdjustSampleDistances (coarser ray and image
 * sampling to fit the time budget); still frames keep the fixed sample distance.
 */
#ifndef vtkScattererVolumeRepresentation_h
#define vtkScattererVolumeRepresentation_h

#include "ScattererParaViewRepresentationModule.h" // for export macro
#include "vtkImageVolumeRepresentation.h"
#include "vtkNew.h"          // for LightExchange
#include "vtkSmartPointer.h" // for VectorInput

#include <memory> // for VectorInputKey

class vtkImageData;
namespace scatterer_render
{
class ChangeKey;
}
class vtkScattererLightExchange;
class vtkScattererTemplateVolumeMapper;

class SCATTERERPARAVIEWREPRESENTATION_EXPORT vtkScattererVolumeRepresentation
  : public vtkImageVolumeRepresentation
{
public:
  static vtkScattererVolumeRepresentation* New();
  vtkTypeMacro(vtkScattererVolumeRepresentation, vtkImageVolumeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The mapper this representation renders with. */
  vtkScattererTemplateVolumeMapper* GetScattererMapper();

  ///@{
  /** Forwarded to vtkScattererTemplateVolumeMapper (same names, ranges, defaults). */
  void SetIlluminationEnabled(bool enabled);
  void SetShadowsEnabled(bool enabled);
  void SetColorBleedingEnabled(bool enabled);
  void SetThinPartCheckEnabled(bool enabled);
  void SetBoundaryRefractionEnabled(bool enabled);
  void SetTemplateBlendingEnabled(bool enabled);
  void SetIlluminationMode(int mode);
  void SetTransportScale(int scale);
  void SetInteractiveTransportScale(int scale);
  void SetMaximumTransportVoxels(int voxels);
  void SetMultipleScattering(double strength);
  void SetTemplateRadius(double radius);
  void SetTemplatesPerMaterial(int count);
  void SetPhotonCap(int cap);
  void SetOcclusionStrength(double strength);
  void SetLongRangeMultiple(double multiple);
  void SetPhotonThreshold(double threshold);
  ///@}

  /** User cropping (ParaView's UseCropping); kept apart from the piece cropping. */
  void SetCropping(int cropping);

  ///@{
  /**
   * Ghost layers (voxels) each piece asks for when the data is split into pieces:
   * -1 (default) as many as the illumination reach needs, so piece borders are lit as
   * in a single-process render; 0 none (less memory and transfer, visible seams where
   * occluders sit across a border); n exactly n.
   */
  void SetGhostLayers(int layers);
  vtkGetMacro(GhostLayers, int);
  ///@}

  ///@{
  /**
   * Split data (several ranks): exchange the light between the pieces (default on),
   * so a piece is shaded by every piece between it and the light. Off: by its own
   * voxels and ghost layers only (the control of the tests).
   */
  void SetLightExchangeEnabled(int exchange);
  ///@}

  /**
   * This rank's light exchange: exchanges so far, milliseconds and bytes received of
   * the last one, and 1 if the last frame's transport used its maps.
   */
  double* GetLightExchangeInfo() VTK_SIZEHINT(4);

  /**
   * This rank's light transport volume: rebuilds so far, of them those that drew the
   * medium's passes again (a new transfer function, clipping, ...), the last rebuild's
   * milliseconds, then its stages' (vtkScattererTransportVolume::StageMilliseconds:
   * medium, sweeps, arriving, gather, diffusion). All 0 before the first. ParaView's
   * progress bar makes each stage wait for the GPU, so here they include its work.
   */
  double* GetIlluminationBuildInfo() VTK_SIZEHINT(8);

  /** Ghost layers the last update asked for (0 when the data is not split). */
  vtkGetMacro(RequestedGhostLevels, int);

  /** True when this rank's piece came with ghost layers and only OwnedBounds render. */
  vtkGetMacro(RendersOwnedPartOnly, bool);

  /** Bounds of the part of the piece this rank renders (without ghost layers). */
  vtkGetVector6Macro(OwnedBounds, double);

  /** Kibibytes of the piece this rank holds, ghost layers included. */
  vtkIdType GetPieceMemorySize() { return static_cast<vtkIdType>(this->DataSize); }

  /** The mapper's account of the last frame: the shader features, or "stock: why". */
  const char* GetShaderFeatures();

protected:
  vtkScattererVolumeRepresentation();
  ~vtkScattererVolumeRepresentation() override;

  int RequestUpdateExtent(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  void UpdateMapperParameters() override;
  bool AddToView(vtkView* view) override;
  bool RemoveFromView(vtkView* view) override;

private:
  /** Before each frame renders, on every rank: the light exchange between the pieces. */
  void ExchangeLight(vtkObject* caller, unsigned long event, void* callData);

  /**
   * The image the mapper renders: the delivered piece, or, where ParaView colours a
   * multi-component array by one component or by its magnitude, one with that array as
   * that component or magnitude alone.
   */
  void UpdateMapperInput();

  /**
   * The piece this render shows: the one the view delivered, which the superclass's
   * REQUEST_RENDER connects to the mapper just before UpdateMapperParameters. With
   * "Cache Geometry For Animation" that is a cached time step's data, while the cache
   * holds the step executed last. While the mapper shows the vector copy, what the copy
   * was made from.
   */
  vtkImageData* DeliveredPiece();

  /** Ghost layers each piece asks for when the illumination reaches @p reach. */
  int GhostLevelsFor(double reach) const;

  /**
   * After a setting of the mapper changed: split data whose pieces would now ask for
   * other ghost layers is requested again (MarkModified); otherwise the mapper alone
   * changed, and its frames rebuild what depends on it (the data, its upload and the
   * medium of the light stay as they are).
   */
  void SettingChanged();

  /** The mapper's ProgressEvent, re-sent as this representation's. */
  void ForwardMapperProgress(vtkObject* caller, unsigned long event, void* callData);

  vtkScattererVolumeRepresentation(const vtkScattererVolumeRepresentation&) = delete;
  void operator=(const vtkScattererVolumeRepresentation&) = delete;

  int GhostLayers = -1;
  int RequestedGhostLevels = 0;
  double FinestSpacing = 0.0;      // of the split data, at the last update (0: not split)
  double Spacing[3] = { 0, 0, 0 }; // of the split data, at the last update
  int UserCropping = 0;
  bool RendersOwnedPartOnly = false; // a piece of split data: OwnedBounds is the part it owns
  double OwnedBounds[6] = { 0, -1, 0, -1, 0, -1 };
  int OwnedExtent[6] = { 0, -1, 0, -1, 0, -1 };
  int WholeExtent[6] = { 0, -1, 0, -1, 0, -1 };
  int Pieces = 1; // the data is split into this many pieces (the same on every rank)
  vtkNew<vtkScattererLightExchange> LightExchange;
  vtkRenderer* ObservedRenderer = nullptr;
  unsigned long ExchangeObserver = 0;
  double LightExchangeInfo[4] = { 0, 0, 0, 0 };
  double IlluminationBuildInfo[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
  vtkSmartPointer<vtkImageData> VectorInput;  // the piece with its array's component or magnitude
  vtkSmartPointer<vtkImageData> VectorSource; // the piece VectorInput was made from
  // what VectorInput was made from (a scatterer_render::ChangeKey, a private header)
  std::unique_ptr<scatterer_render::ChangeKey> VectorInputKey;
};

#endif
