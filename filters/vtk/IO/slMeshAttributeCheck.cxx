#include "slMeshAttributeCheck.h"

#include "shadelab/PrintableText.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <cfloat>
#include <cmath>
#include <cstdlib>

namespace
{
/// Index of the first value of @p values (@p n of them) that is not finite,
/// or -1. A plain loop over the raw values: millions of points take a few
/// milliseconds, where a virtual call per value would take many times that.
template <typename T>
vtkIdType firstNonFinite(const T* values, vtkIdType n)
{
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (!std::isfinite(values[i]))
    {
      return i;
    }
  }
  return -1;
}

/// Index of the first value of @p array that is not finite, or -1. Integer
/// arrays are always finite.
vtkIdType firstNonFinite(vtkDataArray* array)
{
  const vtkIdType n = array->GetNumberOfValues();
  if (auto* f = vtkFloatArray::FastDownCast(array))
  {
    return firstNonFinite(f->GetPointer(0), n);
  }
  if (auto* d = vtkDoubleArray::FastDownCast(array))
  {
    return firstNonFinite(d->GetPointer(0), n);
  }
  if (array->GetDataType() != VTK_FLOAT && array->GetDataType() != VTK_DOUBLE)
  {
    return -1;
  }
  // Another layout (a VTK user's structure-of-arrays array): value by value.
  const int components = array->GetNumberOfComponents();
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (!std::isfinite(array->GetComponent(i / components, static_cast<int>(i % components))))
    {
      return i;
    }
  }
  return -1;
}

/// "" or the problem with the first value of @p array (of @p where, the
/// @p what) that is not finite.
std::string arrayProblem(vtkDataArray* array, const char* where, const char* what)
{
  const vtkIdType bad = array ? firstNonFinite(array) : -1;
  if (bad < 0)
  {
    return std::string();
  }
  const double value = array->GetComponent(bad / array->GetNumberOfComponents(),
    static_cast<int>(bad % array->GetNumberOfComponents()));
  const char* name = array->GetName();
  return std::string(where) + " " + what + " array \"" + shadelab::printableText(name ? name : "", 100) +
    "\", tuple " + std::to_string(bad / array->GetNumberOfComponents()) + ": " +
    (std::isnan(value) ? "nan" : value > 0 ? "inf" : "-inf") + " is not a finite number";
}

/// "" or the problem with the active normals, texture coordinates or
/// tangents of @p data.
std::string attributesProblem(vtkDataSetAttributes* data, const char* where)
{
  std::string problem = arrayProblem(data->GetNormals(), where, "normals");
  if (problem.empty())
  {
    problem = arrayProblem(data->GetTCoords(), where, "texture coordinates");
  }
  if (problem.empty())
  {
    problem = arrayProblem(data->GetTangents(), where, "tangents");
  }
  return problem;
}
} // namespace

std::string slNonFiniteAttributeProblem(vtkPolyData* mesh)
{
  std::string problem = attributesProblem(mesh->GetPointData(), "point");
  // The detail and lighting filters take a point array "Tangents" by name,
  // active or not.
  if (problem.empty())
  {
    problem = arrayProblem(mesh->GetPointData()->GetArray("Tangents"), "point", "tangents");
  }
  if (problem.empty())
  {
    problem = attributesProblem(mesh->GetCellData(), "cell");
  }
  return problem;
}

std::string slNonFiniteTextProblem(const std::string& token, bool asFloat)
{
  // Called on every value of a text file: nothing allocated unless it fails,
  // and strtof only beyond float range (where it may still round to FLT_MAX).
  const double value = std::strtod(token.c_str(), nullptr);
  const char* problem = !std::isfinite(value) ? " is not a finite number"
    : asFloat && std::fabs(value) > FLT_MAX && std::isinf(std::strtof(token.c_str(), nullptr))
    ? " is beyond the range of float"
    : nullptr;
  return problem ? "\"" + shadelab::printableText(token) + "\"" + problem : std::string();
}
