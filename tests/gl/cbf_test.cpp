// The cross-bilateral mode (Mikkelsen 2010) on the GL: against its CPU model on both depth kinds,
// with stencil, separate output, viewport and an orthographic camera; no light crosses a depth step
// from a bright neighbour (where the separable mode lets some through); state restored.
//
// Tolerance against the CPU model: 3e-3 relative, the separable mode's budget (one RGBA16F
// intermediate rounding flip, 2^-10, carried with weight <= 1, plus one on an RGBA16F output: 1.95e-3).
// The taps here are nearest-texel fetches at floor(position): a few float ulps of difference in a
// position can only move a tap to the next texel when it lies within ulps of a texel edge. GLSL
// lets a division be 2.5 ulp off (GLSL 4.60 §4.7.1), so where a tap lies that close, one driver
// floors to one texel and the CPU model to its neighbour: on llvmpipe the scenes below never do
// (every difference is at the half-float rounding level); NVIDIA's driver (580, H100) did once, one
// pixel of the ketchup case at 1.6e-2. So a few values (kEdgeTaps per channel, each under one tap's
// share of the local contrast, kOneTap) may exceed the tolerance; a wrong tap, weight, footprint,
// cosine or range weight moves many values by 1e-2 or more on these scenes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "../support/kernel_of.hpp"
#include "filter_case.hpp"

using namespace host_gl;

namespace sss_test {
namespace {

constexpr float kTolerance = 3e-3f;
constexpr std::size_t kEdgeTaps = 8;
constexpr float kOneTap = 0.05f;

sss_settings cbf_settings(uint32_t profile = SSS_PROFILE_MIKKELSEN_2010, int taps = 13) {  // 13: the documented default (sss.h)
  sss_settings s;
  sss_default_settings(&s);
  s.mode = SSS_MODE_CROSS_BILATERAL;
  s.world_units_per_mm = 0.02f;  // about 1 pixel per profile millimetre on the 64x48 relief scene: r_max spans ~4 px
  s.cbf_profile = profile;
  s.cbf_taps = taps;
  return s;
}

SyntheticScene relief() { return make_relief_scene(64, 48, 3, perspective_matrix(40.0f, 64.0f / 48.0f, 0.1f, 10.0f)); }

using CrossBilateral = FilterCaseTest;

void expect_blurred_and_matching(const FilterOutcome& o) {
  ASSERT_EQ(o.result, SSS_OK);
  const float difference = largest_relative_difference(o.gpu, o.cpu);
  std::size_t beyond = 0;
  for (std::size_t i = 0; i < o.gpu.size(); ++i) {
    const float d = std::fabs(o.gpu[i] - o.cpu[i]) / std::max(1.0f, std::fabs(o.cpu[i]));
    if (!(d <= kTolerance)) {
      ++beyond;
      std::printf("  value %zu (pixel %zu, channel %zu): GPU %.6g, CPU model %.6g\n", i, i / 4, i % 4, o.gpu[i],
                  o.cpu[i]);
    }
  }
  std::printf("cross-bilateral GPU vs CPU model: largest relative difference %.3g (tolerance %.3g; %zu values "
              "beyond it)\n", difference, kTolerance, beyond);
  EXPECT_LE(beyond, kEdgeTaps) << "more values off than taps at a texel edge explain";
  EXPECT_LE(difference, kOneTap) << "more than one tap moved by one texel";
  EXPECT_GT(largest_relative_difference(o.gpu, o.input), 0.02f);  // the case must change the image
}

TEST_F(CrossBilateral, MatchesCpuModelHardwareDepth) {
  FilterCase c;
  c.settings = cbf_settings();
  expect_blurred_and_matching(run_case(relief(), c));
}

// A measured material: the GL blurs with the Gaussians 4a's fit gives its dipole, as the CPU model does.
// As MatchesCpuModel.HalfFloatTargetsRoundToNearest: both passes round what they write to half float
// to nearest, as the CPU model does.
TEST_F(CrossBilateral, HalfFloatTargetsRoundToNearest) {
  FilterCase c;
  c.settings = cbf_settings();
  c.half_color = true;
  expect_half_rounding_like_the_cpu_model(run_case(relief(), c), "cross-bilateral, RGBA16F in place", true);
}

TEST_F(CrossBilateral, MatchesCpuModelMeasuredMaterial) {
  FilterCase c;
  c.settings = cbf_settings(SSS_PROFILE_KETCHUP, 17);
  c.settings.cbf_r_max_mm = 6.0f;
  expect_blurred_and_matching(run_case(relief(), c));
}

// SSS_PROFILE_KERNEL: the cross-bilateral mode takes the kernel families' profile, here a table
// (fitted with four Gaussians) and d'Eon's skin cut to three Gaussians (taken as they are).
TEST_F(CrossBilateral, MatchesCpuModelWithTheKernelsProfile) {
  // A table of d'Eon's red, green and blue profiles at 0..6 mm.
  std::vector<float> radii, rgb;
  for (int i = 0; i <= 60; ++i) {
    const double r = 0.1 * i;
    radii.push_back(static_cast<float>(r));
    sss_profile_desc skin;
    skin.struct_size = sizeof skin;
    skin.profile = SSS_PROFILE_SKIN_DEON;
    skin.gaussian_count = 6;
    skin.table_size = 0;
    skin.table_radius_mm = nullptr;
    skin.table_rgb = nullptr;
    float value[3] = {0.0f, 0.0f, 0.0f};
    const float radius = static_cast<float>(r);
    ASSERT_EQ(sss_profile_evaluate(&skin, 1, &radius, value), SSS_OK) << sss_last_error(nullptr);
    rgb.insert(rgb.end(), {value[0], value[1], value[2]});
  }
  for (int variant = 0; variant < 2; ++variant) {
    SCOPED_TRACE(variant == 0 ? "tabulated" : "skin, 3 Gaussians");
    FilterCase c;
    c.settings = cbf_settings(SSS_PROFILE_KERNEL);
    sss_profile_desc& p = sss_test::kernel_of(c.settings).profile;
    if (variant == 0) {
      p.profile = SSS_PROFILE_TABULATED;
      p.table_size = static_cast<int32_t>(radii.size());
      p.table_radius_mm = radii.data();
      p.table_rgb = rgb.data();
    } else {
      p.profile = SSS_PROFILE_SKIN_DEON;
      p.gaussian_count = 3;
    }
    expect_blurred_and_matching(run_case(relief(), c));
    // The transmittance terms of the same desc are the Gaussians the blur uses: 4 fitted, or 3.
    float terms[4 * SSS_PROFILE_MAX_TERMS];
    int32_t count = 0;
    ASSERT_EQ(sss_profile_desc_transmittance_terms(&p, terms, SSS_PROFILE_MAX_TERMS, &count), SSS_OK)
        << sss_last_error(nullptr);
    EXPECT_EQ(count, variant == 0 ? SSS_PROFILE_FIT_GAUSSIANS : 3);
    for (int ch = 0; ch < 3; ++ch) {
      double sum = 0.0;
      for (int32_t t = 0; t < count; ++t) sum += terms[t * 4 + 1 + ch];
      EXPECT_NEAR(sum, 1.0, 0.05) << ch;  // a fit's weights, or the renormalised Gaussians' exactly
    }
    TearDown();
    SetUp();
  }
}

TEST_F(CrossBilateral, MatchesCpuModelSkinProfileManyTapsLinearDepth) {
  FilterCase c;
  c.settings = cbf_settings(SSS_PROFILE_SKIN_DEON, 25);
  c.settings.cbf_r_max_mm = 8.0f;
  c.depth = DepthKind::linear_r32f;
  expect_blurred_and_matching(run_case(relief(), c));
}

TEST_F(CrossBilateral, MatchesCpuModelWithStencilAndSeparateOutput) {
  for (bool separate : {false, true}) {
    SCOPED_TRACE(separate);
    FilterCase c;
    c.settings = cbf_settings();
    c.depth = DepthKind::depth24_stencil8;
    c.use_stencil = true;
    c.separate_output = separate;
    c.half_color = !separate;
    expect_blurred_and_matching(run_case(relief(), c));
    TearDown();
    SetUp();
  }
}

TEST_F(CrossBilateral, MatchesCpuModelViewportAndOrthographic) {
  FilterCase c;
  c.settings = cbf_settings();
  c.viewport = {5, 7, 40, 30};
  c.separate_output = true;
  expect_blurred_and_matching(run_case(relief(), c));
  TearDown();
  SetUp();
  FilterCase o;
  o.settings = cbf_settings();
  o.settings.world_units_per_mm = 0.015f;
  expect_blurred_and_matching(run_case(make_relief_scene(64, 48, 5, orthographic_matrix(0.6f, 0.45f, 0.1f, 5.0f)), o));
}

// A plane tilted by `degrees` about the view's y axis at distance 1 on the optical axis, with
// vertical stripes in red (so the blur along x shows), and its exact normals.
SyntheticScene tilted_plane(float degrees, std::vector<float>* normals) {
  const auto projection = perspective_matrix(40.0f, 1.0f, 0.1f, 10.0f);
  SyntheticScene s = make_flat_scene(48, 48, {0.5f, 0.5f, 0.5f, 1.0f}, 1.0f, projection);
  const float t = std::tan(degrees * 3.14159265f / 180.0f);
  const float len = std::sqrt(1.0f + t * t);
  normals->assign(s.color.size(), 0.0f);
  for (int y = 0; y < 48; ++y) {
    for (int x = 0; x < 48; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * 48 + x;
      const float ndc_x = (static_cast<float>(x) + 0.5f) / 24.0f - 1.0f;
      s.distance[i] = 1.0f / (1.0f + t * ndc_x / projection[0]);  // the ray meets z = -1 + t·x
      s.color[i * 4] = (x / 2) % 2 == 0 ? 1.0f : 0.1f;
      (*normals)[i * 4 + 0] = -t / len;
      (*normals)[i * 4 + 2] = 1.0f / len;
    }
  }
  compute_window_depth(&s);
  return s;
}

TEST_F(CrossBilateral, MatchesCpuModelWithNormalTexture) {
  FilterCase c;
  c.settings = cbf_settings();
  c.settings.world_units_per_mm = 0.03f;
  const SyntheticScene scene = tilted_plane(60.0f, &c.normals);
  expect_blurred_and_matching(run_case(scene, c));
}

// With exact normals and with normals reconstructed from depth, a tilted plane gets nearly the same
// result: the reconstruction recovers the plane's slope (up to the depth texture's float precision);
// and the cosine correction matters: ignoring the tilt (normals facing the camera) differs more.
TEST_F(CrossBilateral, ReconstructedNormalsAgreeWithExactOnesOnAPlane) {
  FilterCase exact;
  exact.settings = cbf_settings();
  exact.settings.world_units_per_mm = 0.03f;
  exact.separate_output = true;
  const SyntheticScene scene = tilted_plane(60.0f, &exact.normals);
  const FilterOutcome with_normals = run_case(scene, exact);
  TearDown();
  SetUp();
  FilterCase reconstructed = exact;
  reconstructed.normals.clear();
  const FilterOutcome from_depth = run_case(scene, reconstructed);
  TearDown();
  SetUp();
  FilterCase facing = exact;
  for (std::size_t i = 0; i < facing.normals.size(); i += 4) {
    facing.normals[i] = 0.0f;
    facing.normals[i + 2] = 1.0f;
  }
  const FilterOutcome untilted = run_case(scene, facing);
  const float agree = largest_relative_difference(with_normals.gpu, from_depth.gpu);
  const float tilt_matters = largest_relative_difference(with_normals.gpu, untilted.gpu);
  std::printf("tilted plane: exact vs reconstructed normals %.3g, exact vs ignoring the tilt %.3g\n", agree,
              tilt_matters);
  EXPECT_LE(agree, 0.02f);
  EXPECT_GT(tilt_matters, 0.05f);
  EXPECT_GT(tilt_matters, 5.0f * agree);
}

// A translucent dark square at distance 1 over a bright background at distance 3 that is either
// not translucent (alpha 0) or translucent but far behind. The cross-bilateral mode takes nothing
// from it: every pixel of the square stays at its own colour (the square is flat and uniform),
// while the separable mode without a stencil (the background's alpha 0 stops neither its bilinear
// taps nor, at a depth step, its follow-surface blend entirely) brightens the square's edge.
SyntheticScene depth_step_scene(float background_alpha) {
  SyntheticScene s = make_flat_scene(48, 48, {4.0f, 4.0f, 4.0f, background_alpha}, 3.0f,
                                     perspective_matrix(40.0f, 1.0f, 0.1f, 10.0f));
  for (int y = 12; y < 36; ++y) {
    for (int x = 12; x < 36; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * 48 + x;
      s.distance[i] = 1.0f;
      s.color[i * 4 + 0] = 0.1f;
      s.color[i * 4 + 1] = 0.05f;
      s.color[i * 4 + 2] = 0.02f;
      s.color[i * 4 + 3] = 1.0f;
    }
  }
  compute_window_depth(&s);
  return s;
}

// The largest relative brightening of the square's pixels.
float square_leak(const FilterOutcome& o) {
  float worst = 0.0f;
  for (int y = 12; y < 36; ++y) {
    for (int x = 12; x < 36; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * 48 + x) * 4;
      for (int c = 0; c < 3; ++c) worst = std::max(worst, (o.gpu[i + c] - o.input[i + c]) / o.input[i + c]);
    }
  }
  return worst;
}

TEST_F(CrossBilateral, NoLightCrossesADepthStep) {
  for (float background_alpha : {0.0f, 1.0f}) {
    SCOPED_TRACE(background_alpha);
    FilterCase c;
    c.settings = cbf_settings();
    c.settings.world_units_per_mm = 0.06f;  // r_max spans ~10 pixels at the square's distance: taps reach the background
    c.separate_output = true;
    const FilterOutcome cbf = run_case(depth_step_scene(background_alpha), c);
    ASSERT_EQ(cbf.result, SSS_OK);
    // Zero weight for the background (alpha 0), or range weight exp(-(2000 mm)²/4.6 mm²) = 0 at a 2 m
    // step: the square keeps its colour up to the fp16 rounding of the intermediate (2^-11 relative).
    const float leak = square_leak(cbf);
    std::printf("cross-bilateral leak into the square (background alpha %g): %.3g\n", background_alpha, leak);
    EXPECT_LE(leak, 1e-3f);
    EXPECT_LE(largest_relative_difference(cbf.gpu, cbf.cpu), kTolerance);
    TearDown();
    SetUp();
    // The separable mode on the same input, without the follow-surface test: the comparison shows the
    // test above can fail (the square's edge takes light from the background).
    FilterCase s;
    s.settings.struct_size = 0;
    sss_default_settings(&s.settings);
    s.settings.world_units_per_mm = 0.06f;
    s.settings.flags = 0;
    s.separate_output = true;
    const FilterOutcome separable = run_case(depth_step_scene(background_alpha), s);
    std::printf("separable leak into the square (background alpha %g): %.3g\n", background_alpha,
                square_leak(separable));
    EXPECT_GT(square_leak(separable), 0.1f);
    TearDown();
    SetUp();
    // The default mode (follow-surface on) does not leak either: its taps read whole pixels, each with
    // its own depth, and a 2 m step is far past the ramp's reach (0.1's bilinear taps straddling the
    // edge interpolated colour and depth and let a tenth of the background in).
    s.settings.flags = SSS_FOLLOW_SURFACE;
    const float follow_leak = square_leak(run_case(depth_step_scene(background_alpha), s));
    std::printf("separable follow-surface leak into the square (background alpha %g): %.3g\n", background_alpha,
                follow_leak);
    EXPECT_LE(follow_leak, 1e-3f);
    TearDown();
    SetUp();
  }
}

TEST_F(CrossBilateral, SettingsRoundTrip) {
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  sss_settings defaults;
  sss_default_settings(&defaults);
  EXPECT_EQ(defaults.mode, SSS_MODE_SEPARABLE);  // today's behaviour stays the default
  EXPECT_EQ(defaults.cbf_taps, 13);  // Mikkelsen's N, as sss.h documents
  EXPECT_EQ(defaults.cbf_r_max_mm, 4.5f);  // his r_max for skin
  EXPECT_EQ(defaults.cbf_profile, SSS_PROFILE_MIKKELSEN_2010);
  const sss_settings s = cbf_settings(SSS_PROFILE_SKIN_DEON, 15);
  ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK) << sss_last_error(sss_);
  sss_settings back;
  back.struct_size = sizeof back;
  ASSERT_EQ(sss_get_settings(sss_, &back), SSS_OK);
  EXPECT_EQ(back.mode, s.mode);
  EXPECT_EQ(back.cbf_taps, 15);
  EXPECT_EQ(back.cbf_profile, SSS_PROFILE_SKIN_DEON);
  EXPECT_EQ(back.cbf_r_max_mm, s.cbf_r_max_mm);
}

// The kernel follows the cbf fields even when they change while the separable mode is selected.
TEST_F(CrossBilateral, KernelFollowsFieldsChangedInTheOtherMode) {
  FilterCase c;
  c.settings = cbf_settings(SSS_PROFILE_MIKKELSEN_2010, 13);
  c.separate_output = true;
  sss_settings separable = c.settings;
  separable.mode = SSS_MODE_SEPARABLE;
  separable.cbf_taps = 21;
  separable.cbf_profile = SSS_PROFILE_SKIN_DEON;
  // The 21-tap skin kernel set directly (run_case creates the context), then the same context taken
  // through 13 taps, the separable mode with the fields changed there, and back.
  FilterCase direct = c;
  direct.settings.cbf_taps = 21;
  direct.settings.cbf_profile = SSS_PROFILE_SKIN_DEON;
  const FilterOutcome expected = run_case(relief(), direct);
  ASSERT_EQ(expected.result, SSS_OK);
  sss_settings back = separable;
  back.mode = SSS_MODE_CROSS_BILATERAL;
  sss_destroy(sss_);
  sss_ = create_sss();  // a fresh context: its first kernel is the 13-tap one
  ASSERT_NE(sss_, nullptr);
  ASSERT_EQ(sss_set_settings(sss_, &c.settings), SSS_OK);
  ASSERT_EQ(sss_set_settings(sss_, &separable), SSS_OK);
  ASSERT_EQ(sss_set_settings(sss_, &back), SSS_OK);        // must be the 21-tap skin kernel now
  const SyntheticScene scene = relief();
  const GLuint color = make_rgba32f(scene.width, scene.height, scene.color);
  const GLuint depth = make_depth32f(scene.width, scene.height, scene.window_depth);
  const GLuint output = make_rgba32f(scene.width, scene.height, std::vector<float>(scene.color.size(), -7.0f));
  ASSERT_EQ(sss_set_camera(sss_, scene.projection.data()), SSS_OK);
  sss_frame frame = frame_of(color, depth, output);
  if (is_gles()) describe_frame(c, scene.width, scene.height, &frame);  // ES 3.0 cannot be asked
  ASSERT_EQ(sss_apply_frame(sss_, &frame), SSS_OK) << sss_last_error(sss_);
  EXPECT_EQ(read_rgba(output, scene.width, scene.height), expected.gpu);
}

TEST_F(CrossBilateral, BadSettingsAreRejectedAndKeepTheOldOnes) {
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  const sss_settings good = cbf_settings();
  ASSERT_EQ(sss_set_settings(sss_, &good), SSS_OK);
  struct Bad {
    const char* field;
    void (*spoil)(sss_settings*);
  };
  const Bad cases[] = {
      {"settings->mode", [](sss_settings* s) { s->mode = 2; }},
      {"settings->cbf_taps", [](sss_settings* s) { s->cbf_taps = 14; }},
      {"settings->cbf_taps", [](sss_settings* s) { s->cbf_taps = 1; }},
      {"settings->cbf_taps", [](sss_settings* s) { s->cbf_taps = 67; }},
      {"settings->cbf_r_max_mm", [](sss_settings* s) { s->cbf_r_max_mm = 0.0f; }},
      {"settings->cbf_r_max_mm", [](sss_settings* s) { s->cbf_r_max_mm = NAN; }},
      {"settings->cbf_r_max_mm", [](sss_settings* s) { s->cbf_r_max_mm = 51.0f; }},
      {"settings->cbf_profile", [](sss_settings* s) { s->cbf_profile = SSS_PROFILE_TABULATED; }},
  };
  for (const Bad& b : cases) {
    sss_settings s = good;
    b.spoil(&s);
    const sss_settings back = expect_settings_refused(sss_, s, b.field);
    EXPECT_EQ(back.cbf_taps, good.cbf_taps);
    EXPECT_EQ(back.cbf_r_max_mm, good.cbf_r_max_mm);
    EXPECT_EQ(back.mode, good.mode);
  }
}

}  // namespace
}  // namespace sss_test

namespace sss_test {
namespace {

// A bad normal texture is rejected before anything is drawn, whatever the mode.
TEST_F(CrossBilateral, BadNormalTextureIsRejectedAndLeavesTheColourUntouched) {
  const SyntheticScene scene = relief();
  const GLuint color = make_rgba32f(scene.width, scene.height, scene.color);
  const GLuint depth = make_depth32f(scene.width, scene.height, scene.window_depth);
  const GLuint wrong_format = make_texture(GL_R32F, scene.width, scene.height, GL_RED, GL_FLOAT, nullptr);
  const GLuint wrong_size = make_rgba32f(8, 8, std::vector<float>(8 * 8 * 4, 0.0f));
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  for (uint32_t mode : {SSS_MODE_SEPARABLE, SSS_MODE_CROSS_BILATERAL}) {
    sss_settings s = cbf_settings();
    s.mode = mode;
    ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK);
    ASSERT_EQ(sss_set_camera(sss_, scene.projection.data()), SSS_OK);
    if (is_gles()) {
      // OpenGL ES 3.0 cannot be asked for a texture's format or size: the frame's description is
      // what is checked (a wrong size there cannot be seen, the host's description is trusted).
      struct EsCase {
        GLuint normals;
        uint32_t format;
        sss_result expected;
        const char* named;
      };
      const EsCase es_cases[] = {
          {wrong_format, GL_R32F, SSS_ERROR_INVALID_ARGUMENT, "normal_format"},  // not a colour format
          {wrong_format, 0, SSS_ERROR_INVALID_ARGUMENT, "normal_format"},        // not described
          {987654u, GL_RGBA32F, SSS_ERROR_INVALID_TEXTURE, "normal_texture"},    // not a texture
      };
      for (const EsCase& e : es_cases) {
        sss_frame frame = frame_of(color, depth);
        describe_frame(FilterCase{}, scene.width, scene.height, &frame);
        frame.normal_texture = e.normals;
        frame.normal_format = e.format;
        EXPECT_EQ(sss_apply_frame(sss_, &frame), e.expected);
        EXPECT_NE(std::string(sss_last_error(sss_)).find(e.named), std::string::npos) << sss_last_error(sss_);
        EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
      }
      continue;
    }
    for (GLuint normals : {wrong_format, wrong_size, 987654u}) {
      sss_frame frame = frame_of(color, depth);
      frame.normal_texture = normals;
      EXPECT_EQ(sss_apply_frame(sss_, &frame), SSS_ERROR_INVALID_TEXTURE);
      EXPECT_NE(std::string(sss_last_error(sss_)).find("normal_texture"), std::string::npos) << sss_last_error(sss_);
      EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    }
  }
  const std::vector<float> after = read_rgba(color, scene.width, scene.height);
  EXPECT_EQ(after, scene.color);
}

}  // namespace
}  // namespace sss_test
