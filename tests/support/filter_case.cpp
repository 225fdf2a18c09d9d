#include "filter_case.hpp"

#include "math/cpu_half_resolution.hpp"
#include "math/half_resolution.hpp"

#include "kernel_of.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "api/profiles.hpp"
#include "api/validation.hpp"
#include "math/cpu_cbf_filter.hpp"
#include "math/cpu_separable_filter.hpp"
#include "math/cpu_texturing.hpp"
#include "math/pass_kernel.hpp"
#include "math/separable_kernel.hpp"

using namespace host_gl;

namespace sss_test {

float largest_relative_difference(const std::vector<float>& gpu, const std::vector<float>& cpu) {
  float worst = 0.0f;
  for (std::size_t i = 0; i < gpu.size(); ++i) {
    if (gpu[i] == cpu[i] || (std::isnan(gpu[i]) && std::isnan(cpu[i]))) continue;  // same, Inf and NaN too
    const float d = std::fabs(gpu[i] - cpu[i]) / std::max(1.0f, std::fabs(cpu[i]));
    if (!(d <= worst)) worst = d;  // NaN propagates as the worst
  }
  return worst;
}

void expect_matches_model_up_to_tap_flips(const FilterOutcome& o, float tolerance, const char* what) {
  ASSERT_EQ(o.gpu.size(), o.cpu.size()) << what;
  const std::size_t pixels = o.gpu.size() / 4;
  std::size_t flipped = 0;
  float flipped_worst = 0.0f;
  for (std::size_t p = 0; p < pixels; ++p) {
    const std::vector<float> gpu(o.gpu.begin() + static_cast<std::ptrdiff_t>(p * 4),
                                 o.gpu.begin() + static_cast<std::ptrdiff_t>(p * 4 + 4));
    const std::vector<float> cpu(o.cpu.begin() + static_cast<std::ptrdiff_t>(p * 4),
                                 o.cpu.begin() + static_cast<std::ptrdiff_t>(p * 4 + 4));
    const float difference = largest_relative_difference(gpu, cpu);
    if (difference <= tolerance) continue;
    ++flipped;
    if (!(difference <= flipped_worst)) flipped_worst = difference;  // NaN propagates as the worst
  }
  std::printf("%s: %zu of %zu pixels beyond %.3g of the CPU model, the worst %.3g\n", what, flipped, pixels,
              static_cast<double>(tolerance), static_cast<double>(flipped_worst));
  EXPECT_LE(flipped * kTapFlipShare, pixels) << what << ": too many pixels differ from the CPU model";
  EXPECT_LE(flipped_worst, kTapFlipBound) << what;
}

RoundingAgreement rounding_agreement(const FilterOutcome& o) {
  RoundingAgreement a;
  std::size_t equal = 0;
  double sum = 0.0;
  for (std::size_t i = 0; i < o.gpu.size() && i < o.cpu.size() && i < o.input.size(); ++i) {
    if (o.cpu[i] == o.input[i] || !std::isfinite(o.cpu[i]) || !std::isfinite(o.gpu[i])) continue;
    ++a.values;
    if (o.gpu[i] == o.cpu[i]) ++equal;
    sum += static_cast<double>(o.gpu[i] - o.cpu[i]) / std::max(1.0, std::fabs(static_cast<double>(o.cpu[i])));
  }
  if (a.values > 0) {
    a.equal_share = static_cast<double>(equal) / static_cast<double>(a.values);
    a.mean_relative_difference = sum / static_cast<double>(a.values);
  }
  return a;
}

void expect_half_rounding_like_the_cpu_model(const FilterOutcome& o, const char* what, bool bit_exact) {
  ASSERT_EQ(o.result, SSS_OK) << what;
  const RoundingAgreement a = rounding_agreement(o);
  std::printf("%s: %zu changed values, %.4f equal to the CPU model, mean relative difference %.3g\n", what, a.values,
              a.equal_share, a.mean_relative_difference);
  ASSERT_GT(a.values, 1000u) << what;
  if (bit_exact) {
    EXPECT_GE(a.equal_share, 0.999) << what;
  }
  EXPECT_LE(std::fabs(a.mean_relative_difference), 1e-5) << what;
}

sss_settings visible_settings(int samples, uint32_t flags, float width) {
  sss_settings s;
  sss_default_settings(&s);
  s.world_units_per_mm = width;
  s.strength[0] = 0.9f;
  s.strength[1] = 0.8f;
  s.strength[2] = 0.7f;
  s.falloff[0] = 1.0f;
  s.falloff[1] = 0.6f;
  s.falloff[2] = 0.4f;
  s.taps = samples;
  s.flags = flags;
  return s;
}

sss_settings path_case_settings(sss_settings base, uint32_t path, uint32_t mode, bool two_terms) {
  base.path = path;
  base.mode = mode;
  if (two_terms) {
    sss_test::kernel_of(base).family = SSS_KERNEL_SVD;
    sss_test::kernel_of(base).rank = 2;
  }
  return base;
}

void describe_frame(const FilterCase& c, int width, int height, sss_frame* frame) {
  frame->color_format = c.half_color ? GL_RGBA16F : GL_RGBA32F;
  switch (c.depth) {
    case DepthKind::depth32f: frame->depth_format = GL_DEPTH_COMPONENT32F; break;
    case DepthKind::linear_r32f: frame->depth_format = GL_R32F; break;
    case DepthKind::depth24_stencil8: frame->depth_format = GL_DEPTH24_STENCIL8; break;
  }
  frame->output_format = frame->output_texture != 0 ? GL_RGBA32F : 0;
  frame->stencil_format = frame->stencil != nullptr ? GL_DEPTH24_STENCIL8 : 0;
  frame->normal_format = frame->normal_texture != 0 ? GL_RGBA32F : 0;
  frame->texture_width = width;
  frame->texture_height = height;
}

// The math layer's request for a public kernel description (as the API layer maps it).
sss::math::KernelRequest request_for(const sss_kernel_desc& d) {
  sss::math::KernelRequest q;
  q.family = static_cast<sss::math::KernelFamily>(d.family);
  q.taps = d.taps;
  q.rank = d.rank;
  q.rescale_energy = (d.flags & SSS_KERNEL_SVD_NO_RESCALE) == 0u;
  q.guide_k = d.guide_k;
  q.radius_mm = d.radius_mm;
  for (std::size_t c = 0; c < 3; ++c) {
    q.artist.near_variance_mm2[c] = d.near_variance_mm2[c];
    q.artist.far_variance_mm2[c] = d.far_variance_mm2[c];
    q.artist.near_weight[c] = d.near_weight[c];
  }
  q.profile.material = d.profile.profile == SSS_PROFILE_SKIN_DEON ? sss::math::kProfileSkin
                       : d.profile.profile == SSS_PROFILE_TABULATED ? sss::math::kProfileTable
                       : d.profile.profile == SSS_PROFILE_BURLEY    ? sss::math::kProfileBurley
                                                                     : d.profile.profile - 1;
  q.profile.gaussian_count = d.profile.gaussian_count;
  for (std::size_t c = 0; c < 3; ++c) {
    q.profile.burley.albedo[c] = d.profile.burley_albedo[c];
    q.profile.burley.dmfp_mm[c] = d.profile.burley_dmfp_mm[c];
  }
  for (int32_t i = 0; d.profile.profile == SSS_PROFILE_TABULATED && i < d.profile.table_size; ++i) {
    q.profile.table_radii_mm.push_back(d.profile.table_radius_mm[i]);
    q.profile.table_values.push_back({d.profile.table_rgb[i * 3], d.profile.table_rgb[i * 3 + 1], d.profile.table_rgb[i * 3 + 2]});
  }
  return q;
}

sss::math::KernelPlan plan_for(const sss_settings& settings) {
  sss_kernel_desc desc;
  sss_default_kernel_desc(&desc);
  if (settings.kernel != nullptr) desc = *settings.kernel;
  desc.taps = settings.taps;
  for (int c = 0; c < 3; ++c) {
    desc.strength[c] = settings.strength[c];
    desc.falloff[c] = settings.falloff[c];
  }
  const auto taps = static_cast<std::size_t>(desc.taps);
  std::vector<float> packed(SSS_KERNEL_MAX_TERMS * 2 * taps * 4);
  std::array<float, SSS_KERNEL_MAX_TERMS> variance{};
  int32_t terms = 0;
  float reach = 0.0f;
  const sss_result r = sss_kernel_plan(&desc, SSS_KERNEL_MAX_TERMS, packed.data(), variance.data(), &terms, &reach);
  EXPECT_EQ(r, SSS_OK) << sss_last_error(nullptr);
  sss::math::KernelPlan plan;
  for (int32_t t = 0; t < terms && r == SSS_OK; ++t) {
    sss::math::SeparableTerm term;
    for (std::size_t pass = 0; pass < 2; ++pass) {
      auto& out = pass == 0 ? term.horizontal : term.vertical;
      for (std::size_t i = 0; i < taps; ++i) {
        const float* q = &packed[((static_cast<std::size_t>(t) * 2 + pass) * taps + i) * 4];
        out.push_back(sss::math::KernelTap{{q[0], q[1], q[2]}, q[3]});
      }
    }
    term.depth_variance_mm2 = variance[static_cast<std::size_t>(t)];
    plan.terms.push_back(std::move(term));
  }
  plan.reach_mm = reach;
  return plan;
}

uint32_t FilterCaseTest::last_path() {
  sss_stats stats = {};
  stats.struct_size = sizeof stats;
  EXPECT_EQ(sss_get_stats(sss_, &stats), SSS_OK);
  return stats.last_frame_path;
}

FilterOutcome FilterCaseTest::run_case(const SyntheticScene& scene, const FilterCase& c) {
  FilterOutcome outcome;
  const int w = scene.width, h = scene.height;
  const GLuint color = c.half_color ? make_rgba16f(w, h, scene.color) : make_rgba32f(w, h, scene.color);
  GLuint depth = 0;
  switch (c.depth) {
    case DepthKind::depth32f: depth = make_depth32f(w, h, scene.window_depth); break;
    case DepthKind::linear_r32f: depth = make_texture(GL_R32F, w, h, GL_RED, GL_FLOAT, scene.distance.data()); break;
    case DepthKind::depth24_stencil8: {
      std::vector<uint32_t> packed(scene.window_depth.size());
      for (std::size_t i = 0; i < packed.size(); ++i) {
        const auto d24 = static_cast<uint32_t>(std::lround(scene.window_depth[i] * 16777215.0));
        packed[i] = (d24 << 8) | (scene.stencil[i] ? 1u : 0u);
      }
      depth = make_texture(GL_DEPTH24_STENCIL8, w, h, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, packed.data());
      break;
    }
  }
  const GLuint output = c.separate_output ? make_rgba32f(w, h, std::vector<float>(scene.color.size(), -7.0f)) : 0;
  outcome.input = read_rgba(color, w, h);
  std::vector<float> stored_depth;
  if (c.depth == DepthKind::linear_r32f) {
    stored_depth = scene.distance;
  } else if (!is_gles()) {
    stored_depth = read_depth(depth, w, h);
  } else {
    // OpenGL ES cannot read depth back: the stored values, as the GL converts them. DEPTH32F keeps
    // the float; a 24-bit depth d reads as d / (2^24 - 1) (at most an ulp from the GL's own
    // conversion, far below the tolerance of the comparisons).
    stored_depth = scene.window_depth;
    if (c.depth == DepthKind::depth24_stencil8) {
      for (float& d : stored_depth) d = static_cast<float>(static_cast<double>(std::lround(d * 16777215.0)) / 16777215.0);
    }
  }

  if (sss_ != nullptr) sss_destroy(sss_);  // a test may run several cases: each gets a fresh context
  sss_ = create_sss();
  if (sss_ == nullptr) return outcome;
  EXPECT_EQ(sss_set_settings(sss_, &c.settings), SSS_OK) << sss_last_error(sss_);
  EXPECT_EQ(sss_set_camera(sss_, scene.projection.data()), SSS_OK) << sss_last_error(sss_);
  sss_stencil stencil = {depth, 1, 0xFF};
  sss_frame frame = frame_of(color, depth, output);
  frame.stencil = c.use_stencil ? &stencil : nullptr;
  frame.noise_index = c.noise_index;
  frame.debug_view = c.debug_view;
  frame.normal_texture = c.normals.empty() ? 0u : make_rgba32f(w, h, c.normals);
  if (!c.albedo.empty()) {
    frame.albedo_texture = make_rgba16f(w, h, c.albedo);
    frame.albedo_format = GL_RGBA16F;
  }
  for (int i = 0; i < 4; ++i) frame.viewport[i] = c.viewport[static_cast<std::size_t>(i)];
  if (c.use_region) {
    frame.flags |= SSS_FRAME_REGION;
    for (int i = 0; i < 4; ++i) frame.region[i] = c.region[static_cast<std::size_t>(i)];
  }
  if (is_gles()) describe_frame(c, w, h, &frame);  // ES 3.0 cannot be asked for formats and sizes
  if (c.stale_frame_first) {
    std::vector<float> other(scene.color.size());
    for (std::size_t i = 0; i < other.size(); ++i) other[i] = i % 4 == 3 ? 1.0f : 3.0f - scene.color[i];
    const GLuint other_color = c.half_color ? make_rgba16f(w, h, other) : make_rgba32f(w, h, other);
    const GLuint other_output = c.separate_output ? make_rgba32f(w, h, other) : 0;
    sss_frame before = frame;
    before.color_texture = other_color;
    before.output_texture = other_output;
    EXPECT_EQ(sss_apply_frame(sss_, &before), SSS_OK) << sss_last_error(sss_);
  }
  outcome.result = sss_apply_frame(sss_, &frame);
  EXPECT_EQ(outcome.result, SSS_OK) << sss_last_error(sss_);
  outcome.gpu = read_rgba(output != 0 ? output : color, w, h);

  // The CPU model with the same constants.
  sss::math::FilterSettings fs;
  fs.world_units_per_mm = c.settings.world_units_per_mm;
  fs.strength = {c.settings.strength[0], c.settings.strength[1], c.settings.strength[2]};
  fs.falloff = {c.settings.falloff[0], c.settings.falloff[1], c.settings.falloff[2]};
  fs.samples = c.settings.taps;
  fs.follow_surface = (c.settings.flags & SSS_FOLLOW_SURFACE) != 0;
  fs.scale = c.settings.scale;
  fs.separable_scale = c.settings.separable_scale;
  fs.jitter = c.settings.jitter;
  sss_kernel_desc kernel_desc;
  sss_default_kernel_desc(&kernel_desc);
  if (c.settings.kernel != nullptr) kernel_desc = *c.settings.kernel;
  fs.kernel = request_for(kernel_desc);
  sss::math::FrameGeometry g;
  g.texture_width = w;
  g.texture_height = h;
  g.viewport = c.viewport[2] == 0 ? std::array<int, 4>{0, 0, w, h}
                                  : std::array<int, 4>{c.viewport[0], c.viewport[1], c.viewport[2], c.viewport[3]};
  g.depth = c.depth == DepthKind::linear_r32f ? sss::math::DepthEncoding::linear_distance
                                              : sss::math::DepthEncoding::hardware_minus_one_to_one;
  // The kernel the math layer builds from these settings (the footprint tables are its closed forms,
  // which the public tap lists of sss_kernel_plan do not carry).
  const sss::math::PassKernel kernel = sss::math::build_pass_kernel(fs);
  auto constants = sss::math::compute_pass_constants(fs, scene.projection, g, kernel.reach_mm);
  const bool empty_region = c.use_region && (c.region[2] == 0 || c.region[3] == 0);
  if (c.use_region && !empty_region) {  // what sss_apply_frame does: taps and drawn pixels inside the region
    sss::math::clamp_to_rect(&constants, {c.region[0], c.region[1], c.region[2], c.region[3]});
  }
  sss::math::CpuFilterImage image;
  image.width = w;
  image.height = h;
  image.color = outcome.input.data();
  image.depth = stored_depth.data();
  image.mask = c.use_stencil ? scene.stencil.data() : nullptr;
  image.noise_index = c.noise_index;
  image.debug_view = c.debug_view;
  image.output_is_half = c.half_color && !c.separate_output;
  // The module's intermediate is as precise as the colour (RGBA32F colour: RGBA32F), and on ES it
  // sums terms in RGBA16F unless the colour is RGBA32F.
  image.intermediate_is_half = c.half_color;
  image.accumulator_is_half = is_gles() && c.half_color;
  // A texturing mode: the model runs on the module's copy (the colour over A_post, in the
  // intermediate's precision) and multiplies back where it blurs.
  std::vector<float> post, copy;
  if (!c.albedo.empty() && c.settings.texturing != SSS_TEXTURING_PRE_SCATTER) {
    post = sss::math::albedo_post_plane(c.albedo.data(), static_cast<std::size_t>(w) * h, {c.settings.texturing});
    copy = sss::math::colour_over_albedo(outcome.input.data(), post, c.half_color);
    image.color = copy.data();
    image.original = outcome.input.data();
    image.albedo_post = post.data();
  }
  outcome.cpu.resize(outcome.input.size());
  if (empty_region) {
    outcome.cpu = outcome.input;  // nothing translucent: the image (or its copy) as it was
  } else if (c.settings.mode == SSS_MODE_CROSS_BILATERAL) {
    // The profile as sss_set_settings builds it (SSS_PROFILE_KERNEL: from settings.kernel->profile).
    sss_profile_desc profile;
    sss_default_profile_desc(&profile);
    if (c.settings.kernel != nullptr) profile = c.settings.kernel->profile;
    const sss::math::ProfileRequest kernel_profile = sss::api::to_request(profile);
    const auto cbf_kernel = sss::math::cbf_kernel(sss::math::cbf_profile(c.settings.cbf_profile, kernel_profile),
                                                  c.settings.cbf_taps, c.settings.cbf_r_max_mm);
    sss::math::cpu_cbf_filter(cbf_kernel, constants, image, outcome.cpu.data(),
                              c.normals.empty() ? nullptr : c.normals.data());
  } else if (c.settings.path == SSS_PATH_HALF_RESOLUTION && kernel.terms.size() == 1) {
    sss::math::CpuHalfResolutionStats stats;
    sss::math::cpu_half_resolution_filter({&kernel}, {constants}, nullptr, image,
                                          sss::math::kHalfResolutionMinReachPixels, outcome.cpu.data(), &stats);
    outcome.upsampled = stats.upsampled;
    outcome.full_size = stats.full_size;
  } else {
    sss::math::cpu_pass_kernel_filter(kernel, constants, image, outcome.cpu.data());
  }
  if (c.separate_output && c.viewport[2] != 0) {
    // Outside the viewport a separate output keeps what it held.
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const bool inside = x >= c.viewport[0] && x < c.viewport[0] + c.viewport[2] && y >= c.viewport[1] &&
                            y < c.viewport[1] + c.viewport[3];
        if (!inside) {
          for (int ch = 0; ch < 4; ++ch) outcome.cpu[(static_cast<std::size_t>(y) * w + x) * 4 + ch] = -7.0f;
        }
      }
    }
  }
  return outcome;
}

std::vector<const sss::math::PassKernel*> ProfileModels::kernel_pointers() const {
  std::vector<const sss::math::PassKernel*> out;
  for (const sss::math::PassKernel& k : kernels) out.push_back(&k);
  return out;
}

ProfileModels profile_models(const sss_settings* profiles, std::size_t count, const sss::math::Matrix4& projection,
                             int width, int height) {
  ProfileModels m;
  sss::math::FrameGeometry g;
  g.texture_width = width;
  g.texture_height = height;
  g.viewport = {0, 0, width, height};
  m.kernels.reserve(count);  // kernel_pointers() points into it
  for (std::size_t i = 0; i < count; ++i) {
    const sss::math::FilterSettings fs = sss::api::to_filter_settings(profiles[i]);
    m.kernels.push_back(sss::math::build_pass_kernel(fs));
    m.constants.push_back(sss::math::compute_pass_constants(fs, projection, g, m.kernels.back().reach_mm));
  }
  return m;
}

}  // namespace sss_test
