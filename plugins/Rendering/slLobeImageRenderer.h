#ifndef slLobeImageRenderer_h
#define slLobeImageRenderer_h
/**
 * @class   slLobeImageRenderer
 * @brief   One image of BRDF lobes in three parts: the 3D lobes, a polar
 *          plot of the plane of incidence, and directional albedo against
 *          the angle of incidence; several models overlaid in colours.
 *
 * The lobes come from slBRDFLobeSource (output 0 for the surface, output 1
 * for the polar slice), the albedo curves from slAlbedoTable, so every value
 * is the lighting core's. BRDF Explorer `.brdf` files overlay the same way:
 * their lobes and albedo curves (at slAlbedoTable's angles) are evaluated
 * on the GPU by slBRDFFileEvaluator, with the file's parameters. The 3D panel views the plane of incidence from the
 * side and draws the incident and mirror directions; the two plots are
 * vtkChartXY charts with a legend.
 *
 * @warning Needs an X display, like every ShadeLab rendering (xvfb-run).
 *
 * @sa slBRDFLobeSource slAlbedoTable slFieldImageRenderer
 */

#include "ShadeLabRenderPassesModule.h"
#include "slPanelRenderer.h"

#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class slBRDFLobeSource;
class vtkImageData;

class SHADELABRENDERPASSES_EXPORT slLobeImageRenderer : public slPanelRenderer
{
public:
  static slLobeImageRenderer* New();
  vtkTypeMacro(slLobeImageRenderer, slPanelRenderer);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Adds a model by its scene-file name; an unknown name, or a seventh
  /// BRDF (models and files: six are overlaid at most), is an error
  /// (vtkErrorMacro): false, and nothing added.
  bool AddModel(const char* name);

  /// Adds a BRDF Explorer .brdf file, read when rendering; no name, or a
  /// seventh BRDF, is an error (vtkErrorMacro): false, and nothing added.
  /// Its name in the legends is the file's name without its folder
  /// (shadelab::brdfDisplayName()).
  bool AddBRDFFile(const char* path);

  /// A "name=value" override (shadelab::brdfParameterValues()) for the
  /// parameters of the file added last; ignored if no file was added.
  void AddBRDFFileParameter(const char* nameValue);

  /// Removes every model and file.
  void RemoveAllModels();

  /// The colour (0-255) of the @p index-th BRDF added (0 to 5).
  static void GetColor(int index, unsigned char rgb[3]);

  ///@{
  /// After Render(): the directional albedo of each file added, in order,
  /// at the lobes' incidence angle (with its parameters), and its name.
  int GetNumberOfBRDFFiles();
  double GetBRDFFileAlbedo(int index);
  std::string GetBRDFFileName(int index);
  ///@}

  /// The lobe parameters (the material's numbers, incidence angle, k_d, k_s, cosine
  /// factor, resolutions) are set on this source; Render() draws it once per model.
  slBRDFLobeSource* GetLobeParameters();

  bool Render() override;

protected:
  slLobeImageRenderer();
  ~slLobeImageRenderer() override;

private:
  slLobeImageRenderer(const slLobeImageRenderer&) = delete;
  void operator=(const slLobeImageRenderer&) = delete;

  /// A model (Model >= 0) or a .brdf file with its overrides.
  struct Entry
  {
    int Model = -1;
    std::string Path;
    std::vector<std::string> Overrides;
  };
  std::vector<Entry> Entries;
  /// True if another BRDF fits (one colour each); else an error of
  /// @p adder, false.
  bool HasRoomFor(const char* adder);
  std::vector<double> FileAlbedos;
  vtkSmartPointer<slBRDFLobeSource> LobeParameters;
};

#endif
