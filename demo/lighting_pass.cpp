#include "lighting_pass.hpp"

#include "embedded_shaders.hpp"
#include "host_gl_util.hpp"
#include "mesh_vertex_shader.hpp"

#include <sss/sss_tools.h>

#include <glm/gtc/type_ptr.hpp>

#include <string>

#include "preintegrated_glsl.hpp"  // kPreintegratedInclude, generated from integration/preintegrated/

namespace demo {

namespace {

// The mesh's vertex stage (integration/gltf_mesh/mesh_vertex_shader.hpp, shared with the web demo).
const std::string kVertexShader = gltf_mesh::mesh_vertex_shader("#version 330 core");

// After "#version 330 core" and the library's transmittance include (integration/glsl); the
// pre-integrated variant also defines SSS_PREINTEGRATED and prepends
// integration/preintegrated/sss_preintegrated.glsl (embedded at build time: SSS_DEMO_PREINTEGRATED_GLSL).
const char *const kFragmentShader = R"(
in vec3 v_position;
in vec3 v_normal;
in vec4 v_tangent;
in vec2 v_texcoord;

uniform sampler2D u_albedo;        // sRGB texture: decoded to linear by the GL
uniform sampler2D u_normal_map;
uniform sampler2DShadow u_shadow_map0;
uniform sampler2DShadow u_shadow_map1;
uniform int u_light_count;
uniform mat4 u_light_matrix[2];
uniform vec3 u_light_direction[2];
uniform vec3 u_light_irradiance[2];
uniform float u_shadow_texel[2];   // texture units (1 / size)
uniform float u_normal_offset[2];  // world units along the normal before the shadow lookup
uniform vec3 u_sky_ambient;
uniform vec3 u_ground_ambient;
uniform vec3 u_eye;
uniform vec4 u_base_color;
uniform float u_normal_scale;
uniform float u_green_sign;
uniform float u_sss_strength;
uniform float u_specular_intensity;
uniform float u_roughness;
uniform sampler2D u_depth_map0;    // the shadow maps again, plain depth (transmittance)
uniform sampler2D u_depth_map1;
uniform mat4 u_light_view[2];
uniform mat4 u_light_projection[2];
uniform int u_transmittance;       // 1: add the light transmitted through thin parts
uniform float u_sss_width;
uniform float u_translucency;
uniform int u_thickness_source;    // 0: the shadow map, 1: the material's baked thickness, 2: the larger
uniform float u_baked_thickness;   // world units (a host's baked map or attribute would give it per texel)
uniform float u_shrink[2];         // world units the thickness lookup pulls the point inward
uniform uint u_profile_byte;       // the material's profile | object << 4 (sss_frame.profile_texture)
uniform vec3 u_emission;           // unlit radiance (the flame), alpha 0: never scattered
uniform vec3 u_point_position;     // a point light without shadows (the flame); colour 0: none
uniform vec3 u_point_colour;
#ifdef SSS_PREINTEGRATED
uniform sampler2D u_diffuse_lut;     // sss_lut_create_texture(SSS_LUT_DIFFUSE)
uniform sampler2D u_shadow_lut;      // sss_lut_create_texture(SSS_LUT_SHADOW), box filter
uniform vec2 u_curvature_range;      // 1/mm
uniform vec2 u_penumbra_range;       // world units
uniform float u_world_units_per_mm;
uniform float u_shadow_texel_world[2];
#endif

layout(location = 0) out vec4 o_diffuse;
layout(location = 1) out vec4 o_specular;
layout(location = 2) out uint o_profile;
layout(location = 3) out vec4 o_albedo;  // the albedo the diffuse light is multiplied by (sss_frame.albedo_texture)

// PCF: 3x3 taps one texel apart, each a hardware-filtered 2x2 comparison.
float shadow_factor(sampler2DShadow map, mat4 light_matrix, float texel, vec3 p) {
  vec4 clip = light_matrix * vec4(p, 1.0);
  vec3 s = clip.xyz / clip.w * 0.5 + 0.5;
  if (any(lessThan(s, vec3(0.0))) || any(greaterThan(s, vec3(1.0)))) return 1.0;
  float lit = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x) lit += texture(map, vec3(s.xy + vec2(x, y) * texel, s.z));
  return lit / 9.0;
}

// Beckmann distribution (d'Eon & Luebke 2007, GPU Gems 3 ch. 14), m = RMS slope.
float beckmann(float n_dot_h, float m) {
  float c2 = max(n_dot_h * n_dot_h, 1e-6);
  float m2 = m * m;
  return exp((c2 - 1.0) / (c2 * m2)) / (m2 * c2 * c2);
}

// Kelemen/Szirmay-Kalos specular: Beckmann x Schlick's Fresnel (F0 = 0.028, skin) / |L + V|^2.
float ksk_specular(vec3 n, vec3 l, vec3 v, float m, float rho_s) {
  float n_dot_l = dot(n, l);
  if (n_dot_l <= 0.0) return 0.0;
  vec3 h = l + v;
  vec3 hn = normalize(h);
  float ph = beckmann(max(dot(n, hn), 0.0), m);
  float base = pow(1.0 - max(dot(hn, v), 0.0), 5.0);
  float fresnel = base + 0.028 * (1.0 - base);
  return n_dot_l * rho_s * max(ph * fresnel / dot(h, h), 0.0);
}

void main() {
  vec3 geometric = normalize(v_normal) * (gl_FrontFacing ? 1.0 : -1.0);
  vec3 t = normalize(v_tangent.xyz - geometric * dot(geometric, v_tangent.xyz));
  vec3 b = cross(geometric, t) * (v_tangent.w < 0.0 ? -1.0 : 1.0);
  vec3 m = texture(u_normal_map, v_texcoord).xyz * 2.0 - 1.0;
  m.xy *= u_normal_scale;
  m.y *= u_green_sign;
  vec3 n = normalize(t * m.x + b * m.y + geometric * max(m.z, 1e-3));
  vec3 v = normalize(u_eye - v_position);

  vec3 irradiance = mix(u_ground_ambient, u_sky_ambient, n.y * 0.5 + 0.5);
  vec3 specular = vec3(0.0);
  for (int i = 0; i < 2; ++i) {
    if (i >= u_light_count) break;
    vec3 l = u_light_direction[i];
    // No light where the surface itself faces away (the normal map cannot lift it out of its shadow).
    float shadow = 0.0;
    if (dot(geometric, l) > 0.0) {
      vec3 p = v_position + geometric * u_normal_offset[i];
      shadow = i == 0 ? shadow_factor(u_shadow_map0, u_light_matrix[0], u_shadow_texel[0], p)
                      : shadow_factor(u_shadow_map1, u_light_matrix[1], u_shadow_texel[1], p);
    }
#ifdef SSS_PREINTEGRATED
    if (u_sss_strength > 0.0) {
      // Pre-integrated skin (docs/preintegrated.md): the diffuse LUT at the curvature from
      // derivatives, and the shadow LUT on the PCF value (3x3 taps of 2x2 filtered comparisons: a
      // penumbra of about 3 texels). One normal for the three channels (no blurred normal map here).
      float k = sss_curvature_per_mm(geometric, v_position, u_world_units_per_mm);
      vec3 d = sss_skin_diffuse(u_diffuse_lut, u_curvature_range, k, vec3(dot(n, l)));
      vec3 s = sss_skin_shadow(u_shadow_lut, u_penumbra_range, shadow,
                               sss_penumbra_width(3.0 * u_shadow_texel_world[i], geometric, l));
      irradiance += u_light_irradiance[i] * d * s;
    } else {
      irradiance += u_light_irradiance[i] * (max(dot(n, l), 0.0) * shadow);
    }
#else
    irradiance += u_light_irradiance[i] * (max(dot(n, l), 0.0) * shadow);
#endif
    specular += u_light_irradiance[i] * (shadow * ksk_specular(n, l, v, u_roughness, u_specular_intensity));
    // Transmittance through thin parts (ears, nostrils): the thickness from the same shadow map
    // read as plain depth, or the material's baked one, or the larger of both; the profile the blur
    // uses (terms uploaded from the library's C API).
    if (u_transmittance == 1 && u_sss_strength > 0.0) {
      float thickness = u_baked_thickness;
      if (u_thickness_source != 1) {
        float shadow = i == 0 ? sss_thickness(u_depth_map0, u_light_view[0], u_light_projection[0], v_position,
                                              geometric, u_shrink[0])
                              : sss_thickness(u_depth_map1, u_light_view[1], u_light_projection[1], v_position,
                                              geometric, u_shrink[1]);
        thickness = u_thickness_source == 0 ? shadow : sss_thickness_combined(u_baked_thickness, shadow);
      }
      irradiance += u_light_irradiance[i] * sss_transmittance(thickness, u_sss_width, u_translucency, geometric, l);
    }
  }
  vec3 to_point = u_point_position - v_position;
  irradiance += u_point_colour * max(dot(n, normalize(to_point)), 0.0) / max(dot(to_point, to_point), 1e-6);
  vec3 albedo = texture(u_albedo, v_texcoord).rgb * u_base_color.rgb;
  o_diffuse = vec4(albedo * irradiance + u_emission, u_sss_strength);
  o_profile = u_profile_byte;
  o_albedo = vec4(albedo, 1.0);
  o_specular = vec4(specular, 0.0);
}
)";

struct Uniforms {
  GLint transmittance, sss_width, translucency, terms, term_count, thickness_source, baked_thickness;
  GLint light_view[kMaxLights], light_projection[kMaxLights], shrink[kMaxLights];
  GLint profile_byte, emission;
  GLint view_projection, light_count, eye, sky_ambient, ground_ambient, base_color, normal_scale, green_sign,
      sss_strength, specular_intensity, roughness;
  GLint light_matrix[kMaxLights], light_direction[kMaxLights], light_irradiance[kMaxLights],
      shadow_texel[kMaxLights], normal_offset[kMaxLights];
};

Uniforms locate(GLuint p) {
  Uniforms u{};
  u.view_projection = glGetUniformLocation(p, "u_view_projection");
  u.light_count = glGetUniformLocation(p, "u_light_count");
  u.profile_byte = glGetUniformLocation(p, "u_profile_byte");
  u.emission = glGetUniformLocation(p, "u_emission");
  u.eye = glGetUniformLocation(p, "u_eye");
  u.sky_ambient = glGetUniformLocation(p, "u_sky_ambient");
  u.ground_ambient = glGetUniformLocation(p, "u_ground_ambient");
  u.base_color = glGetUniformLocation(p, "u_base_color");
  u.normal_scale = glGetUniformLocation(p, "u_normal_scale");
  u.green_sign = glGetUniformLocation(p, "u_green_sign");
  u.sss_strength = glGetUniformLocation(p, "u_sss_strength");
  u.specular_intensity = glGetUniformLocation(p, "u_specular_intensity");
  u.roughness = glGetUniformLocation(p, "u_roughness");
  u.transmittance = glGetUniformLocation(p, "u_transmittance");
  u.sss_width = glGetUniformLocation(p, "u_sss_width");
  u.translucency = glGetUniformLocation(p, "u_translucency");
  u.terms = glGetUniformLocation(p, "sss_transmittance_terms");
  u.term_count = glGetUniformLocation(p, "sss_transmittance_term_count");
  u.thickness_source = glGetUniformLocation(p, "u_thickness_source");
  u.baked_thickness = glGetUniformLocation(p, "u_baked_thickness");
  for (int i = 0; i < kMaxLights; ++i) {
    const std::string index = "[" + std::to_string(i) + "]";
    u.light_matrix[i] = glGetUniformLocation(p, ("u_light_matrix" + index).c_str());
    u.light_direction[i] = glGetUniformLocation(p, ("u_light_direction" + index).c_str());
    u.light_irradiance[i] = glGetUniformLocation(p, ("u_light_irradiance" + index).c_str());
    u.shadow_texel[i] = glGetUniformLocation(p, ("u_shadow_texel" + index).c_str());
    u.normal_offset[i] = glGetUniformLocation(p, ("u_normal_offset" + index).c_str());
    u.light_view[i] = glGetUniformLocation(p, ("u_light_view" + index).c_str());
    u.shrink[i] = glGetUniformLocation(p, ("u_shrink" + index).c_str());
    u.light_projection[i] = glGetUniformLocation(p, ("u_light_projection" + index).c_str());
  }
  return u;
}

}  // namespace

bool create_lighting_pass(LightingPass *pass) {
  const std::string plain = std::string("#version 330 core\n") + glsl::sss_transmittance_glsl + kFragmentShader;
  const std::string pre = std::string("#version 330 core\n#define SSS_PREINTEGRATED 1\n") + glsl::sss_transmittance_glsl +
                          kPreintegratedInclude + kFragmentShader;
  pass->program = build_program("lighting", kVertexShader.c_str(), plain.c_str());
  if (pass->program == 0) return false;
  pass->preintegrated_program = build_program("lighting (pre-integrated)", kVertexShader.c_str(), pre.c_str());
  if (pass->preintegrated_program == 0) return false;
  glGenSamplers(1, &pass->depth_sampler);
  glSamplerParameteri(pass->depth_sampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(pass->depth_sampler, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glSamplerParameteri(pass->depth_sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(pass->depth_sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(pass->depth_sampler, GL_TEXTURE_COMPARE_MODE, GL_NONE);
  for (GLuint program : {pass->program, pass->preintegrated_program}) {
    glUseProgram(program);
    glUniform1i(glGetUniformLocation(program, "u_albedo"), 0);
    glUniform1i(glGetUniformLocation(program, "u_normal_map"), 1);
    glUniform1i(glGetUniformLocation(program, "u_shadow_map0"), 2);
    glUniform1i(glGetUniformLocation(program, "u_shadow_map1"), 3);
    glUniform1i(glGetUniformLocation(program, "u_depth_map0"), 4);
    glUniform1i(glGetUniformLocation(program, "u_depth_map1"), 5);
    glUniform1i(glGetUniformLocation(program, "u_diffuse_lut"), kDiffuseLutUnit);
    glUniform1i(glGetUniformLocation(program, "u_shadow_lut"), kShadowLutUnit);
  }
  glUseProgram(0);
  return check_gl("lighting pass setup");
}

void run_lighting_pass(const LightingPass &pass, const FrameTargets &targets, const DemoScene &scene,
                       const GpuScene &gpu, const ShadowPass &shadows, const CameraMatrices &camera,
                       const TransmittanceInputs &transmittance, const PreintegratedLuts *luts, bool object_ids) {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, lighting_target(targets));
  glViewport(0, 0, targets.width, targets.height);
  // Background: alpha 0 (no scattering), no specular; depth 1, stencil 0.
  const GLfloat background[4] = {scene.background.r, scene.background.g, scene.background.b, 0.0f};
  const GLfloat black[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearBufferfv(GL_COLOR, 0, background);
  glClearBufferfv(GL_COLOR, 1, black);
  const GLuint background_profile[4] = {0, 0, 0, 0};  // profile 0, object 0 (alpha 0 leaves it alone anyway)
  // The albedo 1 on the background: the texturing modes leave its colour as it is.
  const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  if (targets.samples == 0) glClearBufferuiv(GL_COLOR, 2, background_profile);  // MSAA: no profile target
  glClearBufferfv(GL_COLOR, 3, white);
  glDepthMask(GL_TRUE);
  glStencilMask(0xFF);
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
  // Every fragment that passes the depth test writes its material's mark, so the stencil ends up 1
  // exactly where a translucent material is the visible surface.
  glEnable(GL_STENCIL_TEST);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);

  const GLuint program = luts != nullptr ? pass.preintegrated_program : pass.program;
  const Uniforms u = locate(program);
  glUseProgram(program);
  if (luts != nullptr) {
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + kDiffuseLutUnit));
    glBindTexture(GL_TEXTURE_2D, luts->diffuse);
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + kShadowLutUnit));
    glBindTexture(GL_TEXTURE_2D, luts->shadow);
    glUniform2f(glGetUniformLocation(program, "u_curvature_range"), luts->curvature_range[0], luts->curvature_range[1]);
    glUniform2f(glGetUniformLocation(program, "u_penumbra_range"), luts->penumbra_range[0], luts->penumbra_range[1]);
    glUniform1f(glGetUniformLocation(program, "u_world_units_per_mm"), scene.world_units_per_mm);
    for (int i = 0; i < shadows.light_count; ++i) {
      const std::string name = "u_shadow_texel_world[" + std::to_string(i) + "]";
      glUniform1f(glGetUniformLocation(program, name.c_str()), shadows.maps[static_cast<size_t>(i)].texel_world);
    }
  }
  glUniformMatrix4fv(u.view_projection, 1, GL_FALSE, glm::value_ptr(camera.view_projection));
  glUniform3fv(u.eye, 1, glm::value_ptr(camera.eye));
  glUniform3fv(u.sky_ambient, 1, glm::value_ptr(scene.sky_ambient));
  glUniform3fv(u.ground_ambient, 1, glm::value_ptr(scene.ground_ambient));
  glUniform1f(u.green_sign, scene.normal_green_sign);
  glUniform1i(u.light_count, shadows.light_count);
  glUniform3fv(glGetUniformLocation(program, "u_point_position"), 1, glm::value_ptr(scene.point_light.position));
  glUniform3fv(glGetUniformLocation(program, "u_point_colour"), 1, glm::value_ptr(scene.point_light.colour));
  float terms[SSS_PROFILE_MAX_TERMS * 4] = {};
  int32_t term_count = 0;
  const bool transmit = transmittance.enabled &&
                        sss_profile_transmittance_terms(transmittance.profile, terms, SSS_PROFILE_MAX_TERMS,
                                                        &term_count) == SSS_OK;
  glUniform1i(u.transmittance, transmit ? 1 : 0);
  glUniform4fv(u.terms, SSS_PROFILE_MAX_TERMS, terms);
  glUniform1i(u.term_count, term_count);
  // The include takes the paper's `width` (one profile millimetre = (2/3)·width world units), whose
  // conversion the library keeps: width = world units per profile mm / (2/3).
  glUniform1f(u.sss_width,
              transmittance.world_units_per_profile_mm / sss_world_units_per_mm_from_legacy_width(1.0f));
  glUniform1f(u.translucency, transmittance.translucency);
  glUniform1i(u.thickness_source, transmittance.thickness_source);
  for (int i = 0; i < shadows.light_count; ++i) {
    const ShadowMap &map = shadows.maps[static_cast<size_t>(i)];
    const Light &light = scene.lights[static_cast<size_t>(i)];
    glUniformMatrix4fv(u.light_matrix[i], 1, GL_FALSE, glm::value_ptr(map.light_view_projection));
    glUniform3fv(u.light_direction[i], 1, glm::value_ptr(light.direction));
    glUniform3fv(u.light_irradiance[i], 1, glm::value_ptr(light.irradiance));
    glUniform1f(u.shadow_texel[i], 1.0f / static_cast<float>(kShadowMapSize));
    glUniform1f(u.normal_offset[i], 1.5f * map.texel_world);
    glUniformMatrix4fv(u.light_view[i], 1, GL_FALSE, glm::value_ptr(map.light_view));
    // A few texels inward: less lets the map's own depth steps (near the terminator, where the
    // thickness is ~0) show as red streaks; more thickens the ears.
    glUniform1f(u.shrink[i], 4.0f * map.texel_world);
    glUniformMatrix4fv(u.light_projection[i], 1, GL_FALSE, glm::value_ptr(map.light_projection));
  }
  // Both shadow units hold a depth texture (the first again when there is one light) so that the
  // unused sampler2DShadow never meets an incomplete texture.
  for (int i = 0; i < kMaxLights; ++i) {
    const int map = i < shadows.light_count ? i : 0;
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE2 + i));
    glBindTexture(GL_TEXTURE_2D, shadows.maps[static_cast<size_t>(map)].depth_texture);
    glBindSampler(static_cast<GLuint>(2 + i), shadows.compare_sampler);
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE4 + i));
    glBindTexture(GL_TEXTURE_2D, shadows.maps[static_cast<size_t>(map)].depth_texture);
    glBindSampler(static_cast<GLuint>(4 + i), pass.depth_sampler);
  }

  glBindVertexArray(gpu.vao);
  for (const gltf_mesh::Primitive &p : scene.model.primitives) {
    const size_t index = static_cast<size_t>(p.material);
    const gltf_mesh::Material &material = scene.model.materials[index];
    const MaterialLook &look = scene.looks[index];
    glStencilFunc(GL_ALWAYS, look.sss_strength > 0.0f ? 1 : 0, 0xFF);
    glUniform4fv(u.base_color, 1, material.base_color);
    glUniform1f(u.normal_scale, material.normal_scale);
    glUniform1f(u.sss_strength, look.sss_strength);
    glUniform1f(u.baked_thickness, look.baked_thickness > 0.0f ? look.baked_thickness : transmittance.baked_thickness);
    glUniform1f(u.specular_intensity, look.specular_intensity);
    glUniform1f(u.roughness, look.roughness);
    glUniform1ui(u.profile_byte, profile_byte(look, object_ids));
    glUniform3fv(u.emission, 1, glm::value_ptr(look.emission));
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, gpu.materials[index].albedo);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, gpu.materials[index].normal);
    draw_primitive(p);
  }
  glBindVertexArray(0);
  for (GLuint unit = 0; unit <= static_cast<GLuint>(kShadowLutUnit); ++unit) {  // materials, shadow maps, depth, LUTs
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindSampler(unit, 0);
  }
  glActiveTexture(GL_TEXTURE0);
  glUseProgram(0);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
}

void destroy_lighting_pass(LightingPass *pass) {
  glDeleteProgram(pass->program);
  glDeleteProgram(pass->preintegrated_program);
  glDeleteSamplers(1, &pass->depth_sampler);
  *pass = LightingPass{};
}

}  // namespace demo
