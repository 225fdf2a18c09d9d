// Several materials in one pass pair (issue 23), timed against one profile in the same run: the
// library written back in place as a host's frame calls it (like in_place_method.cpp: only
// sss_set_camera and sss_apply_frame are timed), its settings set once before the first frame.
//   "separable-one-profile"  sss_set_settings with the defaults (d'Eon's skin, eq. (1) kernel), no
//                            profile texture: every translucent pixel is skin.
//   "separable-profiles"     sss_set_profiles with skin (the defaults), Jensen's marble and cream (a
//                            rank-1 pre-integrated kernel each: sss_kernel_desc{SSS_KERNEL_PREINTEGRATED,
//                            rank 1}) or the scene's own materials, and the scene's R8UI profile/object
//                            texture (GpuScene::profile: on a one-material scene, profile 0 of object 1
//                            everywhere, so the frame runs the selection and the ID test for nothing).
// Both take the library's default path (SSS_PATH_AUTO: the masked fragment passes on a software
// rasteriser; a frame with a profile texture never takes the compute path).
#include <vector>

#include "library_frame_method.hpp"

using namespace host_gl;

namespace sss_bench {

namespace {

class ProfilesMethod : public LibraryFrameMethod {
 public:
  ProfilesMethod(const GlLoader& loader, int taps, bool per_pixel)
      : LibraryFrameMethod(loader), taps_(taps), per_pixel_(per_pixel) {}

  std::string name() const override { return per_pixel_ ? "separable-profiles" : "separable-one-profile"; }
  int taps() const override { return taps_; }
  bool follow_surface() const override { return true; }
  int passes() const override { return 2; }

  void before_run(const GpuScene& scene) override {
    if (ensure_work(scene)) set_ = false;
    if (!set_) set_ = set_profiles(scene);
    blit(scene.irradiance, work_, scene.width, scene.height);
  }

  bool run(const GpuScene& scene, GLuint /*output*/, std::string* error) override {
    if (!set_) {
      *error = "sss_set_settings / sss_set_profiles: " + std::string(sss_last_error(ctx_));
      return false;
    }
    sss_frame frame = {};
    frame.struct_size = sizeof frame;
    frame.color_texture = work_;
    frame.depth_texture = scene.depth;
    if (per_pixel_) {
      frame.profile_texture = scene.profile;
      frame.profile_format = GL_R8UI;
    }
    if (sss_set_camera(ctx_, scene.projection.data()) != SSS_OK || sss_apply_frame(ctx_, &frame) != SSS_OK) {
      *error = sss_last_error(ctx_);
      return false;
    }
    return true;
  }

 private:
  // The defaults at the scene's scale as profile 0; with per_pixel_, the scene's other materials (a
  // one-material scene: marble and cream, so that several profiles are set) as rank-1 pre-integrated
  // kernels with profile 0's taps, flags and path.
  bool set_profiles(const GpuScene& scene) {
    sss_settings base;
    sss_default_settings(&base);
    base.world_units_per_mm = scene.world_units_per_mm;
    base.taps = taps_;
    base.flags = SSS_FOLLOW_SURFACE;
    if (!per_pixel_) return sss_set_settings(ctx_, &base) == SSS_OK;
    std::vector<int> materials = scene.profile_materials;
    if (materials.size() < 2) materials = {SSS_PROFILE_SKIN_DEON, SSS_PROFILE_MARBLE, SSS_PROFILE_CREAM};
    kernels_.assign(materials.size(), sss_kernel_desc{});
    std::vector<sss_settings> profiles(materials.size(), base);
    for (std::size_t i = 1; i < materials.size(); ++i) {
      sss_default_kernel_desc(&kernels_[i]);
      kernels_[i].family = SSS_KERNEL_PREINTEGRATED;
      kernels_[i].rank = 1;
      kernels_[i].profile.profile = materials[i];
      profiles[i].kernel = &kernels_[i];
    }
    return sss_set_profiles(ctx_, profiles.data(), static_cast<uint32_t>(profiles.size())) == SSS_OK;
  }

  int taps_;
  bool per_pixel_;
  bool set_ = false;
  std::vector<sss_kernel_desc> kernels_;
};

}  // namespace

std::unique_ptr<Method> make_profiles_method(const GlLoader& loader, int taps, bool per_pixel) {
  return std::make_unique<ProfilesMethod>(loader, taps, per_pixel);
}

}  // namespace sss_bench
