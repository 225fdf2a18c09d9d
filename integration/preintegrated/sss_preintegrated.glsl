// Pre-integrated skin shading for host shaders (Penner and Borshukov 2011): paste or #include after
// your #version line (GLSL 3.30 core or newer; also valid GLSL ES 3.00 with precision highp float).
// Needs the LUTs of <sss/sss_lut.h> (sss_lut_create_texture, or your own upload of the fill
// functions' floats) bound as sampler2D with linear filtering and clamp-to-edge.
//
//   diffuse = sss_skin_diffuse(diffuse_lut, curvature_range, curvature_per_mm, ndotl_rgb)
//   shadow  = sss_skin_shadow(shadow_lut, penumbra_range, shadow_value, penumbra_width)
//   light   = albedo * light_colour * diffuse * shadow   (linear light)
//
// Units: curvature in 1/mm of the profile (as sss_lut_desc.curvature_min/max), penumbra width in world
// units (as penumbra_min/max). The LUTs are endpoint-inclusive: texel 0 holds the first value of a
// range and texel N-1 the last, so lookups go through sss_lut_uv.

// uv of the texel-centre grid for coordinates u in [0, 1] along each axis.
vec2 sss_lut_uv(sampler2D lut, vec2 u) {
  vec2 size = vec2(textureSize(lut, 0));
  return (0.5 + clamp(u, 0.0, 1.0) * (size - 1.0)) / size;
}

// Eq. (1.1): per-channel N·L (from sss_skin_normals, or one N·L three times) and the curvature
// 1/r in 1/mm; curvature_range = (curvature_min, curvature_max) the LUT was made with.
vec3 sss_skin_diffuse(sampler2D lut, vec2 curvature_range, float curvature_per_mm, vec3 ndotl) {
  float v = (curvature_per_mm - curvature_range.x) / (curvature_range.y - curvature_range.x);
  vec3 u = ndotl * 0.5 + 0.5;
  return vec3(texture(lut, sss_lut_uv(lut, vec2(u.r, v))).r,
              texture(lut, sss_lut_uv(lut, vec2(u.g, v))).g,
              texture(lut, sss_lut_uv(lut, vec2(u.b, v))).b);
}

// §1.6: the host's filtered shadow value (0 umbra, 1 lit) and the width of the penumbra at this
// point in world units (wider on surfaces slanted to the light; see sss_penumbra_width);
// penumbra_range = (penumbra_min, penumbra_max) the LUT was made with.
vec3 sss_skin_shadow(sampler2D lut, vec2 penumbra_range, float shadow, float penumbra_width) {
  float v = (penumbra_width - penumbra_range.x) / (penumbra_range.y - penumbra_range.x);
  return texture(lut, sss_lut_uv(lut, vec2(shadow, v))).rgb;
}

// The width of the shadow filter's penumbra on the receiving surface: `filter_width` is the
// penumbra on a surface facing the light (world units), stretched by 1/cos of the light's incidence.
float sss_penumbra_width(float filter_width, vec3 normal, vec3 light_dir) {
  return filter_width / max(abs(dot(normal, light_dir)), 0.05);
}

// Curvature from screen-space derivatives (§1.4, Figure 1.3): how fast the interpolated geometric
// normal turns per world unit, converted to 1/mm. Use the smooth geometric normal (not the normal
// map's), world space; the result is noisy at triangle edges where normals are not smooth.
float sss_curvature_per_mm(vec3 geometric_normal, vec3 world_position, float world_units_per_mm) {
  float turn = length(fwidth(geometric_normal));
  float travel = max(length(fwidth(world_position)), 1e-20);
  return turn / travel * world_units_per_mm;  // 1/world unit × world units per mm = 1/mm
}

// §1.5: per-channel normals between the sharp normal map (N_high) and the profile-blurred one
// (N_low, from tools/sss_blur_normals). blend = how far each channel goes towards N_low; the tool
// prints the value for its profile (red 1, green and blue less: they scatter less far).
void sss_skin_normals(vec3 n_high, vec3 n_low, vec3 blend, out vec3 n_r, out vec3 n_g, out vec3 n_b) {
  n_r = normalize(mix(n_high, n_low, blend.r));
  n_g = normalize(mix(n_high, n_low, blend.g));
  n_b = normalize(mix(n_high, n_low, blend.b));
}

// The per-channel N·L for sss_skin_diffuse.
vec3 sss_skin_ndotl(vec3 n_r, vec3 n_g, vec3 n_b, vec3 light_dir) {
  return vec3(dot(n_r, light_dir), dot(n_g, light_dir), dot(n_b, light_dir));
}
