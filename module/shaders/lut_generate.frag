// Pre-integrated skin LUTs on the GPU, one texel per fragment: the same quadrature as the CPU
// generator (module/src/math/preintegrated_lut.cpp): Gauss–Legendre panels between distances that
// double from 0.01 mm, each split at the kinks of the light function inside it. The profile is a sum
// of up to 8 Gaussians (variance in mm², weights r, g, b), 2D-normalised.
// SSS_LUT_KIND: 0 = diffuse (eq. 1.1, columns N·L, rows curvature 1/mm), 1 = shadow (§1.6, columns
// the shadow value, rows the penumbra width in world units). Grids are endpoint-inclusive.
// Compile-time switches (the variant's #defines, module/src/gl/shader_variants.cpp): SSS_LUT_KIND;
// SSS_MAX_TERMS, the most Gaussians of a profile (u_terms), and SSS_GL_ORDER, the points of the
// Gauss–Legendre rule (u_gl, sss::math::kLutQuadratureOrder: the rule comes from the CPU generator).

#define SSS_PI 3.14159265358979323846

// The numbers (u_size, u_row_range, u_term_count, u_support and the shadow LUT's
// u_world_units_per_mm, u_new_penumbra, u_gaussian_filter) are the LUT generator's uniform struct
// (gl/pass_uniforms.hpp kLutUniforms), declared in the defines; the tables are the shader's own.
uniform vec4 u_terms[SSS_MAX_TERMS];     // variance mm², weight r, g, b
uniform vec4 u_gl[SSS_GL_ORDER];         // Gauss–Legendre node on [-1, 1], weight

out vec4 frag_color;

vec3 profile(float d) {
  vec3 sum = vec3(0.0);
  for (int i = 0; i < SSS_MAX_TERMS; ++i) {
    if (i >= u_term_count) break;
    float v = u_terms[i].x;
    sum += u_terms[i].yzw * (exp(-d * d / (2.0 * v)) / (2.0 * SSS_PI * v));
  }
  return sum;
}

// The four kinks, sorted ascending (unused ones are large).
void sort4(inout vec4 k) {
  for (int pass = 0; pass < 3; ++pass) {
    if (k.x > k.y) k.xy = k.yx;
    if (k.y > k.z) k.yz = k.zy;
    if (k.z > k.w) k.zw = k.wz;
  }
}

#if SSS_LUT_KIND == 0
float light(float theta, float x) {
  return clamp(cos(theta + x), 0.0, 1.0) + clamp(cos(theta - x), 0.0, 1.0);
}
vec3 weight(float r, float x) { return profile(2.0 * r * sin(0.5 * x)); }
#else
float new_penumbra(float t) {
  float f = clamp(u_new_penumbra, 1e-6, 1.0);
  return clamp((t - (0.5 - 0.5 * f)) / f, 0.0, 1.0);
}
float light2(float t0, float q, float y) { return new_penumbra(t0 + y * q) + new_penumbra(t0 - y * q); }
#endif

// Accumulates one panel [a, b] into lit and total.
#if SSS_LUT_KIND == 0
void panel(float a, float b, float theta, float r, inout vec3 lit, inout vec3 total) {
#else
void panel(float a, float b, float t0, float q, inout vec3 lit, inout vec3 total) {
#endif
  if (!(b > a)) return;
  float half_width = 0.5 * (b - a), mid = 0.5 * (a + b);
  for (int i = 0; i < SSS_GL_ORDER; ++i) {
    float x = mid + half_width * u_gl[i].x;
#if SSS_LUT_KIND == 0
    vec3 w = weight(r, x);
    float l = light(theta, x);
#else
    vec3 w = profile(x);
    float l = light2(t0, q, x);
#endif
    float gw = u_gl[i].y * half_width;
    lit += gw * l * w;
    total += gw * w;
  }
}

// Panels over [0, end]: the doubling distances (mapped by `to_x`) split again at the sorted kinks.
#if SSS_LUT_KIND == 0
void integrate(float end, vec4 kinks, float theta, float r, out vec3 lit, out vec3 total) {
#else
void integrate(float end, vec4 kinks, float t0, float q, out vec3 lit, out vec3 total) {
#endif
  lit = vec3(0.0);
  total = vec3(0.0);
  sort4(kinks);
  float lo = 0.0;
  float d = 0.01;
  for (int j = 0; j < 40; ++j) {
    bool last = !(d < u_support);
#if SSS_LUT_KIND == 0
    float hi = last || d >= 2.0 * r ? end : min(end, 2.0 * asin(d / (2.0 * r)));
    if (d >= 2.0 * r) last = true;
#else
    float hi = last ? end : d;
#endif
    for (int k = 0; k < 4; ++k) {
      if (kinks[k] > lo && kinks[k] < hi) {
#if SSS_LUT_KIND == 0
        panel(lo, kinks[k], theta, r, lit, total);
#else
        panel(lo, kinks[k], t0, q, lit, total);
#endif
        lo = kinks[k];
      }
    }
#if SSS_LUT_KIND == 0
    panel(lo, hi, theta, r, lit, total);
#else
    panel(lo, hi, t0, q, lit, total);
#endif
    lo = hi;
    if (last || lo >= end) break;
    d *= 2.0;
  }
}

float grid(vec2 range, int i, int n) { return range.x + (range.y - range.x) * float(i) / float(n - 1); }

#if SSS_LUT_KIND == 0
vec3 diffuse(float ndotl, float curvature) {
  float c = clamp(ndotl, -1.0, 1.0);
  if (!(curvature > 0.0)) return vec3(clamp(c, 0.0, 1.0));
  float r = 1.0 / curvature;
  float theta = acos(c);
  float end = u_support >= 2.0 * r ? SSS_PI : 2.0 * asin(u_support / (2.0 * r));
  vec4 kinks = vec4(0.5 * SSS_PI - theta, 1.5 * SSS_PI - theta, theta - 0.5 * SSS_PI, theta + 0.5 * SSS_PI);
  vec3 lit, total;
  integrate(end, kinks, theta, r, lit, total);
  return clamp(lit / (2.0 * max(total, vec3(1e-30))), 0.0, 1.0);
}
#else
// erf by Abramowitz and Stegun 7.1.26 (|error| < 1.5e-7), enough to invert the Gaussian penumbra.
float erf_approx(float x) {
  float t = 1.0 / (1.0 + 0.3275911 * abs(x));
  float y = 1.0 - (((((1.061405429 * t - 1.453152027) * t) + 1.421413741) * t - 0.284496736) * t + 0.254829592) * t *
                      exp(-x * x);
  return x < 0.0 ? -y : y;
}
float penumbra_position(float s) {
  float v = clamp(s, 0.0, 1.0);
  if (u_gaussian_filter == 0) return v;
  float p = clamp(v, 1e-6, 1.0 - 1e-6);
  float lo = -8.0, hi = 8.0;  // Φ^-1(1e-6) = -4.75
  for (int i = 0; i < 40; ++i) {
    float mid = 0.5 * (lo + hi);
    if (0.5 * (1.0 + erf_approx(mid / sqrt(2.0))) < p) lo = mid; else hi = mid;
  }
  return 0.5 + 0.25 * 0.5 * (lo + hi);
}
vec3 blur(float t0, float q) {
  float f = clamp(u_new_penumbra, 1e-6, 1.0);
  float a = 0.5 - 0.5 * f, b = 0.5 + 0.5 * f;
  vec4 kinks = vec4(abs(a - t0) / q, abs(b - t0) / q, 1e30, 1e30);
  vec3 lit, total;
  integrate(u_support, kinks, t0, q, lit, total);
  return lit / (2.0 * max(total, vec3(1e-30)));
}
vec3 shadow(float s, float penumbra_world) {
  float q = u_world_units_per_mm / max(penumbra_world, 1e-30);
  float t0 = penumbra_position(s);
  vec3 value = blur(t0, q);
  vec3 lo = blur(penumbra_position(0.0), q);
  vec3 hi = blur(penumbra_position(1.0), q);
  vec3 span = hi - lo;
  vec3 sharp = vec3(new_penumbra(t0));
  vec3 scaled = clamp((value - lo) / max(span, vec3(1e-30)), 0.0, 1.0);
  return mix(sharp, scaled, greaterThan(span, vec3(1e-6)));
}
#endif

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
#if SSS_LUT_KIND == 0
  vec3 value = diffuse(grid(vec2(-1.0, 1.0), texel.x, int(u_size.x)), grid(u_row_range, texel.y, int(u_size.y)));
#else
  vec3 value = shadow(grid(vec2(0.0, 1.0), texel.x, int(u_size.x)), grid(u_row_range, texel.y, int(u_size.y)));
#endif
  frag_color = vec4(value, 1.0);
}
