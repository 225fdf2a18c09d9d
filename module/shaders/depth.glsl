// Depth linearisation, for every pass that reads the host's depth (separable_blur.frag and .comp,
// cbf_blur.frag, msaa_resolve.frag). SSS_LINEAR_DEPTH 0: the host's depth is hardware depth,
// linearised with the projection; 1: it holds the view distance already.
#ifndef SSS_UNIFORM_u_depth_terms  // a pass kind's uniform struct declares it (module/src/gl/pass_uniforms.hpp)
uniform vec2 u_ndc_from_depth;  // z_ndc = depth · x + y
uniform vec4 u_depth_terms;     // projection m10, m11, m14, m15
#endif

// The view distance (world units in front of the eye) of a depth texel's value.
float view_distance(float raw_depth) {
#if SSS_LINEAR_DEPTH
  return raw_depth;
#else
  float zn = raw_depth * u_ndc_from_depth.x + u_ndc_from_depth.y;
  return (zn * u_depth_terms.w - u_depth_terms.z) / (zn * u_depth_terms.y - u_depth_terms.x);
#endif
}

// Clip w of a point at view distance `distance`.
float clip_w(float distance) { return -u_depth_terms.y * distance + u_depth_terms.w; }
