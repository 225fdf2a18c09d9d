// Runs one configuration of the filter on the GL and on the CPU model from identical inputs (the
// depth the CPU model sees is read back from the GL texture, so depth quantisation is shared).
#pragma once

#include <cstdint>
#include <vector>

#include "gl_fixture.hpp"
#include "math/filter_constants.hpp"
#include "math/kernel_plan.hpp"
#include "math/pass_kernel.hpp"
#include "synthetic_scene.hpp"

namespace sss_test {

enum class DepthKind { depth32f, depth24_stencil8, linear_r32f };

struct FilterCase {
  sss_settings settings{};
  DepthKind depth = DepthKind::depth32f;
  bool half_color = false;   // RGBA16F instead of RGBA32F
  bool use_stencil = false;  // scene.stencil -> stencil ref 1, mask 0xFF (needs depth24_stencil8)
  bool separate_output = false;
  std::array<int32_t, 4> viewport = {0, 0, 0, 0};
  std::vector<float> normals;  // RGBA32F view-space normals for sss_frame.normal_texture; empty: none
  bool use_region = false;     // SSS_FRAME_REGION with `region` (x, y, width, height)
  std::array<int32_t, 4> region = {0, 0, 0, 0};
  // Before the frame, the same context applies another one of the same size, every pixel
  // translucent and of other colours: what the module's targets hold from it must not show.
  bool stale_frame_first = false;
  std::uint32_t noise_index = 0;  // sss_frame.noise_index (the CPU model's too)
  std::uint32_t debug_view = 0;   // sss_frame.debug_view (the CPU model's too; needs separate_output)
  // sss_frame.albedo_texture (RGBA, uploaded as RGBA16F; empty: none), for settings.texturing; the
  // CPU model then runs on the colour over A_post and multiplies back (math/cpu_texturing.hpp).
  std::vector<float> albedo;
};

struct FilterOutcome {
  std::vector<float> input;   // colour as stored on the GL (after any fp16 rounding)
  std::vector<float> gpu;     // the GL's result
  std::vector<float> cpu;     // the CPU model's result
  sss_result result = SSS_OK;
  // The half-resolution path's CPU model ran: the pixels it upsampled and those it left to the
  // full-size passes (-1: another model ran).
  long long upsampled = -1, full_size = -1;
};

// Settings whose blur shows clearly on the synthetic scenes: strength .9/.8/.7, falloff 1/.6/.4.
sss_settings visible_settings(int samples, uint32_t flags, float width);

// `base` run on `path` in `mode`, its kernel made a rank-2 SVD (two terms) when `two_terms`: the
// settings of a per-path case in the suites that walk every way a frame can run.
sss_settings path_case_settings(sss_settings base, uint32_t path, uint32_t mode, bool two_terms);

// Every way a frame can run, for path_case_settings: each path, a kernel of two terms, and the
// cross-bilateral mode (the compute path is the fragment path where the GL has no compute shaders;
// run_case's CPU model is the half-resolution one where that path runs).
struct PathCase {
  const char* name;
  uint32_t path, mode;
  bool two_terms;
};
inline constexpr PathCase kEveryPath[] = {
    {"fragment", SSS_PATH_FRAGMENT, SSS_MODE_SEPARABLE, false},
    {"masked", SSS_PATH_FRAGMENT_MASKED, SSS_MODE_SEPARABLE, false},
    {"half resolution", SSS_PATH_HALF_RESOLUTION, SSS_MODE_SEPARABLE, false},
    {"compute (the fragment path where the GL has none)", SSS_PATH_COMPUTE, SSS_MODE_SEPARABLE, false},
    {"two kernel terms", SSS_PATH_FRAGMENT, SSS_MODE_SEPARABLE, true},
    {"compute, two kernel terms", SSS_PATH_COMPUTE, SSS_MODE_SEPARABLE, true},
    {"cross-bilateral", SSS_PATH_FRAGMENT, SSS_MODE_CROSS_BILATERAL, false},
};

// Compares GPU and CPU per channel; returns the largest |gpu - cpu| / max(1, |cpu|) (equal values,
// infinities and NaN in both count as no difference; NaN in one only as NaN, the worst).
float largest_relative_difference(const std::vector<float>& gpu, const std::vector<float>& cpu);

// The GL against the CPU model where a tap may land one pixel from where the model puts it: the
// vertical pass's sheared column (x + shear · offset, floored) and a sparse tap's position
// (floor(reach · spacing + 0.5)) come from the surface's tangents, which are differences of
// neighbouring distances: an ulp of one of them, from another order of float operations in the
// driver's compiler, moves the shear by about 1e-4 of itself, and a column that sat within that of a
// pixel's edge reads the next pixel. Such a flip moves one tap's weight between two neighbours, so
// it shows at few pixels (measured on llvmpipe, 600x40 relief at ~80 px per mm, 17 taps: 2 of 24,000
// pixels beyond 3e-3, at most 4.7e-3; 7.3e-3 from a linear depth) and nowhere else; a real difference between the passes and the model moves
// every pixel of the kind it touches. So: every value within `tolerance` (largest_relative_difference's
// measure), except at most 1 pixel in kTapFlipShare, and those within kTapFlipBound (one tap of weight
// up to a tenth moving one pixel on a scene whose neighbouring pixels differ by up to a tenth).
constexpr std::size_t kTapFlipShare = 2000;
constexpr float kTapFlipBound = 1e-2f;
void expect_matches_model_up_to_tap_flips(const FilterOutcome& o, float tolerance, const char* what);

// How the GL's rounding into half-float targets compares with the CPU model's (round to nearest,
// ties to even), over the colour values the filter changed (cpu != input, both finite): the share of
// them where GL and CPU model are equal bit for bit, and the mean of (gpu − cpu) / max(1, |cpu|). A
// driver's conversion that truncates, left alone, makes about half of them differ by one half-float
// step and the mean about −2.4e-4 (half a step, always down).
struct RoundingAgreement {
  double equal_share = 0.0;
  double mean_relative_difference = 0.0;
  std::size_t values = 0;
};
RoundingAgreement rounding_agreement(const FilterOutcome& o);
// Prints `what`'s agreement and checks it: at least 1,000 changed values, no bias (|mean| <= 1e-5,
// a twentieth of what truncation leaves), and, where every rounding is into half floats on both
// sides (`bit_exact`), at least 99.9 % of the values equal bit for bit.
void expect_half_rounding_like_the_cpu_model(const FilterOutcome& o, const char* what, bool bit_exact);

// The kernel the settings select (settings.kernel with samples, strength, falloff), from the public
// sss_kernel_plan: what the CPU model runs.
sss::math::KernelPlan plan_for(const sss_settings& settings);

// Fills the frame's texture description (formats and size) for the textures run_case makes; run_case
// does it on OpenGL ES, which cannot be asked.
void describe_frame(const FilterCase& c, int width, int height, sss_frame* frame);

// Per-pixel profiles' CPU models: each profile's kernel and per-frame constants as sss_set_profiles
// and sss_apply_frame build them, for a width x height frame (viewport: all of it) seen through
// `projection`.
struct ProfileModels {
  std::vector<sss::math::PassKernel> kernels;
  std::vector<sss::math::PassConstants> constants;
  std::vector<const sss::math::PassKernel*> kernel_pointers() const;
};
ProfileModels profile_models(const sss_settings* profiles, std::size_t count, const sss::math::Matrix4& projection,
                             int width, int height);

class FilterCaseTest : public GlTest {
 protected:
  FilterOutcome run_case(const SyntheticScene& scene, const FilterCase& c);
  // The sss_path the last frame of sss_ took (sss_stats.last_frame_path).
  uint32_t last_path();
};

}  // namespace sss_test
