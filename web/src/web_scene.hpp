// The web demo's renderer: the head lit into the targets the library reads (diffuse RGBA16F with
// alpha = strength, a DEPTH24_STENCIL8 depth), the library's sss_apply_frame, the composite into an
// RGBA8 image. The same code runs in the browser (WebGL2, Emscripten) and natively on OpenGL ES 3.0
// (web/src/web_frame.cpp), which is how the browser test compares the two. Not part of the library.
#pragma once

#include <GLES3/gl3.h>

#include <cstdint>
#include <string>
#include <vector>

#include <sss/sss.h>

namespace gltf_mesh {
struct Model;
}

namespace web {

// The camera and lights of the demo's close-up (demo/camera.cpp, demo/scene.cpp): a column-major
// projection for sss_set_camera and the view-projection for the lit pass.
struct View {
  float projection[16];
  float view_projection[16];
  float eye[3];
  float light_matrix[16];  // the key light's shadow-map projection x view
};

class Scene {
 public:
  Scene() = default;
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;
  ~Scene();

  // Uploads the mesh and its two textures and builds the programs and targets (width x height).
  // False with *error set on failure.
  bool init(const gltf_mesh::Model& model, int width, int height, std::string* error);
  const View& view() const { return view_; }
  int width() const { return width_; }
  int height() const { return height_; }

  // One frame: shadow map, lit pass, then (sss != NULL) sss_apply_frame from the diffuse into the
  // scattered target, then the composite (texture x < split shows the unscattered diffuse) into the
  // RGBA8 image. Returns what sss_apply_frame returned (SSS_OK when sss is NULL); on an error the
  // image shows the unscattered frame, never a half-written one.
  sss_result render(sss_context* sss, float split);
  // sss_prepare for the frames render() describes, with the settings `sss` holds now: the next frame
  // compiles and allocates nothing (no hitch when a knob changes).
  sss_result prepare(sss_context* sss) const;
  // The RGBA8 image, bottom row first (glReadPixels order), width * height * 4 bytes.
  void read_pixels(uint8_t* out) const;
  // One pixel of the image: a read that waits for the frame to finish.
  void read_pixel(uint8_t out[4]) const;
  // Draws the image onto the bound draw framebuffer (the canvas), same size.
  void blit_to(GLuint framebuffer) const;

 private:
  void upload_mesh(const gltf_mesh::Model& model);
  bool build_targets();
  void draw_shadow() const;
  void draw_lit() const;
  void composite(bool scattered, float split) const;
  void destroy();

  int width_ = 0, height_ = 0;
  GLsizei index_count_ = 0;
  View view_{};
  float light_direction_[6] = {};
  float light_irradiance_[6] = {};
  GLuint vao_ = 0, vertex_buffer_ = 0, index_buffer_ = 0, albedo_ = 0, normal_map_ = 0;
  GLuint shadow_map_ = 0, shadow_fbo_ = 0, shadow_program_ = 0, lit_program_ = 0, composite_program_ = 0;
  GLuint diffuse_ = 0, specular_ = 0, depth_ = 0, scattered_ = 0, lit_fbo_ = 0;
  GLuint image_ = 0, image_fbo_ = 0, empty_vao_ = 0;
};

// The RGBA8 image as top-row-first RGBA bytes (flipped from read_pixels) for PNG writers and pages.
std::vector<uint8_t> flip_rows(const std::vector<uint8_t>& bottom_first, int width, int height);

}  // namespace web
