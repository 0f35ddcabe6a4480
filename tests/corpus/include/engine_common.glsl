// engine_common.glsl: the shared header of the corpus's "engine" shaders (included with -I).
// Helpers an engine keeps in one place: relative-to-eye positions, (hi, lo) packing of a double
// for float outputs, and a few named constants (macros, as engines write them).
#ifndef ENGINE_COMMON_GLSL
#define ENGINE_COMMON_GLSL

#define ENGINE_MAX_ITERATIONS 32
#define ENGINE_EARTH_GM 3.986004418e14lf

// Position relative to the eye: the large, nearly equal double coordinates cancel exactly here.
dvec3 rte(dvec3 position, dvec3 eye) { return position - eye; }

// A double as the (hi, lo) float pair a float interface can carry (verify joins them: "hi_lo").
vec2 hi_lo(double x) {
  float hi = float(x);
  return vec2(hi, float(x - double(hi)));
}

#endif
