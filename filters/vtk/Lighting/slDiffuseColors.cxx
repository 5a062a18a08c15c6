#include "slDiffuseColors.h"

#include "slImageReader.h"
#include "slUpdateOrThrow.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include "shadelab/SceneLimits.h"

#include <algorithm>
#include <cmath>

namespace shadelab
{

namespace
{
/// Component @p c of tuple @p i as a colour value in the lighting equation:
/// 8-bit values v mean v / 255, as VTK and ShadeLab's render pass use them
/// (no transfer function on either path, so CPU and GPU agree). Values that
/// are not finite count as 0; the others are clamped to ±kMaxColourValue,
/// the scene's own limit, so that no product with the lights can overflow.
float linearComponent(vtkDataArray* a, vtkIdType i, int c)
{
  const double v = a->GetComponent(i, c);
  if (vtkUnsignedCharArray::SafeDownCast(a))
  {
    return static_cast<float>(v / 255.0);
  }
  return std::isfinite(v) ? static_cast<float>(std::max(-kMaxColourValue, std::min(v, kMaxColourValue))) : 0.0f;
}

glm::vec3 colourOf(vtkDataArray* a, vtkIdType i)
{
  const int n = a->GetNumberOfComponents();
  if (n < 3)
  {
    return glm::vec3(linearComponent(a, i, 0)); // grey
  }
  return glm::vec3(linearComponent(a, i, 0), linearComponent(a, i, 1), linearComponent(a, i, 2));
}

float wrap(double t)
{
  return static_cast<float>(t - std::floor(t));
}
} // namespace

void diffuseFromArray(vtkPolyData* mesh, const std::string& arrayName, std::vector<glm::vec3>& out)
{
  vtkDataArray* a = mesh->GetPointData()->GetArray(arrayName.c_str());
  if (!a)
  {
    throw Error("input mesh: no point array \"" + arrayName + "\" for the diffuse colour");
  }
  if (a->GetNumberOfComponents() != 3 && a->GetNumberOfComponents() != 4)
  {
    throw Error("input mesh: point array \"" + arrayName + "\" has " + std::to_string(a->GetNumberOfComponents()) +
      " components; a diffuse colour needs 3 (RGB) or 4 (RGBA)");
  }
  out.resize(static_cast<size_t>(mesh->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    out[static_cast<size_t>(i)] = colourOf(a, i);
  }
}

void diffuseFromTexture(vtkPolyData* mesh, vtkImageData* texture, std::vector<glm::vec3>& out)
{
  vtkDataArray* uv = mesh->GetPointData()->GetTCoords();
  if (!uv || uv->GetNumberOfComponents() < 2)
  {
    throw Error("input mesh: a diffuse texture needs point texture coordinates, and the mesh has none");
  }
  vtkDataArray* pixels = texture ? texture->GetPointData()->GetScalars() : nullptr;
  int dims[3] = { 0, 0, 0 };
  if (texture)
  {
    texture->GetDimensions(dims);
  }
  if (!pixels || dims[0] < 1 || dims[1] < 1)
  {
    throw Error("diffuse texture: the image is empty");
  }
  out.resize(static_cast<size_t>(mesh->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    if (!std::isfinite(uv->GetComponent(i, 0)) || !std::isfinite(uv->GetComponent(i, 1)))
    {
      // No place in the image: colour 0, like a colour value that is not finite.
      out[static_cast<size_t>(i)] = glm::vec3(0.0f);
      continue;
    }
    // Bilinear lookup with repeat wrapping, texel centres at (k + 0.5) / size.
    const float x = wrap(uv->GetComponent(i, 0)) * dims[0] - 0.5f;
    const float y = wrap(uv->GetComponent(i, 1)) * dims[1] - 0.5f;
    const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
    const float fx = x - x0, fy = y - y0;
    glm::vec3 sum(0.0f);
    for (int dy = 0; dy < 2; ++dy)
    {
      for (int dx = 0; dx < 2; ++dx)
      {
        const int px = ((x0 + dx) % dims[0] + dims[0]) % dims[0];
        const int py = ((y0 + dy) % dims[1] + dims[1]) % dims[1];
        const float w = (dx ? fx : 1.0f - fx) * (dy ? fy : 1.0f - fy);
        sum += w * colourOf(pixels, static_cast<vtkIdType>(py) * dims[0] + px);
      }
    }
    out[static_cast<size_t>(i)] = sum;
  }
}

void baseColourPerPoint(vtkPolyData* mesh, const char* arrayName, const char* textureFileName,
  vtkImageData* texture, std::vector<glm::vec3>& out)
{
  out.clear();
  if (arrayName && *arrayName)
  {
    diffuseFromArray(mesh, arrayName, out);
  }
  else if (textureFileName && *textureFileName)
  {
    // Read at each call: ParaView's properties are plain values, so the file
    // name is how a ParaView user gives a texture.
    vtkNew<slImageReader> reader;
    reader->SetFileName(textureFileName);
    slUpdateOrThrow(reader);
    diffuseFromTexture(mesh, reader->GetOutput(), out);
  }
  else if (texture)
  {
    diffuseFromTexture(mesh, texture, out);
  }
}

} // namespace shadelab
