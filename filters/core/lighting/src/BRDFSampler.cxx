#include "shadelab/BRDFSampler.h"

#include <algorithm>

namespace shadelab
{

namespace
{
float mean3(const glm::vec3& v)
{
  return (v.x + v.y + v.z) / 3.0f;
}

bool isMicrofacet(SpecularLobe lobe)
{
  return lobe != SpecularLobe::None && lobe != SpecularLobe::Mirror && lobe != SpecularLobe::Halfway;
}
} // namespace

BRDFSampler::BRDFSampler(
  int model, const glsl::slMaterial& m, const glm::vec3& N, const glm::vec3& T, const glm::vec3& eye)
  : Local(N, glsl::slTangentX(N, T))
{
  const LightingModelInfo& info = modelInfo(static_cast<ShadingModel>(model));
  this->Lobe = info.lobe;
  this->V = this->Local.toLocal(eye);
  this->Mirror = glsl::slSafeNormalize(glm::vec3(-this->V.x, -this->V.y, this->V.z));
  this->Power = std::max(m.shininess, 0.0f);
  const bool anisotropic = (info.reads & kReadsRoughnessPair) != 0;
  this->AlphaX = std::max(anisotropic ? m.roughnessX : m.roughness, glsl::SL_MIN_ROUGHNESS);
  this->AlphaY = std::max(anisotropic ? m.roughnessY : m.roughness, glsl::SL_MIN_ROUGHNESS);

  const float kd = mean3(m.diffuse), ks = (info.reads & kReadsSpecular) ? mean3(m.specular) : 0.0f;
  this->DiffuseWeight = kd + ks > 0.0f ? kd / (kd + ks) : 1.0f;
  // No mirror direction (the eye in the tangent plane or at the point), or
  // a microfacet lobe seen from below: nothing to sample but k_d.
  const bool noMirror = glm::dot(this->Mirror, this->Mirror) == 0.0f;
  if (this->Lobe == SpecularLobe::None || noMirror || (isMicrofacet(this->Lobe) && !(this->V.z > 0.0f)))
  {
    this->DiffuseWeight = 1.0f;
  }
}

glm::vec3 BRDFSampler::sample(float choice, float u1, float u2) const
{
  if (choice < this->DiffuseWeight)
  {
    return this->Local.toWorld(sampleCosineHemisphere(u1, u2));
  }
  glm::vec3 H(0.0f, 0.0f, 1.0f);
  switch (this->Lobe)
  {
    case SpecularLobe::Mirror:
      return this->Local.toWorld(Frame(this->Mirror).toWorld(samplePhongLobe(u1, u2, this->Power)));
    case SpecularLobe::Halfway:
      H = samplePhongLobe(u1, u2, this->Power);
      break;
    case SpecularLobe::GGX:
      H = sampleGGXVisibleNormal(this->V, this->AlphaX, u1, u2);
      break;
    case SpecularLobe::Beckmann:
      H = sampleBeckmannNormal(this->AlphaX, u1, u2);
      break;
    case SpecularLobe::Ward:
      H = sampleWardNormal(this->AlphaX, this->AlphaY, u1, u2);
      break;
    case SpecularLobe::AshikhminShirley:
      H = sampleAshikhminShirleyNormal(glsl::slAshikhminShirleyExponent(this->AlphaX),
        glsl::slAshikhminShirleyExponent(this->AlphaY), u1, u2);
      break;
    case SpecularLobe::None:
      break;
  }
  return this->Local.toWorld(reflectAbout(this->V, H));
}

float BRDFSampler::halfwayPdf(const glm::vec3& H) const
{
  switch (this->Lobe)
  {
    case SpecularLobe::Halfway:
      return phongLobePdf(H.z, this->Power);
    case SpecularLobe::GGX:
      return ggxVisibleNormalPdf(this->V, H, this->AlphaX);
    case SpecularLobe::Beckmann:
      return beckmannNormalPdf(H, this->AlphaX);
    case SpecularLobe::Ward:
      return wardNormalPdf(H, this->AlphaX, this->AlphaY);
    case SpecularLobe::AshikhminShirley:
      return ashikhminShirleyNormalPdf(
        H, glsl::slAshikhminShirleyExponent(this->AlphaX), glsl::slAshikhminShirleyExponent(this->AlphaY));
    case SpecularLobe::None:
    case SpecularLobe::Mirror:
      break;
  }
  return 0.0f;
}

float BRDFSampler::pdf(const glm::vec3& L) const
{
  const glm::vec3 l = this->Local.toLocal(L);
  float specular = 0.0f;
  if (this->DiffuseWeight < 1.0f)
  {
    if (this->Lobe == SpecularLobe::Mirror)
    {
      specular = phongLobePdf(glm::dot(this->Mirror, l), this->Power);
    }
    else
    {
      // The facet normal that reflects V to l, taken above the surface (the
      // samplers draw no other): +-(l + V) / |l + V|.
      glm::vec3 H = glsl::slSafeNormalize(l + this->V);
      H = H.z < 0.0f ? -H : H;
      specular = reflectedPdf(this->halfwayPdf(H), this->V, H);
    }
  }
  return this->DiffuseWeight * cosineHemispherePdf(l.z) + (1.0f - this->DiffuseWeight) * specular;
}

} // namespace shadelab
