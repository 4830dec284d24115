/**
 * @class   vtkScattererTemplateSource
 * @brief   Generates, saves and loads scatterer templates and outputs their photons as points.
 *
 * The scatterer-template method (docs/model.md) precomputes, per material, a
 * few templates of absorbed light ("photons") around a point of scattering.
 * This source runs the physics core's generator for a list of
 * vtkScattererMaterial and outputs every photon of every template as one
 * point with a vertex cell, so the templates can be inspected, glyphed and
 * coloured in VTK or ParaView. Point data:
 *
 * - `Intensity` (float, the active scalars): the photon's share of its
 *   template's initial energy 1; within a template the points are sorted by
 *   descending intensity.
 * - `TemplateId` (int): the template's index within its material, 0 ..
 *   TemplatesPerMaterial - 1.
 * - `MaterialId` (int): the material's index in this source.
 *
 * Field data `MaterialName` (string, one per material) names the materials.
 *
 * Positions are in template radii (|p| <= 1), multiplied by TemplateRadius
 * (default 1). All templates share the origin, so use a threshold on
 * TemplateId / MaterialId to look at one of them.
 *
 * Generation is deterministic: the same materials and settings give
 * bit-identical points (template t of material m is the core's
 * generateAllTemplates(materials, settings)[m][t]). The templates are kept
 * between updates and regenerated only when a material or a generator setting
 * changes (TemplateRadius only rescales the output). Progress events are fired
 * after each template and end at 1.0. An invalid material (e.g. a scalar range
 * with lo > hi, a negative label or a name over 255 bytes) is reported with
 * the core's message through vtkErrorMacro, and the output is empty.
 *
 * SaveTemplates() writes the current templates in the core's binary template
 * file format (docs/model.md, "Template file format"); LoadTemplates() reads
 * such a file, replaces the materials and settings with the file's and makes
 * the source output the loaded templates until a material or setting changes.
 *
 * @sa vtkScattererMaterial
 */
#ifndef vtkScattererTemplateSource_h
#define vtkScattererTemplateSource_h

#include "ScattererTemplateModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h" // for Materials
#include "vtkType.h"         // for vtkTypeUInt64

#include <memory> // for Internals
#include <vector> // for Materials

class vtkScattererMaterial;

class SCATTERERTEMPLATE_EXPORT vtkScattererTemplateSource : public vtkPolyDataAlgorithm
{
public:
  static vtkScattererTemplateSource* New();
  vtkTypeMacro(vtkScattererTemplateSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The materials, in MaterialId order. AddMaterial keeps a reference (later
   * changes to the material are seen); nullptr is an error.
   * GetMaterial returns nullptr for an index out of range.
   */
  void AddMaterial(vtkScattererMaterial* material);
  void RemoveAllMaterials();
  int GetNumberOfMaterials() const;
  vtkScattererMaterial* GetMaterial(int index) const;
  ///@}

  ///@{
  /** Templates per material, each from its own random stream. Clamped to [1, 1024]; default 8. */
  vtkSetClampMacro(TemplatesPerMaterial, int, 1, 1024);
  vtkGetMacro(TemplatesPerMaterial, int);
  ///@}

  ///@{
  /** L: the initial energy 1 is split across L lights (paper Table 2). Clamped to [1, 1024];
   * default 4. */
  vtkSetClampMacro(InitialLights, int, 1, 1024);
  vtkGetMacro(InitialLights, int);
  ///@}

  ///@{
  /**
   * A packet below Threshold x (1 / InitialLights) stops branching. Clamped to
   * [1e-9, 1] (below that only the hard caps bind); NaN is rejected. Default 0.01.
   */
  virtual void SetThreshold(double threshold);
  vtkGetMacro(Threshold, double);
  ///@}

  ///@{
  /** Seed of the random streams. Default 0x5CA77E2E5EED (the core's). */
  vtkSetMacro(Seed, vtkTypeUInt64);
  vtkGetMacro(Seed, vtkTypeUInt64);
  ///@}

  ///@{
  /**
   * Advanced: dx of Eq. 2 between scattering events and the edge of the merge
   * lattice, in template radii. Each clamped to [1e-4, 1]; NaN is rejected.
   * Defaults 0.05 and 0.02 (the core's).
   */
  virtual void SetStepLength(double step);
  vtkGetMacro(StepLength, double);
  virtual void SetLatticeCell(double cell);
  vtkGetMacro(LatticeCell, double);
  ///@}

  ///@{
  /**
   * Advanced: hard caps per template that keep generation bounded whatever the
   * threshold. Clamped to [1, 2^20] photons and [1, 2^24] packets; defaults
   * 4096 and 65536 (the core's).
   */
  vtkSetClampMacro(MaxPhotonsPerTemplate, int, 1, 1 << 20);
  vtkGetMacro(MaxPhotonsPerTemplate, int);
  vtkSetClampMacro(MaxEventsPerTemplate, int, 1, 1 << 24);
  vtkGetMacro(MaxEventsPerTemplate, int);
  ///@}

  ///@{
  /**
   * World size of one template radius: output positions are the template
   * coordinates times this. Must be finite and > 0 (other values are rejected
   * with an error). Changing it does not regenerate the templates. Default 1.
   */
  virtual void SetTemplateRadius(double radius);
  vtkGetMacro(TemplateRadius, double);
  ///@}

  /**
   * Writes the templates for the current materials and settings (generating
   * them first if needed) to @p path in the core's template file format.
   * On failure (generation error, path not writable) reports an error and
   * returns false.
   */
  bool SaveTemplates(const char* path);

  /**
   * Reads a template file. On success the materials and settings become the
   * file's (the material list is replaced by new vtkScattererMaterial
   * objects; get them with GetMaterial), and the output is the loaded templates until a material or
   * setting changes (then they are regenerated). On failure (missing,
   * truncated, corrupt file) reports the core's message as an error, leaves
   * the source as it was and returns false.
   */
  bool LoadTemplates(const char* path);

  ///@{
  /**
   * Inspection of the templates of the last update, save or load (0 before
   * any): the number of templates over all materials, the number of photons
   * (= output points), the largest |energy ledger residual| over the
   * templates (initial - stored - lost - escaped - dropped; ~1e-15) and how
   * many templates a hard cap stopped early.
   */
  int GetNumberOfTemplates() const;
  vtkIdType GetNumberOfPhotons() const;
  double GetMaxLedgerResidual() const;
  int GetNumberOfCappedTemplates() const;
  ///@}

  /** Includes the materials' modification times. */
  vtkMTimeType GetMTime() override;

protected:
  vtkScattererTemplateSource();
  ~vtkScattererTemplateSource() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /**
   * Makes the cached templates match the current materials and settings,
   * generating them if they do not (with progress events). Reports an error
   * and returns false when the core rejects a material or a setting.
   */
  bool UpdateTemplates();

  std::vector<vtkSmartPointer<vtkScattererMaterial>> Materials;
  int TemplatesPerMaterial;
  int InitialLights;
  double Threshold;
  vtkTypeUInt64 Seed;
  double StepLength;
  double LatticeCell;
  int MaxPhotonsPerTemplate;
  int MaxEventsPerTemplate;
  double TemplateRadius = 1.0;

private:
  vtkScattererTemplateSource(const vtkScattererTemplateSource&) = delete;
  void operator=(const vtkScattererTemplateSource&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
