#include "gpu_scene.hpp"

#include "host_gl_util.hpp"

#include <cstdint>

namespace demo {

namespace {

GLuint upload_texture(GLint internal_format, GLenum format, int width, int height, const void *pixels) {
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, internal_format, width, height, 0, format, GL_UNSIGNED_BYTE, pixels);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glBindTexture(GL_TEXTURE_2D, 0);
  return texture;
}

GLuint upload_image(const gltf_mesh::Image &image, bool srgb) {
  // 1 and 2 components are widened to RGB(A) so that the shaders see grey, not red.
  std::vector<uint8_t> widened;
  const uint8_t *pixels = image.pixels.data();
  int components = image.components;
  if (components <= 2) {
    const size_t count = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
    widened.resize(count * 4);
    for (size_t i = 0; i < count; ++i) {
      const uint8_t grey = image.pixels[i * static_cast<size_t>(components)];
      const uint8_t alpha = components == 2 ? image.pixels[i * 2 + 1] : 255;
      widened[i * 4 + 0] = grey;
      widened[i * 4 + 1] = grey;
      widened[i * 4 + 2] = grey;
      widened[i * 4 + 3] = alpha;
    }
    pixels = widened.data();
    components = 4;
  }
  const bool rgba = components == 4;
  const GLint internal_format = srgb ? (rgba ? GL_SRGB8_ALPHA8 : GL_SRGB8) : (rgba ? GL_RGBA8 : GL_RGB8);
  return upload_texture(internal_format, rgba ? GL_RGBA : GL_RGB, image.width, image.height, pixels);
}

}  // namespace

bool create_gpu_scene(const DemoScene &scene, GpuScene *gpu) {
  const gltf_mesh::Model &model = scene.model;
  glGenVertexArrays(1, &gpu->vao);
  glBindVertexArray(gpu->vao);
  glGenBuffers(1, &gpu->vertex_buffer);
  glBindBuffer(GL_ARRAY_BUFFER, gpu->vertex_buffer);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(model.vertices.size() * sizeof(float)), model.vertices.data(),
               GL_STATIC_DRAW);
  glGenBuffers(1, &gpu->index_buffer);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu->index_buffer);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(model.indices.size() * sizeof(uint32_t)),
               model.indices.data(), GL_STATIC_DRAW);
  const GLsizei stride = static_cast<GLsizei>(gltf_mesh::Model::kFloatsPerVertex * sizeof(float));
  const GLint sizes[4] = {3, 3, 2, 4};
  const size_t offsets[4] = {0, 3, 6, 8};
  for (GLuint a = 0; a < 4; ++a) {
    glEnableVertexAttribArray(a);
    glVertexAttribPointer(a, sizes[a], GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void *>(offsets[a] * sizeof(float)));
  }
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);

  // Images are uploaded once each, as sRGB when some material uses them as base colour.
  std::vector<GLuint> image_textures(model.images.size(), 0);
  std::vector<bool> is_albedo(model.images.size(), false);
  for (const gltf_mesh::Material &m : model.materials)
    if (m.base_color_image >= 0) is_albedo[static_cast<size_t>(m.base_color_image)] = true;
  for (size_t i = 0; i < model.images.size(); ++i) {
    bool used = is_albedo[i];
    for (const gltf_mesh::Material &m : model.materials) used = used || m.normal_image == static_cast<int>(i);
    if (!used) continue;
    image_textures[i] = upload_image(model.images[i], is_albedo[i]);
    gpu->textures.push_back(image_textures[i]);
  }
  const uint8_t white[4] = {255, 255, 255, 255};
  const uint8_t flat[4] = {128, 128, 255, 255};
  const GLuint white_texture = upload_texture(GL_RGBA8, GL_RGBA, 1, 1, white);
  const GLuint flat_texture = upload_texture(GL_RGBA8, GL_RGBA, 1, 1, flat);
  gpu->textures.push_back(white_texture);
  gpu->textures.push_back(flat_texture);
  for (const gltf_mesh::Material &m : model.materials) {
    GpuMaterial g;
    g.albedo = m.base_color_image >= 0 ? image_textures[static_cast<size_t>(m.base_color_image)] : white_texture;
    g.normal = m.normal_image >= 0 ? image_textures[static_cast<size_t>(m.normal_image)] : flat_texture;
    gpu->materials.push_back(g);
  }
  return check_gl("scene upload");
}

void destroy_gpu_scene(GpuScene *gpu) {
  glDeleteVertexArrays(1, &gpu->vao);
  glDeleteBuffers(1, &gpu->vertex_buffer);
  glDeleteBuffers(1, &gpu->index_buffer);
  if (!gpu->textures.empty()) glDeleteTextures(static_cast<GLsizei>(gpu->textures.size()), gpu->textures.data());
  *gpu = GpuScene{};
}

void draw_primitive(const gltf_mesh::Primitive &primitive) {
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(primitive.index_count), GL_UNSIGNED_INT,
                 reinterpret_cast<const void *>(static_cast<size_t>(primitive.first_index) * sizeof(uint32_t)));
}

}  // namespace demo
