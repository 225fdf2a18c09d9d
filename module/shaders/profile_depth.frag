// Per-pixel profiles (SSS_PROFILE_IDS): each pixel's view distance, as its float's bits, and its
// profile and object index in one RG32UI texel, so that the blur passes read a tap's distance and
// index with one fetch (separable_blur.frag) instead of two, and linearise no depth per tap. Bits,
// not a float target: the passes get exactly the float view_distance() gives, so their
// follow-surface arithmetic is the single-profile variant's, and RG32UI is renderable on OpenGL 3.3
// and ES 3.0 alike. Switch: SSS_LINEAR_DEPTH (depth.glsl).
#include "depth.glsl"

SSS_BINDING(1) uniform highp sampler2D u_depth;         // the host's depth (hardware or linear)
SSS_BINDING(4) uniform highp usampler2D u_profile_ids;  // the host's R8UI/R16UI indices

out uvec2 o_depth_id;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  o_depth_id = uvec2(floatBitsToUint(view_distance(texelFetch(u_depth, pixel, 0).r)),
                     texelFetch(u_profile_ids, pixel, 0).r);
}
