// The host's GL state after sss_apply equals the state before it, for every state in the list of
// sss.h (set to unusual values first) and for the states the module promises not to touch; and
// the result does not depend on that state.
#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <sstream>

#include "filter_case.hpp"
#include "gl_state_snapshot.hpp"
#include "multisample_textures.hpp"
#include "sss/sss_lut.h"

using namespace host_gl;

namespace sss_test {
namespace {

class StateRestore : public FilterCaseTest {
 protected:
  // Host objects bound while the module runs; deleted in the test's TearDown via textures_ or here.
  GLuint program_ = 0, vao_ = 0, fbo_draw_ = 0, fbo_read_ = 0, renderbuffer_ = 0, buffers_[3] = {0, 0, 0};
  GLuint samplers_[7] = {0, 0, 0, 0, 0, 0, 0};

  void set_unusual_state() {
    program_ = make_host_program(false);
    glUseProgram(program_);
    glGenVertexArrays(1, &vao_);
    glBindVertexArray(vao_);
    glGenBuffers(3, buffers_);
    glBindBuffer(GL_ARRAY_BUFFER, buffers_[0]);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buffers_[1]);
    glBufferData(GL_PIXEL_UNPACK_BUFFER, 64, nullptr, GL_STREAM_DRAW);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, buffers_[2]);
    const GLuint target = make_rgba16f(8, 8, std::vector<float>(8 * 8 * 4, 0.25f));
    glGenFramebuffers(1, &fbo_draw_);
    glGenFramebuffers(1, &fbo_read_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_draw_);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target, 0);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_read_);
    glGenRenderbuffers(1, &renderbuffer_);
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer_);
    glGenSamplers(7, samplers_);
    for (GLenum unit = 0; unit < 7; ++unit) {  // every unit of the restored list (sss.h)
      glActiveTexture(GL_TEXTURE0 + unit);
      glBindTexture(GL_TEXTURE_2D, make_rgba16f(2, 2, std::vector<float>(16, 1.0f)));
      glBindSampler(unit, samplers_[unit]);
    }
    glActiveTexture(GL_TEXTURE5);
    glViewport(3, 5, 17, 19);
    glScissor(1, 2, 3, 4);
    for (GLenum cap : {GL_SCISSOR_TEST, GL_DEPTH_TEST, GL_STENCIL_TEST, GL_BLEND, GL_CULL_FACE, GL_FRAMEBUFFER_SRGB,
                       GL_RASTERIZER_DISCARD, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_COVERAGE, GL_SAMPLE_MASK,
                       GL_POLYGON_OFFSET_FILL, GL_DEPTH_CLAMP, GL_COLOR_LOGIC_OP, GL_CLIP_DISTANCE0, GL_CLIP_DISTANCE5}) {
      glEnable(cap);
    }
    glDisable(GL_DITHER);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glDepthMask(GL_FALSE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glDepthFunc(GL_GEQUAL);
    glBlendFunc(GL_DST_COLOR, GL_ONE_MINUS_SRC_ALPHA);
    glCullFace(GL_FRONT_AND_BACK);
    glFrontFace(GL_CW);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
    glPixelStorei(GL_PACK_ALIGNMENT, 8);
    glStencilFuncSeparate(GL_FRONT, GL_GREATER, 7, 0x3C);
    glStencilOpSeparate(GL_FRONT, GL_INCR, GL_DECR, GL_INVERT);
    glStencilMaskSeparate(GL_FRONT, 0x0F);
    glStencilFuncSeparate(GL_BACK, GL_LESS, 3, 0xF0);
    glStencilOpSeparate(GL_BACK, GL_ZERO, GL_REPLACE, GL_INCR_WRAP);
    glStencilMaskSeparate(GL_BACK, 0xA5);
    ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  }
  void check_restore(const SyntheticScene& scene, FilterCase c);
};

TEST_F(StateRestore, EveryListedStateIsRestoredAndTheResultIsUnaffected) {
  const SyntheticScene scene = make_relief_scene(32, 24, 2, perspective_matrix(40.0f, 32.0f / 24.0f, 0.1f, 10.0f));
  FilterCase c;
  sss_default_settings(&c.settings);
  c.settings.world_units_per_mm = 0.05f;
  check_restore(scene, c);
}

// The cross-bilateral mode with a stencil also clears and draws into its masked colour copy.
TEST_F(StateRestore, CrossBilateralModeRestoresEveryListedState) {
  const SyntheticScene scene = make_relief_scene(32, 24, 2, perspective_matrix(40.0f, 32.0f / 24.0f, 0.1f, 10.0f));
  FilterCase c;
  sss_default_settings(&c.settings);
  c.settings.world_units_per_mm = 0.05f;
  c.settings.mode = SSS_MODE_CROSS_BILATERAL;
  check_restore(scene, c);
}

void StateRestore::check_restore(const SyntheticScene& scene, FilterCase c) {
  c.depth = DepthKind::depth24_stencil8;
  c.use_stencil = true;
  const FilterOutcome clean = run_case(scene, c);  // default GL state
  ASSERT_EQ(clean.result, SSS_OK);
  sss_destroy(sss_);
  sss_ = nullptr;

  set_unusual_state();
  const Snapshot before = take_snapshot();
  const FilterOutcome messy = run_case(scene, c);  // creates the context and applies under that state
  const Snapshot after = take_snapshot();
  EXPECT_EQ(describe_differences(before, after), "");
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  ASSERT_EQ(messy.result, SSS_OK);
  EXPECT_EQ(0, std::memcmp(messy.gpu.data(), clean.gpu.data(), clean.gpu.size() * sizeof(float)));
}

// A steady frame (described, as the last one: sss.h, "GL queries" on sss_frame) saves only the part
// of the list its path can change: every path's steady frames still restore everything.
TEST_F(StateRestore, SteadyFramesOfEveryPathRestoreEveryListedState) {
  const SyntheticScene scene = make_relief_scene(16, 12, 2, perspective_matrix(40.0f, 16.0f / 12.0f, 0.1f, 10.0f));
  const GLuint color = make_rgba16f(16, 12, scene.color);
  const GLuint depth = make_depth32f(16, 12, scene.window_depth);
  const GLuint output = make_rgba32f(16, 12, scene.color);
  std::vector<uint32_t> packed(scene.window_depth.size());
  for (std::size_t i = 0; i < packed.size(); ++i) packed[i] = (1u << 31) | (scene.stencil[i] ? 1u : 0u);
  const GLuint depth_stencil = make_texture(GL_DEPTH24_STENCIL8, 16, 12, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8,
                                            packed.data());
  const SyntheticScene fine = make_relief_scene(32, 24, 2, perspective_matrix(40.0f, 16.0f / 12.0f, 0.1f, 10.0f));
  const GLuint msaa_color = make_multisample_texture(GL_RGBA16F, 16, 12, 4, fine.color);
  const GLuint msaa_depth = make_multisample_texture(GL_DEPTH_COMPONENT32F, 16, 12, 4, fine.window_depth);
  // The MSAA path's albedo is multisampled like its colour (a texturing mode on that path).
  const GLuint msaa_albedo = make_multisample_texture(GL_RGBA16F, 16, 12, 4, std::vector<float>(32 * 24 * 4, 0.5f));
  ASSERT_NE(msaa_color, 0u);
  ASSERT_NE(msaa_depth, 0u);
  ASSERT_NE(msaa_albedo, 0u);
  // An R11F_G11F_B10F colour with its strength in an R8 texture (sss_frame.strength_texture).
  std::vector<float> rgb;
  std::vector<uint8_t> strength;
  for (std::size_t i = 0; i < scene.color.size(); ++i) {
    if (i % 4 != 3) rgb.push_back(scene.color[i]);
    if (i % 4 == 3) strength.push_back(static_cast<uint8_t>(scene.color[i] * 255.0f));
  }
  const GLuint r11f = make_texture(GL_R11F_G11F_B10F, 16, 12, GL_RGB, GL_FLOAT, rgb.data());
  const GLuint mask = make_texture(GL_R8, 16, 12, GL_RED, GL_UNSIGNED_BYTE, strength.data());
  const GLuint albedo = make_rgba16f(16, 12, std::vector<float>(16 * 12 * 4, 0.5f));  // texturing modes
  sss_stencil stencil = {depth_stencil, 1, 0xFF};
  struct Case {
    const char* name;
    uint32_t path = SSS_PATH_FRAGMENT, mode = SSS_MODE_SEPARABLE;
    bool stencil = false, output = false, two_terms = false, msaa = false, strength = false;
    uint32_t debug_view = 0;  // sss_frame.debug_view (needs `output`)
    uint32_t texturing = SSS_TEXTURING_PRE_SCATTER;  // another mode: with an albedo texture (unit 6)
  };
  const Case cases[] = {{"in place"},
                        {"host stencil, separate output", SSS_PATH_FRAGMENT, SSS_MODE_SEPARABLE, true, true},
                        {"masked path", SSS_PATH_FRAGMENT_MASKED},
                        {"half resolution", SSS_PATH_HALF_RESOLUTION},
                        {"half resolution, host stencil, separate output", SSS_PATH_HALF_RESOLUTION,
                         SSS_MODE_SEPARABLE, true, true},
                        {"compute path", SSS_PATH_COMPUTE},
                        {"compute path, host stencil, two kernel terms, separate output", SSS_PATH_COMPUTE,
                         SSS_MODE_SEPARABLE, true, true, true},
                        {"automatic path", SSS_PATH_AUTO},
                        {"cross-bilateral with a stencil", SSS_PATH_FRAGMENT, SSS_MODE_CROSS_BILATERAL, true},
                        {"two kernel terms", SSS_PATH_FRAGMENT, SSS_MODE_SEPARABLE, false, false, true},
                        {"MSAA", SSS_PATH_FRAGMENT, SSS_MODE_SEPARABLE, false, false, false, true},
                        {"strength texture", SSS_PATH_FRAGMENT, SSS_MODE_SEPARABLE, false, false, false, false, true},
                        {"strength texture, masked path", SSS_PATH_FRAGMENT_MASKED, SSS_MODE_SEPARABLE, false, false,
                         false, false, true},
                        {"strength texture, compute path", SSS_PATH_COMPUTE, SSS_MODE_SEPARABLE, false, false, false,
                         false, true},
                        {"taps debug view, host stencil", SSS_PATH_FRAGMENT, SSS_MODE_SEPARABLE, true, true, false,
                         false, false, SSS_DEBUG_VIEW_TAPS},
                        {"tiles debug view (its colour masks)", SSS_PATH_FRAGMENT, SSS_MODE_SEPARABLE, false, true,
                         false, false, false, SSS_DEBUG_VIEW_TILES},
                        {"post-scatter", SSS_PATH_FRAGMENT, SSS_MODE_SEPARABLE, false, false, false, false, false, 0,
                         SSS_TEXTURING_POST_SCATTER},
                        {"pre- and post-scatter, compute path, separate output", SSS_PATH_COMPUTE, SSS_MODE_SEPARABLE,
                         false, true, false, false, false, 0, SSS_TEXTURING_PRE_AND_POST_SCATTER},
                        {"post-scatter, cross-bilateral", SSS_PATH_FRAGMENT, SSS_MODE_CROSS_BILATERAL, false, false,
                         false, false, false, 0, SSS_TEXTURING_POST_SCATTER},
                        {"post-scatter, half resolution", SSS_PATH_HALF_RESOLUTION, SSS_MODE_SEPARABLE, false, false,
                         false, false, false, 0, SSS_TEXTURING_POST_SCATTER},
                        {"post-scatter, MSAA", SSS_PATH_FRAGMENT, SSS_MODE_SEPARABLE, false, false, false, true, false, 0,
                         SSS_TEXTURING_POST_SCATTER},
                        {"pre- and post-scatter, MSAA, separate output", SSS_PATH_FRAGMENT, SSS_MODE_SEPARABLE, false,
                         true, false, true, false, 0, SSS_TEXTURING_PRE_AND_POST_SCATTER}};
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  ASSERT_EQ(sss_set_camera(sss_, scene.projection.data()), SSS_OK);
  set_unusual_state();
  const Snapshot before = take_snapshot();
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    sss_settings s;
    sss_default_settings(&s);
    s.world_units_per_mm = 0.05f;
    s = path_case_settings(s, c.path, c.mode, c.two_terms);
    s.texturing = c.texturing;
    ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK) << sss_last_error(sss_);
    sss_frame f = frame_of(c.msaa ? msaa_color : color, c.msaa ? msaa_depth : c.stencil ? depth_stencil : depth,
                           c.output ? output : 0);
    f.stencil = c.stencil ? &stencil : nullptr;
    f.debug_view = c.debug_view;
    FilterCase description;
    description.half_color = true;
    description.depth = c.stencil ? DepthKind::depth24_stencil8 : DepthKind::depth32f;
    describe_frame(description, 16, 12, &f);
    if (c.texturing != SSS_TEXTURING_PRE_SCATTER) {
      f.albedo_texture = c.msaa ? msaa_albedo : albedo;
      f.albedo_format = GL_RGBA16F;
      f.flags = SSS_FRAME_TARGET_COMPLETE;  // the compute path writes the target (GL_NEAREST: complete)
    }
    if (c.strength) {
      f.color_texture = r11f;
      f.color_format = GL_R11F_G11F_B10F;
      f.strength_texture = mask;
      f.strength_format = GL_R8;
      f.flags = SSS_FRAME_TARGET_COMPLETE;  // the compute path writes the colour (GL_NEAREST: complete)
    }
    for (int frame = 0; frame < 3; ++frame) {  // the first is not steady, the others are
      ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
      EXPECT_EQ(describe_differences(before, take_snapshot()), "") << "frame " << frame;
      EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    }
  }
}

TEST_F(StateRestore, CreateAndDestroyLeaveTheStateAsTheyFoundIt) {
  set_unusual_state();
  const Snapshot before = take_snapshot();
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  EXPECT_EQ(describe_differences(before, take_snapshot()), "");
  sss_destroy(sss_);
  sss_ = nullptr;
  EXPECT_EQ(describe_differences(before, take_snapshot()), "");
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(StateRestore, FailedCallsLeaveNoErrorAndNoStateBehind) {
  set_unusual_state();
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  const float projection[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, -1, 0, 0, -0.2f, 0};
  ASSERT_EQ(sss_set_camera(sss_, projection), SSS_OK);
  const Snapshot before = take_snapshot();
  GLuint multisample = 0;
  glGenTextures(1, &multisample);
  textures_.push_back(multisample);
  GLint active = 0;
  glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
  glActiveTexture(GL_TEXTURE7);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, multisample);
  glTexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, 4, GL_RGBA16F, 8, 8, GL_TRUE);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
  glActiveTexture(static_cast<GLenum>(active));
  const GLuint depth = make_depth32f(8, 8, std::vector<float>(64, 0.5f));
  // Multisampled colour with single-sample depth: the module's bind to GL_TEXTURE_2D fails with
  // GL_INVALID_OPERATION (how it finds the target), which it must swallow.
  EXPECT_EQ(sss_apply(sss_, multisample, depth, nullptr), SSS_ERROR_INVALID_TEXTURE);
  EXPECT_EQ(describe_differences(before, take_snapshot()), "");
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(StateRestore, AProgramDeletedWhileCurrentLeavesNoErrorBehind) {
  const SyntheticScene scene = make_relief_scene(16, 16, 2, perspective_matrix(40.0f, 1.0f, 0.1f, 10.0f));
  FilterCase c;
  sss_default_settings(&c.settings);
  c.settings.world_units_per_mm = 0.05f;
  set_unusual_state();
  glDeleteProgram(program_);  // flagged for deletion; stays current until another is bound
  sss_context* created = create_sss();  // builds programs, so binds others
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  sss_destroy(created);
  set_unusual_state();
  glDeleteProgram(program_);
  const FilterOutcome o = run_case(scene, c);
  ASSERT_EQ(o.result, SSS_OK);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  GLint current = -1;
  glGetIntegerv(GL_CURRENT_PROGRAM, &current);
  EXPECT_EQ(current, 0);
}

TEST_F(StateRestore, LutTexturesRestoreEveryListedStateOnBothGenerators) {
  // The GPU generator draws (program, framebuffer, viewport, pass state); the CPU path uploads
  // (unpack buffer and the unpack parameters, set oddly here, must not reshape the rows).
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  set_unusual_state();
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 3);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
  const Snapshot before = take_snapshot();
  GLint row_length_before = 0;
  glGetIntegerv(GL_UNPACK_ROW_LENGTH, &row_length_before);
  sss_lut_desc desc;
  sss_lut_default_desc(&desc);
  desc.width = 8;
  desc.height = 4;
  for (uint32_t flags : {0u, static_cast<uint32_t>(SSS_LUT_CPU)}) {
    desc.flags = flags;
    for (int32_t which : {SSS_LUT_DIFFUSE, SSS_LUT_SHADOW}) {
      uint32_t texture = 0;
      ASSERT_EQ(sss_lut_create_texture(sss_, which, &desc, &texture), SSS_OK) << sss_last_error(sss_);
      EXPECT_NE(texture, 0u);
      EXPECT_EQ(describe_differences(before, take_snapshot()), "") << "flags " << flags << " which " << which;
      EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    }
  }
  GLint row_length_after = 0;
  glGetIntegerv(GL_UNPACK_ROW_LENGTH, &row_length_after);
  EXPECT_EQ(row_length_after, row_length_before);
}

}  // namespace
}  // namespace sss_test
