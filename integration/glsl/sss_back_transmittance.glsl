// sss_back_transmittance.glsl: Mikkelsen's (2010, §6) transmittance from a back-facing irradiance
// buffer, for a host pass that runs before the sss filter (a deferred lighting or a small
// full-screen pass). Include sss_transmittance.glsl first: this uses its profile terms
// (sss_transmittance_terms, uploaded from sss_profile_transmittance_terms with the blur's profile).
//
// The host renders its translucent objects' back faces (front faces culled) into a second target:
// rgb = the irradiance × albedo those back faces receive, a = their view distance -z_view (world
// units; 0 where there is no back face), and their view-space unit normal into another target. For
// each front pixel this gathers 16 taps of that buffer inside the footprint of the bounding sphere
// of radius r_max (the cross-bilateral mode's footprint: the sphere projected at the pixel's
// depth), weights each by the 2D diffusion profile at the 3D distance between the front and the
// back point, by the share of the footprint disc it stands for, and by sqrt(max(0, -n_t · n_o)) so
// only back surfaces whose tangent planes oppose the front one contribute. Add the result to the
// front pixel's diffuse before sss_apply.
//
// Why an include and not a library input: the host already has the back-face buffer and its G-buffer
// normals in the pass where it lights; the gather needs only the camera, width and r_max, which the
// host knows; a library input would add three textures, texture units and state to every frame of
// hosts that do not use it. The footprint formula is the cross-bilateral mode's, with the same
// millimetre: one profile millimetre = (2/3)·width world units = world_units_per_mm · scale.
//
// Which to use: sss_transmittance with a thickness (shadow map, baked map or both; see
// sss_transmittance.glsl) lights each pixel from its own thickness and the light's direction, for
// any lighting path. This gather needs a back-face pass but no thickness: it spreads the light the
// back faces actually receive (their shadows and colours included) through the front by the 3D
// distance between them, so it suits deferred hosts that already render back faces.
//
// Bad values in the back-face buffer: a texel whose distance is not a positive finite number (0 for
// no back face, a negative, NaN or infinity) adds nothing, as sss_transmittance gives no light for a
// NaN or infinite thickness (an infinite distance would otherwise put NaN into the pixel and the blur).
//
// Inputs (view space, world units):
//   pixel         gl_FragCoord.xy of the front pixel
//   x_o, n_o      the front point and its unit normal
//   projection    the camera's projection (column-major, as the library's sss_set_camera takes it)
//   viewport      x, y, width, height in pixels
//   width         as for sss_transmittance: 1.5 · sss_settings.world_units_per_mm · sss_settings.scale;
//                 r_max_mm: the footprint radius in profile mm (Mikkelsen: 4.5)

const int SSS_BACK_TAPS = 16;

// The 2D diffusion profile (1/mm²) at distance r mm: Σ w · exp(-r² / 2v) / (2π v).
vec3 sss_profile_2d(float r_mm) {
  vec3 sum = vec3(0.0);
  for (int i = 0; i < SSS_TRANSMITTANCE_MAX_TERMS; ++i) {
    if (i >= sss_transmittance_term_count) break;
    float v = sss_transmittance_terms[i].x;
    sum += sss_transmittance_terms[i].yzw * (exp(-r_mm * r_mm / (2.0 * v)) / (6.28318530718 * v));
  }
  return sum;
}

// The view-space point under window position `position` at view distance `distance`.
vec3 sss_view_point(vec2 position, float distance, mat4 projection, vec4 viewport) {
  vec2 ndc = (position - viewport.xy) / viewport.zw * 2.0 - 1.0;
  float z = -distance;
  float w = projection[2][3] * z + projection[3][3];
  return vec3((ndc.x * w - projection[2][0] * z - projection[3][0]) / projection[0][0],
              (ndc.y * w - projection[2][1] * z - projection[3][1]) / projection[1][1], z);
}

vec3 sss_back_transmittance(sampler2D back_irradiance, sampler2D back_normal, vec2 pixel, vec3 x_o, vec3 n_o,
                            mat4 projection, vec4 viewport, float width, float r_max_mm) {
  float world_per_mm = width * (2.0 / 3.0);
  float w = projection[2][3] * x_o.z + projection[3][3];
  // Half-extent of the projected sphere in pixels, per axis (the footprint d / 2).
  vec2 half_extent = vec2(projection[0][0], projection[1][1]) * 0.5 * viewport.zw * (r_max_mm * world_per_mm) / w;
  float tap_area_mm2 = 3.14159265359 * r_max_mm * r_max_mm / float(SSS_BACK_TAPS);
  vec2 lo = viewport.xy, hi = viewport.xy + viewport.zw - 1.0;
  vec3 sum = vec3(0.0);
  for (int i = 0; i < SSS_BACK_TAPS; ++i) {
    // A Vogel spiral: equal-area rings, golden-angle turns.
    float radius = sqrt((float(i) + 0.5) / float(SSS_BACK_TAPS));
    float angle = float(i) * 2.39996322973;
    ivec2 texel = ivec2(clamp(floor(pixel + half_extent * radius * vec2(cos(angle), sin(angle))), lo, hi));
    vec4 back = texelFetch(back_irradiance, texel, 0);
    // isnan() spelt out: NVIDIA's compiler takes !(a > 0.0) for a <= 0.0, which NaN fails.
    if (isnan(back.a) || !(back.a > 0.0) || isinf(back.a)) continue;
    vec3 x_t = sss_view_point(vec2(texel) + 0.5, back.a, projection, viewport);
    vec3 n_t = texelFetch(back_normal, texel, 0).xyz;
    float facing = sqrt(max(0.0, -dot(n_t, n_o)));
    float r_mm = length(x_t - x_o) / world_per_mm;
    sum += back.rgb * sss_profile_2d(r_mm) * (tap_area_mm2 * facing);
  }
  return sum;
}
