// Marks translucent pixels in the module's stencil (the draw replaces the stencil value of every
// fragment that survives): the paper's multisampling path builds the stencil from the strength
// mask in alpha. The resolved alpha is the mean of the samples' alphas, so it is > 0 exactly when
// some sample is translucent: a silhouette pixel partly covered by skin is blurred (with its
// strength, and so its kernel width, scaled by the coverage).
SSS_BINDING(0) uniform sampler2D u_source;  // the resolved colour
void main() {
  vec4 c = texelFetch(u_source, ivec2(gl_FragCoord.xy), 0);
  if (!(c.a > 0.0) || any(isnan(c)) || any(isinf(c))) discard;
}
