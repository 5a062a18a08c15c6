#include "BaseColourOptions.h"

#include "slBaseColouredFilter.h"
#include "slImageReader.h"
#include "slSceneTexture.h"
#include "slUpdateOrThrow.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

namespace shadelab
{
namespace app
{

std::vector<OptionSpec> baseColourOptions()
{
  return {
    { "diffuse-array", "", "NAME",
      "an RGB(A) point array of MESH: a base colour multiplying k_a and k_d (as in render)" },
    { "diffuse-texture", "", "FILE",
      "an image: a base colour multiplying k_a and k_d at the texture coordinates (default: the scene's "
      "material.diffuseTexture)" },
  };
}

void checkBaseColourOptions(const CommandLine& cl)
{
  if (cl.has("diffuse-array") && cl.has("diffuse-texture"))
  {
    // The filters would take the array and never read the texture.
    throw UsageError("--diffuse-texture: give either --diffuse-array or --diffuse-texture, not both");
  }
}

BaseColour::BaseColour(const CommandLine& cl, slScene* scene)
{
  checkBaseColourOptions(cl);
  if (cl.has("diffuse-array"))
  {
    this->ArrayName = cl.get("diffuse-array");
  }
  else if (cl.has("diffuse-texture"))
  {
    // Read once for every mesh, and before any: an unreadable file stops the
    // command with nothing written.
    vtkNew<slImageReader> reader;
    reader->SetFileName(cl.get("diffuse-texture").c_str());
    slUpdateOrThrow(reader);
    this->Texture = reader->GetOutput();
  }
  else
  {
    this->Texture = slReadSceneTexture(scene);
    this->SceneTexture = true;
  }
}

vtkImageData* BaseColour::textureFor(vtkPolyData* mesh) const
{
  return this->SceneTexture ? slSceneTextureFor(this->Texture, mesh) : this->Texture.Get();
}

void BaseColour::applyTo(slBaseColouredFilter* filter, vtkPolyData* mesh) const
{
  filter->SetDiffuseColorArrayName(this->arrayName().c_str());
  filter->SetDiffuseTexture(this->textureFor(mesh));
}

} // namespace app
} // namespace shadelab
