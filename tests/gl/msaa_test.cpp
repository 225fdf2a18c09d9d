// The MSAA path (paper §4): multisampled colour and depth are resolved (box-averaged colour, mean of
// the samples' linear depths) and filtered like single-sample input; written back, only the
// translucent samples change and the box resolve of the result is the blurred image. Bad
// multisampled input fails with a specific code and message and changes nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

#include "counting_loader.hpp"
#include "fault_loader.hpp"
#include "filter_case.hpp"
#include "gl_state_snapshot.hpp"
#include "math/filter_constants.hpp"
#include "multisample_textures.hpp"

using namespace host_gl;

namespace sss_test {
namespace {

constexpr int kW = 48, kH = 40;  // the filtered size; the fine (per-sample) scenes are 96 x 80
const sss::math::Matrix4 kCamera = perspective_matrix(40.0f, float(kW) / float(kH), 0.1f, 10.0f);

class Msaa : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    if (HasFatalFailure()) return;
    // sss.h: the MSAA path is desktop GL only; on ES a multisampled input is refused (MsaaOnGles).
    if (is_gles()) GTEST_SKIP() << "the MSAA path is desktop OpenGL only (see MsaaOnGles for ES)";
    glGetIntegerv(GL_MAX_SAMPLES, &max_samples_);
    if (max_samples_ < 4) GTEST_SKIP() << "the context offers " << max_samples_ << " samples";
    fresh_context();
  }

  // A new context (created with `flags`) with the tests' camera and settings.
  void fresh_context(uint32_t flags = 0) {
    if (sss_ != nullptr) sss_destroy(sss_);
    sss_ = create_sss(flags);
    ASSERT_NE(sss_, nullptr);
    ASSERT_EQ(sss_set_camera(sss_, kCamera.data()), SSS_OK);
    sss_settings s;
    sss_default_settings(&s);
    s.world_units_per_mm = 0.05f;  // several pixels of reach at this size, so the kernel crosses the depth step
    ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK);
  }

  GLuint ms(GLenum format, const std::vector<float>& fine, int samples = 4) {
    const GLuint t = make_multisample_texture(format, kW, kH, samples, fine);
    textures_.push_back(t);
    return t;
  }

  sss_frame frame(GLuint color, GLuint depth, GLuint output = 0) const { return frame_of(color, depth, output); }

  // The scene `fine` (made at twice the size) filtered into an output, then written back in place:
  // the output, and the colour's samples before and after the write-back.
  struct WriteBack {
    std::vector<float> blurred;
    std::vector<std::vector<float>> before, after;
  };
  WriteBack write_back(const SyntheticScene& fine) {
    WriteBack w;
    const GLuint color = ms(GL_RGBA32F, fine.color);
    const GLuint depth = ms(GL_DEPTH_COMPONENT32F, fine.window_depth);
    w.blurred = apply_to_output(frame(color, depth));
    w.before = read_samples(color, kW, kH, 4);
    const sss_frame in_place = frame(color, depth);
    EXPECT_EQ(sss_apply_frame(sss_, &in_place), SSS_OK) << sss_last_error(sss_);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    w.after = read_samples(color, kW, kH, 4);
    return w;
  }

  std::vector<float> apply_to_output(const sss_frame& in) {
    sss_frame f = in;
    f.output_texture = make_rgba32f(kW, kH, std::vector<float>(kW * kH * 4, -7.0f));
    EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    return read_rgba(f.output_texture, kW, kH);
  }

  GLint max_samples_ = 0;
};

// Linear view distance per fine texel, as the shader computes it from hardware depth (float).
std::vector<float> linearised(const SyntheticScene& fine) {
  sss::math::FrameGeometry g;
  g.texture_width = fine.width;
  g.texture_height = fine.height;
  g.viewport = {0, 0, fine.width, fine.height};
  const auto k = sss::math::compute_pass_constants(sss::math::FilterSettings{}, fine.projection, g);
  std::vector<float> d(fine.window_depth.size());
  for (std::size_t i = 0; i < d.size(); ++i) d[i] = sss::math::linearise_depth(k, fine.window_depth[i]);
  return d;
}

// Tolerance for "the same filter on the same numbers": the resolve sums four samples in float
// (a rounding of 2^-24 relative) which can flip one rounding of the RGBA16F intermediate (2^-11
// relative); the vertical pass's weights sum to 1, so the output moves by at most about 2^-11.
// 2^-10 leaves room for two such flips.
constexpr float kSameFilter = 1.0f / 1024.0f;

TEST_F(Msaa, ResolvedInputsGiveTheSingleSampleResultOfTheirBoxAverage) {
  // The relief scene at twice the size has a depth step, a spherical bump, alpha bands and
  // per-sample noise: every pixel's samples differ.
  const SyntheticScene fine = make_relief_scene(2 * kW, 2 * kH, 7, kCamera);
  const SyntheticScene coarse = downsample_2x2(fine);
  const GLuint color = ms(GL_RGBA32F, fine.color);
  const GLuint depth = ms(GL_R32F, fine.distance);
  ASSERT_EQ(texture_samples(color), 4);
  const std::vector<float> msaa = apply_to_output(frame(color, depth));

  const GLuint single_color = make_rgba32f(kW, kH, coarse.color);
  const GLuint single_depth = make_texture(GL_R32F, kW, kH, GL_RED, GL_FLOAT, coarse.distance.data());
  const std::vector<float> single = apply_to_output(frame(single_color, single_depth));
  EXPECT_LE(largest_relative_difference(msaa, single), kSameFilter);
}

TEST_F(Msaa, HardwareDepthIsLinearisedPerSampleBeforeAveraging) {
  // Same scene with hardware depth: the resolve must linearise each sample, then average. The
  // reference gets the linearised samples directly (float, the shader's formula), so any other
  // order (averaging window depth first) shows at the depth step.
  const SyntheticScene fine = make_relief_scene(2 * kW, 2 * kH, 8, kCamera);
  const GLuint color = ms(GL_RGBA32F, fine.color);
  const std::vector<float> hardware = apply_to_output(frame(color, ms(GL_DEPTH_COMPONENT32F, fine.window_depth)));
  const std::vector<float> linear = apply_to_output(frame(color, ms(GL_R32F, linearised(fine))));
  // The GPU's division differs from the CPU's by a few float ulps (~1e-6 relative in distance);
  // the follow-surface factor (~1/reach) turns that into blend changes far below kSameFilter.
  EXPECT_LE(largest_relative_difference(hardware, linear), kSameFilter);

  // And the other resolves really differ from the average along the silhouettes.
  for (uint32_t mode : {SSS_MSAA_DEPTH_SAMPLE0, SSS_MSAA_DEPTH_MIN, SSS_MSAA_DEPTH_MAX}) {
    sss_frame f = frame(color, ms(GL_DEPTH_COMPONENT32F, fine.window_depth));
    f.msaa_depth_resolve = mode;
    const std::vector<float> other = apply_to_output(f);
    EXPECT_GT(largest_relative_difference(other, hardware), kSameFilter) << "mode " << mode;
  }
}

TEST_F(Msaa, InteriorPixelsWhoseSamplesAgreeMatchTheSingleSampleResult) {
  // Every sample equals its pixel: the MSAA result must be the single-sample one, hardware depth
  // on both sides. The single-sample path interpolates hardware depth between texels and then
  // linearises; the MSAA path interpolates linearised depth: on smooth surfaces the two differ
  // at second order (tiny), across the depth step both are far beyond the kernel's reach (the
  // tap falls back to the centre either way).
  const SyntheticScene coarse = make_relief_scene(kW, kH, 9, kCamera);
  const SyntheticScene fine = upsample_2x2(coarse);
  const std::vector<float> msaa =
      apply_to_output(frame(ms(GL_RGBA32F, fine.color), ms(GL_DEPTH_COMPONENT32F, fine.window_depth)));
  const std::vector<float> single =
      apply_to_output(frame(make_rgba32f(kW, kH, coarse.color), make_depth32f(kW, kH, coarse.window_depth)));
  EXPECT_LE(largest_relative_difference(msaa, single), kSameFilter);
}

TEST_F(Msaa, WriteBackChangesOnlyTranslucentSamplesAndResolvesToTheBlurredImage) {
  const SyntheticScene fine = make_relief_scene(2 * kW, 2 * kH, 10, kCamera);
  const WriteBack w = write_back(fine);
  const std::vector<float>& blurred = w.blurred;
  const auto& before = w.before;
  const auto& after = w.after;

  int changed_pixels = 0, checked_pixels = 0;
  for (std::size_t p = 0; p < static_cast<std::size_t>(kW * kH); ++p) {
    bool clamped = false, changed = false;
    for (std::size_t s = 0; s < 4; ++s) {
      const float* b = &before[s][p * 4];
      const float* a = &after[s][p * 4];
      ASSERT_EQ(0, std::memcmp(&a[3], &b[3], sizeof(float))) << "alpha changed, pixel " << p << " sample " << s;
      if (!(b[3] > 0.0f)) {
        ASSERT_EQ(0, std::memcmp(a, b, 4 * sizeof(float))) << "opaque sample changed, pixel " << p << " sample " << s;
      }
      for (int c = 0; c < 3; ++c) {
        if (a[c] == 0.0f && b[c] != 0.0f) clamped = true;
        if (a[c] != b[c]) changed = true;
      }
    }
    changed_pixels += changed ? 1 : 0;
    if (clamped) continue;  // a sample clamped at 0 breaks the average by design (documented)
    ++checked_pixels;
    for (std::size_t c = 0; c < 3; ++c) {
      const float mean = (after[0][p * 4 + c] + after[1][p * 4 + c] + after[2][p * 4 + c] + after[3][p * 4 + c]) / 4.0f;
      // float rounding of (sample + delta · 4/n) and of the mean: a few 2^-24 relative steps.
      EXPECT_NEAR(mean, blurred[p * 4 + c], 1e-5f * std::fmax(1.0f, std::fabs(blurred[p * 4 + c])))
          << "pixel " << p << " channel " << c;
    }
  }
  EXPECT_GT(changed_pixels, kW * kH / 2) << "the filter must actually have changed most pixels";
  EXPECT_GT(checked_pixels, kW * kH * 9 / 10);
}

TEST_F(Msaa, AMultisampledHostStencilLimitsTheFilter) {
  // The relief scene's stencil excludes the right quarter; its edge falls between pixels, so every
  // sample of a pixel agrees and the sample the driver's stencil resolve keeps does not matter.
  const SyntheticScene fine = make_relief_scene(2 * kW, 2 * kH, 13, kCamera);
  const GLuint color = ms(GL_RGBA32F, fine.color);
  const GLuint depth_stencil = make_multisample_depth_stencil(kW, kH, 4, fine.window_depth, fine.stencil);
  textures_.push_back(depth_stencil);
  const sss_stencil stencil = {depth_stencil, 1, 0xFF};
  sss_frame f = frame(color, depth_stencil);
  f.stencil = &stencil;
  const std::vector<float> filtered = apply_to_output(f);
  sss_settings s;
  ASSERT_EQ((s.struct_size = sizeof s, sss_get_settings(sss_, &s)), SSS_OK);
  const float width = s.world_units_per_mm;
  s.world_units_per_mm = 0.0f;  // identity: the output is the resolved colour
  ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK);
  const std::vector<float> resolved = apply_to_output(f);
  s.world_units_per_mm = width;
  ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK);

  const SyntheticScene coarse = downsample_2x2(fine);
  int outside = 0, changed_inside = 0, inside = 0;
  for (std::size_t p = 0; p < static_cast<std::size_t>(kW * kH); ++p) {
    if (coarse.stencil[p] == 0) {
      ++outside;
      EXPECT_EQ(0, std::memcmp(&filtered[p * 4], &resolved[p * 4], 4 * sizeof(float))) << "pixel " << p;
    } else if (coarse.color[p * 4 + 3] > 0.0f) {
      ++inside;
      changed_inside += std::memcmp(&filtered[p * 4], &resolved[p * 4], 3 * sizeof(float)) != 0;
    }
  }
  EXPECT_GT(outside, kW * kH / 8);
  EXPECT_GT(changed_inside, inside * 9 / 10);

  // Written back behind the stencil: no sample outside it changes (the write-back reads the blurred
  // image there too, where the passes copied the resolved colour), and the samples inside resolve to
  // the filtered output.
  const auto before = read_samples(color, kW, kH, 4);
  sss_frame g = frame(color, depth_stencil);
  g.stencil = &stencil;
  ASSERT_EQ(sss_apply_frame(sss_, &g), SSS_OK) << sss_last_error(sss_);
  const auto after = read_samples(color, kW, kH, 4);
  int outside_changed = 0, inside_checked = 0;
  for (std::size_t p = 0; p < static_cast<std::size_t>(kW * kH); ++p) {
    for (std::size_t i = 0; i < 4; ++i) {
      const bool same = std::memcmp(&before[i][p * 4], &after[i][p * 4], 4 * sizeof(float)) == 0;
      if (coarse.stencil[p] == 0) outside_changed += same ? 0 : 1;
    }
    if (coarse.stencil[p] == 0 || !(coarse.color[p * 4 + 3] > 0.0f)) continue;
    bool clamped = false;
    for (std::size_t i = 0; i < 4; ++i) {
      for (std::size_t c = 0; c < 3; ++c) clamped = clamped || (after[i][p * 4 + c] == 0.0f && before[i][p * 4 + c] != 0.0f);
    }
    if (clamped) continue;
    ++inside_checked;
    for (std::size_t c = 0; c < 3; ++c) {
      const float mean = (after[0][p * 4 + c] + after[1][p * 4 + c] + after[2][p * 4 + c] + after[3][p * 4 + c]) / 4.0f;
      EXPECT_NEAR(mean, filtered[p * 4 + c], 1e-5f * std::fmax(1.0f, std::fabs(filtered[p * 4 + c]))) << "pixel " << p;
    }
  }
  EXPECT_EQ(outside_changed, 0);
  EXPECT_GT(inside_checked, inside / 2);
}

TEST_F(Msaa, BadMultisampledInputFailsWithASpecificMessageAndChangesNothing) {
  const SyntheticScene fine = make_relief_scene(2 * kW, 2 * kH, 11, kCamera);
  const SyntheticScene coarse = downsample_2x2(fine);
  const GLuint color = ms(GL_RGBA16F, fine.color);
  const GLuint depth = ms(GL_DEPTH_COMPONENT32F, fine.window_depth);
  const GLuint single_color = make_rgba16f(kW, kH, coarse.color);
  const GLuint single_depth = make_depth32f(kW, kH, coarse.window_depth);
  const auto before = read_samples(color, kW, kH, 4);
  const std::vector<float> single_before = read_rgba(single_color, kW, kH);

  auto expect_fails = [&](const sss_frame& f, sss_result code, const std::string& fragment) {
    EXPECT_EQ(sss_apply_frame(sss_, &f), code) << sss_last_error(sss_);
    const std::string message = sss_last_error(sss_);
    EXPECT_NE(message.find(fragment), std::string::npos) << message;
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  };
  const std::string c = std::to_string(color), d = std::to_string(depth);
  expect_fails(frame(color, single_depth), SSS_ERROR_INVALID_TEXTURE,
               "depth_texture = " + std::to_string(single_depth) + " is GL_TEXTURE_2D but color_texture = " + c +
                   " is GL_TEXTURE_2D_MULTISAMPLE with 4 samples");
  expect_fails(frame(single_color, depth), SSS_ERROR_INVALID_TEXTURE,
               "depth_texture = " + d + " is GL_TEXTURE_2D_MULTISAMPLE with 4 samples but color_texture");
  sss_frame bad_mode = frame(color, depth);
  bad_mode.msaa_depth_resolve = 9;
  expect_fails(bad_mode, SSS_ERROR_INVALID_ARGUMENT, "frame->msaa_depth_resolve = 9");
  const GLuint ms_output = ms(GL_RGBA32F, {});
  expect_fails(frame(color, depth, ms_output), SSS_ERROR_INVALID_TEXTURE,
               "output_texture = " + std::to_string(ms_output) + " is GL_TEXTURE_2D_MULTISAMPLE with 4 samples");

  // A sample count the context does not offer: the GL refuses the storage, the module says so.
  const GLuint too_many = ms(GL_RGBA16F, {}, 2 * max_samples_);
  expect_fails(frame(too_many, depth), SSS_ERROR_INVALID_TEXTURE,
               "color_texture = " + std::to_string(too_many) + " (GL_TEXTURE_2D_MULTISAMPLE) has no storage");
  EXPECT_NE(std::string(sss_last_error(sss_)).find("at most " + std::to_string(max_samples_) + " samples"),
            std::string::npos);

  // Mismatched and unsupported counts. llvmpipe makes every multisample texture with 4 samples,
  // so a module created through the fault loader is told another count for one texture (what a
  // driver offering 2, 4 and 8 would report).
  sss_create_desc desc = {};
  desc.struct_size = sizeof desc;
  desc.get_proc_address = fault_get_proc_address;
  desc.get_proc_address_user = headless_;
  sss_context* faulty = nullptr;
  ASSERT_EQ(sss_create(&desc, &faulty), SSS_OK);
  ASSERT_EQ(sss_set_camera(faulty, kCamera.data()), SSS_OK);
  auto expect_faulty_fails = [&](GLuint texture, int samples, sss_result code, const std::string& fragment) {
    reset_faults();
    faults().fake_samples_texture = texture;
    faults().fake_samples = samples;
    const sss_frame f = frame(color, depth);
    EXPECT_EQ(sss_apply_frame(faulty, &f), code) << sss_last_error(faulty);
    const std::string message = sss_last_error(faulty);
    EXPECT_NE(message.find(fragment), std::string::npos) << message;
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    reset_faults();
  };
  expect_faulty_fails(depth, 2, SSS_ERROR_INVALID_TEXTURE,
                      "depth_texture = " + d + " is GL_TEXTURE_2D_MULTISAMPLE with 2 samples but color_texture = " +
                          c + " is GL_TEXTURE_2D_MULTISAMPLE with 4 samples");
  // Counts above what the context offers (llvmpipe: 4 at most; NVIDIA: 32).
  const int over = 2 * max_samples_;
  expect_faulty_fails(color, over, SSS_ERROR_UNSUPPORTED,
                      "color_texture = " + c + " has " + std::to_string(over) +
                          " samples: this context supports at most " + std::to_string(max_samples_));
  expect_faulty_fails(color, 16 * max_samples_, SSS_ERROR_UNSUPPORTED, "has " + std::to_string(16 * max_samples_) + " samples");
  sss_destroy(faulty);

  const auto after = read_samples(color, kW, kH, 4);
  for (std::size_t s = 0; s < 4; ++s) {
    EXPECT_EQ(0, std::memcmp(before[s].data(), after[s].data(), before[s].size() * sizeof(float))) << "sample " << s;
  }
  const std::vector<float> single_after = read_rgba(single_color, kW, kH);
  EXPECT_EQ(0, std::memcmp(single_before.data(), single_after.data(), single_before.size() * sizeof(float)));
}

TEST_F(Msaa, StateIsRestoredAndNoErrorIsLeftInBothOutputModes) {
  const SyntheticScene fine = make_relief_scene(2 * kW, 2 * kH, 12, kCamera);
  const GLuint color = ms(GL_RGBA16F, fine.color);
  const GLuint depth = ms(GL_DEPTH24_STENCIL8, fine.window_depth);
  const GLuint output = make_rgba16f(kW, kH, std::vector<float>(kW * kH * 4, 0.0f));
  // Host bindings on every unit the module uses, on both targets, and a sample mask.
  const GLuint extra_ms = ms(GL_RGBA16F, {});
  for (GLenum unit = 0; unit < 3; ++unit) {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, output);
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, extra_ms);
  }
  glActiveTexture(GL_TEXTURE1);
  glEnable(GL_SAMPLE_MASK);
  glSampleMaski(0, 0x5u);
  ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  for (GLuint out : {output, 0u}) {
    const Snapshot before = take_snapshot();
    const sss_frame f = frame(color, depth, out);
    EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
    EXPECT_EQ(describe_differences(before, take_snapshot()), "") << "output " << out;
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  }
}

// A host that switched multisample rasterisation off (glDisable(GL_MULTISAMPLE), say for its own
// single-sample passes): the GL then ignores the sample mask, so each draw of the per-sample
// write-back (one per sample under glSampleMaski) would write every sample of its pixels, the
// opaque ones included. The module switches it on for its passes and back off before it returns:
// the samples come out as for a host that left it on, and GL_MULTISAMPLE stays off.
TEST_F(Msaa, WriteBackIsTheSameForAHostThatDisabledMultisampling) {
  SyntheticScene fine = make_relief_scene(2 * kW, 2 * kH, 14, kCamera);
  // Sample 1 of every third column opaque: pixels whose samples are translucent and opaque, the
  // ones a write-back that ignored the sample mask would spoil (see downsample_2x2 for the layout).
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; x += 3) fine.color[(static_cast<std::size_t>(2 * y) * 2 * kW + 2 * x + 1) * 4 + 3] = 0.0f;
  }
  std::vector<std::vector<float>> before, after[2];
  for (int disabled = 0; disabled < 2; ++disabled) {
    SCOPED_TRACE(disabled ? "GL_MULTISAMPLE disabled by the host" : "GL_MULTISAMPLE enabled");
    const GLuint color = ms(GL_RGBA32F, fine.color);
    const GLuint depth = ms(GL_DEPTH_COMPONENT32F, fine.window_depth);
    before = read_samples(color, kW, kH, 4);
    disabled ? glDisable(GL_MULTISAMPLE) : glEnable(GL_MULTISAMPLE);
    const Snapshot state = take_snapshot();
    const sss_frame f = frame(color, depth);
    ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    EXPECT_EQ(describe_differences(state, take_snapshot()), "");
    EXPECT_EQ(glIsEnabled(GL_MULTISAMPLE), disabled ? GL_FALSE : GL_TRUE);
    glEnable(GL_MULTISAMPLE);  // the read-back below draws
    after[disabled] = read_samples(color, kW, kH, 4);
  }
  // With it disabled: the opaque samples and every alpha keep their exact value...
  int opaque_changed = 0, alpha_changed = 0, opaque = 0, mixed = 0;
  for (std::size_t p = 0; p < static_cast<std::size_t>(kW * kH); ++p) {
    bool translucent = false;
    for (std::size_t s = 0; s < 4; ++s) translucent = translucent || before[s][p * 4 + 3] > 0.0f;
    for (std::size_t s = 0; s < 4; ++s) {
      const float* b = &before[s][p * 4];
      const float* a = &after[1][s][p * 4];
      alpha_changed += std::memcmp(&a[3], &b[3], sizeof(float)) != 0;
      if (b[3] > 0.0f) continue;
      ++opaque;
      mixed += translucent;
      opaque_changed += std::memcmp(a, b, 4 * sizeof(float)) != 0;
    }
  }
  // Opaque samples in pixels the write-back draws (a translucent sample beside them) are the ones
  // a write without the sample mask overwrites.
  EXPECT_GT(mixed, 20) << "the scene must have opaque samples beside translucent ones";
  EXPECT_EQ(opaque_changed, 0) << "of " << opaque << " opaque samples, " << mixed << " beside translucent ones";
  EXPECT_EQ(alpha_changed, 0);
  // ...and every sample equals the one written back with it enabled.
  for (std::size_t s = 0; s < 4; ++s) EXPECT_EQ(after[1][s], after[0][s]) << "sample " << s;
}

// sss_get_stats counts every full-screen draw of the MSAA path: the resolve (which also writes the
// passes' inputs and fills the stencil-rejected pixels of the horizontal pass's target: no inputs
// draw of their own since issue 24), the stencil mark from alpha, then the single-sample passes on
// the resolved images (horizontal blur, vertical blur + copy
// into a separate output; written back, the vertical pass copies nothing: the write-back reads only
// the pixels the mask let through), and written back in one draw (GLSL 4.20: gl_SampleMask picks
// each pixel's translucent samples) or, on a GL 3.3 context, one draw per sample (4 here).
TEST_F(Msaa, StatsCountEveryDrawOfTheMsaaPath) {
  const SyntheticScene fine = make_relief_scene(2 * kW, 2 * kH, 13, kCamera);
  const GLuint color = ms(GL_RGBA16F, fine.color);
  const GLuint depth = ms(GL_DEPTH_COMPONENT32F, fine.window_depth);
  const GLuint output = make_rgba16f(kW, kH, std::vector<float>(kW * kH * 4, 0.0f));
  for (const bool gl33 : {false, true}) {
    SCOPED_TRACE(gl33 ? "a GL 3.3 context" : "this context");
    if (gl33) {
      sss_destroy(sss_);
      loader_override_ = loader_telling(GL_VERSION, "3.3 (Core Profile) as told by the test", sss_headless_get_proc_address);
      sss_ = create_sss();
      ASSERT_NE(sss_, nullptr);
      ASSERT_EQ(sss_set_camera(sss_, kCamera.data()), SSS_OK);
    }
    const uint32_t write_back = gl33 ? 4 : 1;
    const uint32_t expected[2] = {1 + 1 + 1 + 2, 1 + 1 + 1 + 1 + write_back};  // into output, written back
    const GLuint outputs[2] = {output, 0u};
    for (int i = 0; i < 2; ++i) {
      const sss_frame f = frame(color, depth, outputs[i]);
      ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
      sss_stats st = {};
      st.struct_size = sizeof st;
      ASSERT_EQ(sss_get_stats(sss_, &st), SSS_OK);
      EXPECT_EQ(st.frames, static_cast<uint64_t>(i + 1));
      EXPECT_EQ(st.last_frame_passes, expected[i]) << "output " << outputs[i];
      EXPECT_EQ(st.glsl_variant, static_cast<uint32_t>(gl33 ? SSS_GLSL_330_CORE : SSS_GLSL_420_CORE));
      // The resolve, then the fragment passes, whatever path the last single-sample frame took.
      EXPECT_EQ(st.last_frame_path, static_cast<uint32_t>(SSS_PATH_FRAGMENT));
    }
  }
}

// An MSAA frame after a compute frame reports the fragment passes it ran, not the compute path.
TEST_F(Msaa, TheLastFramePathOfAnMsaaFrameIsTheFragmentPasses) {
  const SyntheticScene fine = make_relief_scene(2 * kW, 2 * kH, 13, kCamera);
  const SyntheticScene coarse = make_relief_scene(kW, kH, 13, kCamera);
  sss_settings s = visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f);
  s.path = SSS_PATH_COMPUTE;
  ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK);
  sss_frame single = frame_of(make_rgba16f(kW, kH, coarse.color), make_depth32f(kW, kH, coarse.window_depth));
  single.flags = SSS_FRAME_TARGET_COMPLETE;
  ASSERT_EQ(sss_apply_frame(sss_, &single), SSS_OK) << sss_last_error(sss_);
  sss_stats st = {};
  st.struct_size = sizeof st;
  ASSERT_EQ(sss_get_stats(sss_, &st), SSS_OK);
  const uint32_t single_path = st.last_frame_path;  // compute where the GL has it
  const sss_frame f = frame(ms(GL_RGBA16F, fine.color), ms(GL_DEPTH_COMPONENT32F, fine.window_depth), 0u);
  ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
  ASSERT_EQ(sss_get_stats(sss_, &st), SSS_OK);
  EXPECT_EQ(st.last_frame_path, static_cast<uint32_t>(SSS_PATH_FRAGMENT)) << "after a frame on path " << single_path;
}

// The write-back never copies the host's samples: the module allocates no multisampled texture
// (counted through the loader), on a first frame and on later ones.
TEST_F(Msaa, WritingBackAllocatesNoMultisampledCopy) {
  sss_destroy(sss_);
  loader_override_ = counting_loader(sss_headless_get_proc_address);
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  ASSERT_EQ(sss_set_camera(sss_, kCamera.data()), SSS_OK);
  const SyntheticScene fine = make_relief_scene(2 * kW, 2 * kH, 15, kCamera);
  const GLuint color = ms(GL_RGBA16F, fine.color);
  const GLuint depth = ms(GL_DEPTH_COMPONENT32F, fine.window_depth);
  reset_call_counts();
  const sss_frame f = frame(color, depth);
  for (int i = 0; i < 2; ++i) ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
  const GlCallCounts n = call_counts();
  EXPECT_EQ(n.creations.count("glTexImage2DMultisample"), 0u) << n.describe_creations();
  EXPECT_GT(n.creations.count("glTexImage2D"), 0u) << "the count is real: the resolve targets were allocated";
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// A GL 3.3 context (GLSL 3.30: no gl_SampleMask) writes back one draw per sample under
// glSampleMaski: the samples come out exactly as from the one draw.
TEST_F(Msaa, WriteBackOnAGl33ContextGivesTheSameSamples) {
  SyntheticScene fine = make_relief_scene(2 * kW, 2 * kH, 16, kCamera);
  for (std::size_t i = 0; i < fine.color.size() / 4; i += 7) fine.color[i * 4 + 3] = 0.0f;  // opaque samples beside translucent ones
  std::vector<std::vector<float>> after[2];
  for (int gl33 = 0; gl33 < 2; ++gl33) {
    if (gl33 != 0) {
      loader_override_ = loader_telling(GL_VERSION, "3.3 (Core Profile) as told by the test", sss_headless_get_proc_address);
      fresh_context();
      if (HasFatalFailure()) return;
    }
    const GLuint color = ms(GL_RGBA32F, fine.color);
    const sss_frame f = frame(color, ms(GL_DEPTH_COMPONENT32F, fine.window_depth));
    ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    after[gl33] = read_samples(color, kW, kH, 4);
  }
  const auto before = read_samples(ms(GL_RGBA32F, fine.color), kW, kH, 4);
  EXPECT_NE(after[0][0], before[0]) << "the write-back must have changed samples";
  for (std::size_t s = 0; s < 4; ++s) EXPECT_EQ(after[1][s], after[0][s]) << "sample " << s;
}

// Where adding the pixel's change would take a translucent sample below 0, the pixel's translucent
// samples are pulled towards their smallest value instead, which lands on 0 (exactly, but for a
// fused blender's rounding of one product: see below): no sample is negative, and the written
// pixel's box resolve is still the blurred pixel (to the rounding of the factor, 2^-11 of the
// samples' spread), unless the blurred pixel is darker than its opaque samples alone, where every
// translucent sample becomes 0.
TEST_F(Msaa, ASampleThatWouldGoNegativeKeepsTheResolveOnTheBlurredPixel) {
  SyntheticScene fine = make_relief_scene(2 * kW, 2 * kH, 17, kCamera);
  // A near-black translucent sample in every third pixel: wherever its pixel darkens, it would go
  // below 0.
  for (int y = 0; y < kH; ++y) {
    for (int x = (y % 3); x < kW; x += 3) {
      float* c = &fine.color[(static_cast<std::size_t>(2 * y) * 2 * kW + 2 * x) * 4];
      if (c[3] > 0.0f) c[0] = c[1] = c[2] = 1e-4f;
    }
  }
  const WriteBack w = write_back(fine);
  const std::vector<float>& blurred = w.blurred;
  const auto& before = w.before;
  const auto& after = w.after;
  int pulled = 0, all_black = 0;
  for (std::size_t p = 0; p < static_cast<std::size_t>(kW * kH); ++p) {
    for (std::size_t c = 0; c < 3; ++c) {
      float opaque = 0.0f, lowest = 1e30f, highest = -1e30f, mean = 0.0f;
      // The sample at the smallest value m becomes b * m - (b * m), the blender's product less the
      // shader's rounded one. A blender that fuses the multiply and the add (NVIDIA's) keeps the
      // product's rounding error, at most half an ulp of b * m <= m (b <= 1), of either sign: 0 up
      // to that (measured there: -1.8e-12).
      float residual = 0.0f;
      for (std::size_t s = 0; s < 4; ++s) residual = std::fmax(residual, std::fabs(before[s][p * 4 + c]));
      residual = std::ldexp(residual, -24);
      bool went_to_zero = false;
      for (std::size_t s = 0; s < 4; ++s) {
        const float b = before[s][p * 4 + c], a = after[s][p * 4 + c];
        mean += a / 4.0f;
        if (!(before[s][p * 4 + 3] > 0.0f)) {
          opaque += b;
          continue;
        }
        ASSERT_GE(a, -residual) << "pixel " << p << " sample " << s << " channel " << c;
        lowest = std::fmin(lowest, b);
        highest = std::fmax(highest, b);
        went_to_zero = went_to_zero || (std::fabs(a) <= residual && b != 0.0f);
      }
      if (!went_to_zero) continue;
      if (4.0f * blurred[p * 4 + c] <= opaque) {
        ++all_black;
        continue;
      }
      ++pulled;
      EXPECT_NEAR(mean, blurred[p * 4 + c], (highest - lowest) / 2048.0f + 1e-5f * std::fmax(1.0f, blurred[p * 4 + c]))
          << "pixel " << p << " channel " << c;
    }
  }
  EXPECT_GT(pulled, 50) << "the scene must have samples that would go negative (" << all_black << " all black)";
}

// Without a host stencil the path marks its own from the resolved alpha (the paper's multisampling
// path), so the blur passes touch exactly the pixels with a translucent sample: the vertical pass's
// sample count (SSS_CREATE_STATS, into a separate output) equals that many pixels.
TEST_F(Msaa, TheStencilBuiltFromTheMaskLimitsThePassesToTranslucentPixels) {
  fresh_context(SSS_CREATE_STATS);
  if (HasFatalFailure()) return;
  const SyntheticScene fine = make_relief_scene(2 * kW, 2 * kH, 13, kCamera);
  uint64_t translucent = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      bool any = false;
      for (int i = 0; i < 4; ++i) {
        const std::size_t t = static_cast<std::size_t>(2 * y + i / 2) * (2 * kW) + static_cast<std::size_t>(2 * x + i % 2);
        any = any || fine.color[t * 4 + 3] > 0.0f;
      }
      translucent += any ? 1u : 0u;
    }
  }
  ASSERT_GT(translucent, 0u);
  ASSERT_LT(translucent, static_cast<uint64_t>(kW) * kH);  // the relief scene has an opaque corner
  const GLuint color = ms(GL_RGBA16F, fine.color);
  const GLuint depth = ms(GL_DEPTH_COMPONENT32F, fine.window_depth);
  const GLuint output = make_rgba16f(kW, kH, std::vector<float>(kW * kH * 4, 0.0f));
  const sss_frame f = frame(color, depth, output);
  for (int i = 0; i < 3; ++i) {  // the counts are read back without stalling, a frame or more later
    ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
    glFinish();
  }
  sss_stats st = {};
  st.struct_size = sizeof st;
  ASSERT_EQ(sss_get_stats(sss_, &st), SSS_OK);
  ASSERT_NE(st.measured & SSS_STATS_PIXELS, 0u);
  EXPECT_EQ(st.pixels_touched, translucent);
}

// OpenGL ES (backend egl-gles; llvmpipe gives ES 3.2, so multisampled textures exist): the MSAA
// path is desktop-only, so a multisampled input fails with SSS_ERROR_UNSUPPORTED and a message
// that says what to do, before anything is drawn, leaving no error and the state as it was. The
// module is created the fixture's way on ES (no glGetTexLevelParameteriv), so this also checks
// that the refusal comes before the ES 3.0 texture description is asked for.
class MsaaOnGles : public GlTest {};

TEST_F(MsaaOnGles, AMultisampledInputIsUnsupported) {
  if (!is_gles()) GTEST_SKIP() << "OpenGL ES only (backend egl-gles); desktop GL runs the MSAA path (Msaa.*)";
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  ASSERT_EQ(sss_set_camera(sss_, kCamera.data()), SSS_OK);
  GLuint color = 0;
  glGenTextures(1, &color);
  textures_.push_back(color);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, color);
  glTexStorage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, 4, GL_RGBA8, kW, kH, GL_TRUE);  // ES 3.1
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
  ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  const GLuint depth = make_depth32f(kW, kH, std::vector<float>(kW * kH, 0.5f));
  const GLuint bound = make_rgba16f(4, 4, std::vector<float>(64, 0.25f));
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, bound);  // the module's probe binds on unit 0: this must survive it
  const Snapshot before = take_snapshot(true);
  sss_frame f = frame_of(color, depth);
  EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_ERROR_UNSUPPORTED) << sss_last_error(sss_);
  const std::string message = sss_last_error(sss_);
  EXPECT_NE(message.find("color_texture = " + std::to_string(color) + " is GL_TEXTURE_2D_MULTISAMPLE"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("desktop OpenGL"), std::string::npos) << message;
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(describe_differences(before, take_snapshot(true)), "");
}

// OpenGL ES 3.0 has no GL_TEXTURE_2D_MULTISAMPLE (an invalid enum there), so the module must never
// bind or query it. llvmpipe gives ES 3.2, so the module is told "OpenGL ES 3.0" by the loader
// (glGetString), loses the ES 3.1 texture query (as on a real ES 3.0 driver), and every use of the
// multisample enums through glBindTexture, glGetIntegerv and glGetIntegeri_v is counted.
using GetStringFn = const GLubyte* (*)(GLenum);
using BindTextureFn = void (*)(GLenum, GLuint);
using GetIntegervFn = void (*)(GLenum, GLint*);
using GetIntegeriVFn = void (*)(GLenum, GLuint, GLint*);
GetStringFn g_real_get_string = nullptr;
BindTextureFn g_real_bind_texture = nullptr;
GetIntegervFn g_real_get_integerv = nullptr;
GetIntegeriVFn g_real_get_integeri_v = nullptr;
int g_multisample_uses = 0;

const GLubyte* get_string_es30(GLenum name) {
  if (name == GL_VERSION) return reinterpret_cast<const GLubyte*>("OpenGL ES 3.0 as told by the test");
  return g_real_get_string(name);
}
void bind_texture_counted(GLenum target, GLuint texture) {
  if (target == GL_TEXTURE_2D_MULTISAMPLE) ++g_multisample_uses;
  g_real_bind_texture(target, texture);
}
void get_integerv_counted(GLenum pname, GLint* data) {
  if (pname == GL_TEXTURE_BINDING_2D_MULTISAMPLE || pname == GL_MAX_COLOR_TEXTURE_SAMPLES ||
      pname == GL_MAX_DEPTH_TEXTURE_SAMPLES) {
    ++g_multisample_uses;
  }
  g_real_get_integerv(pname, data);
}
void get_integeri_v_counted(GLenum pname, GLuint index, GLint* data) {
  if (pname == GL_SAMPLE_MASK_VALUE) ++g_multisample_uses;
  g_real_get_integeri_v(pname, index, data);
}
template <typename Fn>
void* wrap(Fn* real, void* address, void* wrapper) {
  *real = reinterpret_cast<Fn>(address);
  return wrapper;
}
void* es30_told_get_proc_address(const char* name, void* user) {
  const std::string n = name;
  void* real = sss_headless_get_proc_address(name, user);
  if (n == "glGetTexLevelParameteriv") return nullptr;  // ES 3.1+
  if (n == "glGetString") return wrap(&g_real_get_string, real, reinterpret_cast<void*>(&get_string_es30));
  if (n == "glBindTexture") return wrap(&g_real_bind_texture, real, reinterpret_cast<void*>(&bind_texture_counted));
  if (n == "glGetIntegerv") return wrap(&g_real_get_integerv, real, reinterpret_cast<void*>(&get_integerv_counted));
  if (n == "glGetIntegeri_v") {
    return wrap(&g_real_get_integeri_v, real, reinterpret_cast<void*>(&get_integeri_v_counted));
  }
  return real;
}

TEST_F(MsaaOnGles, OnEs30TheMultisampleTargetIsNeverTouched) {
  if (!is_gles()) GTEST_SKIP() << "OpenGL ES only (backend egl-gles)";
  loader_override_ = es30_told_get_proc_address;
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  ASSERT_EQ(sss_set_camera(sss_, kCamera.data()), SSS_OK);
  GLuint multisampled = 0;
  glGenTextures(1, &multisampled);
  textures_.push_back(multisampled);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, multisampled);
  glTexStorage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, 4, GL_RGBA8, kW, kH, GL_TRUE);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
  const std::vector<float> rgba(kW * kH * 4, 0.5f);
  const GLuint color = make_rgba16f(kW, kH, rgba);
  const GLuint depth = make_depth32f(kW, kH, std::vector<float>(kW * kH, 0.5f));
  ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  sss_frame f = frame_of(multisampled, depth);
  f.color_format = GL_RGBA16F;
  f.depth_format = GL_DEPTH_COMPONENT32F;
  f.texture_width = kW;
  f.texture_height = kH;
  g_multisample_uses = 0;
  EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_ERROR_INVALID_TEXTURE) << sss_last_error(sss_);
  const std::string message = sss_last_error(sss_);
  EXPECT_NE(message.find("color_texture = " + std::to_string(multisampled) + " is not a GL_TEXTURE_2D"),
            std::string::npos)
      << message;
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  f.color_texture = color;  // the ES 3.0 path itself works and touches no multisample state either
  EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
  EXPECT_EQ(g_multisample_uses, 0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

}  // namespace
}  // namespace sss_test
