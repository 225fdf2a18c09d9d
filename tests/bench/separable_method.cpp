// The library's separable filter, through its public C API, as a host would call it.
#include <algorithm>
#include <stdexcept>
#include <vector>

#include "../support/kernel_of.hpp"
#include "method.hpp"
#include "sss/sss_tools.h"

namespace sss_bench {

namespace {

class SeparableMethod : public Method {
 public:
  SeparableMethod(const GlLoader& loader, int taps, bool follow, uint32_t create_flags,
                  const KernelChoice* kernel = nullptr)
      : taps_(taps), follow_(follow), restores_state_((create_flags & SSS_CREATE_NO_STATE_RESTORE) == 0) {
    if (kernel != nullptr) kernel_ = *kernel;
    sss_create_desc desc = {};
    desc.struct_size = sizeof desc;
    desc.flags = create_flags;
    desc.get_proc_address = loader.get_proc_address;
    desc.get_proc_address_user = loader.user;
    if (sss_create(&desc, &ctx_) != SSS_OK) throw std::runtime_error(sss_last_error(nullptr));
  }
  ~SeparableMethod() override { sss_destroy(ctx_); }

  std::string name() const override {
    if (!kernel_.name.empty()) return kernel_.name;
    return restores_state_ ? "separable" : "separable-no-restore";
  }
  int taps() const override { return taps_; }
  bool follow_surface() const override { return follow_; }
  int passes() const override { return passes_; }

  bool run(const GpuScene& scene, GLuint output, std::string* error) override {
    sss_settings s;
    sss_default_settings(&s);
    s.world_units_per_mm = (scene.world_units_per_mm);
    s.taps = taps_;
    s.flags = follow_ ? SSS_FOLLOW_SURFACE : 0u;
    // The filter's own passes, on the plain fragment path: what these rows have always timed. The
    // default path (SSS_PATH_AUTO) is timed by the in-place rows ("separable-auto", ...).
    s.path = SSS_PATH_FRAGMENT;
    if (!kernel_.name.empty()) {
      sss_test::kernel_of(s).family = kernel_.family;
      sss_test::kernel_of(s).rank = kernel_.rank;
      if (kernel_.profile != nullptr) sss_test::kernel_of(s).profile = *kernel_.profile;
      s.jitter = kernel_.jitter;
    }
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
    sss_stats stats;
    stats.struct_size = sizeof stats;
    // The library's draws: its inputs, a pass pair per term, the copy of the culled pixels.
    if (sss_get_stats(ctx_, &stats) == SSS_OK) passes_ = static_cast<int>(stats.last_frame_passes);
    return true;
  }

 private:
  KernelChoice kernel_;
  int passes_ = 4;
  int taps_;
  bool follow_;
  bool restores_state_;
  sss_context* ctx_ = nullptr;
};

}  // namespace

std::unique_ptr<Method> make_separable_method(const GlLoader& loader, int taps, bool follow_surface,
                                              uint32_t create_flags) {
  return std::make_unique<SeparableMethod>(loader, taps, follow_surface, create_flags);
}

const std::vector<KernelChoice>& kernel_family_choices() {
  static const std::vector<KernelChoice> choices = {
      {"kernel-separable-jitter-33", SSS_KERNEL_SEPARABLE, 1, 0.33f},
      {"kernel-sum-of-gaussians-2", SSS_KERNEL_SUM_OF_GAUSSIANS, 2, 0.0f},
      {"kernel-svd-1", SSS_KERNEL_SVD, 1, 0.0f},
      {"kernel-svd-2", SSS_KERNEL_SVD, 2, 0.0f},
      {"kernel-svd-3", SSS_KERNEL_SVD, 3, 0.0f},
      {"kernel-preintegrated", SSS_KERNEL_PREINTEGRATED, 1, 0.0f},
      {"kernel-preintegrated-2", SSS_KERNEL_PREINTEGRATED, 2, 0.0f},
      {"kernel-guided", SSS_KERNEL_GUIDED, 1, 0.0f},
      {"kernel-artist", SSS_KERNEL_ARTIST, 1, 0.0f},
  };
  return choices;
}

const KernelChoice& sum_of_gaussians_baseline() {
  static const KernelChoice baseline = {"sum-of-gaussians", SSS_KERNEL_SUM_OF_GAUSSIANS, 6, 0.0f};
  return baseline;
}

std::unique_ptr<Method> make_kernel_family_method(const GlLoader& loader, const KernelChoice& kernel, int taps) {
  return std::make_unique<SeparableMethod>(loader, taps, true, 0u, &kernel);
}

}  // namespace sss_bench
