// slLighting.glsl -- the ShadeLab lighting equation, written exactly once.
//
// This file is the single source of truth for every lighting formula in
// ShadeLab. It is compiled three ways and must stay valid for all of them:
//   * as C++17 through GLM, by shadelab/LightingGLSL.h (CPU filters, tests);
//   * as C++17 with 8-lane SIMD batches standing in for float and vec3, by
//     shadelab/LightingGLSLBatch.h (the CPU radiance filter's fast loop);
//   * as GLSL 1.50 (the desktop profile VTK 9.1 uses), embedded verbatim into
//     the render pass shaders through shadelab/LightingShaderSource.h.
//
// The subset both languages accept, and therefore the rules for editing here:
//   * float literals carry an f suffix (1.0f): GLSL >= 1.30 accepts it and it
//     keeps GLM overloads unambiguous in C++;
//   * every function is prefixed SL_FUNC (inline in C++, empty in GLSL);
//   * structs are filled member by member (no GLSL constructors, no C++
//     brace initialisers), parameters are passed by value, no out/inout;
//   * only built-ins that GLM also provides: dot, normalize, length, sqrt,
//     inversesqrt, max, min, clamp, pow, exp2, smoothstep, and mix(a, b, c)
//     with a bool (or bvec3) c, which is GLSL's per-component select: c ? b : a;
//   * a choice that depends on a float value (a length, a cosine, ...) is made
//     with that select, never with if or ?: -- in the SIMD compilation each
//     lane makes its own choice, and a branch cannot. Branches on int
//     parameters (model, light type) and on struct constants are fine; a
//     float condition is written where it is used (no bool variables: the
//     SIMD compilation's conditions are lane masks);
//   * integer constants are `const int`, never preprocessor macros.
//
// Conventions: all vectors are in one space (world space on the CPU, view
// space in the shaders). N is the surface normal, L points from the surface
// toward the light, V from the surface toward the eye. Colours are linear RGB.

// The SL_LIGHT_* and SL_MODEL_* constants, slIsNormalizedModel() and the
// structs slLight (one light, ready for evaluation: angles already turned
// into cosines) and slMaterial (k_a, k_d, k_s, k_e and the shininess n) come
// from slLightingTables.glsl, which the build generates from
// shadelab/LightingTables.h and every compilation puts before this file.

const float SL_PI = 3.14159265358979f;
// Below this length a vector has no direction; see slSafeNormalize. The
// squares of longer lengths are normal floats (FLT_MIN is 1.2e-38), so every
// compilation -- libm, the SIMD estimate (which takes a subnormal for 0),
// GPUs that flush subnormals -- agrees on which vectors have one.
const float SL_TINY_LENGTH = 1e-18f;

// The four terms of the lighting equation; the total is their sum.
struct slTerms
{
  vec3 ambient;
  vec3 diffuse;
  vec3 specular;
  vec3 emission;
};

// v times inverseLength = inversesqrt(dot(v, v)): the unit vector along v, or
// the zero vector where v is too short, too long or not finite to have a
// direction. Taking the inverse length from the caller lets slIncidenceAt
// reuse it for the distance; multiplying by it is cheaper than dividing by a
// length (one square root estimate, no divisions in the SIMD compilation).
// One test covers all three cases: len is NaN, which fails every comparison,
// when dot(v, v) is 0 (0 * inf), infinite (inf * 0) or NaN.
SL_FUNC vec3 slScaleToUnit(vec3 v, float inverseLength)
{
  float len = dot(v, v) * inverseLength;
  return mix(vec3(0.0f), v * inverseLength, bvec3(len > SL_TINY_LENGTH));
}

// normalize() that returns the zero vector instead of NaN for zero-length or
// non-finite input, so degenerate geometry shades as "no direction".
SL_FUNC vec3 slSafeNormalize(vec3 v)
{
  return slScaleToUnit(v, inversesqrt(dot(v, v)));
}

// x^e for x clamped to >= 0, defined everywhere: GLSL leaves pow(0, e)
// undefined for e <= 0, so 0^0 is taken as 1 (the limit from inside the lobe).
SL_FUNC float slPow(float x, float e)
{
  return mix(mix(1.0f, 0.0f, e > 0.0f), pow(x, e), x > 0.0f);
}

// Distance attenuation f_att = min(1, 1 / (c1 + c2 d + c3 d^2)). A sum that is
// not positive (all constants zero) means "no attenuation".
SL_FUNC float slAttenuation(vec3 c, float d)
{
  float denominator = c.x + c.y * d + c.z * d * d;
  return 1.0f / max(1.0f, denominator);
}

// Spot cone factor for a unit vector L toward the light: 0 outside the cutoff,
// cos^exponent inside, times a smoothstep across the edge band when
// cosInner > cosCutoff. Non-spot lights return 1.
SL_FUNC float slSpotFactor(slLight light, vec3 L)
{
  if (light.type != SL_LIGHT_SPOT)
  {
    return 1.0f;
  }
  float cosAngle = dot(-L, light.direction);
  float edge = mix(1.0f, smoothstep(light.cosCutoff, light.cosInner, cosAngle), light.cosInner > light.cosCutoff);
  return mix(edge * slPow(cosAngle, light.exponent), 0.0f, cosAngle < light.cosCutoff);
}

// What arrives at P from one light: the unit vector L toward it (zero for
// ambient lights and for a light sitting exactly at P) and its reach, the
// attenuation times the spot factor. The distance is computed once.
struct slIncidence
{
  vec3 L;
  float reach;
};

SL_FUNC slIncidence slIncidenceAt(slLight light, vec3 P)
{
  slIncidence inc;
  inc.reach = 1.0f;
  if (light.type == SL_LIGHT_DIRECTIONAL)
  {
    inc.L = slSafeNormalize(-light.direction);
    return inc;
  }
  if (light.type == SL_LIGHT_AMBIENT)
  {
    inc.L = vec3(0.0f);
    return inc;
  }
  vec3 toLight = light.position - P;
  float inverseD = inversesqrt(dot(toLight, toLight));
  float d = dot(toLight, toLight) * inverseD;
  inc.L = slScaleToUnit(toLight, inverseD);
  inc.reach = slAttenuation(light.attenuation, d) * slSpotFactor(light, inc.L);
  return inc;
}

// Unit vector from the surface point P toward the light.
SL_FUNC vec3 slDirectionToLight(slLight light, vec3 P)
{
  return slIncidenceAt(light, P).L;
}

// Attenuation times spot factor for the unit vector L toward the light: how
// much of the light reaches P (1 for directional and ambient lights).
SL_FUNC float slLightReach(slLight light, vec3 P, vec3 L)
{
  if (light.type == SL_LIGHT_DIRECTIONAL || light.type == SL_LIGHT_AMBIENT)
  {
    return 1.0f;
  }
  return slAttenuation(light.attenuation, length(light.position - P)) * slSpotFactor(light, L);
}

// Exact Blinn-Phong normalisation (Giesen 2009): makes the directional albedo
// of the cosine-weighted lobe exactly 1 at normal incidence, which is its
// maximum over all incidence angles. The popular (n+8)/(8 pi) approximation
// exceeds 1 by up to 7.5%, so it is not used.
SL_FUNC float slBlinnPhongNormalization(float n)
{
  return (n + 2.0f) * (n + 4.0f) / (8.0f * SL_PI * (exp2(-0.5f * n) + n));
}

// Below this cosine an incident direction counts as grazing: slBRDF returns 0
// there rather than dividing by (almost) zero.
const float SL_MIN_COS_THETA = 1.0e-6f;

// The microfacet models' roughness alpha is at least this: at alpha -> 0 their
// lobes become a mirror's delta, which no sampled or rasterised evaluation
// can show, and float exponents overflow.
const float SL_MIN_ROUGHNESS = 0.01f;

// e^x, through exp2 (the built-in every compilation shares).
SL_FUNC float slExp(float x)
{
  return exp2(1.44269504088896f * x);
}

// Schlick's Fresnel F0 of a dielectric with index of refraction ior (from
// air): ((ior - 1) / (ior + 1))^2, 0.04 at ior 1.5.
SL_FUNC float slFresnelF0(float ior)
{
  float r = (ior - 1.0f) / (ior + 1.0f);
  return r * r;
}

// Schlick's approximation of the Fresnel reflectance at cosine c between the
// incident direction and the facet normal: F0 + (1 - F0) (1 - c)^5.
SL_FUNC float slSchlickFresnel(float f0, float c)
{
  float m = clamp(1.0f - c, 0.0f, 1.0f);
  float m2 = m * m;
  return f0 + (1.0f - f0) * m2 * m2 * m;
}

// The unit tangent X of the surface at unit normal n: t with its component
// along n removed. Where t gives no direction (no tangent, or one along n) a
// fixed frame around n takes its place (Duff et al. 2017, "Building an
// orthonormal basis, revisited"), so every compilation agrees on a result.
SL_FUNC vec3 slTangentX(vec3 n, vec3 t)
{
  vec3 projected = slSafeNormalize(t - dot(n, t) * n);
  float s = mix(-1.0f, 1.0f, n.z >= 0.0f);
  float a = -1.0f / (s + n.z);
  float b = n.x * n.y * a;
  vec3 fallback = vec3(1.0f + s * n.x * n.x * a, s * b, -s * n.x);
  return mix(fallback, projected, bvec3(dot(projected, projected) > 0.5f));
}

// Y = n x X for unit, orthogonal n and X: the bitangent of the frame.
SL_FUNC vec3 slBitangentY(vec3 n, vec3 X)
{
  return vec3(n.y * X.z - n.z * X.y, n.z * X.x - n.x * X.z, n.x * X.y - n.y * X.x);
}

// The GGX (Trowbridge-Reitz) distribution of facet normals at cosine cosH
// between the half vector and the normal, width alpha:
// alpha^2 / (pi ((alpha^2 - 1) cosH^2 + 1)^2), 0 below the surface. Its
// projected area integrates to 1: the integral of D cosH dw_h is 1.
SL_FUNC float slGGXDistribution(float cosH, float alpha)
{
  float a2 = alpha * alpha;
  float d = cosH * cosH * (a2 - 1.0f) + 1.0f;
  return mix(0.0f, a2 / (SL_PI * d * d), cosH > 0.0f);
}

// Smith's height-correlated masking-shadowing for GGX over 4 cos_i cos_o
// (Heitz 2014, "Understanding the masking-shadowing function", eq. 99):
// G2 / (4 ci co) = 0.5 / (co sqrt(a^2 + (1 - a^2) ci^2) + ci sqrt(a^2 + (1 - a^2) co^2)),
// for ci, co > 0.
SL_FUNC float slGGXVisibility(float ci, float co, float alpha)
{
  float a2 = alpha * alpha;
  float towardLight = co * sqrt(a2 + (1.0f - a2) * ci * ci);
  float towardEye = ci * sqrt(a2 + (1.0f - a2) * co * co);
  return 0.5f / (towardLight + towardEye);
}

// The Beckmann distribution of facet normals: exp(-tan^2 / alpha^2) /
// (pi alpha^2 cos^4), 0 below the surface; its projected area integrates to 1.
SL_FUNC float slBeckmannDistribution(float cosH, float alpha)
{
  float c2 = max(cosH * cosH, SL_MIN_COS_THETA);
  float a2 = alpha * alpha;
  return mix(0.0f, slExp((c2 - 1.0f) / (c2 * a2)) / (SL_PI * a2 * c2 * c2), cosH > 0.0f);
}

// Smith's Lambda for the Beckmann distribution seen at cosine c from the
// normal, in Walter et al.'s rational form (2007, eq. 27; G1 = 1 / (1 + Lambda)
// is within 0.35 % of G1 from the exact Lambda = (erf(a) - 1) / 2 +
// exp(-a^2) / (2 a sqrt(pi)), a = c / (alpha sin)): GLSL has no erf.
SL_FUNC float slBeckmannLambda(float c, float alpha)
{
  float a = c * inversesqrt(max(1.0f - c * c, 1e-12f)) / alpha;
  float lambda = (1.0f - 1.259f * a + 0.396f * a * a) / (3.535f * a + 2.181f * a * a);
  return mix(lambda, 0.0f, a >= 1.6f);
}

// Oren-Nayar's qualitative model (1994) times cos theta_i / pi, for unit N, L,
// V and sigma = roughness: (A + B max(0, cos(phi_i - phi_o)) sin(a) tan(b)),
// a = max(theta_i, theta_o), b = min. With s = L.V - ci co = sin_i sin_o
// cos(phi_i - phi_o) the product is max(0, s) / max(ci, co) (sin a sin b =
// sin_i sin_o), which needs no angles. sigma = 0 gives A = 1, B = 0: Lambert.
SL_FUNC float slOrenNayarFactor(vec3 N, vec3 L, vec3 V, float sigma)
{
  float ci = dot(N, L);
  float co = dot(N, V);
  float s2 = sigma * sigma;
  float A = 1.0f - 0.5f * s2 / (s2 + 0.33f);
  float B = 0.45f * s2 / (s2 + 0.09f);
  float s = max(dot(L, V) - ci * co, 0.0f);
  return A + B * s / max(max(ci, co), SL_MIN_COS_THETA);
}

// Ashikhmin and Shirley's (2000) diffuse term over k_d, for a specular layer
// of normal-incidence reflectance f0 on top: (28 / (23 pi)) (1 - f0)
// (1 - (1 - ci/2)^5) (1 - (1 - co/2)^5).
SL_FUNC float slAshikhminShirleyDiffuse(float ci, float co, float f0)
{
  float a = 1.0f - 0.5f * max(ci, 0.0f);
  float b = 1.0f - 0.5f * max(co, 0.0f);
  float a5 = a * a * a * a * a;
  float b5 = b * b * b * b * b;
  return 28.0f / (23.0f * SL_PI) * (1.0f - f0) * (1.0f - a5) * (1.0f - b5);
}

// Ashikhmin and Shirley's exponent for roughness alpha: the Phong exponent n
// whose lobe matches a Beckmann lobe of width alpha, n = 2 / alpha^2 - 2
// (Walter et al. 2007), so the anisotropic models share one roughness pair.
SL_FUNC float slAshikhminShirleyExponent(float alpha)
{
  return max(2.0f / (alpha * alpha) - 2.0f, 0.0f);
}

// The diffuse reflection factor (f_r's k_d part times cos theta_i) for unit N,
// L and V: max(0, N.L) for the lecture Lambert term, (1/pi) max(0, N.L) for
// the energy-normalised rho/pi, times Oren-Nayar's roughness factor, or
// Ashikhmin-Shirley's coupled diffuse term. Multiply by light colour and k_d.
SL_FUNC float slDiffuseFactor(int model, slMaterial m, vec3 N, vec3 L, vec3 V)
{
  float cosTheta = max(dot(N, L), 0.0f);
  float factor = slIsNormalizedModel(model) ? cosTheta / SL_PI : cosTheta;
  if (model == SL_MODEL_OREN_NAYAR)
  {
    factor = factor * slOrenNayarFactor(N, L, V, m.roughness);
  }
  if (model == SL_MODEL_ASHIKHMIN_SHIRLEY)
  {
    factor = cosTheta * slAshikhminShirleyDiffuse(cosTheta, dot(N, V), slFresnelF0(m.ior));
  }
  return factor;
}

// The specular reflection factor (f_r's k_s part times cos theta_i) for unit
// N, L, V, the surface's tangent T (any length; only the anisotropic models
// read it, see slTangentX) and the material; multiply by light colour and k_s.
// Zero where N.L <= 0 (the light is behind the surface), for the microfacet
// models also where N.V <= 0, and for the diffuse-only models.
//   Phong:        max(0, R.V)^n,                R = 2 (N.L) N - L
//   Blinn-Phong:  max(0, N.H)^n,                H = (L + V) / |L + V|
//   normalised:   f_r cos theta_i with f_r = (n+2)/(2 pi) max(0,R.V)^n (Phong)
//                 or slBlinnPhongNormalization(n) max(0,N.H)^n (Blinn-Phong).
//   Cook-Torrance: f_r = D(H) G2(L, V) F(V.H) / (4 ci co), D GGX or Beckmann,
//                 G2 Smith's height-correlated, F Schlick's with F0 from ior.
//   Ward:         f_r = exp(-((H.X/ax)^2 + (H.Y/ay)^2) / (H.N)^2) / (4 pi ax ay sqrt(ci co))
//   Ashikhmin-Shirley: f_r = sqrt((nu+1)(nv+1)) / (8 pi) (N.H)^((nu (H.X)^2 + nv (H.Y)^2) / (1 - (N.H)^2))
//                 F(L.H) / ((L.H) max(ci, co)), nu, nv from the roughness pair.
SL_FUNC float slSpecularFactor(int model, slMaterial m, vec3 N, vec3 T, vec3 L, vec3 V)
{
  float cosTheta = dot(N, L);
  float cosView = dot(N, V);
  float n = m.shininess;
  // Each model with a specular lobe sets its factor below; the diffuse-only
  // models have none.
  float factor = 0.0f;
  if (model == SL_MODEL_PHONG || model == SL_MODEL_PHONG_NORMALIZED)
  {
    vec3 R = 2.0f * cosTheta * N - L;
    factor = slPow(max(dot(R, V), 0.0f), n);
    if (model == SL_MODEL_PHONG_NORMALIZED)
    {
      factor = factor * (n + 2.0f) / (2.0f * SL_PI) * cosTheta;
    }
  }
  // The half vector H = (L + V) / |L + V| as the models below need it; where
  // L + V has no direction (L = -V) there is none, and they give 0.
  vec3 halfway = L + V;
  float squaredLength = dot(halfway, halfway);
  float inverseLength = inversesqrt(squaredLength);
  float halfwayLength = squaredLength * inverseLength;
  if (model == SL_MODEL_BLINN_PHONG || model == SL_MODEL_BLINN_PHONG_NORMALIZED)
  {
    // N.H as (N.L + N.V) / |L + V| (N.V is the same for every light).
    float cosHalf = mix(0.0f, (cosTheta + cosView) * inverseLength, halfwayLength > SL_TINY_LENGTH);
    // Clamped above too: where L is nearly -V (the eye looks at the light
    // through the surface) |L + V| is tiny and the quotient is rounding
    // noise that can exceed 1 by any amount, and x^n would overflow.
    factor = slPow(clamp(cosHalf, 0.0f, 1.0f), n);
    if (model == SL_MODEL_BLINN_PHONG_NORMALIZED)
    {
      factor = factor * slBlinnPhongNormalization(n) * cosTheta;
    }
  }
  vec3 H = halfway * inverseLength;
  float cosHalf = clamp(dot(N, H), 0.0f, 1.0f);
  float f0 = slFresnelF0(m.ior);
  // The microfacet models below exist only where both directions are above
  // the surface (and L + V has a direction).
  if (model == SL_MODEL_COOK_TORRANCE_GGX)
  {
    float alpha = max(m.roughness, SL_MIN_ROUGHNESS);
    factor = slGGXDistribution(cosHalf, alpha) * slGGXVisibility(cosTheta, cosView, alpha) *
      slSchlickFresnel(f0, dot(V, H)) * cosTheta;
    factor = mix(0.0f, factor, halfwayLength > SL_TINY_LENGTH && cosView > 0.0f);
  }
  if (model == SL_MODEL_COOK_TORRANCE_BECKMANN)
  {
    float alpha = max(m.roughness, SL_MIN_ROUGHNESS);
    float G2 = 1.0f / (1.0f + slBeckmannLambda(cosTheta, alpha) + slBeckmannLambda(cosView, alpha));
    factor = slBeckmannDistribution(cosHalf, alpha) * G2 * slSchlickFresnel(f0, dot(V, H)) / (4.0f * cosView);
    factor = mix(0.0f, factor, halfwayLength > SL_TINY_LENGTH && cosView > 0.0f);
  }
  if (model == SL_MODEL_WARD || model == SL_MODEL_ASHIKHMIN_SHIRLEY)
  {
    vec3 X = slTangentX(N, T);
    vec3 Y = slBitangentY(N, X);
    float hx = dot(H, X);
    float hy = dot(H, Y);
    float ax = max(m.roughnessX, SL_MIN_ROUGHNESS);
    float ay = max(m.roughnessY, SL_MIN_ROUGHNESS);
    if (model == SL_MODEL_WARD)
    {
      float e = -((hx * hx) / (ax * ax) + (hy * hy) / (ay * ay)) / max(cosHalf * cosHalf, SL_MIN_COS_THETA);
      factor = slExp(e) * sqrt(max(cosTheta, 0.0f) / max(cosView, SL_MIN_COS_THETA)) / (4.0f * SL_PI * ax * ay);
    }
    if (model == SL_MODEL_ASHIKHMIN_SHIRLEY)
    {
      float nu = slAshikhminShirleyExponent(ax);
      float nv = slAshikhminShirleyExponent(ay);
      // (nu hx^2 + nv hy^2) / (1 - (N.H)^2), with 1 - (N.H)^2 = hx^2 + hy^2;
      // at H = N the power is of 1 and the exponent does not matter.
      float across = hx * hx + hy * hy;
      float exponent = mix(0.5f * (nu + nv), (nu * hx * hx + nv * hy * hy) / across, across > SL_MIN_COS_THETA);
      float LdotH = max(dot(L, H), SL_MIN_COS_THETA);
      factor = sqrt((nu + 1.0f) * (nv + 1.0f)) / (8.0f * SL_PI) * slPow(cosHalf, exponent) *
        slSchlickFresnel(f0, LdotH) / (LdotH * max(max(cosTheta, cosView), SL_MIN_COS_THETA)) * cosTheta;
    }
    factor = mix(0.0f, factor, halfwayLength > SL_TINY_LENGTH && cosView > 0.0f);
  }
  return mix(0.0f, factor, cosTheta > 0.0f);
}

SL_FUNC slTerms slZeroTerms()
{
  slTerms t;
  t.ambient = vec3(0.0f);
  t.diffuse = vec3(0.0f);
  t.specular = vec3(0.0f);
  t.emission = vec3(0.0f);
  return t;
}

// How strongly one light shows at surface point P with unit normal n and
// unit direction v toward the eye (either may be zero: no direction): the
// scalars that multiply its ambient, diffuse and specular colour products
// (light colour times k_a, k_d, k_s). They are its intensity times its reach
// (attenuation and spot factor), times 1, the diffuse factor and the
// specular factor.
struct slLightWeights
{
  float ambient;
  float diffuse;
  float specular;
};

SL_FUNC slLightWeights slLightWeightsAt(slLight light, slMaterial m, int model, vec3 P, vec3 n, vec3 t, vec3 v)
{
  slLightWeights w;
  if (light.type == SL_LIGHT_AMBIENT)
  {
    w.ambient = light.intensity;
    w.diffuse = 0.0f;
    w.specular = 0.0f;
    return w;
  }
  slIncidence inc = slIncidenceAt(light, P);
  float reach = light.intensity * inc.reach;
  w.ambient = reach;
  w.diffuse = reach * slDiffuseFactor(model, m, n, inc.L, v);
  w.specular = reach * slSpecularFactor(model, m, n, t, inc.L, v);
  return w;
}

// A light's terms from its weights: each weight times light colour times
// material coefficient; emission stays zero (it belongs to the material, see
// slAddEmission).
SL_FUNC slTerms slWeightedTerms(slLightWeights w, slLight light, slMaterial m)
{
  slTerms t;
  t.ambient = w.ambient * (light.ambient * m.ambient);
  t.diffuse = w.diffuse * (light.diffuse * m.diffuse);
  t.specular = w.specular * (light.specular * m.specular);
  t.emission = vec3(0.0f);
  return t;
}

// The lighting equation is linear in each light's intensity and colours and
// in the material's k_a, k_d and k_s, so their products can be formed once
// per light rather than once per point and light: slFoldLight multiplies the
// intensity and k_a, k_d, k_s into the light's colours (intensity 1), and
// slUnitMaterial is the material left to shade with (k_a = k_d = k_s = 1,
// emission and shininess kept). slShadeLightUnit(slFoldLight(l, m),
// slUnitMaterial(m), ...) is slShadeLightUnit(l, m, ...). The CPU radiance
// kernel and the render pass both shade this way.
SL_FUNC slLight slFoldLight(slLight light, slMaterial m)
{
  slLight folded = light;
  folded.ambient = light.intensity * (light.ambient * m.ambient);
  folded.diffuse = light.intensity * (light.diffuse * m.diffuse);
  folded.specular = light.intensity * (light.specular * m.specular);
  folded.intensity = 1.0f;
  return folded;
}

SL_FUNC slMaterial slUnitMaterial(slMaterial m)
{
  slMaterial unit = m;
  unit.ambient = vec3(1.0f);
  unit.diffuse = vec3(1.0f);
  unit.specular = vec3(1.0f);
  return unit;
}

// A base colour (vertex colours, a diffuse texture) multiplies k_a and k_d,
// so it multiplies the ambient and diffuse terms, once per point after the
// lights are summed.
SL_FUNC slTerms slWithBaseColour(slTerms t, vec3 base)
{
  slTerms coloured = t;
  coloured.ambient = t.ambient * base;
  coloured.diffuse = t.diffuse * base;
  return coloured;
}

// What one light contributes at surface point P with unit normal n, tangent
// t (any length, read by the anisotropic models only: slTangentX) and unit
// direction v toward the eye: ambient, diffuse and specular. Shaders
// normalise n and v once for all lights.
SL_FUNC slTerms slShadeLightUnit(slLight light, slMaterial m, int model, vec3 P, vec3 n, vec3 t, vec3 v)
{
  return slWeightedTerms(slLightWeightsAt(light, m, model, P, n, t, v), light, m);
}

// slShadeLightUnit for any normal N (need not be unit length), tangent T and
// the eye at E.
SL_FUNC slTerms slShadeLight(slLight light, slMaterial m, int model, vec3 P, vec3 N, vec3 T, vec3 E)
{
  return slShadeLightUnit(light, m, model, P, slSafeNormalize(N), T, slSafeNormalize(E - P));
}

SL_FUNC slTerms slAddTerms(slTerms a, slTerms b)
{
  slTerms t;
  t.ambient = a.ambient + b.ambient;
  t.diffuse = a.diffuse + b.diffuse;
  t.specular = a.specular + b.specular;
  t.emission = a.emission + b.emission;
  return t;
}

// Emission is added once per point and lights nothing else.
SL_FUNC slTerms slAddEmission(slTerms t, slMaterial m)
{
  t.emission = t.emission + m.emission;
  return t;
}

SL_FUNC vec3 slTotal(slTerms t)
{
  return t.ambient + t.diffuse + t.specular + t.emission;
}

// ---------------------------------------------------------------------------
// Derived quantities for the CPU lighting filters. Each is built on
// the functions above, never a second copy of their formulas.

// Relative luminance of a linear RGB colour (Rec. 709 primaries): what false-
// colour views and field images show of an RGB term, and what environment-map
// importance sampling follows.
SL_FUNC float slLuminance(vec3 c)
{
  return dot(c, vec3(0.2126f, 0.7152f, 0.0722f));
}

// The raw cosine N.L between the unit normal and the unit direction toward the
// light, unclamped: negative where the surface faces away from the light (it
// shadows itself). 0 for ambient lights, zero-length normals and a light at P.
SL_FUNC float slCosTheta(slLight light, vec3 P, vec3 N)
{
  return dot(slSafeNormalize(N), slDirectionToLight(light, P));
}

// The BRDF value f_r(L, V) for unit N, L (toward the light) and V (toward the
// eye), and the tangent T (anisotropic models): the reflection factors above
// are f_r cos(theta_i), so f_r is their k_d / k_s weighted sum divided by
// N.L. For the lecture models this is the "BRDF" they imply when read
// literally (k_d + k_s S / cos(theta_i)). Zero where N.L <= SL_MIN_COS_THETA
// (light behind or grazing) and for zero vectors.
SL_FUNC vec3 slBRDF(int model, slMaterial m, vec3 N, vec3 T, vec3 L, vec3 V)
{
  float cosTheta = dot(N, L);
  vec3 reflected = slDiffuseFactor(model, m, N, L, V) * m.diffuse + slSpecularFactor(model, m, N, T, L, V) * m.specular;
  return mix(vec3(0.0f), reflected / cosTheta, bvec3(cosTheta > SL_MIN_COS_THETA));
}
