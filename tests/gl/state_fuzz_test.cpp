// The state-hygiene harness: every GL state of sss.h's list (and the ones it promises not to touch)
// set to random values, then each entry point called, then the state compared. Seeded, so a
// failure names its seed. Two checks show the harness can fail: with the restores switched off
// (SSS_CREATE_NO_STATE_RESTORE) it reports differences, and changing any single listed state
// is seen by the comparison.
#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <random>

#include "../support/kernel_of.hpp"
#include "filter_case.hpp"
#include "host_gl_util.hpp"
#include "gl/state_guard.hpp"
#include "gl_state_snapshot.hpp"
#include "multisample_textures.hpp"
#include "sss/sss_lut.h"

using namespace host_gl;

namespace sss_test {
namespace {

constexpr int kSize = 24;

class StateHarness : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    if (HasFatalFailure()) return;
    for (GLuint& p : programs_) p = make_host_program(false);
    glGenVertexArrays(2, vaos_);
    glGenFramebuffers(2, fbos_);
    glGenRenderbuffers(1, &renderbuffer_);
    glGenBuffers(2, buffers_);
    glGenSamplers(2, samplers_);
    glGenBuffers(1, &uniform_buffer_);
    glBindBuffer(GL_UNIFORM_BUFFER, uniform_buffer_);
    glBufferData(GL_UNIFORM_BUFFER, 2048, nullptr, GL_STATIC_DRAW);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
    for (GLuint& t : host_textures_) t = make_rgba16f(2, 2, std::vector<float>(16, 0.5f));
    // Make the names objects (FBOs, VAOs, renderbuffers and buffers exist from their first bind).
    for (GLuint f : fbos_) glBindFramebuffer(GL_FRAMEBUFFER, f);
    for (GLuint v : vaos_) glBindVertexArray(v);
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer_);
    for (GLuint b : buffers_) glBindBuffer(GL_PIXEL_UNPACK_BUFFER, b);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glBindVertexArray(0);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);

    scene_ = make_relief_scene(kSize, kSize, 4, perspective_matrix(40.0f, 1.0f, 0.1f, 10.0f));
    color_ = make_rgba32f(kSize, kSize, scene_.color);
    output_ = make_rgba32f(kSize, kSize, scene_.color);
    std::vector<uint32_t> packed(scene_.window_depth.size());
    for (std::size_t i = 0; i < packed.size(); ++i) {
      packed[i] = (static_cast<uint32_t>(scene_.window_depth[i] * 16777215.0) << 8) | scene_.stencil[i];
    }
    depth_ = make_texture(GL_DEPTH24_STENCIL8, kSize, kSize, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, packed.data());
    std::vector<uint8_t> ids(static_cast<std::size_t>(kSize) * kSize);
    for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<uint8_t>((i % kSize) < kSize / 2 ? 0 : 0x11);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    profile_ids_ = make_texture(GL_R8UI, kSize, kSize, GL_RED_INTEGER, GL_UNSIGNED_BYTE, ids.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  }

  void TearDown() override {
    if (headless_ != nullptr) {
      glUseProgram(0);
      for (GLuint p : programs_) glDeleteProgram(p);
      glDeleteVertexArrays(2, vaos_);
      glDeleteFramebuffers(2, fbos_);
      glDeleteRenderbuffers(1, &renderbuffer_);
      glDeleteBuffers(2, buffers_);
      glDeleteSamplers(2, samplers_);
      glDeleteBuffers(1, &uniform_buffer_);
    }
    GlTest::TearDown();
  }

  template <typename T>
  T pick(std::mt19937& rng, std::initializer_list<T> values) {
    std::uniform_int_distribution<std::size_t> d(0, values.size() - 1);
    return *(values.begin() + d(rng));
  }

  // Random values for every state in the list (and for the ones the module must not touch).
  void randomise(std::mt19937& rng) {
    std::uniform_int_distribution<int> coin(0, 1), small(0, 20), unit(0, 7), byte(0, 255);
    glUseProgram(pick<GLuint>(rng, {0, programs_[0], programs_[1]}));
    glBindVertexArray(pick<GLuint>(rng, {0, vaos_[0], vaos_[1]}));
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, pick<GLuint>(rng, {0, fbos_[0], fbos_[1]}));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, pick<GLuint>(rng, {0, fbos_[0], fbos_[1]}));
    glBindRenderbuffer(GL_RENDERBUFFER, pick<GLuint>(rng, {0, renderbuffer_}));
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, pick<GLuint>(rng, {0, buffers_[0]}));
    glBindBuffer(GL_PIXEL_PACK_BUFFER, pick<GLuint>(rng, {0, buffers_[1]}));
    for (GLenum u = 0; u < 4; ++u) {
      glActiveTexture(GL_TEXTURE0 + u);
      glBindTexture(GL_TEXTURE_2D, pick<GLuint>(rng, {0, host_textures_[0], host_textures_[1], host_textures_[2]}));
      glBindSampler(u, pick<GLuint>(rng, {0, samplers_[0], samplers_[1]}));
    }
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit(rng)));
    for (GLuint image = 0; image < 2 && has_image_units(); ++image) {  // the module binds units 0 and 1
      glBindImageTexture(image, pick<GLuint>(rng, {0, host_textures_[0], host_textures_[1]}), 0, GL_FALSE, 0,
                         pick<GLenum>(rng, {GL_READ_ONLY, GL_WRITE_ONLY, GL_READ_WRITE}),
                         pick<GLenum>(rng, {GL_RGBA16F, GL_RG32F, GL_RGBA16UI}));
    }
    glViewport(small(rng), small(rng), 1 + small(rng), 1 + small(rng));
    glScissor(small(rng), small(rng), 1 + small(rng), 1 + small(rng));
    for (GLenum cap : {GL_SCISSOR_TEST, GL_DEPTH_TEST, GL_STENCIL_TEST, GL_BLEND, GL_CULL_FACE, GL_FRAMEBUFFER_SRGB,
                       GL_RASTERIZER_DISCARD, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_COVERAGE, GL_SAMPLE_MASK,
                       GL_POLYGON_OFFSET_FILL, GL_DEPTH_CLAMP, GL_COLOR_LOGIC_OP, GL_CLIP_DISTANCE0, GL_CLIP_DISTANCE5,
                       GL_CLIP_DISTANCE7, GL_DITHER, GL_MULTISAMPLE}) {
      coin(rng) ? glEnable(cap) : glDisable(cap);
    }
    glColorMask(static_cast<GLboolean>(coin(rng)), static_cast<GLboolean>(coin(rng)), static_cast<GLboolean>(coin(rng)),
                static_cast<GLboolean>(coin(rng)));
    glDepthMask(static_cast<GLboolean>(coin(rng)));
    glPolygonMode(GL_FRONT_AND_BACK, pick<GLenum>(rng, {GL_FILL, GL_LINE, GL_POINT}));
    glDepthFunc(pick<GLenum>(rng, {GL_LESS, GL_GEQUAL, GL_NEVER, GL_ALWAYS}));
    glDepthRangef(pick<GLfloat>(rng, {0.0f, 0.25f}), pick<GLfloat>(rng, {1.0f, 0.0f, 0.75f}));
    glBlendFuncSeparate(pick<GLenum>(rng, {GL_ONE, GL_ZERO, GL_DST_COLOR}), pick<GLenum>(rng, {GL_ONE, GL_ONE_MINUS_SRC_ALPHA}),
                        pick<GLenum>(rng, {GL_ONE, GL_SRC_ALPHA}), pick<GLenum>(rng, {GL_ZERO, GL_DST_ALPHA}));
    glBlendEquationSeparate(pick<GLenum>(rng, {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_MAX}),
                            pick<GLenum>(rng, {GL_FUNC_ADD, GL_MIN}));
    glCullFace(pick<GLenum>(rng, {GL_FRONT, GL_BACK, GL_FRONT_AND_BACK}));
    glFrontFace(pick<GLenum>(rng, {GL_CW, GL_CCW}));
    glPixelStorei(GL_UNPACK_ALIGNMENT, pick<GLint>(rng, {1, 2, 4, 8}));
    glPixelStorei(GL_PACK_ALIGNMENT, pick<GLint>(rng, {1, 2, 4, 8}));
    glPixelStorei(GL_PACK_ROW_LENGTH, pick<GLint>(rng, {0, 7, 64}));
    glPixelStorei(GL_PACK_SKIP_ROWS, pick<GLint>(rng, {0, 3}));
    glPixelStorei(GL_PACK_SKIP_PIXELS, pick<GLint>(rng, {0, 5}));
    glBindBuffer(GL_PIXEL_PACK_BUFFER, pick<GLuint>(rng, {0u, buffers_[1]}));
    // Uniform buffer binding point 0 (whole, a range, or none) and the generic binding.
    switch (small(rng) % 3) {
      case 0: glBindBufferBase(GL_UNIFORM_BUFFER, 0, 0); break;
      case 1: glBindBufferBase(GL_UNIFORM_BUFFER, 0, uniform_buffer_); break;
      default: glBindBufferRange(GL_UNIFORM_BUFFER, 0, uniform_buffer_, 256, 512); break;
    }
    glBindBuffer(GL_UNIFORM_BUFFER, pick<GLuint>(rng, {0u, buffers_[0], uniform_buffer_}));
    glActiveTexture(GL_TEXTURE4);
    glBindTexture(GL_TEXTURE_2D, pick<GLuint>(rng, {0u, host_textures_[2]}));
    glBindSampler(4, pick<GLuint>(rng, {0u, samplers_[0]}));
    glActiveTexture(GL_TEXTURE0);
    for (GLenum face : {GL_FRONT, GL_BACK}) {
      glStencilFuncSeparate(face, pick<GLenum>(rng, {GL_NEVER, GL_LESS, GL_GREATER, GL_ALWAYS}), byte(rng),
                            static_cast<GLuint>(byte(rng)));
      glStencilOpSeparate(face, pick<GLenum>(rng, {GL_KEEP, GL_ZERO, GL_INCR}), pick<GLenum>(rng, {GL_REPLACE, GL_DECR}),
                          pick<GLenum>(rng, {GL_INVERT, GL_INCR_WRAP}));
      glStencilMaskSeparate(face, static_cast<GLuint>(byte(rng)));
    }
  }

  // The defaults with a width that blurs visibly on the harness's scene.
  static sss_settings harness_settings() {
    sss_settings s;
    sss_default_settings(&s);
    s.world_units_per_mm = 0.05f;
    return s;
  }

  static sss_frame with_region(sss_frame f, const std::array<int32_t, 4>& region) {
    f.flags |= SSS_FRAME_REGION;
    for (std::size_t i = 0; i < 4; ++i) f.region[i] = region[i];
    return f;
  }

  // Image load/store (desktop GL 4.3+): the compute path binds image unit 0, the fragment passes
  // units 0 and 1.
  bool has_image_units() { return host_gl::has_compute_shaders(); }

  // The entry points that call GL, each as the harness runs it.
  std::vector<std::pair<std::string, std::function<void()>>> entry_points(uint32_t create_flags) {
    return {
        {"sss_create + sss_destroy",
         [this, create_flags] { sss_destroy(create_sss(create_flags)); }},
        {"sss_apply (alpha mask, write back)",
         [this] { EXPECT_EQ(sss_apply(sss_, color_, depth_, nullptr), SSS_OK) << sss_last_error(sss_); }},
        {"sss_apply (stencil)",
         [this] {
           const sss_stencil stencil = {depth_, 1, 0xFF};
           EXPECT_EQ(sss_apply(sss_, color_, depth_, &stencil), SSS_OK) << sss_last_error(sss_);
         }},
        {"sss_apply_frame (separate output, viewport)",
         [this] {
           sss_frame f = frame_of(color_, depth_, output_);
           f.viewport[0] = 2;
           f.viewport[1] = 3;
           f.viewport[2] = 17;
           f.viewport[3] = 15;
           EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
         }},
        // Skipping work: a region inside the viewport into a separate output (the
        // viewport copied first, then the passes over the region), and an empty region in place.
        {"sss_apply_frame (region, separate output; then an empty region)",
         [this] {
           sss_settings s = harness_settings();
           EXPECT_EQ(sss_set_settings(sss_, &s), SSS_OK) << sss_last_error(sss_);
           sss_frame f = with_region(frame_of(color_, depth_, output_), {4, 5, 12, 9});
           EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
           f.output_texture = 0;
           f.region[2] = 0;
           EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
           s.flags = SSS_FOLLOW_SURFACE;
           EXPECT_EQ(sss_set_settings(sss_, &s), SSS_OK);
         }},
        // The compute path (image unit 0, dispatches, memory barriers): in place, then a region into
        // a separate output (its copy outside the region is a fragment draw).
        {"sss_apply_frame (compute path: in place; a region into an output; masked and half-resolution paths)",
         [this] {
           sss_settings s = harness_settings();
           s.path = SSS_PATH_COMPUTE;
           EXPECT_EQ(sss_set_settings(sss_, &s), SSS_OK) << sss_last_error(sss_);
           sss_frame f = frame_of(color_, depth_);
           EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
           f = with_region(frame_of(color_, depth_, output_), {3, 4, 14, 11});
           EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
           // The masked fragment path: its own stencil marked from alpha, then the masked passes.
           s.path = SSS_PATH_FRAGMENT_MASKED;
           EXPECT_EQ(sss_set_settings(sss_, &s), SSS_OK) << sss_last_error(sss_);
           EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
           // The half-resolution path (its depth range, clears and units 2-4), the region into the output
           // (at odd offsets: whole-rectangle draws), then the whole frame in place (its tiles, unit 5).
           s.path = SSS_PATH_HALF_RESOLUTION;
           EXPECT_EQ(sss_set_settings(sss_, &s), SSS_OK) << sss_last_error(sss_);
           EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
           const sss_frame whole = frame_of(color_, depth_);
           EXPECT_EQ(sss_apply_frame(sss_, &whole), SSS_OK) << sss_last_error(sss_);
           s.path = SSS_PATH_FRAGMENT;
           EXPECT_EQ(sss_set_settings(sss_, &s), SSS_OK);
         }},
        // Per-pixel profiles: texture unit 4 and uniform buffer binding 0; under the debug checks
        // also the read-back of the indices (the pack state), on a context of its own.
        {"sss_apply_frame (per-pixel profiles; then with debug checks)",
         [this] {
           sss_settings p[2] = {harness_settings(), harness_settings()};
           p[1].scale = 2.0f;
           EXPECT_EQ(sss_set_profiles(sss_, p, 2), SSS_OK) << sss_last_error(sss_);
           sss_frame f = frame_of(color_, depth_);
           f.profile_texture = profile_ids_;
           EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
           sss_context* checked = create_sss(SSS_CREATE_DEBUG_CHECKS);
           EXPECT_EQ(sss_set_profiles(checked, p, 2), SSS_OK) << sss_last_error(checked);
           EXPECT_EQ(sss_set_camera(checked, scene_.projection.data()), SSS_OK);
           EXPECT_EQ(sss_apply_frame(checked, &f), SSS_OK) << sss_last_error(checked);
           sss_destroy(checked);
           EXPECT_EQ(sss_set_settings(sss_, &p[0]), SSS_OK);
         }},
        {"sss_apply (failing: wrong format)",
         [this] { EXPECT_EQ(sss_apply(sss_, host_textures_[3] /* RGBA16F */, color_, nullptr), SSS_ERROR_INVALID_TEXTURE); }},
        // New inputs on every call (a cached LUT would call no GL): the GPU generator and the CPU upload.
        {"sss_lut_create_texture (GPU generator)",
         [this] {
           sss_lut_desc d;
           sss_lut_default_desc(&d);
           d.width = 4;
           d.height = 2;
           d.curvature_max = 1.0f + 0.01f * static_cast<float>(++lut_calls_);
           uint32_t texture = 0;
           EXPECT_EQ(sss_lut_create_texture(sss_, SSS_LUT_DIFFUSE, &d, &texture), SSS_OK) << sss_last_error(sss_);
         }},
        {"sss_lut_create_texture (CPU upload)",
         [this] {
           sss_lut_desc d;
           sss_lut_default_desc(&d);
           d.width = 4;
           d.height = 2;
           d.flags = SSS_LUT_CPU;
           d.penumbra_max = 0.032f + 0.001f * static_cast<float>(++lut_calls_);
           uint32_t texture = 0;
           EXPECT_EQ(sss_lut_create_texture(sss_, SSS_LUT_SHADOW, &d, &texture), SSS_OK) << sss_last_error(sss_);
         }},
        // A kernel of several terms (the accumulators on unit 3), jittered taps and the artist
        // model's Gaussian depth correction: every shader variant and target the families add.
        {"sss_apply (3 Gaussians, jitter; then the artist model), stencil",
         [this] {
           sss_settings s = harness_settings();
           sss_test::kernel_of(s).family = SSS_KERNEL_SUM_OF_GAUSSIANS;
           sss_test::kernel_of(s).rank = 3;
           s.jitter = 0.5f;
           EXPECT_EQ(sss_set_settings(sss_, &s), SSS_OK) << sss_last_error(sss_);
           const sss_stencil stencil = {depth_, 1, 0xFF};
           EXPECT_EQ(sss_apply(sss_, color_, depth_, &stencil), SSS_OK) << sss_last_error(sss_);
           sss_test::kernel_of(s).family = SSS_KERNEL_ARTIST;
           EXPECT_EQ(sss_set_settings(sss_, &s), SSS_OK) << sss_last_error(sss_);
           EXPECT_EQ(sss_apply(sss_, color_, depth_, &stencil), SSS_OK) << sss_last_error(sss_);
           s = harness_settings();
           EXPECT_EQ(sss_set_settings(sss_, &s), SSS_OK);
         }},
        {"sss_set_settings + sss_set_camera",
         [this] {
           sss_settings s = harness_settings();
           EXPECT_EQ(sss_set_settings(sss_, &s), SSS_OK);
           EXPECT_EQ(sss_set_camera(sss_, scene_.projection.data()), SSS_OK);
         }},
    };
  }

  void prepare(uint32_t create_flags) {
    sss_ = create_sss(create_flags);
    ASSERT_NE(sss_, nullptr);
    sss_settings s = harness_settings();
    ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK);
    ASSERT_EQ(sss_set_camera(sss_, scene_.projection.data()), SSS_OK);
  }

  GLuint programs_[2] = {0, 0}, vaos_[2] = {0, 0}, fbos_[2] = {0, 0}, renderbuffer_ = 0, buffers_[2] = {0, 0};
  GLuint samplers_[2] = {0, 0}, host_textures_[4] = {0, 0, 0, 0}, uniform_buffer_ = 0, profile_ids_ = 0;
  SyntheticScene scene_;
  GLuint color_ = 0, output_ = 0, depth_ = 0;
  int lut_calls_ = 0;
};

TEST_F(StateHarness, EveryEntryPointRestoresRandomState) {
  prepare(0);
  int checked = 0;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    std::mt19937 rng(seed);
    for (auto& [name, call] : entry_points(0)) {
      randomise(rng);
      const Snapshot before = take_snapshot();
      call();
      const Snapshot after = take_snapshot();
      ASSERT_EQ(describe_differences(before, after), "") << name << ", seed " << seed;
      ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << name << ", seed " << seed;
      ++checked;
    }
  }
  RecordProperty("calls_checked", checked);
  EXPECT_EQ(checked, 40 * 12);
}

TEST_F(StateHarness, FailsWhenTheRestoresAreOff) {
  prepare(SSS_CREATE_NO_STATE_RESTORE);
  std::mt19937 rng(7);
  randomise(rng);
  const Snapshot before = take_snapshot();
  const sss_stencil stencil = {depth_, 1, 0xFF};
  ASSERT_EQ(sss_apply(sss_, color_, depth_, &stencil), SSS_OK) << sss_last_error(sss_);
  EXPECT_NE(describe_differences(before, take_snapshot()), "");
  glGetError();
}

// Each group of restores removed alone (through the module's test hook): the harness must notice,
// for some seed and entry point, that a state was left behind. The groups only the MSAA write-back
// touches (GL_SAMPLE_MASK_VALUE, the blend function: nothing this harness's single-sample entry
// points change) are checked by MsaaWriteBackRestoresAreEachNoticed below.
TEST_F(StateHarness, FailsWhenAnySingleRestoreIsRemoved) {
  namespace g = sss::gl::restore_group;
  const std::vector<std::pair<const char*, uint32_t>> groups = {
      {"stencil", g::stencil},
      {"colour mask", g::color_mask},
      {"polygon mode", g::polygon_mode},
      {"clip distances", g::clip_distances},
      {"desktop enables", g::desktop_enables},
      {"sample mask enable", g::sample_mask_enable},
      {"enables", g::enables},
      {"viewport", g::viewport},
      {"texture units", g::texture_units},
      {"active texture", g::active_texture},
      {"unpack buffer", g::unpack_buffer},
      {"renderbuffer", g::renderbuffer},
      {"read framebuffer", g::read_framebuffer},
      {"draw framebuffer", g::draw_framebuffer},
      {"vertex array", g::vertex_array},
      {"program", g::program},
      {"image unit", g::image_unit},
      {"uniform buffer", g::uniform_buffer},
      {"pack state", g::pack_state},
      {"depth", g::depth},
  };
  std::atomic<uint32_t>& skip = sss::gl::restore_skip_mask_for_tests();
  for (const auto& [name, group] : groups) {
    if (group == g::image_unit && !has_image_units()) continue;  // no compute path to restore it for
    // A new context each time: some restores matter only on a first frame (the renderbuffer is
    // bound only while the stencil copy is allocated).
    if (sss_ != nullptr) sss_destroy(sss_);
    sss_ = nullptr;
    prepare(0);
    skip = group;
    bool noticed = false;
    for (unsigned seed = 1; seed <= 20 && !noticed; ++seed) {
      std::mt19937 rng(seed);
      for (auto& [entry, call] : entry_points(0)) {
        randomise(rng);
        const Snapshot before = take_snapshot();
        call();
        if (!describe_differences(before, take_snapshot()).empty()) {
          noticed = true;
          break;
        }
      }
    }
    skip = 0;
    glGetError();
    EXPECT_TRUE(noticed) << "the harness did not notice the missing '" << name << "' restore";
  }
}

// The MSAA write-back (in place, desktop GL) sets the blend function, and on a GL 3.3-4.1 context
// (one draw per sample) the sample mask word: with the host's own values there, leaving out either
// restore is seen, and with both the state is as it was.
TEST_F(StateHarness, MsaaWriteBackRestoresAreEachNoticed) {
  if (is_gles()) GTEST_SKIP() << "the MSAA path is desktop OpenGL only";
  namespace g = sss::gl::restore_group;
  const SyntheticScene fine = make_relief_scene(2 * kSize, 2 * kSize, 5, perspective_matrix(40.0f, 1.0f, 0.1f, 10.0f));
  const GLuint color = make_multisample_texture(GL_RGBA16F, kSize, kSize, 4, fine.color);
  const GLuint depth = make_multisample_texture(GL_DEPTH_COMPONENT32F, kSize, kSize, 4, fine.window_depth);
  ASSERT_NE(color, 0u);
  ASSERT_NE(depth, 0u);
  std::atomic<uint32_t>& skip = sss::gl::restore_skip_mask_for_tests();
  const uint32_t kSampleMask = g::sample_mask_value, kBlend = g::blend_function;
  const std::pair<uint32_t, bool> cases[] = {{0u, false}, {kBlend, false}, {0u, true}, {kSampleMask, true}, {kBlend, true}};
  for (const auto& [group, gl33] : cases) {
    SCOPED_TRACE(std::string(gl33 ? "GL 3.3 (a draw per sample)" : "this context (one draw)") + ", restores left out: " +
                 std::to_string(group));
    if (sss_ != nullptr) sss_destroy(sss_);
    loader_override_ =
        gl33 ? loader_telling(GL_VERSION, "3.3 (Core Profile) as told by the test", sss_headless_get_proc_address) : nullptr;
    prepare(0);
    glSampleMaski(0, 0x5u);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ZERO);
    glBlendEquationSeparate(GL_FUNC_SUBTRACT, GL_MAX);
    const Snapshot before = take_snapshot();
    skip = group;
    EXPECT_EQ(sss_apply(sss_, color, depth, nullptr), SSS_OK) << sss_last_error(sss_);
    skip = 0;
    const std::string differences = describe_differences(before, take_snapshot());
    if (group == 0) {
      EXPECT_EQ(differences, "");
    } else {
      EXPECT_NE(differences.find(group == kSampleMask ? "GL_SAMPLE_MASK_VALUE" : "GL_BLEND_EQUATION_RGB"), std::string::npos)
          << differences;
    }
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  }
  loader_override_ = nullptr;
  glSampleMaski(0, ~0u);
  glBlendFuncSeparate(GL_ONE, GL_ZERO, GL_ONE, GL_ZERO);
  glBlendEquationSeparate(GL_FUNC_ADD, GL_FUNC_ADD);
  const GLuint textures[2] = {color, depth};
  glDeleteTextures(2, textures);
}

TEST_F(StateHarness, SeesAChangeOfAnySingleListedState) {
  // Each line: a state of sss.h's list and a change to it, as a missing restore would leave it.
  const std::vector<std::pair<const char*, std::function<void()>>> changes = {
      {"GL_CURRENT_PROGRAM", [this] { glUseProgram(programs_[1]); }},
      {"GL_VERTEX_ARRAY_BINDING", [this] { glBindVertexArray(vaos_[1]); }},
      {"GL_DRAW_FRAMEBUFFER_BINDING", [this] { glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbos_[1]); }},
      {"GL_READ_FRAMEBUFFER_BINDING", [this] { glBindFramebuffer(GL_READ_FRAMEBUFFER, fbos_[1]); }},
      {"GL_RENDERBUFFER_BINDING", [this] { glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer_); }},
      {"GL_PIXEL_UNPACK_BUFFER_BINDING", [this] { glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buffers_[0]); }},
      {"GL_ACTIVE_TEXTURE", [] { glActiveTexture(GL_TEXTURE3); }},
      {"GL_TEXTURE_BINDING_2D unit 2", [this] { glActiveTexture(GL_TEXTURE2); glBindTexture(GL_TEXTURE_2D, host_textures_[1]); glActiveTexture(GL_TEXTURE0); }},
      {"GL_SAMPLER_BINDING unit 1", [this] { glBindSampler(1, samplers_[1]); }},
      {"GL_TEXTURE_BINDING_2D unit 4", [this] { glActiveTexture(GL_TEXTURE4); glBindTexture(GL_TEXTURE_2D, host_textures_[1]); glActiveTexture(GL_TEXTURE0); }},
      {"GL_UNIFORM_BUFFER_BINDING index 0", [this] { glBindBufferRange(GL_UNIFORM_BUFFER, 0, uniform_buffer_, 256, 512); }},
      {"GL_UNIFORM_BUFFER_BINDING", [this] { glBindBuffer(GL_UNIFORM_BUFFER, uniform_buffer_); }},
      {"GL_PACK_ROW_LENGTH", [] { glPixelStorei(GL_PACK_ROW_LENGTH, 9); }},
      {"GL_VIEWPORT", [] { glViewport(1, 2, 3, 4); }},
      {"GL_SCISSOR_TEST", [] { glEnable(GL_SCISSOR_TEST); }},
      {"GL_RASTERIZER_DISCARD", [] { glEnable(GL_RASTERIZER_DISCARD); }},
      {"GL_CLIP_DISTANCE5", [] { glEnable(GL_CLIP_DISTANCE5); }},
      {"GL_COLOR_WRITEMASK", [] { glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE); }},
      {"GL_POLYGON_MODE", [] { glPolygonMode(GL_FRONT_AND_BACK, GL_LINE); }},
      {"GL_STENCIL_BACK_FUNC", [] { glStencilFuncSeparate(GL_BACK, GL_NEVER, 0, 0xFF); }},
      {"GL_STENCIL_WRITEMASK", [] { glStencilMaskSeparate(GL_FRONT, 0x0F); }},
      {"GL_BLEND_DST_RGB", [] { glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_COLOR, GL_ONE, GL_ZERO); }},
      {"GL_BLEND_EQUATION_ALPHA", [] { glBlendEquationSeparate(GL_FUNC_ADD, GL_MAX); }},
  };
  for (const auto& [state, change] : changes) {
    glUseProgram(programs_[0]);
    const Snapshot before = take_snapshot();
    change();
    const std::string differences = describe_differences(before, take_snapshot());
    EXPECT_NE(differences.find(state), std::string::npos) << state << ": " << differences;
    // Back to defaults for the next line.
    glUseProgram(0);
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE4);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindSampler(1, 0);
    glBindBufferBase(GL_UNIFORM_BUFFER, 0, 0);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glViewport(0, 0, 16, 16);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_RASTERIZER_DISCARD);
    glDisable(GL_CLIP_DISTANCE5);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glBlendFuncSeparate(GL_ONE, GL_ZERO, GL_ONE, GL_ZERO);
    glBlendEquationSeparate(GL_FUNC_ADD, GL_FUNC_ADD);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glStencilFuncSeparate(GL_BACK, GL_ALWAYS, 0, 0xFF);
    glStencilMaskSeparate(GL_FRONT, 0xFF);
  }
}

}  // namespace
}  // namespace sss_test
