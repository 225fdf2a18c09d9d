// Integration trap (issue 22): the strength in a separate texture (sss_frame.strength_texture), for
// the common deferred layout of an R11F_G11F_B10F colour, which has no alpha. Before, the strength
// could only be the colour's alpha, and such a colour was refused (a format outside the list).
//
// What it must give: the image an RGBA16F colour holding the same rgb with that strength as alpha
// gives. The scene's rgb is made R11F_G11F_B10F-exact (7 significant bits in red and green, 6 in
// blue), which RGBA16F (11) holds exactly too; the strength is k / 255 in an R8 texture, and the
// RGBA16F reference's alpha is that rounded to half float to nearest, which is what the module's
// copy holds (colour_copy.frag rounds so, whatever the driver's conversion does). So:
// - into a separate RGBA16F output both frames run the same passes on the same bits: equal bit for
//   bit, alpha included (the output's alpha is the strength);
// - written back, the reference stores half floats and the R11F_G11F_B10F colour its own format:
//   within one step of that format at the value (2^-6 of the value's power of two for red and green,
//   2^-5 for blue; a driver's conversion may round or truncate), and pixels of strength 0 keep their
//   exact value.
// Every path and mode is run. The refusals: a strength texture of another format or size, a bad
// strength_format, an R11F_G11F_B10F colour without one, an RGBA colour written back with one (its
// alpha would become the strength), a multisampled colour; each leaves the colour unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "filter_case.hpp"
#include "host_gl_util.hpp"
#include "math/half_float.hpp"
#include "multisample_textures.hpp"

using namespace host_gl;

namespace sss_test {
namespace {

constexpr int kW = 64, kH = 48;

// `v` (> 0) rounded to `bits` significant bits, to nearest: exact in a float format with bits - 1
// stored mantissa bits.
float round_to_bits(float v, int bits) {
  if (!(v > 0.0f)) return 0.0f;
  int e = 0;
  const float m = std::frexp(v, &e);
  return std::ldexp(std::round(std::ldexp(m, bits)), e - bits);
}
// One step of a float format of `bits` significant bits at `v`.
float step_at(float v, int bits) {
  int e = 0;
  std::frexp(std::fabs(v), &e);
  return std::ldexp(1.0f, e - bits);
}
constexpr int kBits[3] = {7, 7, 6};  // R11F, G11F, B10F significant bits

struct Inputs {
  std::vector<float> rgb;        // R11F_G11F_B10F-exact
  std::vector<uint8_t> strength; // R8
  std::vector<float> rgba;       // the RGBA16F reference: rgb, alpha = the strength rounded to half
};

Inputs make_inputs(const SyntheticScene& scene) {
  Inputs in;
  const std::size_t n = static_cast<std::size_t>(kW) * kH;
  in.rgb.resize(n * 3);
  in.strength.resize(n);
  in.rgba.resize(n * 4);
  for (std::size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) in.rgb[i * 3 + c] = round_to_bits(scene.color[i * 4 + c], kBits[c]);
    // A strength that varies per pixel (it scales each pixel's kernel), 0 where the scene has alpha 0.
    const int x = static_cast<int>(i % kW), y = static_cast<int>(i / kW);
    in.strength[i] = scene.color[i * 4 + 3] > 0.0f ? static_cast<uint8_t>(40 + (x * 7 + y * 3) % 216) : 0;
    for (int c = 0; c < 3; ++c) in.rgba[i * 4 + c] = in.rgb[i * 3 + c];
    in.rgba[i * 4 + 3] = sss::math::round_to_half(static_cast<float>(in.strength[i]) / 255.0f);
  }
  return in;
}

class StrengthTexture : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    scene_ = make_relief_scene(kW, kH, 3, perspective_matrix(40.0f, 64.0f / 48.0f, 0.1f, 10.0f));
    in_ = make_inputs(scene_);
  }
  GLuint make_r11f() { return make_texture(GL_R11F_G11F_B10F, kW, kH, GL_RGB, GL_FLOAT, in_.rgb.data()); }
  GLuint make_strength() {
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    const GLuint t = make_texture(GL_R8, kW, kH, GL_RED, GL_UNSIGNED_BYTE, in_.strength.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    return t;
  }
  GLuint make_depth() { return make_depth32f(kW, kH, scene_.window_depth); }
  // A fresh context with `s` and the scene's camera.
  void fresh(const sss_settings& s) { fresh_sss(s, scene_.projection.data()); }
  // The frame, described (ES 3.0 cannot be asked; elsewhere it makes no difference to the image).
  sss_result apply(sss_frame f) {
    f.texture_width = kW;
    f.texture_height = kH;
    f.depth_format = GL_DEPTH_COMPONENT32F;
    if (f.output_texture != 0) f.output_format = GL_RGBA16F;
    return sss_apply_frame(sss_, &f);
  }
  void compare_on(const PathCase& p, bool separate);

  SyntheticScene scene_;
  Inputs in_;
};

void StrengthTexture::compare_on(const PathCase& p, bool separate) {
  const sss_settings s = path_case_settings(visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f), p.path, p.mode, p.two_terms);
  const GLuint depth = make_depth();
  // The R11F_G11F_B10F colour with the R8 strength.
  fresh(s);
  const GLuint r11f = make_r11f();
  const GLuint out_a = separate ? make_rgba16f(kW, kH, std::vector<float>(in_.rgba.size(), -7.0f)) : 0;
  sss_frame a = frame_of(r11f, depth, out_a);
  a.color_format = GL_R11F_G11F_B10F;
  a.strength_texture = make_strength();
  a.strength_format = GL_R8;
  a.flags = SSS_FRAME_TARGET_COMPLETE;  // described: the compute path needs the promise (GL_NEAREST here)
  ASSERT_EQ(apply(a), SSS_OK) << sss_last_error(sss_);
  sss_stats stats = {};
  stats.struct_size = sizeof stats;
  ASSERT_EQ(sss_get_stats(sss_, &stats), SSS_OK);
  const bool compute = !is_gles() && host_gl::has_compute_shaders();
  if (p.path == SSS_PATH_COMPUTE) {
    EXPECT_EQ(stats.last_frame_path, compute ? SSS_PATH_COMPUTE : SSS_PATH_FRAGMENT);
  }
  std::printf("%s: the path that ran: %u\n", p.name, stats.last_frame_path);
  const std::vector<float> result_a = read_rgba(separate ? out_a : r11f, kW, kH);
  // The RGBA16F colour with that strength as alpha.
  fresh(s);
  const GLuint rgba = make_rgba16f(kW, kH, in_.rgba);
  const GLuint out_b = separate ? make_rgba16f(kW, kH, std::vector<float>(in_.rgba.size(), -7.0f)) : 0;
  sss_frame b = frame_of(rgba, depth, out_b);
  b.color_format = GL_RGBA16F;
  b.flags = SSS_FRAME_TARGET_COMPLETE;
  ASSERT_EQ(apply(b), SSS_OK) << sss_last_error(sss_);
  const std::vector<float> result_b = read_rgba(separate ? out_b : rgba, kW, kH);

  std::size_t differing = 0, changed = 0, beyond_a_step = 0, strength0_moved = 0;
  for (std::size_t i = 0; i < result_a.size(); ++i) {
    const std::size_t pixel = i / 4;
    const int c = static_cast<int>(i % 4);
    if (separate) {
      differing += result_a[i] != result_b[i] ? 1 : 0;
      continue;
    }
    if (c == 3) continue;  // R11F_G11F_B10F has no alpha (it reads as 1)
    const float input = in_.rgb[pixel * 3 + static_cast<std::size_t>(c)];
    changed += result_a[i] != input ? 1 : 0;
    if (in_.strength[pixel] == 0) strength0_moved += result_a[i] != input ? 1 : 0;
    beyond_a_step += std::fabs(result_a[i] - result_b[i]) > step_at(result_b[i], kBits[c]) ? 1 : 0;
  }
  if (separate) {
    std::printf("%s, separate RGBA16F output: %zu values differ from the RGBA16F colour's bit for bit\n", p.name,
                differing);
  } else {
    std::printf("%s, in place: %zu values beyond one step of R11F_G11F_B10F from the RGBA16F colour's, %zu changed\n",
                p.name, beyond_a_step, changed);
  }
  if (separate) {
    EXPECT_EQ(differing, 0u);
    EXPECT_GT(largest_relative_difference(result_a, in_.rgba), 0.02f) << "nothing was blurred";
  } else {
    EXPECT_EQ(beyond_a_step, 0u);
    EXPECT_EQ(strength0_moved, 0u) << "pixels of strength 0 must keep their exact value";
    EXPECT_GT(changed, result_a.size() / 8) << "nothing was blurred";
  }
}

TEST_F(StrengthTexture, R11fColourWithAnR8StrengthMatchesRgba16fWithThatAlpha) {
  for (const PathCase& p : kEveryPath) {
    for (bool separate : {false, true}) {
      SCOPED_TRACE(std::string(p.name) + (separate ? ", separate output" : ", in place"));
      compare_on(p, separate);
      TearDown();
      SetUp();
    }
  }
}

// Each refusal names the field, and leaves the colour as it was.
TEST_F(StrengthTexture, BadStrengthTexturesAreRefused) {
  fresh(visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f));
  const GLuint depth = make_depth();
  const GLuint r11f = make_r11f();
  const GLuint strength = make_strength();
  const std::vector<float> before = read_rgba(r11f, kW, kH);
  const auto expect_refused = [&](sss_frame f, sss_result expected, const char* part, bool described = true) {
    SCOPED_TRACE(part);
    const sss_result r = described ? apply(f) : sss_apply_frame(sss_, &f);
    EXPECT_EQ(r, expected) << sss_result_string(r) << ": " << sss_last_error(sss_);
    EXPECT_NE(std::string(sss_last_error(sss_)).find(part), std::string::npos) << sss_last_error(sss_);
    EXPECT_EQ(read_rgba(r11f, kW, kH), before);
  };
  sss_frame f = frame_of(r11f, depth);
  f.color_format = GL_R11F_G11F_B10F;
  expect_refused(f, SSS_ERROR_INVALID_TEXTURE, "needs a strength_texture");  // no alpha, no strength
  f.strength_texture = strength;
  f.strength_format = GL_RGBA8;
  expect_refused(f, SSS_ERROR_INVALID_ARGUMENT, "frame->strength_format = 0x8058");
  if (!is_gles()) {  // ES 3.0 cannot be asked: the description is taken as it is there
    sss_frame u = frame_of(r11f, depth);  // undescribed: the GL is asked
    u.strength_texture = make_rgba16f(kW, kH, in_.rgba);
    expect_refused(u, SSS_ERROR_INVALID_TEXTURE, "strength_texture", false);
    u.strength_texture = make_texture(GL_R8, kW / 2, kH, GL_RED, GL_UNSIGNED_BYTE, nullptr);
    expect_refused(u, SSS_ERROR_INVALID_TEXTURE, "strength_texture", false);
  }
  f.strength_texture = r11f;
  f.strength_format = GL_R8;
  expect_refused(f, SSS_ERROR_INVALID_ARGUMENT, "strength_texture");
  // An RGBA colour written back: its alpha would become the strength.
  const GLuint rgba = make_rgba16f(kW, kH, in_.rgba);
  const std::vector<float> rgba_before = read_rgba(rgba, kW, kH);
  sss_frame g = frame_of(rgba, depth);
  g.color_format = GL_RGBA16F;
  g.strength_texture = strength;
  g.strength_format = GL_R8;
  EXPECT_EQ(apply(g), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("give an output_texture"), std::string::npos);
  EXPECT_EQ(read_rgba(rgba, kW, kH), rgba_before);
  // sss_prepare refuses the same descriptions.
  sss_prepare_desc d = {};
  d.struct_size = sizeof d;
  d.width = kW;
  d.height = kH;
  d.color_format = GL_R11F_G11F_B10F;
  d.depth_format = GL_DEPTH_COMPONENT32F;
  EXPECT_EQ(sss_prepare(sss_, &d), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("desc->color_format"), std::string::npos);
  d.strength_format = GL_RGBA8;
  EXPECT_EQ(sss_prepare(sss_, &d), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("desc->strength_format"), std::string::npos);
  d.strength_format = GL_R8;
  d.color_format = GL_RGBA16F;
  EXPECT_EQ(sss_prepare(sss_, &d), SSS_ERROR_INVALID_ARGUMENT);
  d.color_format = GL_R11F_G11F_B10F;
  EXPECT_EQ(sss_prepare(sss_, &d), SSS_OK) << sss_last_error(sss_);
}

TEST_F(StrengthTexture, MultisampledColourIsRefused) {
  if (is_gles()) GTEST_SKIP() << "no MSAA path on OpenGL ES";
  fresh(visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f));
  const SyntheticScene fine = make_relief_scene(2 * kW, 2 * kH, 3, scene_.projection);  // the samples' source
  const GLuint color = make_multisample_texture(GL_RGBA16F, kW, kH, 4, fine.color);
  const GLuint depth = make_multisample_texture(GL_DEPTH_COMPONENT32F, kW, kH, 4, fine.window_depth);
  textures_.push_back(color);
  textures_.push_back(depth);
  sss_frame f = frame_of(color, depth, make_rgba16f(kW, kH, in_.rgba));
  f.strength_texture = make_strength();
  const sss_result r = sss_apply_frame(sss_, &f);
  EXPECT_EQ(r, SSS_ERROR_UNSUPPORTED) << sss_last_error(sss_);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("strength_texture"), std::string::npos) << sss_last_error(sss_);
}

}  // namespace
}  // namespace sss_test
