// slFalseColor.glsl -- the false-colour ramps of component views (render
// pass) and field images (slFieldImageRenderer), written once.
//
// Compiled like slLighting.glsl (see its rules), after it: as C++ through GLM
// (shadelab/LightingGLSL.h, namespace shadelab::glsl) and as GLSL 1.50
// embedded in the render pass's fragment shader.

// A perceptually ordered ramp for s in 0..1 (clamped): dark blue through
// teal to yellow, piecewise linear through three viridis colours.
SL_FUNC vec3 slRamp(float s)
{
  float x = clamp(s, 0.0f, 1.0f);
  vec3 a = vec3(0.267f, 0.005f, 0.329f);
  vec3 b = vec3(0.128f, 0.567f, 0.551f);
  vec3 c = vec3(0.993f, 0.906f, 0.144f);
  return mix(mix(a, b, 2.0f * x), mix(b, c, 2.0f * x - 1.0f), bvec3(x >= 0.5f));
}

// A diverging ramp for s in -1..1 (clamped): blue at -1, white at 0, red at +1.
SL_FUNC vec3 slDiverging(float s)
{
  float x = clamp(s, -1.0f, 1.0f);
  vec3 blue = mix(vec3(1.0f), vec3(0.23f, 0.30f, 0.75f), -x);
  vec3 red = mix(vec3(1.0f), vec3(0.71f, 0.02f, 0.15f), x);
  return mix(blue, red, bvec3(x >= 0.0f));
}
