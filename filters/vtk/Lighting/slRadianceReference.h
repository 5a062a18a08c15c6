#ifndef slRadianceReference_h
#define slRadianceReference_h
/**
 * @class   slRadianceReference
 * @brief   Monte Carlo reference of the radiance equation per point,
 *          L_o = L_e + integral of f_r L_i cos(theta) dw, and its difference
 *          from the discrete-light lighting equation.
 *
 * Light sources for L_i: an equirectangular HDR environment map (SetEnvironmentFileName(),
 * .hdr or .exr through OpenImageIO, or SetEnvironmentMap() with a float
 * vtkImageData of 2:1 layout) and/or the scene's lights as small spherical
 * area lights (UseSceneLights, LightRadius, DirectionalLightAngle); see
 * shadelab/RadianceEstimator.h for how a light's radiance is chosen so that
 * the reference tends to the discrete formula as the lights shrink.
 *
 * Sampling (SetStrategy()): uniform, cosine-weighted, BRDF importance (the
 * model's own lobe, shadelab/BRDFSampler.h), light
 * (with the environment map's own importance sampling) or multiple
 * importance sampling (default). SamplesPerPoint per point; every point has
 * its own random stream derived from Seed and its id, so output does not
 * depend on threads. Progress through UpdateProgress().
 *
 * The mesh can colour the material as in slRadianceFilter: both take the
 * base colour through slBaseColouredFilter (a point array, else an image
 * file, else an image such as a scene's material.diffuseTexture from
 * slReadSceneTexture()), so they pick the same input and fail with the same
 * errors. The colour multiplies k_a and k_d at each point: the reference's
 * BRDF and the discrete radiance both use the coloured material.
 *
 * Output point arrays (input arrays pass through): "Radiance" (the
 * reference), "RadianceStdError" (standard error of the mean, per channel),
 * "DiscreteRadiance" (the lighting equation with the scene's lights, as
 * slRadianceFilter computes it) and "RadianceError" = reference − discrete.
 * Field data "RadianceErrorMean", "RadianceErrorRMS", "RadianceErrorMaxAbs"
 * (RGB) and "MeanStdError" summarise them.
 *
 * @warning No shadows or interreflection: this is the local radiance
 * equation. The reference has no ambient term (the environment map plays its
 * part); the discrete radiance includes the scene's ambient terms, which then
 * show up in RadianceError. A light's single colour is its diffuse colour.
 *
 * @sa slBaseColouredFilter slRadianceFilter slLitFilter slImageReader slSceneTexture.h
 */

#include "ShadeLabLightingModule.h"
#include "slBaseColouredFilter.h"

class vtkImageData;

class SHADELABLIGHTING_EXPORT slRadianceReference : public slBaseColouredFilter
{
public:
  static slRadianceReference* New();
  vtkTypeMacro(slRadianceReference, slBaseColouredFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Strategies
  {
    UNIFORM = 0,
    COSINE = 1,
    BRDF = 2,
    LIGHT = 3,
    MIS = 4
  };

  ///@{
  /// Sampling strategy (default MIS).
  vtkSetClampMacro(Strategy, int, UNIFORM, MIS);
  vtkGetMacro(Strategy, int);
  void SetStrategyToUniform() { this->SetStrategy(UNIFORM); }
  void SetStrategyToCosine() { this->SetStrategy(COSINE); }
  void SetStrategyToBRDF() { this->SetStrategy(BRDF); }
  void SetStrategyToLight() { this->SetStrategy(LIGHT); }
  void SetStrategyToMIS() { this->SetStrategy(MIS); }
  ///@}

  ///@{
  /// Samples per point (default 64; MIS takes two per iteration).
  vtkSetClampMacro(SamplesPerPoint, int, 1, 1 << 24);
  vtkGetMacro(SamplesPerPoint, int);
  ///@}

  ///@{
  /// Seed of the random streams (default 1).
  vtkSetMacro(Seed, int);
  vtkGetMacro(Seed, int);
  ///@}

  ///@{
  /// Environment map file (.hdr, .exr, ...); "" (default): none.
  vtkSetStringMacro(EnvironmentFileName);
  vtkGetStringMacro(EnvironmentFileName);
  ///@}

  ///@{
  /// An environment map image (float RGB, width = 2 x height, row 0 at the
  /// bottom); used when no EnvironmentFileName is set.
  virtual void SetEnvironmentMap(vtkImageData* image);
  vtkGetObjectMacro(EnvironmentMap, vtkImageData);
  ///@}

  ///@{
  /// Scale applied to the environment's radiance (default 1).
  vtkSetClampMacro(EnvironmentScale, double, 0.0, 1.0e6);
  vtkGetMacro(EnvironmentScale, double);
  ///@}

  ///@{
  /// Whether the scene's lights light the reference (default on).
  vtkSetMacro(UseSceneLights, bool);
  vtkGetMacro(UseSceneLights, bool);
  vtkBooleanMacro(UseSceneLights, bool);
  ///@}

  ///@{
  /// Radius of point and spot lights in world units; 0 (default): 1% of the
  /// input's bounding-box diagonal (of the whole input, over all MPI ranks).
  vtkSetClampMacro(LightRadius, double, 0.0, 1.0e30);
  vtkGetMacro(LightRadius, double);
  ///@}

  ///@{
  /// Angular radius of directional lights in degrees (default 0.5).
  vtkSetClampMacro(DirectionalLightAngle, double, 1.0e-4, 45.0);
  vtkGetMacro(DirectionalLightAngle, double);
  ///@}

  vtkMTimeType GetMTime() override;

protected:
  slRadianceReference();
  ~slRadianceReference() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  slRadianceReference(const slRadianceReference&) = delete;
  void operator=(const slRadianceReference&) = delete;

  int Strategy = MIS;
  int SamplesPerPoint = 64;
  int Seed = 1;
  char* EnvironmentFileName = nullptr;
  vtkImageData* EnvironmentMap = nullptr;
  double EnvironmentScale = 1.0;
  bool UseSceneLights = true;
  double LightRadius = 0.0;
  double DirectionalLightAngle = 0.5;
};

#endif
