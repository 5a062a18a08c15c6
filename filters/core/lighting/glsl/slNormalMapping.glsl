// slNormalMapping.glsl -- how a normal map's texel becomes a surface normal,
// written once for the CPU normal-map filter and the render pass.
//
// Compiled like slLighting.glsl (see its rules), after it: as C++ through GLM
// in float (shadelab/LightingGLSL.h, namespace shadelab::glsl) and in double
// (shadelab/LightingGLSLDouble.h, namespace shadelab::glsld), and as GLSL 1.50
// embedded in the render pass's fragment shader. Vectors are scaled by
// vectors, not by float literals, so that the double compilation has one type
// per operation.

// The tangent-space normal an RGB texel encodes: rgb in 0..1 becomes xyz in
// -1..1 (OpenGL convention, green up; greenSign -1 flips green for DirectX
// maps), x and y are scaled by strength, and the result is made unit length.
// (0, 0, 1), the unperturbed normal, where that has no direction.
SL_FUNC vec3 slDecodeNormal(vec3 rgb, float greenSign, float strength)
{
  vec3 n = rgb * vec3(2.0f) - vec3(1.0f);
  vec3 unit = slSafeNormalize(n * vec3(strength, greenSign * strength, 1.0f));
  return mix(vec3(0.0f, 0.0f, 1.0f), unit, bvec3(dot(unit, unit) > 0.5f));
}

// The tangent-space vector ts in the frame of the surface normal N and the
// tangent T with handedness w (MikkTSpace): T is first made orthogonal to N
// (interpolated tangents and normals drift apart), the bitangent is
// sign(w) (N x T). Unit length; N itself where the result has no direction.
SL_FUNC vec3 slTangentToSurface(vec3 ts, vec3 N, vec3 T, float w)
{
  vec3 n = slSafeNormalize(N);
  vec3 t = slSafeNormalize(T - n * dot(T, n));
  float handedness = mix(1.0f, -1.0f, w < 0.0f);
  vec3 b = cross(n, t) * handedness;
  vec3 r = slSafeNormalize(t * ts.x + b * ts.y + n * ts.z);
  return mix(n, r, bvec3(dot(r, r) > 0.5f));
}
