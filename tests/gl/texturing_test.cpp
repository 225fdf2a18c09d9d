// The texturing modes (sss.h sss_texturing, issue 48): the host's colour is irradiance E times
// albedo A; post-scatter blurs E alone and multiplies by A after, pre- and post-scatter takes
// sqrt(A) on each side. What they must give, on every path, mode and kernel family run here:
// - uniform light over an albedo with detail at the pixel (a checker of 2-pixel cells): the blur of
//   a constant is that constant, so post-scatter gives the input back at every pixel (the albedo's
//   detail kept), to within the half-float steps the copy, the intermediate and the output round to;
//   pre-scatter, today's behaviour and the default, blurs the checker (the check's own test);
// - any light: the module's post-scatter output equals A_post times the pre-scatter filter of the
//   host's colour over A_post, run by the same module on a texture holding that quotient (the
//   divide, the filter and the multiply as one reference); pixels the passes leave alone are the
//   host's colour bit for bit in a separate output;
// - the refusals: a mode without an albedo texture, an albedo of another size or format, a bad
//   albedo_format, and on the MSAA path an albedo of another sample count or size; each names its
//   field and leaves the colour untouched;
// - a multisampled colour with an albedo multisampled alike: each sample is divided by its own
//   A_post, and the write-back multiplies each sample's change by it (TexturingMsaa.*).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "fault_loader.hpp"
#include "filter_case.hpp"
#include "host_gl_util.hpp"
#include "math/cpu_msaa_texturing.hpp"
#include "math/cpu_texturing.hpp"
#include "math/half_float.hpp"
#include "multisample_textures.hpp"

using namespace host_gl;

namespace sss_test {
namespace {

constexpr int kW = 64, kH = 48;
constexpr float kFloor = sss::math::kAlbedoFloor;  // albedo.glsl's kSssAlbedoFloor (sss.h sss_texturing)
// One half-float step relative to the value: 2^-11 (10 stored fraction bits, rounding to nearest).
constexpr float kHalfStep = 1.0f / 2048.0f;

struct Inputs {
  std::vector<float> albedo;  // RGBA16F-exact: a checker of 2-pixel cells, and one dark cell below the floor
  std::vector<float> color;   // E · A rounded to half, alpha the scene's strength
};

constexpr float kUniform[3] = {0.8f, 0.55f, 0.4f};  // the uniform light
// The near-black freckle's pixels (albedo 0.001, below the floor).
bool in_freckle(int x, int y) { return x >= 40 && x < 44 && y >= 20 && y < 24; }

// `light`: the scene's own colour as irradiance (false: the uniform light); `freckle`: with it.
Inputs make_inputs(const SyntheticScene& scene, bool light, bool freckle = true) {
  Inputs in;
  const std::size_t n = static_cast<std::size_t>(kW) * kH;
  in.albedo.resize(n * 4);
  in.color.resize(n * 4);
  for (std::size_t i = 0; i < n; ++i) {
    const int x = static_cast<int>(i % kW), y = static_cast<int>(i / kW);
    const bool dark = ((x / 2) + (y / 2)) % 2 == 0;
    for (int c = 0; c < 3; ++c) {
      float a = dark ? 0.2f + 0.05f * static_cast<float>(c) : 0.9f - 0.1f * static_cast<float>(c);
      if (freckle && in_freckle(x, y)) a = 0.001f;  // below the floor
      in.albedo[i * 4 + c] = sss::math::round_to_half(a);
      const float e = light ? scene.color[i * 4 + c] : kUniform[c];
      in.color[i * 4 + c] = sss::math::round_to_half(e * in.albedo[i * 4 + c]);
    }
    in.albedo[i * 4 + 3] = 1.0f;
    in.color[i * 4 + 3] = scene.color[i * 4 + 3];
  }
  return in;
}

class Texturing : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    scene_ = make_relief_scene(kW, kH, 3, perspective_matrix(40.0f, 64.0f / 48.0f, 0.1f, 10.0f));
  }
  void fresh(const sss_settings& s) { fresh_sss(s, scene_.projection.data()); }
  // The frame, described (ES 3.0 cannot be asked), into a separate RGBA16F output.
  sss_result apply(sss_frame f) {
    f.texture_width = kW;
    f.texture_height = kH;
    f.color_format = GL_RGBA16F;
    f.depth_format = GL_DEPTH_COMPONENT32F;
    if (f.output_texture != 0) f.output_format = GL_RGBA16F;
    if (f.albedo_texture != 0) f.albedo_format = GL_RGBA16F;
    f.flags = SSS_FRAME_TARGET_COMPLETE;  // the compute path needs the promise
    return sss_apply_frame(sss_, &f);
  }
  // The frame of `colour` with `settings` (texturing as given) into a fresh output, read back.
  std::vector<float> filtered(const sss_settings& settings, const std::vector<float>& colour, GLuint albedo) {
    fresh(settings);
    const GLuint depth = make_depth32f(kW, kH, scene_.window_depth);
    const GLuint color = make_rgba16f(kW, kH, colour);
    const GLuint out = make_rgba16f(kW, kH, std::vector<float>(colour.size(), -7.0f));
    sss_frame f = frame_of(color, depth, out);
    f.albedo_texture = albedo;
    EXPECT_EQ(apply(f), SSS_OK) << sss_last_error(sss_);
    return read_rgba(out, kW, kH);
  }
  SyntheticScene scene_;
};

sss_settings case_settings(const PathCase& p, uint32_t texturing) {
  sss_settings s = path_case_settings(visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f), p.path, p.mode, p.two_terms);
  s.texturing = texturing;
  return s;
}

// The largest |out − in| / in over the translucent pixels' rgb (alpha above 0), and the number of
// values beyond `bound` of that.
float largest_change(const std::vector<float>& out, const Inputs& in, float bound, std::size_t* beyond) {
  float largest = 0.0f;
  *beyond = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (i % 4 == 3 || !(in.color[i - i % 4 + 3] > 0.0f)) continue;
    const float relative = std::fabs(out[i] - in.color[i]) / std::max(in.color[i], 1e-6f);
    largest = std::max(largest, relative);
    *beyond += relative > bound ? 1 : 0;
  }
  return largest;
}

// Uniform light over the checker: post-scatter gives the input back (each value passes through
// four roundings to half: the quotient, the horizontal pass's target, the weighted mean of equal
// values, the output; each within half a step of its value, so at most 4 half steps in all, plus
// the mean's own float error, far below). Pre- and post-scatter blurs sqrt(A) and pre-scatter A:
// both change the checker's pixels by far more (measured, printed).
TEST_F(Texturing, UniformLightKeepsTheAlbedoDetailInPostScatter) {
  const Inputs in = make_inputs(scene_, false, false);
  for (const PathCase& p : kEveryPath) {
    SCOPED_TRACE(p.name);
    const GLuint albedo = make_rgba16f(kW, kH, in.albedo);
    std::size_t beyond = 0, beyond_pre = 0, beyond_both = 0;
    const float bound = 4.0f * kHalfStep;
    const float post = largest_change(filtered(case_settings(p, SSS_TEXTURING_POST_SCATTER), in.color, albedo), in,
                                      bound, &beyond);
    const float both = largest_change(
        filtered(case_settings(p, SSS_TEXTURING_PRE_AND_POST_SCATTER), in.color, albedo), in, bound, &beyond_both);
    const float pre = largest_change(filtered(case_settings(p, SSS_TEXTURING_PRE_SCATTER), in.color, albedo), in,
                                     bound, &beyond_pre);
    std::printf("%s: uniform light, largest relative change of a translucent value: post-scatter %.5f (%zu beyond "
                "%.5f), pre- and post-scatter %.3f, pre-scatter %.3f\n",
                p.name, post, beyond, bound, both, pre);
    EXPECT_EQ(beyond, 0u);
    EXPECT_GT(pre, 0.1f) << "pre-scatter must blur the albedo's checker (else this check cannot fail)";
    EXPECT_GT(both, 0.05f);
    EXPECT_LT(both, pre);
    TearDown();
    SetUp();
  }
}

// The near-zero rule (sss.h sss_texturing): under uniform light a freckle of albedo 0.001, below the
// floor of 1/256, is taken to hold colour / (1/256) of light, a quarter of what it has; its own
// output is 1/256 times its blurred light, brighter than its colour (at most 1/256 · E, to within
// the roundings' 4 half steps), and it darkens its neighbours' light. Measured and printed: the
// freckle's output over its colour, and the largest relative change elsewhere.
TEST_F(Texturing, AnAlbedoBelowTheFloorCountsAsTheFloor) {
  const Inputs in = make_inputs(scene_, false, true);
  const GLuint albedo = make_rgba16f(kW, kH, in.albedo);
  const std::vector<float> out = filtered(case_settings(kEveryPath[0], SSS_TEXTURING_POST_SCATTER), in.color, albedo);
  float lowest = 1e30f, highest = 0.0f, elsewhere = 0.0f;
  std::size_t beyond_floor = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const int c = static_cast<int>(i % 4);
    const int x = static_cast<int>((i / 4) % kW), y = static_cast<int>((i / 4) / kW);
    if (c == 3 || !(in.color[i - i % 4 + 3] > 0.0f)) continue;
    const float ratio = out[i] / in.color[i];
    if (in_freckle(x, y)) {
      lowest = std::min(lowest, ratio);
      highest = std::max(highest, ratio);
      beyond_floor += out[i] > kFloor * kUniform[c] * (1.0f + 4.0f * kHalfStep) ? 1 : 0;
    } else {
      elsewhere = std::max(elsewhere, std::fabs(ratio - 1.0f));
    }
  }
  std::printf("albedo 0.001 under the floor 1/256: the freckle's output is %.2f to %.2f times its colour (the exact "
              "answer: 1); elsewhere the largest relative change is %.4f\n", lowest, highest, elsewhere);
  EXPECT_EQ(beyond_floor, 0u);
  EXPECT_GT(lowest, 1.0f);
}

// Any light: the module's output of mode `mode` against A_post times its own pre-scatter filter of
// colour / A_post. The quotient the reference is handed is the copy's (rounded to half from the
// float quotient); the GL's division may differ from the CPU's in the last float bit, which moves
// a quotient by at most one half step in rare cases, and the product and its rounding add one more:
// 3 half steps relative to the value. The pixels the passes leave alone (alpha 0) must be the
// host's colour exactly.
void expect_equivalent(const PathCase& p, uint32_t mode, const Inputs& in, const std::vector<float>& module,
                       const std::vector<float>& reference_filtered) {
  std::size_t beyond = 0, untouched_moved = 0, translucent = 0;
  float largest = 0.0f;
  for (std::size_t i = 0; i < module.size(); ++i) {
    const std::size_t pixel = i / 4;
    const int c = static_cast<int>(i % 4);
    if (!(in.color[pixel * 4 + 3] > 0.0f)) {
      untouched_moved += module[i] != in.color[i] ? 1 : 0;
      continue;
    }
    if (c == 3) continue;
    ++translucent;
    const float expected = sss::math::round_to_half(reference_filtered[i] * sss::math::albedo_post(in.albedo[i], mode));
    const float relative = std::fabs(module[i] - expected) / std::max(std::fabs(expected), 1e-6f);
    largest = std::max(largest, relative);
    beyond += relative > 3.0f * kHalfStep ? 1 : 0;
  }
  std::printf("%s, mode %u: %zu translucent values, largest relative difference from A_post x filter(colour / "
              "A_post) %.5f, %zu beyond %.5f; %zu untouched values moved\n",
              p.name, mode, translucent, largest, beyond, 3.0f * kHalfStep, untouched_moved);
  EXPECT_EQ(beyond, 0u);
  EXPECT_EQ(untouched_moved, 0u);
}

TEST_F(Texturing, EachModeIsAPostTimesThePreScatterFilterOfTheColourOverAPost) {
  const Inputs in = make_inputs(scene_, true);
  for (const PathCase& p : kEveryPath) {
    for (const uint32_t mode : {SSS_TEXTURING_POST_SCATTER, SSS_TEXTURING_PRE_AND_POST_SCATTER}) {
      SCOPED_TRACE(std::string(p.name) + ", mode " + std::to_string(mode));
      const GLuint albedo = make_rgba16f(kW, kH, in.albedo);
      const std::vector<float> module = filtered(case_settings(p, mode), in.color, albedo);
      std::vector<float> quotient = in.color;
      for (std::size_t i = 0; i < quotient.size(); ++i) {
        if (i % 4 != 3) quotient[i] = sss::math::round_to_half(in.color[i] / sss::math::albedo_post(in.albedo[i], mode));
      }
      const std::vector<float> reference = filtered(case_settings(p, SSS_TEXTURING_PRE_SCATTER), quotient, 0);
      expect_equivalent(p, mode, in, module, reference);
      TearDown();
      SetUp();
    }
  }
}

// Pre-scatter, the default, reads no albedo: the same image with an albedo texture given or not,
// bit for bit (and today's: the other suites' images are unchanged).
TEST_F(Texturing, PreScatterIgnoresTheAlbedo) {
  const Inputs in = make_inputs(scene_, true);
  const sss_settings s = case_settings(kEveryPath[0], SSS_TEXTURING_PRE_SCATTER);
  const std::vector<float> without = filtered(s, in.color, 0);
  const std::vector<float> with = filtered(s, in.color, make_rgba16f(kW, kH, in.albedo));
  EXPECT_EQ(with, without);
}

// The CPU model of the modes (math/cpu_texturing.hpp: the passes' model run on the colour over
// A_post, multiplied back where it blurs, every other pixel the host's colour) against the GL, on
// the separable paths the model covers (the fragment, masked and compute paths, a kernel of two
// terms), in place into an RGBA16F colour and into an RGBA32F output: within matches_cpu_model_test's
// tolerance, 3e-3 (the tap flips its comment describes aside), and the image changed.
using TexturingModel = FilterCaseTest;
TEST_F(TexturingModel, EachModeMatchesTheCpuModel) {
  const SyntheticScene scene = make_relief_scene(kW, kH, 3, perspective_matrix(40.0f, 64.0f / 48.0f, 0.1f, 10.0f));
  const Inputs in = make_inputs(scene, true);
  SyntheticScene textured = scene;
  textured.color = in.color;
  for (const PathCase& p : kEveryPath) {
    if (p.path == SSS_PATH_HALF_RESOLUTION || p.mode == SSS_MODE_CROSS_BILATERAL) continue;  // their own models
    for (const uint32_t mode : {SSS_TEXTURING_POST_SCATTER, SSS_TEXTURING_PRE_AND_POST_SCATTER}) {
      for (const bool separate : {false, true}) {
        SCOPED_TRACE(std::string(p.name) + ", mode " + std::to_string(mode) + (separate ? ", RGBA32F output" : ""));
        FilterCase c;
        c.settings = case_settings(p, mode);
        c.half_color = true;
        c.separate_output = separate;
        c.albedo = in.albedo;
        const FilterOutcome o = run_case(textured, c);
        ASSERT_EQ(o.result, SSS_OK);
        std::printf("%s, mode %u%s: GL vs the CPU model, largest relative difference %.3g\n", p.name, mode,
                    separate ? ", RGBA32F output" : "", largest_relative_difference(o.gpu, o.cpu));
        expect_matches_model_up_to_tap_flips(o, 3e-3f, p.name);
        EXPECT_GT(largest_relative_difference(o.gpu, o.input), 0.02f) << "nothing was blurred";
        TearDown();
        SetUp();
      }
    }
  }
}

// In place (the host's colour is the target, the passes read the module's divided copy): the pixels
// the passes leave alone (alpha 0, and with per-pixel profiles an index without a profile, as the
// three.js pass marks everything that is not translucent) keep the host's colour bit for bit; they
// are never copied back from the copy, which holds colour / A_post there (the three.js package's
// comparison with the native frame found the background 256 times brighter: colour over the floor
// of a 0 albedo).
TEST_F(Texturing, InPlaceUntouchedPixelsKeepTheHostsColour) {
  const Inputs in = make_inputs(scene_, true);
  std::vector<uint8_t> ids(static_cast<std::size_t>(kW) * kH, 0);
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = i % kW < kW / 3 ? 15 : 0;  // the left third: no profile
  for (const PathCase& p : kEveryPath) {
    for (const bool per_pixel : {false, true}) {
      SCOPED_TRACE(std::string(p.name) + (per_pixel ? ", per-pixel profiles" : ""));
      if (per_pixel && p.mode == SSS_MODE_CROSS_BILATERAL) continue;  // one profile only there
      const sss_settings s = case_settings(p, SSS_TEXTURING_POST_SCATTER);
      fresh(s);
      if (per_pixel) {
        ASSERT_EQ(sss_set_profiles(sss_, &s, 1), SSS_OK) << sss_last_error(sss_);
      }
      const GLuint color = make_rgba16f(kW, kH, in.color);
      sss_frame f = frame_of(color, make_depth32f(kW, kH, scene_.window_depth));
      f.albedo_texture = make_rgba16f(kW, kH, in.albedo);
      if (per_pixel) {
        f.profile_texture = make_texture(GL_R8UI, kW, kH, GL_RED_INTEGER, GL_UNSIGNED_BYTE, ids.data());
        f.profile_format = GL_R8UI;
      }
      ASSERT_EQ(apply(f), SSS_OK) << sss_last_error(sss_);
      const std::vector<float> out = read_rgba(color, kW, kH);
      std::size_t untouched = 0, moved = 0, blurred = 0;
      for (std::size_t i = 0; i < ids.size(); ++i) {
        const bool alone = !(in.color[i * 4 + 3] > 0.0f) || (per_pixel && ids[i] == 15);
        bool same = true;
        for (int c = 0; c < 4; ++c) same = same && out[i * 4 + c] == in.color[i * 4 + c];
        untouched += alone ? 1 : 0;
        moved += alone && !same ? 1 : 0;
        blurred += !alone && !same ? 1 : 0;
      }
      EXPECT_GT(untouched, 0u);
      EXPECT_EQ(moved, 0u) << "of " << untouched << " pixels the passes leave alone";
      EXPECT_GT(blurred, 0u) << "the frame must filter the others (else this check cannot fail)";
      TearDown();
      SetUp();
    }
  }
}

TEST_F(Texturing, BadAlbedoInputsAreRefusedByName) {
  const Inputs in = make_inputs(scene_, true);
  sss_settings s = case_settings(kEveryPath[0], SSS_TEXTURING_POST_SCATTER);
  fresh(s);
  const GLuint depth = make_depth32f(kW, kH, scene_.window_depth);
  const GLuint color = make_rgba16f(kW, kH, in.color);
  const std::vector<float> before = read_rgba(color, kW, kH);
  const auto expect_refused = [&](sss_frame f, sss_result expected, const char* part, bool described = true) {
    SCOPED_TRACE(part);
    const sss_result r = described ? apply(f) : sss_apply_frame(sss_, &f);
    EXPECT_EQ(r, expected) << sss_result_string(r) << ": " << sss_last_error(sss_);
    EXPECT_NE(std::string(sss_last_error(sss_)).find(part), std::string::npos) << sss_last_error(sss_);
    EXPECT_EQ(read_rgba(color, kW, kH), before);
  };
  sss_frame f = frame_of(color, depth);
  expect_refused(f, SSS_ERROR_INVALID_ARGUMENT, "settings->texturing = 1 (SSS_TEXTURING_POST_SCATTER) with "
                                                "frame->albedo_texture = 0");
  sss_frame bad_format = frame_of(color, depth);
  bad_format.albedo_texture = make_rgba16f(kW, kH, in.albedo);
  bad_format.texture_width = kW;
  bad_format.texture_height = kH;
  bad_format.color_format = GL_RGBA16F;
  bad_format.depth_format = GL_DEPTH_COMPONENT32F;
  bad_format.albedo_format = GL_R8;
  expect_refused(bad_format, SSS_ERROR_INVALID_ARGUMENT, "frame->albedo_format = 0x8229", false);
  if (!is_gles()) {  // ES 3.0 cannot be asked: the description is taken as it is there
    sss_frame u = frame_of(color, depth);  // undescribed: the GL is asked
    u.albedo_texture = make_texture(GL_RGBA8, kW / 2, kH, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    expect_refused(u, SSS_ERROR_INVALID_TEXTURE, "albedo_texture", false);
    u.albedo_texture = make_texture(GL_R8, kW, kH, GL_RED, GL_UNSIGNED_BYTE, nullptr);
    expect_refused(u, SSS_ERROR_INVALID_TEXTURE, "albedo_texture", false);
  }
  s.texturing = 7;
  EXPECT_EQ(sss_set_settings(sss_, &s), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("settings->texturing = 7"), std::string::npos);
  sss_prepare_desc d = {};
  d.struct_size = sizeof d;
  d.width = kW;
  d.height = kH;
  d.color_format = GL_RGBA16F;
  d.depth_format = GL_DEPTH_COMPONENT32F;
  d.albedo_format = GL_R8;
  EXPECT_EQ(sss_prepare(sss_, &d), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("desc->albedo_format"), std::string::npos);
  d.albedo_format = GL_SRGB8_ALPHA8;
  EXPECT_EQ(sss_prepare(sss_, &d), SSS_OK) << sss_last_error(sss_);
}

// ---- The MSAA path (a multisampled colour and an albedo multisampled alike) ----------------------
// The resolve divides each sample by its own A_post, the passes blur the resolved quotient, and the
// write-back adds A_post_s times the pixel's change of quotient to each translucent sample
// (msaa_resolve.frag, msaa_write.frag; the model: math/cpu_msaa_texturing.hpp).

using Samples = std::vector<std::vector<float>>;

// The fine image (2w x 2h) whose 2x2 blocks are the samples (multisample_textures.hpp's layout).
std::vector<float> fine_of(const Samples& samples) {
  std::vector<float> fine(samples[0].size() * 4);
  for (std::size_t s = 0; s < 4; ++s) {
    for (std::size_t p = 0; p < samples[s].size() / 4; ++p) {
      const std::size_t x = p % kW, y = p / kW;
      const std::size_t f = (2 * y + s / 2) * (2 * kW) + 2 * x + s % 2;
      for (std::size_t c = 0; c < 4; ++c) fine[f * 4 + c] = samples[s][p * 4 + c];
    }
  }
  return fine;
}

// A fine albedo with detail at the pixel and below it: a checker of 2-pixel cells (as the
// single-sample tests'), every other sample of it 0.7 times darker (so a pixel's samples differ but
// not its cells' means), and (`freckle`) 4x4 samples below the floor; the colour E · A (E the fine scene's light,
// or the uniform light) rounded to half, alpha the scene's.
Inputs make_fine_inputs(const SyntheticScene& fine, bool light, bool freckle = true) {
  Inputs in;
  const std::size_t n = fine.color.size() / 4;
  in.albedo.resize(n * 4);
  in.color.resize(n * 4);
  for (std::size_t i = 0; i < n; ++i) {
    const int x = static_cast<int>(i % (2 * kW)), y = static_cast<int>(i / (2 * kW));
    const bool dark = ((x / 4) + (y / 4)) % 2 == 0;
    const float sample_detail = (x + y) % 2 == 0 ? 0.7f : 1.0f;
    for (int c = 0; c < 3; ++c) {
      float a = (dark ? 0.2f + 0.05f * static_cast<float>(c) : 0.9f - 0.1f * static_cast<float>(c)) * sample_detail;
      if (freckle && x >= 60 && x < 64 && y >= 40 && y < 44) a = 0.001f;
      in.albedo[i * 4 + c] = sss::math::round_to_half(a);
      const float e = light ? fine.color[i * 4 + c] : kUniform[c];
      in.color[i * 4 + c] = sss::math::round_to_half(e * in.albedo[i * 4 + c]);
    }
    in.albedo[i * 4 + 3] = 1.0f;
    in.color[i * 4 + 3] = fine.color[i * 4 + 3];
  }
  return in;
}

class TexturingMsaa : public Texturing {
 protected:
  void SetUp() override {
    Texturing::SetUp();
    if (HasFatalFailure()) return;
    if (is_gles()) GTEST_SKIP() << "the MSAA path is desktop OpenGL only";
    fine_ = make_relief_scene(2 * kW, 2 * kH, 3, scene_.projection);
  }
  GLuint ms(GLenum format, const std::vector<float>& fine, int samples = 4, int w = kW) {
    const GLuint t = make_multisample_texture(format, w, kH, samples, fine);
    textures_.push_back(t);
    return t;
  }
  // The frame of `colour` (multisampled, `format`) over `albedo` with `settings`, in place or into a
  // fresh RGBA32F output; the colour's samples after it, and the output.
  struct Result {
    Samples samples;
    std::vector<float> output;
  };
  Result run(const sss_settings& settings, GLenum format, const std::vector<float>& colour, GLuint albedo,
             bool output) {
    fresh(settings);
    const GLuint color = ms(format, colour);
    sss_frame f = frame_of(color, ms(GL_DEPTH_COMPONENT32F, fine_.window_depth));
    if (output) f.output_texture = make_rgba32f(kW, kH, std::vector<float>(kW * kH * 4, -7.0f));
    f.albedo_texture = albedo;
    EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    Result r;
    r.samples = read_samples(color, kW, kH, 4);
    if (output) r.output = read_rgba(f.output_texture, kW, kH);
    return r;
  }
  SyntheticScene fine_;
};

// The largest |after − before| / before over the translucent samples' rgb.
float largest_sample_change(const Samples& after, const Samples& before) {
  float largest = 0.0f;
  for (std::size_t s = 0; s < before.size(); ++s) {
    for (std::size_t i = 0; i < before[s].size(); ++i) {
      if (i % 4 == 3 || !(before[s][i - i % 4 + 3] > 0.0f)) continue;
      largest = std::max(largest, std::fabs(after[s][i] - before[s][i]) / std::max(before[s][i], 1e-6f));
    }
  }
  return largest;
}

// Uniform light over an albedo whose samples differ within each pixel, RGBA16F, written back:
// post-scatter gives every sample back. Each sample's quotient is the light to within its colour's
// rounding (1 half step); the resolved quotient rounds once more, the intermediate and the blurred
// image once each, so the pixel's change of quotient B − E is a few steps of the light, and the
// sample moves by A_post_s times it (n / translucent samples more on a silhouette pixel), then the
// store rounds it (llvmpipe: toward zero). The bound: 6 half steps. Pre-scatter blurs the checker
// into every sample (the check's own test), pre- and post-scatter half of it.
TEST_F(TexturingMsaa, UniformLightKeepsEachSampleInPostScatter) {
  const Inputs in = make_fine_inputs(fine_, false, false);
  const GLuint albedo = ms(GL_RGBA16F, in.albedo);
  const Samples before = read_samples(ms(GL_RGBA16F, in.color), kW, kH, 4);
  const sss_settings base = case_settings(kEveryPath[0], SSS_TEXTURING_POST_SCATTER);
  float change[3] = {};
  for (const uint32_t mode : {SSS_TEXTURING_PRE_SCATTER, SSS_TEXTURING_POST_SCATTER,
                              SSS_TEXTURING_PRE_AND_POST_SCATTER}) {
    sss_settings s = base;
    s.texturing = mode;
    change[mode] = largest_sample_change(run(s, GL_RGBA16F, in.color, albedo, false).samples, before);
  }
  const float bound = 6.0f * kHalfStep;
  std::printf("MSAA, uniform light, largest relative change of a translucent sample: post-scatter %.3g (bound %.5f), "
              "pre- and post-scatter %.3f, pre-scatter %.3f\n", change[1], bound, change[2], change[0]);
  EXPECT_LE(change[1], bound);
  EXPECT_GT(change[0], 0.1f) << "pre-scatter must blur the albedo's checker (else this check cannot fail)";
  EXPECT_GT(change[2], 0.05f);
  EXPECT_LT(change[2], change[0]);
}

// The near-zero rule on the MSAA path: under uniform light, fine samples of albedo 0.001 (below the
// floor of 1/256; make_fine_inputs' freckle, 2x2 whole pixels) count as the floor in the resolve's
// divide and in the write-back's per-sample multiply. So each such sample comes out brighter than
// its colour (the blurred quotient around it is above its own) but at most floor · E: its colour
// 0.001 · E plus at most (1 − 0.256) · E / 256, to within the resolve's, the passes' and the store's
// roundings (6 half steps, as the uniform-light test's); the samples away from the freckle's
// reach hardly move.
TEST_F(TexturingMsaa, AnAlbedoBelowTheFloorCountsAsTheFloor) {
  const Inputs in = make_fine_inputs(fine_, false, true);
  const GLuint albedo = ms(GL_RGBA16F, in.albedo);
  const Samples before = read_samples(ms(GL_RGBA16F, in.color), kW, kH, 4);
  const Samples after =
      run(case_settings(kEveryPath[0], SSS_TEXTURING_POST_SCATTER), GL_RGBA16F, in.color, albedo, false).samples;
  float lowest = 1e30f, highest = 0.0f;
  std::size_t freckled = 0, beyond_floor = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    for (std::size_t i = 0; i < before[k].size(); ++i) {
      const std::size_t p = i / 4, c = i % 4;
      if (c == 3 || !(before[k][p * 4 + 3] > 0.0f)) continue;
      const std::size_t fx = 2 * (p % kW) + k % 2, fy = 2 * (p / kW) + k / 2;
      if (!(fx >= 60 && fx < 64 && fy >= 40 && fy < 44)) continue;
      ++freckled;
      const float ratio = after[k][i] / before[k][i];
      lowest = std::min(lowest, ratio);
      highest = std::max(highest, ratio);
      beyond_floor += after[k][i] > kFloor * kUniform[c] * (1.0f + 6.0f * kHalfStep) ? 1 : 0;
    }
  }
  std::printf("MSAA, albedo 0.001 under the floor 1/256: %zu freckled sample values come out %.2f to %.2f times their "
              "colour (the exact answer: 1)\n", freckled, lowest, highest);
  EXPECT_EQ(freckled, 4u * 4u * 3u) << "the freckle: 2x2 translucent pixels of 4 samples, 3 channels";
  EXPECT_EQ(beyond_floor, 0u);
  EXPECT_GT(lowest, 1.0f);
}

// Any light, RGBA32F colour, each mode, written back and into an RGBA32F output: the GL against the
// model (math/cpu_msaa_texturing: the per-sample divide, the write-back's per-sample multiply) fed
// with the module's own pre-scatter filter of the model's quotient samples (the same resolve and
// passes on the same numbers). The GPU's division, square root and sums may differ from the CPU's in
// the last float bit, which the passes carry through at float precision (RGBA32F intermediate):
// a bound of 1e-5 relative to the sample's value (about 2^-17, a hundred float ulps).
TEST_F(TexturingMsaa, EachModeMatchesTheModel) {
  const Inputs in = make_fine_inputs(fine_, true);
  const GLuint albedo = ms(GL_RGBA16F, in.albedo);
  const Samples colour = read_samples(ms(GL_RGBA32F, in.color), kW, kH, 4);
  const Samples albedos = read_samples(albedo, kW, kH, 4);
  for (const uint32_t mode : {SSS_TEXTURING_POST_SCATTER, SSS_TEXTURING_PRE_AND_POST_SCATTER}) {
    SCOPED_TRACE("mode " + std::to_string(mode));
    const sss::math::MsaaQuotientResolve resolved = sss::math::resolve_over_albedo(colour, albedos, mode, false);
    const std::vector<float> quotient_fine = fine_of(sss::math::samples_over_albedo(colour, albedos, mode));
    const std::vector<float> blurred =
        run(case_settings(kEveryPath[0], SSS_TEXTURING_PRE_SCATTER), GL_RGBA32F, quotient_fine, 0, true).output;
    const sss_settings s = case_settings(kEveryPath[0], mode);
    const Samples model = sss::math::write_back_over_albedo(colour, albedos, mode, resolved, blurred);
    const Samples gl = run(s, GL_RGBA32F, in.color, albedo, false).samples;
    float largest = 0.0f;
    std::size_t changed = 0;
    for (std::size_t k = 0; k < 4; ++k) {
      for (std::size_t i = 0; i < gl[k].size(); ++i) {
        const float scale = std::max({std::fabs(model[k][i]), std::fabs(colour[k][i]), 1e-4f});
        largest = std::max(largest, std::fabs(gl[k][i] - model[k][i]) / scale);
        changed += gl[k][i] != colour[k][i] ? 1 : 0;
      }
    }
    // Into an output: A_post's mean times the blurred quotient where the passes drew (the resolved
    // alpha above 0), the undivided mean elsewhere, bit for bit.
    const std::vector<float> out = run(s, GL_RGBA32F, in.color, albedo, true).output;
    float largest_out = 0.0f;
    std::size_t untouched = 0, untouched_moved = 0;
    for (std::size_t p = 0; p < out.size() / 4; ++p) {
      const bool drawn = resolved.quotient[p * 4 + 3] > 0.0f;
      for (std::size_t c = 0; c < 4; ++c) {
        if (!drawn) {
          ++untouched;
          untouched_moved += out[p * 4 + c] != resolved.original[p * 4 + c] ? 1 : 0;
        } else if (c < 3) {
          const float expected = resolved.albedo_post[p * 3 + c] * blurred[p * 4 + c];
          largest_out = std::max(largest_out,
                                 std::fabs(out[p * 4 + c] - expected) / std::max(std::fabs(expected), 1e-4f));
        }
      }
    }
    std::printf("MSAA, mode %u: GL vs the model, largest relative difference written back %.3g (%zu values changed), "
                "into an output %.3g; %zu of %zu untouched values moved\n",
                mode, largest, changed, largest_out, untouched_moved, untouched);
    EXPECT_LE(largest, 1e-5f);
    EXPECT_LE(largest_out, 1e-5f);
    EXPECT_GT(changed, static_cast<std::size_t>(kW * kH)) << "nothing was blurred";
    EXPECT_GT(untouched, 0u);
    EXPECT_EQ(untouched_moved, 0u);
  }
}

// A GL 3.3 context (GLSL 3.30: no gl_SampleID) writes back one draw per sample under glSampleMaski,
// each reading its own sample of the albedo (msaa_write.frag's u_sample): the samples come out as
// from the one draw of a GL 4.2+ context, bit for bit (the same operations on the same numbers).
TEST_F(TexturingMsaa, WriteBackOnAGl33ContextGivesTheSameSamples) {
  const Inputs in = make_fine_inputs(fine_, true);
  const GLuint albedo = ms(GL_RGBA16F, in.albedo);
  const Samples before = read_samples(ms(GL_RGBA32F, in.color), kW, kH, 4);
  for (const uint32_t mode : {SSS_TEXTURING_POST_SCATTER, SSS_TEXTURING_PRE_AND_POST_SCATTER}) {
    SCOPED_TRACE("mode " + std::to_string(mode));
    const sss_settings s = case_settings(kEveryPath[0], mode);
    uint32_t passes[2] = {}, dialect[2] = {};
    Samples after[2];
    for (int gl33 = 0; gl33 < 2; ++gl33) {
      loader_override_ = gl33 != 0 ? loader_telling(GL_VERSION, "3.3 (Core Profile) as told by the test",
                                                    sss_headless_get_proc_address)
                                   : nullptr;
      after[gl33] = run(s, GL_RGBA32F, in.color, albedo, false).samples;
      sss_stats st = {};
      st.struct_size = sizeof st;
      ASSERT_EQ(sss_get_stats(sss_, &st), SSS_OK);
      passes[gl33] = st.last_frame_passes;
      dialect[gl33] = st.glsl_variant;
    }
    loader_override_ = nullptr;
    EXPECT_EQ(dialect[1], static_cast<uint32_t>(SSS_GLSL_330_CORE));
    EXPECT_EQ(passes[1], passes[0] + 3) << "the write-back as one draw per sample (4 instead of 1)";
    EXPECT_GT(largest_sample_change(after[0], before), 0.01f) << "the write-back must have changed samples";
    for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(after[1][k], after[0][k]) << "sample " << k;
  }
}

// An albedo of another sample count, size or target than the multisampled colour is refused by
// name and value (INVALID_TEXTURE), nothing drawn: the colour's samples and the output untouched. A
// single-sample albedo has no value per sample, so it is refused too rather than guessed at.
// llvmpipe makes every multisampled texture with 4 samples, so the other count is what the fault
// loader tells a module created through it (as Msaa.BadMultisampledInput... does for the depth).
TEST_F(TexturingMsaa, AnAlbedoOfAnotherSampleCountOrSizeIsRefused) {
  const Inputs in = make_fine_inputs(fine_, true);
  sss_create_desc desc = {};
  desc.struct_size = sizeof desc;
  desc.get_proc_address = fault_get_proc_address;
  desc.get_proc_address_user = headless_;
  sss_context* faulty = nullptr;
  ASSERT_EQ(sss_create(&desc, &faulty), SSS_OK);
  const sss_settings settings = case_settings(kEveryPath[0], SSS_TEXTURING_POST_SCATTER);
  ASSERT_EQ(sss_set_settings(faulty, &settings), SSS_OK);
  ASSERT_EQ(sss_set_camera(faulty, scene_.projection.data()), SSS_OK);
  const GLuint color = ms(GL_RGBA16F, in.color);
  const GLuint depth = ms(GL_DEPTH_COMPONENT32F, fine_.window_depth);
  const Samples before = read_samples(color, kW, kH, 4);
  const GLuint two = ms(GL_RGBA16F, in.albedo);  // told 2 samples
  const GLuint narrow = ms(GL_RGBA16F, in.albedo, 4, kW / 2);
  const GLuint single = make_rgba16f(kW, kH, std::vector<float>(kW * kH * 4, 0.5f));
  const std::string colour = " but color_texture = " + std::to_string(color) + " is GL_TEXTURE_2D_MULTISAMPLE with 4 samples";
  const struct {
    GLuint albedo;
    std::string part;
  } cases[] = {{two, "albedo_texture = " + std::to_string(two) + " is GL_TEXTURE_2D_MULTISAMPLE with 2 samples" + colour},
               {narrow, "albedo_texture = " + std::to_string(narrow) + " is 32x48 but the colour texture is 64x48"},
               {single, "albedo_texture = " + std::to_string(single) + " is GL_TEXTURE_2D" + colour}};
  for (const auto& c : cases) {
    for (const bool output : {false, true}) {
      SCOPED_TRACE(c.part + (output ? ", into an output" : ""));
      reset_faults();
      if (c.albedo == two) {
        faults().fake_samples_texture = two;
        faults().fake_samples = 2;
      }
      sss_frame f = frame_of(color, depth);
      const std::vector<float> initial(kW * kH * 4, -7.0f);
      if (output) f.output_texture = make_rgba32f(kW, kH, initial);
      f.albedo_texture = c.albedo;
      const sss_result r = sss_apply_frame(faulty, &f);
      reset_faults();
      EXPECT_EQ(r, SSS_ERROR_INVALID_TEXTURE) << sss_result_string(r) << ": " << sss_last_error(faulty);
      EXPECT_NE(std::string(sss_last_error(faulty)).find(c.part), std::string::npos) << sss_last_error(faulty);
      EXPECT_EQ(read_samples(color, kW, kH, 4), before);
      if (output) {
        EXPECT_EQ(read_rgba(f.output_texture, kW, kH), initial);
      }
      EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    }
  }
  // The same albedo with 4 samples is taken (the refusals above were the counts and sizes alone).
  sss_frame f = frame_of(color, depth);
  f.albedo_texture = two;
  EXPECT_EQ(sss_apply_frame(faulty, &f), SSS_OK) << sss_last_error(faulty);
  EXPECT_NE(read_samples(color, kW, kH, 4), before);
  sss_destroy(faulty);
}

}  // namespace
}  // namespace sss_test
