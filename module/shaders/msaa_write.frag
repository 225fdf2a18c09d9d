// Writes the blurred result back into the host's multisampled colour, one sample per draw (the
// module sets GL_SAMPLE_MASK to that sample alone). Only translucent samples change: each gets the
// pixel's change (blurred - resolved) scaled by samples / translucent samples, so the box resolve
// of the written pixel equals the blurred pixel while opaque samples (the background side of a
// silhouette) keep their exact values and per-sample detail survives for a host that tone-maps
// before it resolves. The result is clamped at 0 (irradiance), which only matters where a dark
// translucent sample sits in a pixel that got much darker.
SSS_BINDING(0) uniform sampler2DMS u_copy;      // a copy of the host's colour samples (never the attached texture)
SSS_BINDING(1) uniform sampler2D u_blurred;     // the vertical pass's single-sample result
SSS_BINDING(2) uniform sampler2D u_resolved;    // the resolve pass's colour
uniform int u_sample;            // the sample this draw writes
uniform int u_samples;
out vec4 o_color;

bool translucent(vec4 c) { return c.a > 0.0 && !any(isnan(c)) && !any(isinf(c)); }

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 s = texelFetch(u_copy, pixel, u_sample);
  if (!translucent(s)) discard;
  vec3 delta = texelFetch(u_blurred, pixel, 0).rgb - texelFetch(u_resolved, pixel, 0).rgb;
  if (all(equal(delta, vec3(0.0))) || any(isnan(delta)) || any(isinf(delta))) discard;
  int count = 0;
  for (int i = 0; i < u_samples; ++i) {
    if (translucent(texelFetch(u_copy, pixel, i))) ++count;
  }
  o_color = vec4(max(s.rgb + delta * (float(u_samples) / float(count)), vec3(0.0)), s.a);
}
