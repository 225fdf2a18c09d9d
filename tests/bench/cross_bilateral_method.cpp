// The library's cross-bilateral mode (Mikkelsen 2010), through the public C API as a host would call it.
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "method.hpp"
#include "sss/sss_tools.h"

using namespace host_gl;

namespace sss_bench {

namespace {

class CrossBilateralMethod : public Method {
 public:
  CrossBilateralMethod(const GlLoader& loader, int taps, bool tilt_correction)
      : taps_(taps), tilt_correction_(tilt_correction) {
    sss_create_desc desc = {};
    desc.struct_size = sizeof desc;
    desc.get_proc_address = loader.get_proc_address;
    desc.get_proc_address_user = loader.user;
    if (sss_create(&desc, &ctx_) != SSS_OK) throw std::runtime_error(sss_last_error(nullptr));
  }
  ~CrossBilateralMethod() override {
    sss_destroy(ctx_);
    if (zero_normals_ != 0) glDeleteTextures(1, &zero_normals_);
  }

  std::string name() const override { return tilt_correction_ ? "cross-bilateral" : "cross-bilateral-no-tilt"; }
  int taps() const override { return taps_; }
  bool follow_surface() const override { return false; }
  int passes() const override { return 2; }

  bool run(const GpuScene& scene, GLuint output, std::string* error) override {
    sss_settings s;
    sss_default_settings(&s);
    s.world_units_per_mm = (scene.world_units_per_mm);
    s.mode = SSS_MODE_CROSS_BILATERAL;
    s.cbf_taps = taps_;
    s.cbf_profile = SSS_PROFILE_SKIN_DEON;
    s.cbf_r_max_mm = 8.0f;  // d'Eon's radius of significant contributions for skin (Mikkelsen §5)
    sss_frame frame = {};
    frame.struct_size = sizeof frame;
    frame.color_texture = scene.irradiance;
    frame.depth_texture = scene.depth;
    frame.output_texture = output;
    if (!tilt_correction_) {
      // A zero normal means "no cosine correction" (sss_frame.normal_texture): the footprint is the
      // projected sphere alone, which is what the per-axis correction is measured against.
      ensure_zero_normals(scene.width, scene.height);
      frame.normal_texture = zero_normals_;
    }
    if (sss_set_settings(ctx_, &s) != SSS_OK || sss_set_camera(ctx_, scene.projection.data()) != SSS_OK ||
        sss_apply_frame(ctx_, &frame) != SSS_OK) {
      *error = sss_last_error(ctx_);
      return false;
    }
    return true;
  }

 private:
  void ensure_zero_normals(int width, int height) {
    if (zero_normals_ != 0 && normals_width_ == width && normals_height_ == height) return;
    if (zero_normals_ == 0) glGenTextures(1, &zero_normals_);
    const std::vector<float> zeros(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0.0f);
    glBindTexture(GL_TEXTURE_2D, zero_normals_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, width, height, 0, GL_RGBA, GL_FLOAT, zeros.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    normals_width_ = width;
    normals_height_ = height;
  }

  int taps_;
  bool tilt_correction_;
  sss_context* ctx_ = nullptr;
  GLuint zero_normals_ = 0;
  int normals_width_ = 0, normals_height_ = 0;
};

}  // namespace

std::unique_ptr<Method> make_cross_bilateral_method(const GlLoader& loader, int taps, bool tilt_correction) {
  return std::make_unique<CrossBilateralMethod>(loader, taps, tilt_correction);
}

}  // namespace sss_bench
