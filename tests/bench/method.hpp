// A screen-space subsurface-scattering method the benchmark times and scores: the library's
// separable filter, and the baselines a user would compare it with (sum of Gaussians, exact 2D),
// plus a two-pass copy that every time is normalised by.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "gpu_scene.hpp"
#include "sss/sss_tools.h"

namespace sss_bench {

class Method {
 public:
  virtual ~Method() = default;
  virtual std::string name() const = 0;  // "separable", "cross-bilateral", "sum-of-gaussians", "exact-2d", "copy"
  virtual int taps() const = 0;          // taps per 1D pass (window width for exact-2d: 0)
  virtual bool follow_surface() const = 0;
  virtual int passes() const = 0;        // full-screen passes per frame
  // Renders the result for `scene` into `output` (GL_RGBA32F, scene size). Non-translucent pixels
  // must hold the input. Returns false with `error` set when the GL refused something.
  virtual bool run(const GpuScene& scene, GLuint output, std::string* error) = 0;
  // Untimed work around each run (time_frames' before and after): an in-place method refills its
  // colour target before, and copies its result into `output` after.
  virtual void before_run(const GpuScene& /*scene*/) {}
  virtual void after_run(const GpuScene& /*scene*/, GLuint /*output*/) {}
  // How the library ran the last frame ("fragment", "masked", "compute"; sss_stats.last_frame_path),
  // for the progress log; "" for methods that do not choose.
  virtual std::string path_ran() const { return ""; }
};

// The loader the library gets from its host (sss_create_desc.get_proc_address and its user).
struct GlLoader {
  void* (*get_proc_address)(const char* name, void* user) = nullptr;
  void* user = nullptr;
};

// create_flags: sss_create_desc.flags (SSS_CREATE_NO_STATE_RESTORE measures the state queries).
std::unique_ptr<Method> make_separable_method(const GlLoader& loader, int taps, bool follow_surface,
                                              uint32_t create_flags = 0);
// A kernel family of sss_kernels.h run by the library (sss_settings.kernel, jitter), on the skin
// profile or the choice's, follow-surface on. Its passes are 2 × the plan's terms.
struct KernelChoice {
  std::string name;  // the method's name in the results, "kernel-svd-3"
  int32_t family = 0, rank = 1;
  float jitter = 0.0f;
  const sss_profile_desc* profile = nullptr;  // nullptr: the default (d'Eon's skin); else kept by the caller
};
const std::vector<KernelChoice>& kernel_family_choices();
// The 12-pass baseline ("sum-of-gaussians"): d'Eon's six Gaussians as the library's family, each
// Gaussian's footprint-integrated weights in a pass of its own, the accuracy ceiling of the tables.
const KernelChoice& sum_of_gaussians_baseline();
std::unique_ptr<Method> make_kernel_family_method(const GlLoader& loader, const KernelChoice& kernel, int taps);
// Mikkelsen's cross-bilateral mode (SSS_MODE_CROSS_BILATERAL) with d'Eon's six-Gaussian skin profile,
// the profile the exact reference uses, so its error is the method's and not a profile mismatch.
// tilt_correction false: a zero normal texture switches the per-axis cosine correction of the
// footprint off ("cross-bilateral-no-tilt"), to show what that correction buys on tilted surfaces.
std::unique_ptr<Method> make_cross_bilateral_method(const GlLoader& loader, int taps, bool tilt_correction = true);
// receiver_stride s > 1: only pixels with x % s == s / 2 and y % s == s / 2 are computed (the
// others keep the input); the full-size exact filter is too slow on a CPU rasteriser otherwise.
// band_rows = {y0, y1} with y1 > y0: only receivers in those rows (a timing sample; the other
// rows of the output are left as they were).
// The library written back in place (sss_apply_frame with output_texture 0, into an RGBA16F copy of
// the irradiance refilled before each timed frame), as a host's frame calls it, 17 taps or `taps`,
// follow-surface on: "separable-in-place" (the whole viewport) and "separable-region"
// (SSS_FRAME_REGION: the translucent pixels' bounding rectangle padded by the kernel's reach at the
// nearest translucent pixel, as a host would project its skin meshes' bounds; the result equals the
// whole viewport's).
// path: sss_settings.path (SSS_PATH_FRAGMENT: "separable-in-place", "separable-region";
// SSS_PATH_FRAGMENT_MASKED: "separable-masked[-region]"; SSS_PATH_COMPUTE:
// "separable-compute[-region]"; SSS_PATH_AUTO: "separable-auto[...]"; SSS_PATH_HALF_RESOLUTION:
// "separable-half"). texturing: sss_settings.texturing over a constant 0.5 albedo (its name gains
// "-post-scatter" or "-pre-and-post-scatter"; the answer is the scene's reference all the same).
std::unique_ptr<Method> make_in_place_method(const GlLoader& loader, int taps, bool region,
                                             uint32_t path = SSS_PATH_FRAGMENT,
                                             uint32_t texturing = SSS_TEXTURING_PRE_SCATTER);
// Several materials in one pass pair, in place, 17 taps or `taps`, follow-surface on: one profile and
// no profile texture ("separable-one-profile"), or several profiles and the scene's profile/object
// texture ("separable-profiles"); see profiles_method.cpp.
std::unique_ptr<Method> make_profiles_method(const GlLoader& loader, int taps, bool per_pixel);
std::unique_ptr<Method> make_exact_method(int receiver_stride = 1, std::pair<int, int> band_rows = {0, 0});
std::unique_ptr<Method> make_copy_method();
// The same two copies as compute dispatches ("copy-compute"); nullptr below GL 4.3.
std::unique_ptr<Method> make_compute_copy_method();

}  // namespace sss_bench
