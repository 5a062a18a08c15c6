#include "slRadianceKernel.h"

#include "shadelab/LightingGLSLBatch.h"
#include "slBatchIO.h"

#include <algorithm>

namespace shadelab
{

namespace
{
using simd::vec3x8;
using simd::vfloat8;

/// The first point of @p batch whose lane of @p squaredLength is not about 1
/// (slSafeNormalize gave the zero vector), or @p none. The common case, a
/// batch of unit normals, costs one comparison and one mask test.
long long firstZeroLane(vfloat8 squaredLength, BatchRange batch, long long none)
{
  const simd::vmask8 zero = squaredLength < 0.5f;
  if (!simd::any(zero))
  {
    return none;
  }
  for (int i = 0; i < batch.count; ++i)
  {
    if (zero.m[i])
    {
      return batch.first + i;
    }
  }
  return none;
}

/// The light in the batch compilation of slLighting.glsl (every lane holds
/// its values), folded by slFoldLight(): its intensity and the material's
/// k_a, k_d, k_s multiplied into its colours, once per light.
glsl8::slLight foldLight(const glsl::slLight& light, const glsl::slMaterial& m)
{
  const glsl::slLight l = glsl::slFoldLight(light, m);
  glsl8::slLight v;
#define SHADELAB_COPY(type, field, ...) v.field = l.field;
  SHADELAB_LIGHT_FIELDS(SHADELAB_COPY)
#undef SHADELAB_COPY
  return v;
}

/// slLightWeightsAt() with the light's type fixed at compile time, so that
/// the compiler drops the other types' branches, and its intensity fixed at
/// 1: foldLight() has put the intensity into the colours.
template <int MODEL, int TYPE>
__attribute__((always_inline)) inline glsl8::slLightWeights weightsOf(glsl8::slLight light,
  const glsl8::slMaterial& m, const vec3x8& P, const vec3x8& n, const vec3x8& t, const vec3x8& v)
{
  light.type = TYPE;
  light.intensity = 1.0f;
  return glsl8::slLightWeightsAt(light, m, MODEL, P, n, t, v);
}

template <int MODEL>
__attribute__((always_inline)) inline glsl8::slLightWeights weightsOfAnyLight(const glsl8::slLight& light,
  const glsl8::slMaterial& m, const vec3x8& P, const vec3x8& n, const vec3x8& t, const vec3x8& v)
{
  // One case per row of the light-type table (sceneValueProblem() has
  // checked every light's type).
  switch (static_cast<LightType>(light.type))
  {
#define SHADELAB_CASE(Enumerator, ...)                                                                                \
  case LightType::Enumerator:                                                                                         \
    return weightsOf<MODEL, static_cast<int>(LightType::Enumerator)>(light, m, P, n, t, v);
    SHADELAB_LIGHT_TYPES(SHADELAB_CASE)
#undef SHADELAB_CASE
  }
  return glsl8::slLightWeights{ vfloat8(0.0f), vfloat8(0.0f), vfloat8(0.0f) };
}

/// slUnitMaterial() in the batch compilation: the lights carry k_a, k_d, k_s
/// (foldLight), so slWeightedTerms() multiplies by constants the compiler
/// removes.
glsl8::slMaterial unitMaterial(const glsl::slMaterial& material)
{
  const glsl::slMaterial u = glsl::slUnitMaterial(material);
  glsl8::slMaterial m;
#define SHADELAB_COPY(type, field, ...) m.field = u.field;
  SHADELAB_MATERIAL_PARAMETERS(SHADELAB_COPY)
#undef SHADELAB_COPY
  return m;
}

/// Points [begin, end), 8 at a time. For each batch of 8 points, first the
/// scalar weights of every light (slLightWeightsAt, the costly part), then
/// their colour products summed in registers. The terms are linear in the
/// colours, so the light colours, each light's intensity and the material's
/// k_a, k_d, k_s are multiplied once per light (foldLight), and a base colour
/// once per point after the sum, instead of once per point and light.
/// flatten inlines every lighting function, so that its batches live in
/// registers, not memory.
template <int MODEL, bool PER_LIGHT>
__attribute__((flatten)) long long shadeBatches(const RadianceKernelInput& in, const RadianceKernelOutput& out,
  const std::vector<glsl8::slLight>& lights, long long begin, long long end)
{
  const vec3x8 eye(in.eye);
  const glsl8::slMaterial unit = unitMaterial(in.material);
  std::vector<glsl8::slLightWeights> weights(lights.size());
  long long firstWithoutNormal = end;
  for (long long first = begin; first < end; first += 8)
  {
    const BatchRange batch{ first, static_cast<int>(std::min<long long>(8, end - first)) };
    // Normalised once per point, not once per light (slShadeLight does the same).
    const vec3x8 P = loadBatch(in.points, batch);
    const vec3x8 n = glsl8::slSafeNormalize(loadBatch(in.normals, batch));
    const vec3x8 v = glsl8::slSafeNormalize(eye - P);
    const bool readsTangent = modelNeedsTangents(static_cast<ShadingModel>(MODEL)) && in.tangents;
    const vec3x8 t = readsTangent ? loadBatch(in.tangents, batch) : vec3x8(vfloat8(0.0f));
    if (firstWithoutNormal == end)
    {
      firstWithoutNormal = firstZeroLane(simd::dot(n, n), batch, end);
    }
    for (size_t l = 0; l < lights.size(); ++l)
    {
      weights[l] = weightsOfAnyLight<MODEL>(lights[l], unit, P, n, t, v);
    }
    const vec3x8 base = in.baseColour ? loadBatch(in.baseColour, batch) : vec3x8(vfloat8(1.0f));
    glsl8::slTerms sum = glsl8::slZeroTerms();
    for (size_t l = 0; l < lights.size(); ++l)
    {
      glsl8::slTerms t = glsl8::slWeightedTerms(weights[l], lights[l], unit);
      sum = glsl8::slAddTerms(sum, t);
      if (PER_LIGHT)
      {
        storeBatch(out.perLight[l], batch, glsl8::slTotal(glsl8::slWithBaseColour(t, base)));
      }
    }
    sum = glsl8::slAddEmission(glsl8::slWithBaseColour(sum, base), unit);
    storeBatch(out.ambient, batch, sum.ambient);
    storeBatch(out.diffuse, batch, sum.diffuse);
    storeBatch(out.specular, batch, sum.specular);
    storeBatch(out.emission, batch, sum.emission);
    storeBatch(out.radiance, batch, glsl8::slTotal(sum));
  }
  return firstWithoutNormal;
}

template <int MODEL>
long long shadeModel(const RadianceKernelInput& in, const RadianceKernelOutput& out,
  const std::vector<glsl8::slLight>& lights, long long begin, long long end)
{
  if (out.perLight.empty())
  {
    return shadeBatches<MODEL, false>(in, out, lights, begin, end);
  }
  return shadeBatches<MODEL, true>(in, out, lights, begin, end);
}
} // namespace

long long shadeRange(const RadianceKernelInput& in, const RadianceKernelOutput& out, long long begin, long long end)
{
  std::vector<glsl8::slLight> lights;
  for (const glsl::slLight& l : in.lights)
  {
    lights.push_back(foldLight(l, in.material));
  }
  // One case per row of the model table (sceneValueProblem() has checked
  // the model).
  switch (in.model)
  {
#define SHADELAB_CASE(Enumerator, ...)                                                                                \
  case ShadingModel::Enumerator:                                                                                      \
    return shadeModel<static_cast<int>(ShadingModel::Enumerator)>(in, out, lights, begin, end);
    SHADELAB_LIGHTING_MODELS(SHADELAB_CASE)
#undef SHADELAB_CASE
  }
  return begin;
}

} // namespace shadelab
