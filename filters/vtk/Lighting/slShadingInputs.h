#ifndef slShadingInputs_h
#define slShadingInputs_h
/**
 * @file slShadingInputs.h
 * @brief Internal: what slRadianceFilter and slRadianceReference hand the
 * radiance kernel (slRadianceKernel.h) for a mesh, and the kernel's RGB
 * output arrays. Not wrapped.
 *
 * Both filters get the kernel's input from
 * slBaseColouredFilter::PrepareShading(), so the discrete lighting of the
 * one and the DiscreteRadiance of the other read the same points, normals,
 * tangents, base colours, lights, material, model and eye.
 */

#include "slFloat3View.h"
#include "slLightingSetup.h"
#include "slParallelFillArray.h"
#include "slRadianceKernel.h"

#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <glm/glm.hpp>

#include <memory>
#include <string>
#include <vector>

namespace shadelab
{

/// The kernel's input for a mesh together with the storage it points into
/// (the base colours, and the views of arrays that are not 3-component
/// floats): @c kernel is valid while this object lives. Neither copied nor
/// moved, so that those pointers cannot dangle.
struct ShadingInputs
{
  /// @p tangentArray: slLitFilter::GetTangents()'s, null when the model reads none.
  ShadingInputs(vtkPolyData* mesh, vtkDataArray* tangentArray, std::vector<glm::vec3> baseColours,
    const LightingSetup& setup)
    : base(std::move(baseColours))
    , points(mesh->GetPoints()->GetData())
    , normals(mesh->GetPointData()->GetNormals())
    , tangents(tangentArray ? std::make_unique<Float3View>(tangentArray) : nullptr)
  {
    this->kernel.points = this->points.data();
    this->kernel.normals = this->normals.data();
    this->kernel.tangents = this->tangents ? this->tangents->data() : nullptr;
    this->kernel.baseColour = this->base.empty() ? nullptr : &this->base[0].x;
    this->kernel.lights = setup.lights;
    this->kernel.material = setup.material;
    this->kernel.model = static_cast<ShadingModel>(setup.model);
    this->kernel.eye = setup.eye;
  }
  ShadingInputs(const ShadingInputs&) = delete;
  ShadingInputs& operator=(const ShadingInputs&) = delete;

  const std::vector<glm::vec3> base; ///< base colour per point (empty: none): multiplies k_a and k_d
  const Float3View points;
  const Float3View normals;
  const std::unique_ptr<Float3View> tangents; ///< null when the model reads none
  RadianceKernelInput kernel;
};

/// An RGB output array of @p n points named @p name, uninitialised: its
/// filler writes every value once (the kernel does, in parallel).
inline vtkSmartPointer<vtkFloatArray> rgbArray(const std::string& name, vtkIdType n)
{
  return newParallelFillArray(name, 3, n);
}

} // namespace shadelab

#endif
