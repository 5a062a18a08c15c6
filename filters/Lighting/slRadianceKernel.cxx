#include "slRadianceKernel.h"

#include "shadelab/LightingGLSLVectorizable.h"

#include <algorithm>

namespace shadelab
{

namespace
{
constexpr int kBlock = 128;

/// The same struct in the vectorisable compilation of slLighting.glsl.
glslv::slLight toV(const glsl::slLight& l)
{
  glslv::slLight v;
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

glslv::slMaterial toV(const glsl::slMaterial& m)
{
  glslv::slMaterial v;
  v.ambient = m.ambient;
  v.diffuse = m.diffuse;
  v.specular = m.specular;
  v.emission = m.emission;
  v.shininess = m.shininess;
  return v;
}

/// Block buffers, structure of arrays [term or channel][point]: the sums of
/// the ambient, diffuse and specular terms, the current light's total, and
/// k_d. Keeping every branch out of the point loop lets it vectorise.
struct Block
{
  float terms[3][3][kBlock];
  float lightTotal[3][kBlock];
  float kd[3][kBlock];
  float position[3][kBlock];
  float normal[3][kBlock]; ///< unit (or zero)
  float view[3][kBlock];   ///< unit direction toward the eye (or zero)
};

glm::vec3 load(const float* a, long long i)
{
  return glm::vec3(a[3 * i], a[3 * i + 1], a[3 * i + 2]);
}

void store(float* a, long long i, const glm::vec3& v)
{
  a[3 * i] = v.x;
  a[3 * i + 1] = v.y;
  a[3 * i + 2] = v.z;
}

/// One light over one block, MODEL and TYPE known at compile time.
template <int MODEL, int TYPE>
__attribute__((always_inline)) inline void shadeLightBlock(const glslv::slLight& light0,
  const glslv::slMaterial& material, int count, Block& block)
{
  glslv::slLight light = light0;
  light.type = TYPE;
  for (int i = 0; i < count; ++i)
  {
    glslv::slMaterial m = material;
    m.diffuse = glm::vec3(block.kd[0][i], block.kd[1][i], block.kd[2][i]);
    const glm::vec3 P(block.position[0][i], block.position[1][i], block.position[2][i]);
    const glm::vec3 n(block.normal[0][i], block.normal[1][i], block.normal[2][i]);
    const glm::vec3 v(block.view[0][i], block.view[1][i], block.view[2][i]);
    const glslv::slTerms t = glslv::slShadeLightUnit(light, m, MODEL, P, n, v);
    const glm::vec3 terms[3] = { t.ambient, t.diffuse, t.specular };
    for (int k = 0; k < 3; ++k)
    {
      block.terms[k][0][i] += terms[k].x;
      block.terms[k][1][i] += terms[k].y;
      block.terms[k][2][i] += terms[k].z;
    }
    const glm::vec3 total = glslv::slTotal(t);
    block.lightTotal[0][i] = total.x;
    block.lightTotal[1][i] = total.y;
    block.lightTotal[2][i] = total.z;
  }
}

template <int MODEL>
__attribute__((always_inline)) inline void shadeBlock(const RadianceKernelInput& in, const RadianceKernelOutput& out,
  const std::vector<glslv::slLight>& lights, const glslv::slMaterial& material, long long first, int count)
{
  Block block;
  std::fill(&block.terms[0][0][0], &block.terms[0][0][0] + 9 * kBlock, 0.0f);
  for (int i = 0; i < count; ++i)
  {
    const glm::vec3 kd = in.diffuse ? load(in.diffuse, first + i) : material.diffuse;
    // Normalised once per point, not once per light (slShadeLight does the same).
    const glm::vec3 P = load(in.points, first + i);
    const glm::vec3 n = glslv::slSafeNormalize(load(in.normals, first + i));
    const glm::vec3 v = glslv::slSafeNormalize(in.eye - P);
    for (int c = 0; c < 3; ++c)
    {
      block.kd[c][i] = kd[c];
      block.position[c][i] = P[c];
      block.normal[c][i] = n[c];
      block.view[c][i] = v[c];
    }
  }
  for (size_t l = 0; l < lights.size(); ++l)
  {
    switch (lights[l].type)
    {
      case glsl::SL_LIGHT_DIRECTIONAL:
        shadeLightBlock<MODEL, glsl::SL_LIGHT_DIRECTIONAL>(lights[l], material, count, block);
        break;
      case glsl::SL_LIGHT_POINT:
        shadeLightBlock<MODEL, glsl::SL_LIGHT_POINT>(lights[l], material, count, block);
        break;
      case glsl::SL_LIGHT_SPOT:
        shadeLightBlock<MODEL, glsl::SL_LIGHT_SPOT>(lights[l], material, count, block);
        break;
      default:
        shadeLightBlock<MODEL, glsl::SL_LIGHT_AMBIENT>(lights[l], material, count, block);
        break;
    }
    if (!out.perLight.empty())
    {
      for (int i = 0; i < count; ++i)
      {
        store(out.perLight[l], first + i,
          glm::vec3(block.lightTotal[0][i], block.lightTotal[1][i], block.lightTotal[2][i]));
      }
    }
  }
  for (int i = 0; i < count; ++i)
  {
    glslv::slTerms sum;
    sum.ambient = glm::vec3(block.terms[0][0][i], block.terms[0][1][i], block.terms[0][2][i]);
    sum.diffuse = glm::vec3(block.terms[1][0][i], block.terms[1][1][i], block.terms[1][2][i]);
    sum.specular = glm::vec3(block.terms[2][0][i], block.terms[2][1][i], block.terms[2][2][i]);
    sum.emission = glm::vec3(0.0f);
    sum = glslv::slAddEmission(sum, material);
    const long long p = first + i;
    store(out.ambient, p, sum.ambient);
    store(out.diffuse, p, sum.diffuse);
    store(out.specular, p, sum.specular);
    store(out.emission, p, sum.emission);
    store(out.radiance, p, glslv::slTotal(sum));
  }
}

/// The whole range; compiled for AVX2+FMA and for the baseline, picked at run
/// time; flatten inlines the lighting functions so the point loops vectorise.
__attribute__((flatten)) void shadeRangeImpl(
  const RadianceKernelInput& in, const RadianceKernelOutput& out, long long begin, long long end)
{
  std::vector<glslv::slLight> lights;
  for (const glsl::slLight& l : in.lights)
  {
    lights.push_back(toV(l));
  }
  const glslv::slMaterial material = toV(in.material);
  for (long long first = begin; first < end; first += kBlock)
  {
    const int count = static_cast<int>(std::min<long long>(kBlock, end - first));
    switch (in.model)
    {
      case glsl::SL_MODEL_LAMBERT:
        shadeBlock<glsl::SL_MODEL_LAMBERT>(in, out, lights, material, first, count);
        break;
      case glsl::SL_MODEL_PHONG:
        shadeBlock<glsl::SL_MODEL_PHONG>(in, out, lights, material, first, count);
        break;
      case glsl::SL_MODEL_BLINN_PHONG:
        shadeBlock<glsl::SL_MODEL_BLINN_PHONG>(in, out, lights, material, first, count);
        break;
      case glsl::SL_MODEL_LAMBERT_NORMALIZED:
        shadeBlock<glsl::SL_MODEL_LAMBERT_NORMALIZED>(in, out, lights, material, first, count);
        break;
      case glsl::SL_MODEL_PHONG_NORMALIZED:
        shadeBlock<glsl::SL_MODEL_PHONG_NORMALIZED>(in, out, lights, material, first, count);
        break;
      default:
        shadeBlock<glsl::SL_MODEL_BLINN_PHONG_NORMALIZED>(in, out, lights, material, first, count);
        break;
    }
  }
}
} // namespace

void shadeRange(const RadianceKernelInput& in, const RadianceKernelOutput& out, long long begin, long long end)
{
  shadeRangeImpl(in, out, begin, end);
}

} // namespace shadelab
