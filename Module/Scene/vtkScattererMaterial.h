/**
 * @class   vtkScattererMaterial
 * @brief   One material of the scatterer-template model: opacity, refractive index, colour, and
 * where it is in a volume.
 *
 * The scatterer-template method (docs/model.md) precomputes photon templates per
 * material. This object holds what the generator and the mapper need to know
 * about one material:
 *
 * - Opacity, the paper's 1 - T(d) in [0, 1]: the extinction per template radius.
 * - RefractiveIndex n, clamped to [GetRefractiveIndexMinValue(),
 *   GetRefractiveIndexMaxValue()] = [1e-4, 1e4], the range the physics core accepts.
 * - DiffuseColor, RGB in [0, 1].
 * - How the material is found in a volume: either a scalar range (SetScalarRange,
 *   inclusive, e.g. a density class in HU) or a label id of a label map (SetLabel).
 *   The last of the two calls decides GetSelectorType() (SCALAR_RANGE or LABEL).
 *
 * Every setter rejects NaN with an error naming the setter and keeps the old
 * value; out-of-range values are clamped. The scalar range, the label and the
 * name are not checked here: the physics core checks them when templates are
 * generated (vtkScattererTemplateSource reports lo > hi, an infinite bound, a
 * negative label or a name over 255 bytes as an error).
 *
 * @sa vtkScattererTemplateSource
 */
#ifndef vtkScattererMaterial_h
#define vtkScattererMaterial_h

#include "ScattererTemplateModule.h" // for export macro
#include "vtkObject.h"

#include <string> // for Name

class SCATTERERTEMPLATE_EXPORT vtkScattererMaterial : public vtkObject
{
public:
  static vtkScattererMaterial* New();
  vtkTypeMacro(vtkScattererMaterial, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** How the material is found in a volume. */
  enum SelectorTypes
  {
    SCALAR_RANGE = 0, ///< scalars in [lo, hi] (inclusive)
    LABEL = 1         ///< scalars equal to one label id
  };

  ///@{
  /** Name, used in messages and template files (the core accepts at most 255 bytes). */
  vtkSetStdStringFromCharMacro(Name);
  vtkGetCharFromStdStringMacro(Name);
  ///@}

  ///@{
  /**
   * Opacity, the paper's 1 - T(d): extinction per template radius. Clamped to
   * [0, 1]; NaN is rejected. Default 0.5.
   */
  virtual void SetOpacity(double opacity);
  vtkGetMacro(Opacity, double);
  ///@}

  ///@{
  /**
   * Refractive index n of the material (the facets are interfaces into n = 1).
   * Clamped to [GetRefractiveIndexMinValue(), GetRefractiveIndexMaxValue()];
   * NaN is rejected. Default 1.4 (soft tissue).
   */
  virtual void SetRefractiveIndex(double n);
  vtkGetMacro(RefractiveIndex, double);
  double GetRefractiveIndexMinValue() const;
  double GetRefractiveIndexMaxValue() const;
  ///@}

  ///@{
  /**
   * Diffuse colour, RGB each clamped to [0, 1]; a call with any NaN component is
   * rejected as a whole. Default (1, 1, 1).
   */
  virtual void SetDiffuseColor(double r, double g, double b);
  void SetDiffuseColor(const double rgb[3]) { this->SetDiffuseColor(rgb[0], rgb[1], rgb[2]); }
  vtkGetVector3Macro(DiffuseColor, double);
  ///@}

  ///@{
  /**
   * Select the material by the scalar range [lo, hi] (inclusive) and make
   * SCALAR_RANGE the selector type. NaN bounds are rejected. lo > hi and
   * infinite bounds are accepted here but rejected by template generation.
   * Default [0, 1].
   */
  virtual void SetScalarRange(double lo, double hi);
  void SetScalarRange(const double range[2]) { this->SetScalarRange(range[0], range[1]); }
  vtkGetVector2Macro(ScalarRange, double);
  ///@}

  ///@{
  /**
   * Select the material by a label id of a label map and make LABEL the
   * selector type. Negative ids are rejected by template generation. Default 0.
   */
  virtual void SetLabel(int label);
  vtkGetMacro(Label, int);
  ///@}

  ///@{
  /** SCALAR_RANGE (default) or LABEL: whichever of SetScalarRange / SetLabel was called last. */
  vtkGetMacro(SelectorType, int);
  const char* GetSelectorTypeAsString() const;
  ///@}

  /** Copies every parameter of @p other (nullptr is an error). */
  void DeepCopy(vtkScattererMaterial* other);

protected:
  vtkScattererMaterial();
  ~vtkScattererMaterial() override;

  // Defaults are the physics core's (scatterer::Material), set in the constructor.
  std::string Name;
  double Opacity;
  double RefractiveIndex;
  double DiffuseColor[3];
  int SelectorType;
  double ScalarRange[2];
  int Label;

private:
  vtkScattererMaterial(const vtkScattererMaterial&) = delete;
  void operator=(const vtkScattererMaterial&) = delete;
};

#endif
