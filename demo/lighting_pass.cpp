#include "lighting_pass.hpp"

#include "host_gl_util.hpp"

#include <glm/gtc/type_ptr.hpp>

namespace demo {

namespace {

const char *const kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
uniform mat4 u_view_projection;
out vec3 v_position;
out vec3 v_normal;
void main() {
  v_position = a_position;
  v_normal = a_normal;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
)";

const char *const kFragmentShader = R"(#version 330 core
in vec3 v_position;
in vec3 v_normal;

uniform sampler2DShadow u_shadow_map;
uniform mat4 u_light_view_projection;
uniform float u_shadow_texel;      // 1 / shadow map size
uniform float u_normal_offset;     // metres along the normal before the shadow lookup
uniform vec3 u_light_direction;
uniform vec3 u_light_irradiance;
uniform vec3 u_sky_ambient;
uniform vec3 u_ground_ambient;
uniform vec3 u_eye;
uniform vec3 u_albedo;
uniform float u_sss_strength;
uniform float u_specular_f0;
uniform float u_gloss;

layout(location = 0) out vec4 o_diffuse;
layout(location = 1) out vec4 o_specular;

// 3x3 taps of hardware 2x2 PCF.
float shadow_factor(vec3 p, vec3 n) {
  vec4 clip = u_light_view_projection * vec4(p + n * u_normal_offset, 1.0);
  vec3 s = clip.xyz / clip.w * 0.5 + 0.5;
  if (any(lessThan(s, vec3(0.0))) || any(greaterThan(s, vec3(1.0)))) return 1.0;
  float lit = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x)
      lit += texture(u_shadow_map, vec3(s.xy + vec2(x, y) * u_shadow_texel, s.z));
  return lit / 9.0;
}

void main() {
  vec3 n = normalize(v_normal);
  vec3 l = u_light_direction;
  vec3 v = normalize(u_eye - v_position);
  float n_dot_l = max(dot(n, l), 0.0);
  float shadow = n_dot_l > 0.0 ? shadow_factor(v_position, n) : 0.0;

  vec3 ambient = mix(u_ground_ambient, u_sky_ambient, n.y * 0.5 + 0.5);
  vec3 irradiance = u_light_irradiance * (n_dot_l * shadow) + ambient;
  o_diffuse = vec4(u_albedo * irradiance, u_sss_strength);

  // Normalised Blinn-Phong with Schlick's Fresnel.
  vec3 h = normalize(l + v);
  float fresnel = u_specular_f0 + (1.0 - u_specular_f0) * pow(1.0 - max(dot(h, v), 0.0), 5.0);
  float lobe = (u_gloss + 8.0) / 25.1327412 * pow(max(dot(n, h), 0.0), u_gloss);
  o_specular = vec4(u_light_irradiance * (fresnel * lobe * n_dot_l * shadow), 1.0);
}
)";

struct Uniforms {
  GLint view_projection, shadow_map, light_view_projection, shadow_texel, normal_offset, light_direction,
      light_irradiance, sky_ambient, ground_ambient, eye, albedo, sss_strength, specular_f0, gloss;
};

Uniforms locate(GLuint p) {
  return Uniforms{glGetUniformLocation(p, "u_view_projection"), glGetUniformLocation(p, "u_shadow_map"),
                  glGetUniformLocation(p, "u_light_view_projection"), glGetUniformLocation(p, "u_shadow_texel"),
                  glGetUniformLocation(p, "u_normal_offset"), glGetUniformLocation(p, "u_light_direction"),
                  glGetUniformLocation(p, "u_light_irradiance"), glGetUniformLocation(p, "u_sky_ambient"),
                  glGetUniformLocation(p, "u_ground_ambient"), glGetUniformLocation(p, "u_eye"),
                  glGetUniformLocation(p, "u_albedo"), glGetUniformLocation(p, "u_sss_strength"),
                  glGetUniformLocation(p, "u_specular_f0"), glGetUniformLocation(p, "u_gloss")};
}

}  // namespace

bool create_lighting_pass(LightingPass *pass, GLsizei width, GLsizei height) {
  pass->width = width;
  pass->height = height;
  pass->program = build_program("lighting", kVertexShader, kFragmentShader);
  if (pass->program == 0) return false;

  pass->diffuse_texture = make_texture(GL_RGBA16F, width, height, GL_RGBA, GL_HALF_FLOAT);
  pass->specular_texture = make_texture(GL_RGBA16F, width, height, GL_RGBA, GL_HALF_FLOAT);
  pass->depth_stencil_texture =
      make_texture(GL_DEPTH24_STENCIL8, width, height, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8);

  glGenFramebuffers(1, &pass->framebuffer);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, pass->framebuffer);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, pass->diffuse_texture, 0);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, pass->specular_texture, 0);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
                         pass->depth_stencil_texture, 0);
  const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(2, buffers);
  const bool complete = check_framebuffer("lighting");
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  return complete && check_gl("lighting pass setup");
}

void run_lighting_pass(const LightingPass &pass, const SceneGeometry &geometry, const SceneView &view,
                       GLuint shadow_map, GLsizei shadow_map_size) {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, pass.framebuffer);
  glViewport(0, 0, pass.width, pass.height);

  // Background: dim colour with alpha 0 (no scattering); depth 1, stencil 0.
  const GLfloat background[4] = {0.020f, 0.024f, 0.030f, 0.0f};
  const GLfloat black[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearBufferfv(GL_COLOR, 0, background);
  glClearBufferfv(GL_COLOR, 1, black);
  glDepthMask(GL_TRUE);
  glStencilMask(0xFF);
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  // Every drawn fragment that passes the depth test writes its object's mark, so the stencil ends up
  // 1 exactly where the sphere is the visible surface.
  glEnable(GL_STENCIL_TEST);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);

  const GLuint p = pass.program;
  const Uniforms u = locate(p);
  glUseProgram(p);
  glUniformMatrix4fv(u.view_projection, 1, GL_FALSE, glm::value_ptr(view.view_projection));
  glUniformMatrix4fv(u.light_view_projection, 1, GL_FALSE, glm::value_ptr(view.light_view_projection));
  glUniform1i(u.shadow_map, 0);
  glUniform1f(u.shadow_texel, 1.0f / static_cast<float>(shadow_map_size));
  glUniform1f(u.normal_offset, 1.5f * view.shadow_extent / static_cast<float>(shadow_map_size));
  glUniform3fv(u.light_direction, 1, glm::value_ptr(view.light_direction));
  glUniform3fv(u.light_irradiance, 1, glm::value_ptr(view.light_irradiance));
  glUniform3fv(u.sky_ambient, 1, glm::value_ptr(view.sky_ambient));
  glUniform3fv(u.ground_ambient, 1, glm::value_ptr(view.ground_ambient));
  glUniform3fv(u.eye, 1, glm::value_ptr(view.eye));
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, shadow_map);

  glBindVertexArray(geometry.vao);
  for (const SceneObject &object : geometry.objects) {
    glStencilFunc(GL_ALWAYS, object.translucent ? 1 : 0, 0xFF);
    glUniform3fv(u.albedo, 1, glm::value_ptr(object.albedo));
    glUniform1f(u.sss_strength, object.sss_strength);
    glUniform1f(u.specular_f0, object.specular_f0);
    glUniform1f(u.gloss, object.gloss);
    draw_object(object);
  }
  glBindVertexArray(0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glUseProgram(0);

  glDisable(GL_STENCIL_TEST);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
}

void destroy_lighting_pass(LightingPass *pass) {
  glDeleteProgram(pass->program);
  glDeleteFramebuffers(1, &pass->framebuffer);
  glDeleteTextures(1, &pass->diffuse_texture);
  glDeleteTextures(1, &pass->specular_texture);
  glDeleteTextures(1, &pass->depth_stencil_texture);
  *pass = LightingPass{};
}

}  // namespace demo
