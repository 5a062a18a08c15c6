#include "slRadianceKernel.h"

#include "shadelab/LightingGLSLBatch.h"
#include "slBatchIO.h"

#include <algorithm>

namespace shadelab
{

namespace
{
using simd::vec3x8;

/// The same struct in the batch compilation of slLighting.glsl: every lane
/// holds the light's values.
glsl8::slLight toBatch(const glsl::slLight& l)
{
  glsl8::slLight v;
  v.type = l.type;
  v.position = l.position;
  v.direction = l.direction;
  v.ambient = l.ambient;
  v.diffuse = l.diffuse;
  v.specular = l.specular;
  v.intensity = l.intensity;
  v.attenuation = l.attenuation;
  v.cosCutoff = l.cosCutoff;
  v.cosInner = l.cosInner;
  v.exponent = l.exponent;
  return v;
}

glsl8::slMaterial toBatch(const glsl::slMaterial& m)
{
  glsl8::slMaterial v;
  v.ambient = m.ambient;
  v.diffuse = m.diffuse;
  v.specular = m.specular;
  v.emission = m.emission;
  v.shininess = m.shininess;
  return v;
}

/// slShadeLightUnit() with the light's type fixed at compile time, so that
/// the compiler drops the other types' branches.
template <int MODEL, int TYPE>
__attribute__((always_inline)) inline glsl8::slTerms shadeLight(glsl8::slLight light, const glsl8::slMaterial& m,
  const vec3x8& P, const vec3x8& n, const vec3x8& v)
{
  light.type = TYPE;
  return glsl8::slShadeLightUnit(light, m, MODEL, P, n, v);
}

template <int MODEL>
__attribute__((always_inline)) inline glsl8::slTerms shadeAnyLight(const glsl8::slLight& light,
  const glsl8::slMaterial& m, const vec3x8& P, const vec3x8& n, const vec3x8& v)
{
  switch (light.type)
  {
    case glsl::SL_LIGHT_DIRECTIONAL:
      return shadeLight<MODEL, glsl::SL_LIGHT_DIRECTIONAL>(light, m, P, n, v);
    case glsl::SL_LIGHT_POINT:
      return shadeLight<MODEL, glsl::SL_LIGHT_POINT>(light, m, P, n, v);
    case glsl::SL_LIGHT_SPOT:
      return shadeLight<MODEL, glsl::SL_LIGHT_SPOT>(light, m, P, n, v);
    default:
      return shadeLight<MODEL, glsl::SL_LIGHT_AMBIENT>(light, m, P, n, v);
  }
}

/// Points [begin, end), 8 at a time: all lights for one batch of 8 points
/// before the next, so the sums stay in registers. flatten inlines every
/// lighting function, so that its batches live in registers, not memory.
template <int MODEL, bool PER_LIGHT>
__attribute__((flatten)) void shadeBatches(const RadianceKernelInput& in, const RadianceKernelOutput& out,
  const std::vector<glsl8::slLight>& lights, const glsl8::slMaterial& material, long long begin, long long end)
{
  const vec3x8 eye(in.eye);
  for (long long first = begin; first < end; first += 8)
  {
    const BatchRange batch{ first, static_cast<int>(std::min<long long>(8, end - first)) };
    glsl8::slMaterial m = material;
    if (in.baseColour)
    {
      const vec3x8 base = loadBatch(in.baseColour, batch);
      m.ambient = material.ambient * base;
      m.diffuse = material.diffuse * base;
    }
    // Normalised once per point, not once per light (slShadeLight does the same).
    const vec3x8 P = loadBatch(in.points, batch);
    const vec3x8 n = glsl8::slSafeNormalize(loadBatch(in.normals, batch));
    const vec3x8 v = glsl8::slSafeNormalize(eye - P);
    glsl8::slTerms sum = glsl8::slZeroTerms();
    for (size_t l = 0; l < lights.size(); ++l)
    {
      const glsl8::slTerms t = shadeAnyLight<MODEL>(lights[l], m, P, n, v);
      sum = glsl8::slAddTerms(sum, t);
      if (PER_LIGHT)
      {
        storeBatch(out.perLight[l], batch, glsl8::slTotal(t));
      }
    }
    sum = glsl8::slAddEmission(sum, m);
    storeBatch(out.ambient, batch, sum.ambient);
    storeBatch(out.diffuse, batch, sum.diffuse);
    storeBatch(out.specular, batch, sum.specular);
    storeBatch(out.emission, batch, sum.emission);
    storeBatch(out.radiance, batch, glsl8::slTotal(sum));
  }
}

template <int MODEL>
void shadeModel(const RadianceKernelInput& in, const RadianceKernelOutput& out,
  const std::vector<glsl8::slLight>& lights, const glsl8::slMaterial& material, long long begin, long long end)
{
  if (out.perLight.empty())
  {
    shadeBatches<MODEL, false>(in, out, lights, material, begin, end);
  }
  else
  {
    shadeBatches<MODEL, true>(in, out, lights, material, begin, end);
  }
}
} // namespace

void shadeRange(const RadianceKernelInput& in, const RadianceKernelOutput& out, long long begin, long long end)
{
  std::vector<glsl8::slLight> lights;
  for (const glsl::slLight& l : in.lights)
  {
    lights.push_back(toBatch(l));
  }
  const glsl8::slMaterial material = toBatch(in.material);
  switch (in.model)
  {
    case glsl::SL_MODEL_LAMBERT:
      return shadeModel<glsl::SL_MODEL_LAMBERT>(in, out, lights, material, begin, end);
    case glsl::SL_MODEL_PHONG:
      return shadeModel<glsl::SL_MODEL_PHONG>(in, out, lights, material, begin, end);
    case glsl::SL_MODEL_BLINN_PHONG:
      return shadeModel<glsl::SL_MODEL_BLINN_PHONG>(in, out, lights, material, begin, end);
    case glsl::SL_MODEL_LAMBERT_NORMALIZED:
      return shadeModel<glsl::SL_MODEL_LAMBERT_NORMALIZED>(in, out, lights, material, begin, end);
    case glsl::SL_MODEL_PHONG_NORMALIZED:
      return shadeModel<glsl::SL_MODEL_PHONG_NORMALIZED>(in, out, lights, material, begin, end);
    default:
      return shadeModel<glsl::SL_MODEL_BLINN_PHONG_NORMALIZED>(in, out, lights, material, begin, end);
  }
}

} // namespace shadelab
