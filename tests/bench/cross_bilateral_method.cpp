// The library's cross-bilateral mode (Mikkelsen 2010), through the public C API as a host would call it.
#include <stdexcept>

#include "method.hpp"
#include "sss/sss.h"

namespace sss_bench {

namespace {

class CrossBilateralMethod : public Method {
 public:
  CrossBilateralMethod(const GlLoader& loader, int taps) : taps_(taps) {
    sss_create_desc desc = {};
    desc.struct_size = sizeof desc;
    desc.get_proc_address = loader.get_proc_address;
    desc.get_proc_address_user = loader.user;
    if (sss_create(&desc, &ctx_) != SSS_OK) throw std::runtime_error(sss_last_error(nullptr));
  }
  ~CrossBilateralMethod() override { sss_destroy(ctx_); }

  std::string name() const override { return "cross-bilateral"; }
  int taps() const override { return taps_; }
  bool follow_surface() const override { return false; }
  int passes() const override { return 2; }

  bool run(const GpuScene& scene, GLuint output, std::string* error) override {
    sss_settings s;
    sss_default_settings(&s);
    s.width = sss_width_for_world_units_per_mm(scene.world_units_per_mm);
    s.mode = SSS_MODE_CROSS_BILATERAL;
    s.cbf_taps = taps_;
    s.cbf_profile = SSS_MATERIAL_SKIN;
    s.cbf_r_max_mm = 8.0f;  // d'Eon's radius of significant contributions for skin (Mikkelsen §5)
    sss_frame frame = {};
    frame.struct_size = sizeof frame;
    frame.color_texture = scene.irradiance;
    frame.depth_texture = scene.depth;
    frame.output_texture = output;
    if (sss_set_settings(ctx_, &s) != SSS_OK || sss_set_camera(ctx_, scene.projection.data()) != SSS_OK ||
        sss_apply_frame(ctx_, &frame) != SSS_OK) {
      *error = sss_last_error(ctx_);
      return false;
    }
    return true;
  }

 private:
  int taps_;
  sss_context* ctx_ = nullptr;
};

}  // namespace

std::unique_ptr<Method> make_cross_bilateral_method(const GlLoader& loader, int taps) {
  return std::make_unique<CrossBilateralMethod>(loader, taps);
}

}  // namespace sss_bench
