#include "web_scene.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "gltf_mesh.hpp"
#include "web_shaders.hpp"

namespace web {

namespace {

constexpr int kShadowSize = 1024;
constexpr GLenum kDrawBuffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
const float kBackground[3] = {0.012f, 0.014f, 0.018f};

GLuint compile(GLenum stage, const char* source, std::string* log) {
  const GLuint shader = glCreateShader(stage);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok == 0) {
    char text[2048] = {};
    glGetShaderInfoLog(shader, sizeof text, nullptr, text);
    *log += text;
  }
  return shader;
}

GLuint link(const char* vertex, const char* fragment, std::string* error) {
  std::string log;
  const GLuint vs = compile(GL_VERTEX_SHADER, vertex, &log);
  const GLuint fs = compile(GL_FRAGMENT_SHADER, fragment, &log);
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok == 0) {
    char text[2048] = {};
    glGetProgramInfoLog(program, sizeof text, nullptr, text);
    *error = "the demo's shader did not build: " + log + text;
    glDeleteProgram(program);
    return 0;
  }
  return program;
}

GLuint texture_2d(GLenum internal_format, int width, int height, GLenum format, GLenum type, const void* pixels,
                  GLenum filter) {
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal_format), width, height, 0, format, type, pixels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter == GL_LINEAR_MIPMAP_LINEAR ? GL_LINEAR : static_cast<GLint>(filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

// A material image (8-bit, 1..4 components) as RGBA8 with mipmaps; sRGB-decoded by the GL for albedo.
GLuint material_texture(const gltf_mesh::Image& image, bool srgb) {
  std::vector<uint8_t> rgba(static_cast<size_t>(image.width) * image.height * 4, 255);
  for (size_t i = 0; i < static_cast<size_t>(image.width) * image.height; ++i) {
    for (int c = 0; c < 4; ++c) {
      const int from = std::min(c, image.components - 1);
      if (c < 3 || image.components == 4) rgba[i * 4 + c] = image.pixels[i * image.components + from];
    }
  }
  const GLuint t = texture_2d(srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                              rgba.data(), GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glGenerateMipmap(GL_TEXTURE_2D);
  return t;
}

// The demo's close-up (demo/camera.cpp preset_camera): 30° field, yawed 20° and pitched 5°, a
// frame 0.583 head heights tall around the face; the key light's orthographic shadow frustum.
View close_up(const gltf_mesh::Model& model, int width, int height, glm::vec3 key) {
  const glm::vec3 lo = glm::make_vec3(model.bounds_min), hi = glm::make_vec3(model.bounds_max);
  const glm::vec3 centre = 0.5f * (lo + hi);
  const float h = std::max(hi.y - lo.y, 1e-6f), radius = 0.5f * glm::length(hi - lo);
  const glm::vec3 target = centre + glm::vec3(0.0f, 0.208f * h, 0.222f * h);
  const float fovy = glm::radians(30.0f), yaw = glm::radians(20.0f), pitch = glm::radians(5.0f);
  const float distance = 0.583f * h / (2.0f * std::tan(0.5f * fovy));
  const glm::vec3 offset(std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch));
  const glm::vec3 eye = target + offset * distance;
  const glm::mat4 view = glm::lookAt(eye, target, glm::vec3(0.0f, 1.0f, 0.0f));
  const float centre_depth = glm::dot(centre - eye, -offset);
  const float far_plane = std::max(centre_depth + radius, 1e-3f);
  const float near_plane = std::max(centre_depth - radius, far_plane * 2e-3f);
  const glm::mat4 projection =
      glm::perspective(fovy, static_cast<float>(width) / static_cast<float>(height), near_plane, far_plane);
  const glm::mat4 light_view = glm::lookAt(centre + key * (2.0f * radius), centre, glm::vec3(0.0f, 1.0f, 0.0f));
  const glm::mat4 light_projection = glm::ortho(-radius, radius, -radius, radius, 0.5f * radius, 3.5f * radius);
  View v{};
  std::memcpy(v.projection, glm::value_ptr(projection), sizeof v.projection);
  std::memcpy(v.view_projection, glm::value_ptr(projection * view), sizeof v.view_projection);
  std::memcpy(v.eye, glm::value_ptr(eye), sizeof v.eye);
  std::memcpy(v.light_matrix, glm::value_ptr(light_projection * light_view), sizeof v.light_matrix);
  return v;
}

}  // namespace

Scene::~Scene() { destroy(); }

void Scene::destroy() {
  const GLuint textures[] = {albedo_, normal_map_, shadow_map_, diffuse_, specular_, depth_, scattered_, image_};
  glDeleteTextures(8, textures);
  const GLuint framebuffers[] = {shadow_fbo_, lit_fbo_, image_fbo_};
  glDeleteFramebuffers(3, framebuffers);
  const GLuint buffers[] = {vertex_buffer_, index_buffer_};
  glDeleteBuffers(2, buffers);
  const GLuint arrays[] = {vao_, empty_vao_};
  glDeleteVertexArrays(2, arrays);
  glDeleteProgram(shadow_program_);
  glDeleteProgram(lit_program_);
  glDeleteProgram(composite_program_);
}

bool Scene::init(const gltf_mesh::Model& model, int width, int height, std::string* error) {
  width_ = width;
  height_ = height;
  // The portrait lighting of demo/scene.cpp: a warm key above and to the subject's right, a dim cool fill.
  const glm::vec3 key = glm::normalize(glm::vec3(-0.55f, 0.62f, 0.56f));
  const glm::vec3 fill = glm::normalize(glm::vec3(0.8f, -0.1f, 0.6f));
  const float directions[6] = {key.x, key.y, key.z, fill.x, fill.y, fill.z};
  const float irradiance[6] = {1.25f, 1.2f, 1.12f, 0.10f, 0.11f, 0.13f};
  std::memcpy(light_direction_, directions, sizeof directions);
  std::memcpy(light_irradiance_, irradiance, sizeof irradiance);
  view_ = close_up(model, width, height, key);

  const gltf_mesh::Material& material = model.materials.at(0);
  if (material.base_color_image < 0 || material.normal_image < 0) {
    *error = "the model's first material needs a base colour and a normal texture";
    return false;
  }
  upload_mesh(model);
  albedo_ = material_texture(model.images.at(static_cast<size_t>(material.base_color_image)), true);
  normal_map_ = material_texture(model.images.at(static_cast<size_t>(material.normal_image)), false);
  shadow_program_ = link(kShadowVertex, kShadowFragment, error);
  lit_program_ = link(kLitVertex.c_str(), kLitFragment, error);
  composite_program_ = link(kFullscreenVertex, kCompositeFragment, error);
  if (shadow_program_ == 0 || lit_program_ == 0 || composite_program_ == 0) return false;
  if (!build_targets()) {
    *error = "the RGBA16F + DEPTH24_STENCIL8 lighting target is incomplete (no EXT_color_buffer_float?)";
    return false;
  }
  if (glGetError() != GL_NO_ERROR) {
    *error = "a GL error while building the scene";
    return false;
  }
  return true;
}

void Scene::upload_mesh(const gltf_mesh::Model& model) {
  glGenVertexArrays(1, &vao_);
  glGenVertexArrays(1, &empty_vao_);
  glBindVertexArray(vao_);
  glGenBuffers(1, &vertex_buffer_);
  glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(model.vertices.size() * sizeof(float)), model.vertices.data(),
               GL_STATIC_DRAW);
  const GLsizei stride = gltf_mesh::Model::kFloatsPerVertex * sizeof(float);
  const GLint sizes[4] = {3, 3, 2, 4};  // position, normal, texcoord, tangent
  size_t offset = 0;
  for (GLuint a = 0; a < 4; ++a) {
    glEnableVertexAttribArray(a);
    glVertexAttribPointer(a, sizes[a], GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offset));
    offset += static_cast<size_t>(sizes[a]) * sizeof(float);
  }
  glGenBuffers(1, &index_buffer_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(model.indices.size() * sizeof(uint32_t)),
               model.indices.data(), GL_STATIC_DRAW);
  index_count_ = static_cast<GLsizei>(model.indices.size());
  glBindVertexArray(0);
}

// The shadow map, the lit pass's targets (what the library reads and writes) and the RGBA8 image.
bool Scene::build_targets() {
  shadow_map_ = texture_2d(GL_DEPTH_COMPONENT24, kShadowSize, kShadowSize, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT,
                           nullptr, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glGenFramebuffers(1, &shadow_fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, shadow_fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, shadow_map_, 0);

  diffuse_ = texture_2d(GL_RGBA16F, width_, height_, GL_RGBA, GL_HALF_FLOAT, nullptr, GL_NEAREST);
  specular_ = texture_2d(GL_RGBA16F, width_, height_, GL_RGBA, GL_HALF_FLOAT, nullptr, GL_NEAREST);
  scattered_ = texture_2d(GL_RGBA16F, width_, height_, GL_RGBA, GL_HALF_FLOAT, nullptr, GL_NEAREST);
  depth_ = texture_2d(GL_DEPTH24_STENCIL8, width_, height_, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, nullptr, GL_NEAREST);
  glGenFramebuffers(1, &lit_fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, lit_fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, diffuse_, 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, specular_, 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, depth_, 0);
  glDrawBuffers(2, kDrawBuffers);
  const bool lit_complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;

  image_ = texture_2d(GL_RGBA8, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, nullptr, GL_NEAREST);
  glGenFramebuffers(1, &image_fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, image_fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, image_, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindTexture(GL_TEXTURE_2D, 0);
  return lit_complete;
}

void Scene::draw_shadow() const {
  glBindFramebuffer(GL_FRAMEBUFFER, shadow_fbo_);
  glViewport(0, 0, kShadowSize, kShadowSize);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(2.0f, 4.0f);
  glUseProgram(shadow_program_);
  glUniformMatrix4fv(glGetUniformLocation(shadow_program_, "u_light_matrix"), 1, GL_FALSE, view_.light_matrix);
  glBindVertexArray(vao_);
  glDrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
  glDisable(GL_POLYGON_OFFSET_FILL);
}

void Scene::draw_lit() const {
  glBindFramebuffer(GL_FRAMEBUFFER, lit_fbo_);
  glViewport(0, 0, width_, height_);
  const float zero[4] = {0, 0, 0, 0};
  glClearBufferfv(GL_COLOR, 0, zero);
  glClearBufferfv(GL_COLOR, 1, zero);
  glClearBufferfi(GL_DEPTH_STENCIL, 0, 1.0f, 0);
  glUseProgram(lit_program_);
  const GLuint p = lit_program_;
  glUniformMatrix4fv(glGetUniformLocation(p, "u_view_projection"), 1, GL_FALSE, view_.view_projection);
  glUniformMatrix4fv(glGetUniformLocation(p, "u_light_matrix"), 1, GL_FALSE, view_.light_matrix);
  glUniform1f(glGetUniformLocation(p, "u_shadow_texel"), 1.0f / kShadowSize);
  glUniform3fv(glGetUniformLocation(p, "u_light_direction"), 2, light_direction_);
  glUniform3fv(glGetUniformLocation(p, "u_light_irradiance"), 2, light_irradiance_);
  glUniform3fv(glGetUniformLocation(p, "u_eye"), 1, view_.eye);
  glUniform1f(glGetUniformLocation(p, "u_sss_strength"), 1.0f);
  glUniform1i(glGetUniformLocation(p, "u_albedo"), 0);
  glUniform1i(glGetUniformLocation(p, "u_normal_map"), 1);
  glUniform1i(glGetUniformLocation(p, "u_shadow_map"), 2);
  const GLuint textures[3] = {albedo_, normal_map_, shadow_map_};
  for (GLuint i = 0; i < 3; ++i) {
    glActiveTexture(GL_TEXTURE0 + i);
    glBindTexture(GL_TEXTURE_2D, textures[i]);
  }
  glBindVertexArray(vao_);
  glDrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
  glDisable(GL_DEPTH_TEST);
}

void Scene::composite(bool scattered, float split) const {
  glBindFramebuffer(GL_FRAMEBUFFER, image_fbo_);
  glViewport(0, 0, width_, height_);
  const GLuint p = composite_program_;
  glUseProgram(p);
  glUniform1i(glGetUniformLocation(p, "u_before"), 0);
  glUniform1i(glGetUniformLocation(p, "u_after"), 1);
  glUniform1i(glGetUniformLocation(p, "u_specular"), 2);
  glUniform1f(glGetUniformLocation(p, "u_split"), scattered ? split : 2.0f);
  glUniform3fv(glGetUniformLocation(p, "u_background"), 1, kBackground);
  const GLuint textures[3] = {diffuse_, scattered ? scattered_ : diffuse_, specular_};
  for (GLuint i = 0; i < 3; ++i) {
    glActiveTexture(GL_TEXTURE0 + i);
    glBindTexture(GL_TEXTURE_2D, textures[i]);
  }
  glBindVertexArray(empty_vao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glActiveTexture(GL_TEXTURE0);
}

sss_result Scene::render(sss_context* sss, float split) {
  draw_shadow();
  draw_lit();
  sss_result r = SSS_OK;
  if (sss != nullptr) {
    r = sss_set_camera(sss, view_.projection);
    if (r == SSS_OK) {
      // OpenGL ES 3.0 cannot be asked for a texture's format: the frame describes every texture.
      sss_frame frame{};
      frame.struct_size = sizeof frame;
      frame.color_texture = diffuse_;
      frame.depth_texture = depth_;
      frame.output_texture = scattered_;
      frame.color_format = GL_RGBA16F;
      frame.depth_format = GL_DEPTH24_STENCIL8;
      frame.output_format = GL_RGBA16F;
      frame.texture_width = width_;
      frame.texture_height = height_;
      r = sss_apply_frame(sss, &frame);
    }
  }
  composite(sss != nullptr && r == SSS_OK, split);
  return r;
}

sss_result Scene::prepare(sss_context* sss) const {
  sss_prepare_desc d{};  // the frame of render(), as sss_prepare_desc says it
  d.struct_size = sizeof d;
  d.width = width_;
  d.height = height_;
  d.color_format = GL_RGBA16F;
  d.output_format = GL_RGBA16F;
  d.depth_format = GL_DEPTH24_STENCIL8;
  return sss_prepare(sss, &d);
}

void Scene::read_pixels(uint8_t* out) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, image_fbo_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, out);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

void Scene::read_pixel(uint8_t out[4]) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, image_fbo_);
  glReadPixels(width_ / 2, height_ / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

void Scene::blit_to(GLuint framebuffer) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, image_fbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
}

std::vector<uint8_t> flip_rows(const std::vector<uint8_t>& bottom_first, int width, int height) {
  std::vector<uint8_t> out(bottom_first.size());
  const size_t row = static_cast<size_t>(width) * 4;
  for (int y = 0; y < height; ++y) {
    std::memcpy(out.data() + static_cast<size_t>(y) * row, bottom_first.data() + static_cast<size_t>(height - 1 - y) * row, row);
  }
  return out;
}

}  // namespace web
