// sss_transmittance.glsl: light transmitted through thin parts (ears, nostrils), for the host's
// lighting pass. Paste or #include it after the #version line (GLSL 3.30 core or newer).
//
// Model (Jimenez, Whelan, Sundstedt, Gutierrez 2010, as the separable SSS reference shader does it;
// DESIGN.md §5): the thickness the light crosses to reach a point is the difference between the
// point's distance from the light and the first surface the light's shadow map saw, after the point
// is pulled inward along its normal (so it lies inside the object, not on its lit side); the
// transmitted light is the diffusion profile evaluated at that thickness, scaled by
// 8.25 · (1 - translucency) / width, times saturate(0.3 + dot(L, -N)).
//
// The profile is the one the blur uses: upload the quadruples sss_profile_transmittance_terms()
// returns (C API, no GL needed) into sss_transmittance_terms and their count into
// sss_transmittance_term_count. Nothing here is typed by hand, so blur and transmittance agree.
//
// Units and inputs:
//   world units   the host's (metres, centimetres, ...): width, thickness, shrink and the light's
//                 distance map all use them. width is sss_settings.width (1 profile mm = 2/3 width).
//   distance map  a 2D texture holding, per texel, the light-space distance -z_light of the first
//                 surface the light sees (world units; R16F/R32F, or a colour target of the shadow
//                 pass). Hardware shadow depth must be linearised by the host into this form.
//   light_view    world -> light view (the light looks down -Z); light_view_projection its
//                 projection times it: both as the shadow pass used them.
//   translucency  0..1 per pixel or material: 1 lets the most light through (thinner look).
//   N, L          world-space unit normal, unit direction from the point to the light.
// The result multiplies the light's colour, attenuation and the albedo, like diffuse light, and is
// added to the diffuse irradiance the sss filter blurs.

#ifndef SSS_TRANSMITTANCE_MAX_TERMS
#define SSS_TRANSMITTANCE_MAX_TERMS 8  // = SSS_PROFILE_MAX_TERMS in sss.h
#endif

uniform vec4 sss_transmittance_terms[SSS_TRANSMITTANCE_MAX_TERMS];  // variance mm², weight r, g, b
uniform int sss_transmittance_term_count;

// The transmittance profile at scaled thickness s: Σ w · exp(-s² / v).
vec3 sss_transmittance_profile(float s) {
  vec3 sum = vec3(0.0);
  for (int i = 0; i < SSS_TRANSMITTANCE_MAX_TERMS; ++i) {
    if (i >= sss_transmittance_term_count) break;
    sum += sss_transmittance_terms[i].yzw * exp(-s * s / sss_transmittance_terms[i].x);
  }
  return sum;
}

// The thickness (world units) the light crosses to reach `world_position`, from the light's
// distance map. `shrink` (world units) pulls the point inward along the normal first: the
// reference uses 0.005 for its head scene in metres-like units; about a shadow-map texel's size.
float sss_thickness(sampler2D light_distance_map, mat4 light_view, mat4 light_view_projection, vec3 world_position,
                    vec3 world_normal, float shrink) {
  vec4 inside = vec4(world_position - shrink * world_normal, 1.0);
  vec4 clip = light_view_projection * inside;
  vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
  float first_surface = texture(light_distance_map, uv).r;
  float here = -(light_view * inside).z;
  return abs(here - first_surface);
}

// Transmitted light factor (rgb) for a point `thickness` world units behind the lit surface.
vec3 sss_transmittance(float thickness, float width, float translucency, vec3 world_normal, vec3 to_light) {
  float s = thickness * 8.25 * (1.0 - translucency) / width;
  return sss_transmittance_profile(s) * clamp(0.3 + dot(to_light, -world_normal), 0.0, 1.0);
}
