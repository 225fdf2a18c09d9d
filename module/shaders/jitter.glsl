// The jitter of sparse taps (SSS_JITTER 1; nothing otherwise), for separable_blur.frag and .comp.

#if SSS_JITTER
#ifndef SSS_UNIFORM_u_noise_index  // a pass kind's uniform struct declares it (module/src/gl/pass_uniforms.hpp)
uniform uint u_noise_index;  // sss_frame.noise_index
#endif

// The jitter noise in [0, 1): must equal sss::math::jitter_noise (module/src/math/pass_kernel.cpp)
// bit for bit, which 32-bit uint arithmetic guarantees; axis 0 horizontal, 1 vertical.
float jitter_noise(ivec2 pixel, int axis) {
  uint h = uint(pixel.x) * 0x8da6b343u ^ uint(pixel.y) * 0xd8163841u ^ uint(axis + 1) * 0xcb1ab31fu ^
           u_noise_index * 0x9e3779b9u;
  h ^= h >> 16u;
  h *= 0x7feb352du;
  h ^= h >> 15u;
  h *= 0x846ca68bu;
  h ^= h >> 16u;
  return float(h >> 8u) * (1.0 / 16777216.0);
}

// The pixel a jittered tap reads in its cell (tap at p, inner neighbour at `inner`, outer one at
// `outer`; the outermost tap's cell is its inner half mirrored), as sss::math::footprint_taps.
float jittered_position(float inner, float p, float outer, bool outermost, float noise) {
  float lo = floor(0.5 * (inner + p)) + 1.0;
  float hi = outermost ? p + (p - lo) : floor(0.5 * (p + outer));
  return lo + min(floor(noise * (hi - lo + 1.0)), hi - lo);
}
#endif
