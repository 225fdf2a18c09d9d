// sss_transmittance.glsl: light transmitted through thin parts (ears, nostrils), for the host's
// lighting pass. Paste or #include it after the #version line (GLSL 3.30 core or newer, or GLSL ES
// 3.00 with highp float as the default precision).
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
//
// Where the thickness comes from (every source gives world units; sss_transmittance takes any):
//   sss_thickness, sss_thickness_linear   the light's shadow map: the path along the light to the
//                 first surface it meets, so another object between them blocks the light. Needs a
//                 shadow map per light; misses detail below its texel size and reads about 0 near the
//                 terminator (shrink hides the depth steps there).
//   sss_thickness_baked, sss_thickness_from_unit   the host's own: a baked "local thickness" texture
//                 (0..1 × a maximum thickness; ambient occlusion of the inverted normals, as content
//                 tools bake it) or a vertex attribute. Any light, no shadow map, detail to the
//                 texel; but it is the object's thickness behind the point, not the path to this
//                 light: nothing between the light and the object blocks it.
//   sss_thickness_combined   both: the larger of a host and a shadow-map thickness. The light gets
//                 through where both say the part is thin: the baked map's detail and no depth-step
//                 streaks, and no glow where another object (or the rest of the head) stands between
//                 the light and the ear. The smaller would let a baked ear glow in another object's
//                 shadow.
// Bad thickness values, from any source (a NaN or infinite texel or attribute, a degenerate light
// projection): sss_transmittance returns 0 for a NaN or infinite thickness (no light through, and
// no NaN into the blur, which would spread it) and counts a negative thickness as 0 (touching
// surfaces: the most light). (GLSL lets a driver without NaNs leave isnan undefined; Mesa keeps
// them, tests/gl/thickness_test.cpp checks it there.)

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

// A host's thickness from a normalised value (a baked map's texel or a vertex attribute, 0..1):
// value × max_thickness world units, the thickness the map was baked with at 1. A map that stores
// translucency instead (white where thin) is 1.0 - value. A NaN or infinite value stays so (no
// light through); negative ones are left for sss_transmittance, which counts them as 0. This is the
// object's whole thickness: no shrink applies (the shadow-map path pulls the point inward only to
// hide its depth steps, so at a back face it reads `shrink` less than the geometry).
float sss_thickness_from_unit(float value, float max_thickness) {
  return value * max_thickness;
}

// The same from the red channel of a baked thickness texture at `uv` (the mesh's texture
// coordinates: the map is baked in the object's UV layout). Any format the host filters: R8 or
// R16 UNORM, a float format, or the channel of a packed map through sss_thickness_from_unit.
float sss_thickness_baked(sampler2D thickness_map, vec2 uv, float max_thickness) {
  return sss_thickness_from_unit(texture(thickness_map, uv).r, max_thickness);
}

// Does `thickness` carry a value (not NaN, not infinite)?
bool sss_thickness_known(float thickness) {
  return !(isnan(thickness) || isinf(thickness));
}

// A host thickness and a shadow-map thickness (both world units) into the one the light crosses:
// the larger (see "Where the thickness comes from" above). An unknown one (NaN, infinite) makes the
// result unknown: no light through.
float sss_thickness_combined(float host_thickness, float shadow_thickness) {
  if (!sss_thickness_known(host_thickness)) return host_thickness;
  if (!sss_thickness_known(shadow_thickness)) return shadow_thickness;
  return max(host_thickness, shadow_thickness);
}

// Transmitted light factor (rgb) for a point `thickness` world units behind the lit surface, from
// any source above. thickness < 0 counts as 0; NaN or infinite: vec3(0.0).
vec3 sss_transmittance(float thickness, float width, float translucency, vec3 world_normal, vec3 to_light) {
  if (!sss_thickness_known(thickness)) return vec3(0.0);
  // The scale first: translucency 1 makes it 0, and 0 × a huge thickness is 0 where (huge × 8.25) × 0
  // would overflow to infinity × 0 = NaN.
  float s = max(thickness, 0.0) * (8.25 * (1.0 - translucency) / width);
  return sss_transmittance_profile(s) * clamp(0.3 + dot(to_light, -world_normal), 0.0, 1.0);
}
