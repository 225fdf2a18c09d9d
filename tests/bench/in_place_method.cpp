// The library as a host's frame calls it: written back in place into the host's lit colour, with the
// options that skip work a frame does not need (the region of translucent pixels), and with a
// texturing mode over an albedo (sss_settings.texturing): the time of its divide and multiply.
// That albedo is a constant 0.5, so each mode's exact answer is the scene's own reference
// (A_post · R ∗ (E·A / A_post) = R ∗ E·A for a constant A, the scene's colour being E·A), and
// post-scatter's division and product by 0.5 are exact: its rows score as the pre-scatter row
// beside them. Only sss_apply_frame is timed: refilling the colour before each frame and copying
// the result out for scoring happen outside the clock (Method::before_run / after_run).
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "library_frame_method.hpp"
#include "math/separable_kernel.hpp"

using namespace host_gl;

namespace sss_bench {

namespace {

class InPlaceMethod : public LibraryFrameMethod {
 public:
  InPlaceMethod(const GlLoader& loader, int taps, bool region, uint32_t path, uint32_t texturing)
      : LibraryFrameMethod(loader), taps_(taps), region_(region), path_(path), texturing_(texturing) {}
  ~InPlaceMethod() override {
    if (albedo_ != 0) glDeleteTextures(1, &albedo_);
  }

  std::string name() const override {
    const std::string base = path_ == SSS_PATH_COMPUTE           ? "separable-compute"
                             : path_ == SSS_PATH_AUTO            ? "separable-auto"
                             : path_ == SSS_PATH_FRAGMENT_MASKED ? "separable-masked"
                             : path_ == SSS_PATH_HALF_RESOLUTION ? "separable-half"
                                                                 : "separable";
    const std::string mode = texturing_ == SSS_TEXTURING_POST_SCATTER           ? "-post-scatter"
                             : texturing_ == SSS_TEXTURING_PRE_AND_POST_SCATTER ? "-pre-and-post-scatter"
                                                                                : "";
    if (region_) return base + "-region" + mode;
    return (path_ == SSS_PATH_FRAGMENT ? std::string("separable-in-place") : base) + mode;
  }
  int taps() const override { return taps_; }
  bool follow_surface() const override { return true; }
  int passes() const override { return 2; }

  void before_run(const GpuScene& scene) override {
    prepare(scene);
    blit(scene.irradiance, work_, scene.width, scene.height);
  }

  bool run(const GpuScene& scene, GLuint /*output*/, std::string* error) override {
    sss_settings s;
    sss_default_settings(&s);
    s.world_units_per_mm = (scene.world_units_per_mm);
    s.taps = taps_;
    s.flags = SSS_FOLLOW_SURFACE;
    s.path = path_;
    s.texturing = texturing_;
    sss_frame frame = {};
    frame.struct_size = sizeof frame;
    frame.color_texture = work_;
    frame.depth_texture = scene.depth;
    if (texturing_ != SSS_TEXTURING_PRE_SCATTER) frame.albedo_texture = albedo_;
    if (region_) {
      frame.flags |= SSS_FRAME_REGION;
      for (int i = 0; i < 4; ++i) frame.region[i] = region_rect_[static_cast<std::size_t>(i)];
    }
    if (sss_set_settings(ctx_, &s) != SSS_OK || sss_set_camera(ctx_, scene.projection.data()) != SSS_OK ||
        sss_apply_frame(ctx_, &frame) != SSS_OK) {
      *error = sss_last_error(ctx_);
      return false;
    }
    return true;
  }

 private:
  // The work texture for this scene's size, and the region a host would pass: the bounding
  // rectangle of the translucent pixels, padded by the kernel's reach in pixels at the nearest
  // translucent pixel (the kernel's 2 mm range, at alpha 1), clipped to the frame; empty when none
  // is. A texturing mode's albedo is made with the work texture, at its size.
  void prepare(const GpuScene& scene) {
    if (ensure_work(scene) && texturing_ != SSS_TEXTURING_PRE_SCATTER) {
      if (albedo_ == 0) glGenTextures(1, &albedo_);
      const std::vector<float> half_grey(static_cast<std::size_t>(scene.width) * scene.height * 4, 0.5f);
      glBindTexture(GL_TEXTURE_2D, albedo_);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, scene.width, scene.height, 0, GL_RGBA, GL_FLOAT, half_grey.data());
      glBindTexture(GL_TEXTURE_2D, 0);
    }
    // Recomputed before every frame (untimed): a host would project its meshes' bounds each frame.
    int x0 = scene.width, y0 = scene.height, x1 = -1, y1 = -1;
    for (int y = 0; y < scene.height; ++y) {
      for (int x = 0; x < scene.width; ++x) {
        if (!(scene.irradiance_half[(static_cast<std::size_t>(y) * scene.width + x) * 4 + 3] > 0.0f)) continue;
        x0 = std::min(x0, x);
        y0 = std::min(y0, y);
        x1 = std::max(x1, x);
        y1 = std::max(y1, y);
      }
    }
    if (x1 < 0) {
      region_rect_ = {0, 0, 0, 0};
      return;
    }
    const double range_mm = sss::math::kSeparableKernelRangeMm;
    const double world_per_mm = scene.world_units_per_mm;
    const double pixels_per_mm = std::max(std::fabs(scene.projection[0]) * 0.5 * scene.width,
                                          std::fabs(scene.projection[5]) * 0.5 * scene.height) *
                                 world_per_mm;
    // Perspective scenes: clip w is the view distance, so the nearest translucent pixel has the
    // widest kernel (alpha at most 1).
    const int pad = static_cast<int>(std::ceil(range_mm * pixels_per_mm / scene.nearest_translucent_distance)) + 2;
    x0 = std::max(0, x0 - pad);
    y0 = std::max(0, y0 - pad);
    x1 = std::min(scene.width - 1, x1 + pad);
    y1 = std::min(scene.height - 1, y1 + pad);
    region_rect_ = {x0, y0, x1 - x0 + 1, y1 - y0 + 1};
  }

  int taps_;
  bool region_;
  uint32_t path_;
  uint32_t texturing_;
  GLuint albedo_ = 0;  // the constant 0.5 albedo of a texturing mode, at the work texture's size
  std::array<int, 4> region_rect_ = {0, 0, 0, 0};
};

}  // namespace

std::unique_ptr<Method> make_in_place_method(const GlLoader& loader, int taps, bool region, uint32_t path,
                                             uint32_t texturing) {
  return std::make_unique<InPlaceMethod>(loader, taps, region, path, texturing);
}

}  // namespace sss_bench
