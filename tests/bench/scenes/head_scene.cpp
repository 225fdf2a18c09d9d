// The head scenes. The scan: "Infinite, 3D Head Scan" by Lee Perry-Smith is licensed under a
// Creative Commons Attribution 3.0 Unported License. Based on a work at www.triplegangers.com.
// Permissions beyond the scope of this license may be available at http://www.ir-ltd.net/
//
// Two passes, GL 3.3 core:
//  1. shadow: the head's depth from the key light (orthographic, directional) into a 2048^2
//     DEPTH_COMPONENT32F texture, compared with linear filtering (one texel of penumbra: hard);
//  2. scene: into RGBA32F (irradiance, alpha = 1 on the head), R32F (view distance -z_view,
//     computed in the shader) and DEPTH_COMPONENT32F attachments cleared to the backdrop (a plane
//     facing the camera at a finite distance, irradiance 0.05, alpha 0), then read back.
// irradiance = albedo (sRGB texture decoded to linear by an SRGB8 format)
//              x (key colour x max(0, N.L) x shadow + fill colour x max(0, N.F) + ambient),
// N from the tangent-space normal map with the glTF frame: bitangent = cross(normal, tangent.xyz)
// x tangent.w. The green channel is inverted (kNormalMapGreenSign = -1): the map stores +green
// towards +v (down the image in glTF's top-left texture space) while the mesh's bitangent points
// towards -v; scenes_test checks this on the asset (normal_map_green_convention).
// HeadView::soft_light filters the key's shadow and projects it through soft-edged bars (the shader's
// soft_shadow and key_pattern). With points (the whole-surface reference), a third pass runs the
// same fragment shader once per point of the mesh (light_at_points).
#include "head_scene.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include <fstream>
#include <sstream>

#include "gl_state_guard.hpp"
#include "head_asset.hpp"
#include "host_gl.hpp"
#include "math/normal_blur.hpp"
#include "math/preintegrated_lut.hpp"

using namespace host_gl;

namespace sss_bench::detail {

const float kNormalMapGreenSign = -1.0f;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kShadowMapSize = 2048;
constexpr float kBackdropIrradiance = 0.05f;

// World-space lighting (the head faces +Z, Y up, so the subject's right is -X): the key from above,
// in front and to the subject's right (elevation ~40 degrees, ~45 degrees off the face's axis), so
// that the nose throws a hard shadow down across the subject's left cheek (+X), which the cameras
// (yawed towards +X) see; a dim cool fill from the other side, slightly below; a small ambient.
const Vec3 kKeyDirection = normalize(Vec3{-0.55, 0.62, 0.56});  // towards the light
const float kKeyColour[3] = {1.25f, 1.2f, 1.12f};
const Vec3 kFillDirection = normalize(Vec3{0.8, -0.1, 0.6});
const float kFillColour[3] = {0.10f, 0.11f, 0.13f};
const float kAmbient[3] = {0.03f, 0.03f, 0.035f};

const char* const kShadowVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_light_matrix;
void main() { gl_Position = u_light_matrix * vec4(a_position, 1.0); }
)";

const char* const kShadowFragment = R"(#version 330 core
void main() {}
)";

const char* const kSceneVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_texcoord;
layout(location = 3) in vec4 a_tangent;
uniform mat4 u_view;
uniform mat4 u_projection;
out vec3 v_world;
out vec3 v_normal;
out vec4 v_tangent;
out vec2 v_texcoord;
out float v_distance;
void main() {
  vec4 view = u_view * vec4(a_position, 1.0);
  v_world = a_position;
  v_normal = a_normal;
  v_tangent = a_tangent;
  v_texcoord = a_texcoord;
  v_distance = -view.z;
  gl_Position = u_projection * view;
}
)";

const char* const kSceneFragment = R"(#version 330 core
in vec3 v_world;
in vec3 v_normal;
in vec4 v_tangent;
in vec2 v_texcoord;
in float v_distance;
layout(location = 0) out vec4 o_irradiance;
layout(location = 1) out vec4 o_distance;
layout(location = 2) out vec4 o_albedo;  // Scene::albedo (the points pass has no target for it)
uniform sampler2D u_albedo;
uniform sampler2D u_normal_map;
uniform sampler2DShadow u_shadow_map;
uniform mat4 u_light_matrix;
uniform float u_normal_offset;
uniform float u_depth_bias;
uniform float u_green_sign;
uniform vec3 u_key_direction;
uniform vec3 u_key_colour;
uniform vec3 u_fill_direction;
uniform vec3 u_fill_colour;
uniform vec3 u_ambient;
// HeadView::soft_light: the key's shadow filtered (a box PCF of (2·u_pcf_radius + 1)² taps a texel
// apart) and the key projected through a pattern of bars u_pattern_period wide, lit 1 and 0.3,
// with edges ramped over u_pattern_edge (world units across the key's beam).
uniform int u_soft_light;
uniform int u_pcf_radius;
uniform float u_shadow_texel_depth;
uniform vec2 u_light_extent;  // the world size the shadow map's [0, 1]² spans
uniform float u_pattern_period;
uniform float u_pattern_edge;

float soft_shadow(vec3 s, vec3 n) {
  // Receiver-plane bias: a tap k texels away compares a depth nearer the light by k texels times
  // the tangent of the incidence (capped at 60 degrees) on a surface slanted to the key.
  float cos_i = max(dot(n, u_key_direction), 0.5);
  float slope = sqrt(1.0 - cos_i * cos_i) / cos_i;
  vec2 texel = 1.0 / vec2(textureSize(u_shadow_map, 0));
  float lit = 0.0, taps = 0.0;
  for (int y = -u_pcf_radius; y <= u_pcf_radius; ++y) {
    for (int x = -u_pcf_radius; x <= u_pcf_radius; ++x) {
      vec2 at = s.xy + vec2(float(x), float(y)) * texel;
      float reach = length(vec2(float(x), float(y))) * u_shadow_texel_depth;
      lit += texture(u_shadow_map, vec3(at, s.z - u_depth_bias - 2.0 * reach * slope));
      taps += 1.0;
    }
  }
  return lit / taps;
}

float key_pattern(vec3 s) {
  vec2 beam = s.xy * u_light_extent;
  float p = dot(beam, vec2(0.8660254, 0.5)) / u_pattern_period;
  float from_bar_centre = abs(fract(p) - 0.5) * u_pattern_period;
  float quarter = 0.25 * u_pattern_period;
  return 0.3 + 0.7 * (1.0 - smoothstep(quarter - 0.5 * u_pattern_edge, quarter + 0.5 * u_pattern_edge, from_bar_centre));
}

void main() {
  vec3 n = normalize(v_normal);
  vec3 t = normalize(v_tangent.xyz - n * dot(n, v_tangent.xyz));
  vec3 b = cross(n, t) * (v_tangent.w < 0.0 ? -1.0 : 1.0);
  vec3 m = texture(u_normal_map, v_texcoord).xyz * 2.0 - 1.0;
  m.y *= u_green_sign;
  vec3 normal = normalize(t * m.x + b * m.y + n * max(m.z, 1e-3));

  // Normal offset against acne: look the shadow up a little off the surface, along the vertex
  // normal; no light where the surface itself faces away from the key.
  vec4 light = u_light_matrix * vec4(v_world + n * u_normal_offset, 1.0);
  vec3 s = light.xyz / light.w * 0.5 + 0.5;
  float shadow;
  if (u_soft_light == 0) {
    shadow = texture(u_shadow_map, vec3(s.xy, s.z - u_depth_bias));
  } else {
    shadow = soft_shadow(s, n) * key_pattern(s);
  }
  if (any(lessThan(s.xy, vec2(0.0))) || any(greaterThan(s.xy, vec2(1.0)))) shadow = 1.0;
  if (dot(n, u_key_direction) <= 0.0) shadow = 0.0;

  vec3 irradiance_in = u_key_colour * max(dot(normal, u_key_direction), 0.0) * shadow +
                       u_fill_colour * max(dot(normal, u_fill_direction), 0.0) + u_ambient;
  vec3 albedo = texture(u_albedo, v_texcoord).rgb;
  o_irradiance = vec4(albedo * irradiance_in, 1.0);
  o_distance = vec4(v_distance, 0.0, 0.0, 0.0);
  o_albedo = vec4(albedo, 1.0);
}
)";

// The light at points of the mesh (head_light_at): each point one texel of a RGBA32F target, its
// attributes interpolated on the CPU as the rasteriser would, and the scene's own fragment shader.
// A point's quad has the same attributes at every fragment, so texture() reads the base level.
const char* const kPointsVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_texcoord;
layout(location = 3) in vec4 a_tangent;
uniform mat4 u_view;
uniform int u_target_width;
uniform vec2 u_target_size;
out vec3 v_world;
out vec3 v_normal;
out vec4 v_tangent;
out vec2 v_texcoord;
out float v_distance;
void main() {
  v_world = a_position;
  v_normal = a_normal;
  v_tangent = a_tangent;
  v_texcoord = a_texcoord;
  v_distance = -(u_view * vec4(a_position, 1.0)).z;
  vec2 texel = vec2(float(gl_VertexID % u_target_width), float(gl_VertexID / u_target_width)) + 0.5;
  gl_Position = vec4(texel / u_target_size * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
}
)";

// The pre-integrated variant (HeadView::preintegrated): the same inputs, the include's functions
// (prepended at run time from SSS_PREINTEGRATED_GLSL), the LUTs on units 4 and 5, the blurred
// normal map on unit 6. The key's shadow
// is a box PCF of (2·u_pcf_radius + 1)² taps u_pcf_step texels apart, whose penumbra on a surface
// facing the light is about u_pcf_width world units; the include stretches it by the incidence.
const char* const kPreintegratedFragment = R"(
in vec3 v_world;
in vec3 v_normal;
in vec4 v_tangent;
in vec2 v_texcoord;
in float v_distance;
layout(location = 0) out vec4 o_irradiance;
layout(location = 1) out vec4 o_distance;
uniform sampler2D u_albedo;
uniform sampler2D u_normal_map;
uniform sampler2D u_normal_low;   // the normal map blurred by the red profile (sss::math::blur_normal_map)
uniform sampler2DShadow u_shadow_map;
uniform sampler2D u_diffuse_lut;
uniform sampler2D u_shadow_lut;
uniform vec2 u_curvature_range;
uniform vec2 u_penumbra_range;
uniform float u_world_units_per_mm;
uniform mat4 u_light_matrix;
uniform float u_normal_offset;
uniform float u_depth_bias;
uniform float u_green_sign;
uniform int u_pcf_radius;
uniform float u_pcf_step;
uniform float u_pcf_width;
uniform float u_shadow_texel_depth;  // a shadow-map texel's world size over the light's depth range
uniform vec3 u_normal_blend;
uniform vec3 u_key_direction;
uniform vec3 u_key_colour;
uniform vec3 u_fill_direction;
uniform vec3 u_fill_colour;
uniform vec3 u_ambient;
void main() {
  vec3 n = normalize(v_normal);
  vec3 t = normalize(v_tangent.xyz - n * dot(n, v_tangent.xyz));
  vec3 b = cross(n, t) * (v_tangent.w < 0.0 ? -1.0 : 1.0);
  vec3 m = texture(u_normal_map, v_texcoord).xyz * 2.0 - 1.0;
  m.y *= u_green_sign;
  vec3 normal = normalize(t * m.x + b * m.y + n * max(m.z, 1e-3));
  vec3 ml = texture(u_normal_low, v_texcoord).xyz * 2.0 - 1.0;
  ml.y *= u_green_sign;
  vec3 normal_low = normalize(t * ml.x + b * ml.y + n * max(ml.z, 1e-3));

  vec4 light = u_light_matrix * vec4(v_world + n * u_normal_offset, 1.0);
  vec3 s = light.xyz / light.w * 0.5 + 0.5;
  vec2 texel = 1.0 / vec2(textureSize(u_shadow_map, 0));
  // A wide PCF kernel compares depths millimetres away: on a surface slanted to the light those are
  // nearer the light by distance × tan(incidence), which would shadow the surface itself; the
  // bias grows with each tap's distance accordingly (receiver-plane bias, capped at 60 degrees).
  float cos_i = max(dot(n, u_key_direction), 0.5);
  float slope = sqrt(1.0 - cos_i * cos_i) / cos_i;
  float lit = 0.0, taps = 0.0;
  for (int y = -u_pcf_radius; y <= u_pcf_radius; ++y) {
    for (int x = -u_pcf_radius; x <= u_pcf_radius; ++x) {
      vec2 at = s.xy + vec2(float(x), float(y)) * u_pcf_step * texel;
      float reach = length(vec2(float(x), float(y))) * u_pcf_step * u_shadow_texel_depth;
      lit += texture(u_shadow_map, vec3(at, s.z - u_depth_bias - 2.0 * reach * slope));
      taps += 1.0;
    }
  }
  float shadow = lit / taps;
  if (any(lessThan(s.xy, vec2(0.0))) || any(greaterThan(s.xy, vec2(1.0)))) shadow = 1.0;

  vec3 nr, ng, nb;
  sss_skin_normals(normal, normal_low, u_normal_blend, nr, ng, nb);
  float k = sss_curvature_per_mm(n, v_world, u_world_units_per_mm);
  vec3 key = sss_skin_diffuse(u_diffuse_lut, u_curvature_range, k, sss_skin_ndotl(nr, ng, nb, u_key_direction));
  vec3 key_shadow = sss_skin_shadow(u_shadow_lut, u_penumbra_range, shadow,
                                    sss_penumbra_width(u_pcf_width, n, u_key_direction));
  vec3 fill = sss_skin_diffuse(u_diffuse_lut, u_curvature_range, k, sss_skin_ndotl(nr, ng, nb, u_fill_direction));
  vec3 irradiance_in = u_key_colour * key * key_shadow + u_fill_colour * fill + u_ambient;
  vec3 albedo = texture(u_albedo, v_texcoord).rgb;
  o_irradiance = vec4(albedo * irradiance_in, 1.0);
  o_distance = vec4(v_distance, 0.0, 0.0, 0.0);
}
)";

std::string preintegrated_fragment_source() {
  std::ifstream file(SSS_PREINTEGRATED_GLSL);
  if (!file) throw std::runtime_error(std::string("head scene: cannot read ") + SSS_PREINTEGRATED_GLSL);
  std::stringstream text;
  text << file.rdbuf();
  return "#version 330 core\n" + text.str() + kPreintegratedFragment;
}

// Every GL object of one make_scene call, deleted when it goes out of scope (before the state
// guard, declared earlier, restores the caller's bindings).
struct GlObjects {
  std::vector<GLuint> textures, buffers, framebuffers, vertex_arrays, programs;
  GlObjects() = default;
  GlObjects(const GlObjects&) = delete;
  GlObjects& operator=(const GlObjects&) = delete;
  ~GlObjects() {
    for (GLuint p : programs) glDeleteProgram(p);
    if (!vertex_arrays.empty()) glDeleteVertexArrays(static_cast<GLsizei>(vertex_arrays.size()), vertex_arrays.data());
    if (!framebuffers.empty()) glDeleteFramebuffers(static_cast<GLsizei>(framebuffers.size()), framebuffers.data());
    if (!buffers.empty()) glDeleteBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
    if (!textures.empty()) glDeleteTextures(static_cast<GLsizei>(textures.size()), textures.data());
  }
};

GLuint compile(GLenum kind, const char* source, const char* what) {
  GLuint shader = glCreateShader(kind);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(length > 1 ? length : 1), '\0');
    glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, &log[0]);
    glDeleteShader(shader);
    throw std::runtime_error(std::string("head scene: the ") + what + " shader does not compile: " + log);
  }
  return shader;
}

GLuint build_program(GlObjects& objects, const char* vertex, const char* fragment, const char* what) {
  const GLuint vs = compile(GL_VERTEX_SHADER, vertex, what);
  GLuint fs = 0;
  try {
    fs = compile(GL_FRAGMENT_SHADER, fragment, what);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  const GLuint program = glCreateProgram();
  objects.programs.push_back(program);
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);  // flagged; freed with the program
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(length > 1 ? length : 1), '\0');
    glGetProgramInfoLog(program, static_cast<GLsizei>(log.size()), nullptr, &log[0]);
    throw std::runtime_error(std::string("head scene: the ") + what + " program does not link: " + log);
  }
  return program;
}

GLuint make_texture(GlObjects& objects, GLenum internal_format, int width, int height, GLenum format, GLenum type,
                    const void* data) {
  GLuint texture = 0;
  glGenTextures(1, &texture);
  objects.textures.push_back(texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal_format), width, height, 0, format, type, data);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return texture;
}

// A mipmapped, repeating material texture (glTF's default sampler).
void make_material_texture(GlObjects& objects, const HeadImage& image, bool srgb) {
  const bool rgba = image.components == 4;
  const GLenum internal_format =
      srgb ? (rgba ? GL_SRGB8_ALPHA8 : GL_SRGB8) : (rgba ? GL_RGBA8 : GL_RGB8);
  make_texture(objects, internal_format, image.width, image.height, rgba ? GL_RGBA : GL_RGB, GL_UNSIGNED_BYTE,
               image.pixels.data());
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
}

GLuint make_framebuffer(GlObjects& objects) {
  GLuint framebuffer = 0;
  glGenFramebuffers(1, &framebuffer);
  objects.framebuffers.push_back(framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  return framebuffer;
}

void check_framebuffer(const char* what) {
  const GLenum status = glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error(std::string("head scene: the ") + what + " framebuffer is incomplete (status " +
                             std::to_string(status) + ")");
}

void set_matrix(GLuint program, const char* name, const Mat4& m) {
  const std::array<float, 16> f = to_float(m);
  glUniformMatrix4fv(glGetUniformLocation(program, name), 1, GL_FALSE, f.data());
}

void set_vec3(GLuint program, const char* name, Vec3 v) {
  const float f[3] = {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
  glUniform3fv(glGetUniformLocation(program, name), 1, f);
}

void set_vec3(GLuint program, const char* name, const float* v) {
  glUniform3fv(glGetUniformLocation(program, name), 1, v);
}

constexpr int kSoftPcfRadius = 4;         // HeadView::soft_light: 9x9 taps, a texel apart
constexpr double kPatternPeriodMm = 14.0;  // its bars' period across the key's beam
constexpr double kPatternEdgeMm = 1.6;     // and the width of their edges' ramp

// The points pass: the points' attributes interpolated from their triangles' corners (position,
// normal, texcoord, tangent: what the rasteriser hands the fragment shader), drawn as GL_POINTS in
// batches into an RGBA32F target of kPointsTargetWidth texels per row, read back. The scene's
// textures and shadow map stay bound on their units; no depth test.
constexpr int kPointsTargetWidth = 1024;
constexpr std::size_t kPointsPerBatch = std::size_t{1} << 20;

void light_at_points(GlObjects& objects, const HeadAsset& asset, GLuint program, const std::vector<SurfacePoint>& points,
                     std::vector<std::array<float, 3>>* light) {
  light->assign(points.size(), {0.0f, 0.0f, 0.0f});
  glUniform1i(glGetUniformLocation(program, "u_target_width"), kPointsTargetWidth);
  const int rows = static_cast<int>((kPointsPerBatch + kPointsTargetWidth - 1) / kPointsTargetWidth);
  glUniform2f(glGetUniformLocation(program, "u_target_size"), static_cast<float>(kPointsTargetWidth), static_cast<float>(rows));
  glActiveTexture(GL_TEXTURE3);
  const GLuint target = make_texture(objects, GL_RGBA32F, kPointsTargetWidth, rows, GL_RGBA, GL_FLOAT, nullptr);
  const GLuint distance = make_texture(objects, GL_R32F, kPointsTargetWidth, rows, GL_RED, GL_FLOAT, nullptr);
  glBindTexture(GL_TEXTURE_2D, 0);
  glActiveTexture(GL_TEXTURE0);
  make_framebuffer(objects);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target, 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, distance, 0);
  const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(2, buffers);
  check_framebuffer("points");
  glViewport(0, 0, kPointsTargetWidth, rows);
  glDisable(GL_DEPTH_TEST);
  GLuint vertex_array = 0, buffer = 0;
  glGenVertexArrays(1, &vertex_array);
  objects.vertex_arrays.push_back(vertex_array);
  glBindVertexArray(vertex_array);
  glGenBuffers(1, &buffer);
  objects.buffers.push_back(buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  constexpr std::size_t kFloats = HeadAsset::kFloatsPerVertex;
  const GLsizei stride = static_cast<GLsizei>(kFloats * sizeof(float));
  const int sizes[4] = {3, 3, 2, 4}, offsets[4] = {0, 3, 6, 8};
  for (GLuint a = 0; a < 4; ++a) {
    glEnableVertexAttribArray(a);
    glVertexAttribPointer(a, sizes[a], GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(static_cast<uintptr_t>(offsets[a]) * sizeof(float)));
  }
  std::vector<float> attributes, read(static_cast<std::size_t>(kPointsTargetWidth) * static_cast<std::size_t>(rows) * 4);
  for (std::size_t first = 0; first < points.size(); first += kPointsPerBatch) {
    const std::size_t count = std::min(kPointsPerBatch, points.size() - first);
    attributes.assign(count * kFloats, 0.0f);
    for (std::size_t i = 0; i < count; ++i) {
      const SurfacePoint& p = points[first + i];
      const float weights[3] = {1.0f - p.b1 - p.b2, p.b1, p.b2};
      for (std::size_t corner = 0; corner < 3; ++corner) {
        const float* v = &asset.vertices[static_cast<std::size_t>(asset.indices[p.triangle * 3u + corner]) * kFloats];
        for (std::size_t k = 0; k < kFloats; ++k) attributes[i * kFloats + k] += weights[corner] * v[k];
      }
    }
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(attributes.size() * sizeof(float)), attributes.data(), GL_STREAM_DRAW);
    const float clear[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, clear);
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(count));
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glReadPixels(0, 0, kPointsTargetWidth, rows, GL_RGBA, GL_FLOAT, read.data());
    for (std::size_t i = 0; i < count; ++i) {
      for (std::size_t c = 0; c < 3; ++c) (*light)[first + i][c] = read[i * 4 + c];
    }
  }
}

}  // namespace

HeadLights head_lights() {
  HeadLights l;
  l.key_direction = kKeyDirection;
  l.fill_direction = kFillDirection;
  for (int c = 0; c < 3; ++c) {
    l.key[c] = kKeyColour[c];
    l.fill[c] = kFillColour[c];
    l.ambient[c] = kAmbient[c];
  }
  return l;
}

void head_camera(const HeadView& view, int width, int height, Mat4* projection, Mat4* view_matrix) {
  *projection = to_double(to_float(perspective(view.fovy_degrees * kPi / 180.0, static_cast<double>(width) / height,
                                               view.near_plane, view.far_plane)));
  const double yaw = view.yaw_degrees * kPi / 180.0, pitch = view.pitch_degrees * kPi / 180.0;
  const Vec3 eye = view.target + Vec3{std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch)} *
                                     view.distance;
  *view_matrix = look_at(eye, view.target, Vec3{0, 1, 0});
}

namespace {

// The scene's mask: its translucent pixels (the shader's alpha, the scattering strength).
void set_mask(Scene* scene) {
  const std::size_t pixels = static_cast<std::size_t>(scene->width) * static_cast<std::size_t>(scene->height);
  scene->mask.resize(pixels);
  for (std::size_t i = 0; i < pixels; ++i) scene->mask[i] = scene->irradiance[i * 4 + 3] > 0.0f ? 1 : 0;
}

}  // namespace

Scene render_head_scene(const std::string& name, int width, int height, const HeadView& view,
                        const PointsOfScene& points_of, std::vector<std::array<float, 3>>* point_light) {
  const HeadAsset& asset = head_asset();  // may throw before any GL call
  if (points_of != nullptr && (view.preintegrated || point_light == nullptr))
    throw std::invalid_argument("head scene " + name + ": the light at points needs a Lambert view and an output");

  Scene scene;
  scene.name = name;
  scene.width = width;
  scene.height = height;
  Mat4 projection{}, view_matrix{};
  head_camera(view, width, height, &projection, &view_matrix);
  scene.projection = to_float(projection);

  // The key light's orthographic frustum around the bounding sphere of the scan.
  const Vec3 lo{asset.bounds_min[0], asset.bounds_min[1], asset.bounds_min[2]};
  const Vec3 hi{asset.bounds_max[0], asset.bounds_max[1], asset.bounds_max[2]};
  const Vec3 centre = (lo + hi) * 0.5;
  const double radius = length(hi - lo) * 0.5 * 1.02;
  const Mat4 light_view = look_at(centre + kKeyDirection * (2 * radius), centre, Vec3{0, 1, 0});
  const Mat4 light_projection = orthographic(-radius, radius, -radius, radius, 0.5 * radius, 3.5 * radius);
  const Mat4 light_matrix = multiply(light_projection, light_view);
  const double texel = 2 * radius / kShadowMapSize;

  const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
  scene.irradiance.resize(pixels * 4);
  scene.distance.resize(pixels);
  scene.window_depth.resize(pixels);

  if (glGetString == nullptr || glGenerateMipmap == nullptr || glGetString(GL_VERSION) == nullptr)
    throw std::runtime_error("head scene " + name + ": no current GL context, or host_gl not loaded for it");
  {
    GlStateGuard guard;
    GlObjects objects;

    // Geometry: one interleaved buffer, 32-bit indices.
    GLuint vertex_array = 0;
    glGenVertexArrays(1, &vertex_array);
    objects.vertex_arrays.push_back(vertex_array);
    glBindVertexArray(vertex_array);
    GLuint buffers[2] = {0, 0};
    glGenBuffers(2, buffers);
    objects.buffers.insert(objects.buffers.end(), buffers, buffers + 2);
    glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(asset.vertices.size() * sizeof(float)),
                 asset.vertices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(asset.indices.size() * sizeof(uint32_t)),
                 asset.indices.data(), GL_STATIC_DRAW);
    const GLsizei stride = static_cast<GLsizei>(HeadAsset::kFloatsPerVertex * sizeof(float));
    const int sizes[4] = {3, 3, 2, 4}, offsets[4] = {0, 3, 6, 8};
    for (GLuint a = 0; a < 4; ++a) {
      glEnableVertexAttribArray(a);
      glVertexAttribPointer(a, sizes[a], GL_FLOAT, GL_FALSE, stride,
                            reinterpret_cast<const void*>(static_cast<uintptr_t>(offsets[a]) * sizeof(float)));
    }
    const GLsizei index_count = static_cast<GLsizei>(asset.indices.size());

    // Pass 1: the shadow map.
    glActiveTexture(GL_TEXTURE2);
    const GLuint shadow_map = make_texture(objects, GL_DEPTH_COMPONENT32F, kShadowMapSize, kShadowMapSize,
                                           GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glBindTexture(GL_TEXTURE_2D, 0);  // not bound while it is the render target
    make_framebuffer(objects);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, shadow_map, 0);
    const GLenum no_colour = GL_NONE;
    glDrawBuffers(1, &no_colour);
    glReadBuffer(GL_NONE);
    check_framebuffer("shadow");
    const GLuint shadow_program = build_program(objects, kShadowVertex, kShadowFragment, "shadow");
    glUseProgram(shadow_program);
    set_matrix(shadow_program, "u_light_matrix", light_matrix);
    glViewport(0, 0, kShadowMapSize, kShadowMapSize);
    const float far_depth = 1.0f;
    glClearBufferfv(GL_DEPTH, 0, &far_depth);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.5f, 2.0f);
    glDrawElements(GL_TRIANGLES, index_count, GL_UNSIGNED_INT, nullptr);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(0.0f, 0.0f);

    // Pass 2: the scene.
    glActiveTexture(GL_TEXTURE0);
    make_material_texture(objects, asset.albedo, true);
    glActiveTexture(GL_TEXTURE1);
    make_material_texture(objects, asset.normal, false);
    glActiveTexture(GL_TEXTURE3);  // targets are made on a unit no sampler reads
    const GLuint colour_target = make_texture(objects, GL_RGBA32F, width, height, GL_RGBA, GL_FLOAT, nullptr);
    const GLuint distance_target = make_texture(objects, GL_R32F, width, height, GL_RED, GL_FLOAT, nullptr);
    const GLuint depth_target =
        make_texture(objects, GL_DEPTH_COMPONENT32F, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    // The Lambert shader also writes the albedo it multiplied by (Scene::albedo); the pre-integrated one does not.
    const GLuint albedo_target =
        view.preintegrated ? 0u : make_texture(objects, GL_RGBA32F, width, height, GL_RGBA, GL_FLOAT, nullptr);
    glBindTexture(GL_TEXTURE_2D, 0);
    make_framebuffer(objects);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_target, 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, distance_target, 0);
    if (albedo_target != 0u) glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, albedo_target, 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_target, 0);
    const GLenum colour_buffers[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    glDrawBuffers(albedo_target != 0u ? 3 : 2, colour_buffers);
    check_framebuffer("scene");
    glViewport(0, 0, width, height);
    const float backdrop[4] = {kBackdropIrradiance, kBackdropIrradiance, kBackdropIrradiance, 0.0f};
    const float backdrop_distance[4] = {static_cast<float>(view.backdrop_distance), 0, 0, 0};
    const float backdrop_depth = window_depth(projection, view.backdrop_distance);
    glClearBufferfv(GL_COLOR, 0, backdrop);
    glClearBufferfv(GL_COLOR, 1, backdrop_distance);
    const float no_albedo[4] = {1.0f, 1.0f, 1.0f, 1.0f};  // the backdrop: nothing to divide by
    if (albedo_target != 0u) glClearBufferfv(GL_COLOR, 2, no_albedo);
    glClearBufferfv(GL_DEPTH, 0, &backdrop_depth);

    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_2D, shadow_map);
    glActiveTexture(GL_TEXTURE0);
    const std::string preintegrated_source = view.preintegrated ? preintegrated_fragment_source() : std::string();
    const GLuint program = build_program(objects, kSceneVertex,
                                         view.preintegrated ? preintegrated_source.c_str() : kSceneFragment, "scene");
    glUseProgram(program);
    if (view.preintegrated) {
      // The library's default LUTs (256², curvature 0..1/mm, penumbra 1..32 mm), linear filtering.
      const sss::math::RadialProfile& profile = sss::math::deon_skin_profile();
      sss::math::DiffuseLutDesc dd;
      sss::math::ShadowLutDesc sd;
      std::vector<float> diffuse(4u * dd.width * dd.height), shadow(4u * sd.width * sd.height);
      sss::math::generate_diffuse_lut(profile, dd, 0, diffuse.data());
      sss::math::generate_shadow_lut(profile, sd, 0, shadow.data());
      glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
      for (int unit : {4, 5}) {
        glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
        const std::vector<float>& data = unit == 4 ? diffuse : shadow;
        make_texture(objects, GL_RGBA32F, dd.width, dd.height, GL_RGBA, GL_FLOAT, data.data());
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
      }
      // N_low: the normal map blurred by the red profile at the map's texel size on the mesh (the
      // median over triangles of sqrt(world area / texel area)).
      std::vector<double> texel_sizes;
      const std::size_t stride_floats = HeadAsset::kFloatsPerVertex;
      for (std::size_t t = 0; t + 2 < asset.indices.size(); t += 3) {
        const float* a = &asset.vertices[asset.indices[t] * stride_floats];
        const float* b = &asset.vertices[asset.indices[t + 1] * stride_floats];
        const float* c = &asset.vertices[asset.indices[t + 2] * stride_floats];
        const Vec3 e1{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const Vec3 cr{e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z, e1.x * e2.y - e1.y * e2.x};
        const double world = 0.5 * length(cr);
        const double texels = 0.5 * std::fabs((b[6] - a[6]) * (c[7] - a[7]) - (c[6] - a[6]) * (b[7] - a[7])) *
                              asset.normal.width * asset.normal.height;
        if (world > 0.0 && texels > 1e-6) texel_sizes.push_back(std::sqrt(world / texels) * 1000.0);
      }
      std::nth_element(texel_sizes.begin(), texel_sizes.begin() + static_cast<std::ptrdiff_t>(texel_sizes.size() / 2),
                       texel_sizes.end());
      const double texel_mm = texel_sizes.empty() ? 0.5 : texel_sizes[texel_sizes.size() / 2];
      std::vector<std::uint8_t> rgb(static_cast<std::size_t>(asset.normal.width) * asset.normal.height * 3);
      const int comps = asset.normal.components;
      for (std::size_t i = 0; i < rgb.size() / 3; ++i) {
        for (std::size_t k = 0; k < 3; ++k) rgb[3 * i + k] = asset.normal.pixels[i * static_cast<std::size_t>(comps) + k];
      }
      HeadImage low;
      low.width = asset.normal.width;
      low.height = asset.normal.height;
      low.components = 3;
      low.pixels = sss::math::blur_normal_map(rgb, low.width, low.height, texel_mm, profile, 0);
      glActiveTexture(GL_TEXTURE6);
      make_material_texture(objects, low, false);
      glUniform1i(glGetUniformLocation(program, "u_normal_low"), 6);
      glActiveTexture(GL_TEXTURE0);
      glUniform1i(glGetUniformLocation(program, "u_diffuse_lut"), 4);
      glUniform1i(glGetUniformLocation(program, "u_shadow_lut"), 5);
      glUniform2f(glGetUniformLocation(program, "u_curvature_range"), static_cast<float>(dd.curvature_min_per_mm),
                  static_cast<float>(dd.curvature_max_per_mm));
      glUniform2f(glGetUniformLocation(program, "u_penumbra_range"), static_cast<float>(sd.penumbra_min),
                  static_cast<float>(sd.penumbra_max));
      glUniform1f(glGetUniformLocation(program, "u_world_units_per_mm"), static_cast<float>(sd.world_units_per_mm));
      // 9x9 taps a texel apart: a box 9 texels (~1.8 mm) wide. Wider boxes (4 texels apart: ~7 mm)
      // hold more of the scattering but shadow the head itself where it curves away from the light
      // (relative RMSE at head-mid 0.043 against 0.011 here, measured at 320x180).
      const int pcf_radius = 4;
      const double pcf_step = 1.0;
      glUniform1i(glGetUniformLocation(program, "u_pcf_radius"), pcf_radius);
      glUniform1f(glGetUniformLocation(program, "u_pcf_step"), static_cast<float>(pcf_step));
      glUniform1f(glGetUniformLocation(program, "u_pcf_width"), static_cast<float>((2 * pcf_radius + 1) * pcf_step * texel));
      // Light NDC depth spans 3·radius (near 0.5r, far 3.5r), window depth half of NDC's 2.
      glUniform1f(glGetUniformLocation(program, "u_shadow_texel_depth"), static_cast<float>(texel / (3.0 * radius)));
      const float blend[3] = {1.0f, 0.222f, 0.134f};  // sss_blur_normals' factors for skin
      set_vec3(program, "u_normal_blend", blend);
    }
    // The uniforms of the Lambert shader, for the scene's program and the points' (head_light_at).
    const auto set_lighting = [&](GLuint p) {
      glUniform1i(glGetUniformLocation(p, "u_albedo"), 0);
      glUniform1i(glGetUniformLocation(p, "u_normal_map"), 1);
      glUniform1i(glGetUniformLocation(p, "u_shadow_map"), 2);
      set_matrix(p, "u_view", view_matrix);
      set_matrix(p, "u_projection", projection);
      set_matrix(p, "u_light_matrix", light_matrix);
      glUniform1f(glGetUniformLocation(p, "u_normal_offset"), static_cast<float>(1.5 * texel));
      glUniform1f(glGetUniformLocation(p, "u_depth_bias"), 1e-4f);
      glUniform1f(glGetUniformLocation(p, "u_green_sign"), kNormalMapGreenSign);
      set_vec3(p, "u_key_direction", kKeyDirection);
      set_vec3(p, "u_key_colour", kKeyColour);
      set_vec3(p, "u_fill_direction", kFillDirection);
      set_vec3(p, "u_fill_colour", kFillColour);
      set_vec3(p, "u_ambient", kAmbient);
      glUniform1i(glGetUniformLocation(p, "u_soft_light"), view.soft_light ? 1 : 0);
      glUniform1i(glGetUniformLocation(p, "u_pcf_radius"), kSoftPcfRadius);
      // Light NDC depth spans 3·radius (near 0.5r, far 3.5r), window depth half of NDC's 2.
      glUniform1f(glGetUniformLocation(p, "u_shadow_texel_depth"), static_cast<float>(texel / (3.0 * radius)));
      glUniform2f(glGetUniformLocation(p, "u_light_extent"), static_cast<float>(2 * radius), static_cast<float>(2 * radius));
      glUniform1f(glGetUniformLocation(p, "u_pattern_period"), static_cast<float>(kPatternPeriodMm * 1e-3));
      glUniform1f(glGetUniformLocation(p, "u_pattern_edge"), static_cast<float>(kPatternEdgeMm * 1e-3));
    };
    set_lighting(program);
    glDrawElements(GL_TRIANGLES, index_count, GL_UNSIGNED_INT, nullptr);

    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, scene.irradiance.data());
    glReadBuffer(GL_COLOR_ATTACHMENT1);
    glReadPixels(0, 0, width, height, GL_RED, GL_FLOAT, scene.distance.data());
    glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, scene.window_depth.data());
    if (albedo_target != 0u) {
      scene.albedo.resize(pixels * 4);
      glReadBuffer(GL_COLOR_ATTACHMENT2);
      glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, scene.albedo.data());
    }

    // The points pass reads the material textures still bound on units 0 and 1 and the shadow map on 2.
    if (points_of != nullptr) {
      set_mask(&scene);
      const std::vector<SurfacePoint> points = points_of(scene);
      const GLuint points_program = build_program(objects, kPointsVertex, kSceneFragment, "points");
      glUseProgram(points_program);
      set_lighting(points_program);
      light_at_points(objects, asset, points_program, points, point_light);
    }
    glBindTexture(GL_TEXTURE_2D, 0);
  }
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR)
    throw std::runtime_error("head scene " + name + ": GL error " + std::to_string(error));

  set_mask(&scene);
  return scene;
}

}  // namespace sss_bench::detail
