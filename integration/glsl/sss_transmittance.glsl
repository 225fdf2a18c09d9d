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
//                 distance map all use them. width keeps the reference shader's convention (1 profile
//                 mm = 2/3 width): 1.5 · sss_settings.world_units_per_mm · sss_settings.scale, the
//                 blur's millimetre (the inverse of sss_world_units_per_mm_from_legacy_width).
//   shadow map    the light's depth texture as its shadow pass wrote it (sss_thickness), or a map of
//                 light-space distances in world units (sss_thickness_linear).
//   light_view    world -> light view (the light looks down -Z) and light_projection: both as the
//                 shadow pass used them (it rendered with light_projection * light_view).
//   translucency  0..1 per pixel or material: 1 lets the most light through (thinner look).
//   N, L          world-space unit normal, unit direction from the point to the light.
// The result multiplies the light's colour, attenuation and the albedo, like diffuse light, and is
// added to the diffuse irradiance the sss filter blurs.

#ifndef SSS_TRANSMITTANCE_MAX_TERMS
#define SSS_TRANSMITTANCE_MAX_TERMS 8  // = SSS_PROFILE_MAX_TERMS in sss_tools.h
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

// The thickness (world units) the light crosses to reach `world_position`, from the light's shadow
// map: the hardware depth the shadow pass wrote (GL's default depth range, [0, 1] from NDC [-1, 1];
// sample it through a sampler WITHOUT compare mode), linearised with the light's projection.
// `shrink` (world units) pulls the point inward along the normal first: the reference uses 0.005
// for its head scene; about one or two shadow-map texels is right (less: acne, more: thin parts
// look thicker). Orthographic (directional) and perspective (spot) light projections both work.
float sss_thickness(sampler2D light_depth_map, mat4 light_view, mat4 light_projection, vec3 world_position,
                    vec3 world_normal, float shrink) {
  vec4 inside = light_view * vec4(world_position - shrink * world_normal, 1.0);
  vec4 clip = light_projection * inside;
  vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
  float zn = texture(light_depth_map, uv).r * 2.0 - 1.0;
  // View z of the first surface from NDC z: z = (m14 - zn·m15) / (zn·m11 - m10), column-major m[c][r].
  float first_z = (light_projection[3][2] - zn * light_projection[3][3]) /
                  (zn * light_projection[2][3] - light_projection[2][2]);
  return abs(inside.z - first_z);
}

// The same from a map that holds the light-space distance -z_light of the first surface directly
// (world units, R16F/R32F or a colour target of the shadow pass).
float sss_thickness_linear(sampler2D light_distance_map, mat4 light_view, mat4 light_projection,
                           vec3 world_position, vec3 world_normal, float shrink) {
  vec4 inside = light_view * vec4(world_position - shrink * world_normal, 1.0);
  vec4 clip = light_projection * inside;
  vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
  return abs(-inside.z - texture(light_distance_map, uv).r);
}

// Transmitted light factor (rgb) for a point `thickness` world units behind the lit surface.
vec3 sss_transmittance(float thickness, float width, float translucency, vec3 world_normal, vec3 to_light) {
  float s = thickness * 8.25 * (1.0 - translucency) / width;
  return sss_transmittance_profile(s) * clamp(0.3 + dot(to_light, -world_normal), 0.0, 1.0);
}
