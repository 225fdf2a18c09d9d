// The GLSL variant negotiated at create time, the log levels, and what only the OpenGL ES path has:
// the frame's texture description (required where the GL cannot be asked), and the ES state list.
//   Variant.*  every backend (desktop GL and egl-gles)
//   Gles.*     egl-gles only (skipped elsewhere)
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "filter_case.hpp"
#include "gl_state_snapshot.hpp"

using namespace host_gl;

namespace sss_test {
namespace {

class Variant : public FilterCaseTest {
 protected:
  sss_context* create_logged(LogRecord* log, sss_get_proc_address_fn loader = nullptr) {
    log_ = log;
    loader_override_ = loader;
    sss_context* ctx = create_sss();
    log_ = nullptr;
    loader_override_ = nullptr;
    return ctx;
  }
  // A camera for sss_ and an 8x8 RGBA16F colour of one value at one depth; returns the colour.
  std::vector<float> flat_frame(GLuint* color, GLuint* depth) {
    const float projection[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1.02f, -1, 0, 0, -0.202f, 0};
    EXPECT_EQ(sss_set_camera(sss_, projection), SSS_OK);
    std::vector<float> rgba(8 * 8 * 4, 0.5f);
    *color = make_rgba16f(8, 8, rgba);
    *depth = make_depth32f(8, 8, std::vector<float>(64, 0.5f));
    return rgba;
  }
};

// GLSL 330 below GL 4.2, 420 from 4.2, ES 300 on OpenGL ES: llvmpipe is GL 4.5 core / ES 3.2.
std::string expected_variant(bool es) { return es ? "GLSL ES 300" : "GLSL 420 core"; }

TEST_F(Variant, CreateLogsTheVariantAndRendererAtInfoAndDetailsAtDebug) {
  LogRecord log;
  sss_ = create_logged(&log);
  ASSERT_NE(sss_, nullptr);
  const std::string renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  EXPECT_TRUE(log.has(SSS_LOG_INFO, renderer)) << "no INFO message names the renderer " << renderer;
  EXPECT_TRUE(log.has(SSS_LOG_INFO, expected_variant(is_gles()))) << "no INFO message names the variant";
  EXPECT_TRUE(log.has(SSS_LOG_INFO, is_gles() ? "OpenGL ES 3." : "OpenGL 4.")) << "no INFO message names the API";
  EXPECT_TRUE(log.has(SSS_LOG_DEBUG, "sss_create: texture formats"));
  EXPECT_TRUE(log.has(SSS_LOG_DEBUG, "built the blur program (" + expected_variant(is_gles())));
  EXPECT_EQ(log.count(SSS_LOG_ERROR), 0);
  EXPECT_EQ(log.count(SSS_LOG_WARNING), 0);
}

TEST_F(Variant, FramesLogAllocationsAtDebugAndFailuresAtErrorWithTheLastErrorText) {
  LogRecord log;
  FilterCase c;
  sss_default_settings(&c.settings);
  c.settings.world_units_per_mm = 0.02f;
  const SyntheticScene scene = make_relief_scene(24, 16, 2, perspective_matrix(40.0f, 1.5f, 0.1f, 10.0f));
  const GLuint color = make_rgba16f(24, 16, scene.color);
  const GLuint depth = make_depth32f(24, 16, scene.window_depth);
  sss_ = create_logged(&log);
  ASSERT_NE(sss_, nullptr);
  ASSERT_EQ(sss_set_camera(sss_, scene.projection.data()), SSS_OK);
  sss_frame frame = frame_of(color, depth);
  c.half_color = true;
  describe_frame(c, 24, 16, &frame);
  ASSERT_EQ(sss_apply_frame(sss_, &frame), SSS_OK) << sss_last_error(sss_);
  EXPECT_TRUE(log.has(SSS_LOG_DEBUG, "allocated the 24x16 RGBA32UI pass input (colour and view distance)"));
  EXPECT_EQ(log.count(SSS_LOG_ERROR), 0);
  frame.color_texture = 0;
  ASSERT_EQ(sss_apply_frame(sss_, &frame), SSS_ERROR_INVALID_TEXTURE);
  EXPECT_TRUE(log.has(SSS_LOG_ERROR, sss_last_error(sss_))) << "the ERROR message is not sss_last_error's text";
  EXPECT_EQ(log.count(SSS_LOG_ERROR), 1);
}

TEST_F(Variant, AGivenDescriptionIsCheckedAgainstTheGlWhereItCanBeAsked) {
  // The real loader: desktop GL, or ES 3.2 (which has glGetTexLevelParameteriv).
  LogRecord log;
  sss_ = create_logged(&log, sss_headless_get_proc_address);
  ASSERT_NE(sss_, nullptr);
  GLuint color = 0, depth = 0;
  const std::vector<float> rgba = flat_frame(&color, &depth);
  sss_frame frame = frame_of(color, depth);
  frame.color_format = GL_RGBA32F;  // wrong: it is RGBA16F
  EXPECT_EQ(sss_apply_frame(sss_, &frame), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("frame->color_format = GL_RGBA32F"), std::string::npos)
      << sss_last_error(sss_);
  frame.color_format = GL_RGBA16F;
  frame.texture_width = 8;
  frame.texture_height = 9;  // wrong
  EXPECT_EQ(sss_apply_frame(sss_, &frame), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("texture_height"), std::string::npos) << sss_last_error(sss_);
  frame.texture_height = 8;
  frame.depth_format = GL_DEPTH_COMPONENT32F;
  EXPECT_EQ(sss_apply_frame(sss_, &frame), SSS_OK) << sss_last_error(sss_);
  // Outside the lists, or one size without the other: rejected before any GL call.
  frame.depth_format = GL_RGBA8;
  EXPECT_EQ(sss_apply_frame(sss_, &frame), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("frame->depth_format = 0x8058"), std::string::npos)
      << sss_last_error(sss_);
  frame.depth_format = 0;
  frame.texture_width = 0;
  EXPECT_EQ(sss_apply_frame(sss_, &frame), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(read_rgba(color, 8, 8), rgba) << "a rejected frame changed the colour texture";
}

TEST_F(Variant, ARebuildAfterALostContextIsLoggedAtInfo) {
  LogRecord log;
  const SyntheticScene scene = make_relief_scene(16, 12, 2, perspective_matrix(40.0f, 16.0f / 12.0f, 0.1f, 10.0f));
  FilterCase c;
  c.half_color = true;
  const auto frame_on = [&](GLuint color, GLuint depth) {
    sss_frame f = frame_of(color, depth);
    describe_frame(c, 16, 12, &f);
    return f;
  };
  sss_ = create_logged(&log);
  ASSERT_NE(sss_, nullptr);
  ASSERT_EQ(sss_set_camera(sss_, scene.projection.data()), SSS_OK);
  sss_frame f = frame_on(make_rgba16f(16, 12, scene.color), make_depth32f(16, 12, scene.window_depth));
  ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);

  // The context goes (its textures with it) and the host carries on in a new one.
  sss_headless_desc desc = {};
  desc.backend = test_backend();
  desc.major = 3;
  desc.minor = is_gles() ? 0 : 3;
  desc.core_profile = 1;
  sss_headless* next = nullptr;
  char error[512] = "";
  ASSERT_EQ(sss_headless_create(&desc, &next, error, sizeof error), 0) << error;
  textures_.clear();
  sss_headless_destroy(headless_);
  headless_ = next;
  ASSERT_EQ(sss_headless_make_current(headless_), 0);
  ASSERT_TRUE(host_gl::load(sss_headless_get_proc_address, headless_, nullptr));
  f = frame_on(make_rgba16f(16, 12, scene.color), make_depth32f(16, 12, scene.window_depth));
  // The new textures have the old ones' names and description: a steady frame, which would trust
  // the context (sss.h, "GL queries" on sss_frame), unless the host says it changed.
  ASSERT_EQ(sss_gl_context_changed(sss_), SSS_OK);
  EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_ERROR_NO_CONTEXT);
  EXPECT_FALSE(log.has(SSS_LOG_INFO, "rebuilt"));
  EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
  EXPECT_TRUE(log.has(SSS_LOG_INFO, "rebuilt the module's GL objects in the current GL context (shaders in " +
                                        expected_variant(is_gles())));
}

TEST_F(Variant, Glsl330OnAGl33ContextMatchesTheCpuModel) {
  if (is_gles()) GTEST_SKIP() << "desktop GL only";
  // A desktop context that says it is OpenGL 3.3 (llvmpipe gives 4.5 for any request), so that the
  // GLSL 330 variant runs.
  loader_override_ = loader_telling(GL_VERSION, "3.3 (Core Profile) as told by the test", sss_headless_get_proc_address);
  FilterCase c;
  sss_default_settings(&c.settings);
  c.settings.world_units_per_mm = 0.045f;
  c.depth = DepthKind::depth24_stencil8;
  c.use_stencil = true;
  const FilterOutcome o = run_case(make_relief_scene(64, 48, 3, perspective_matrix(40.0f, 64.0f / 48.0f, 0.1f, 10.0f)), c);
  ASSERT_EQ(o.result, SSS_OK);
  sss_stats st = {};
  st.struct_size = sizeof st;
  ASSERT_EQ(sss_get_stats(sss_, &st), SSS_OK);
  EXPECT_EQ(st.glsl_variant, static_cast<uint32_t>(SSS_GLSL_330_CORE));
  EXPECT_LE(largest_relative_difference(o.gpu, o.cpu), 3e-3f);  // as matches_cpu_model_test.cpp
  EXPECT_GT(largest_relative_difference(o.gpu, o.input), 0.02f);
}

class Gles : public Variant {
 protected:
  void SetUp() override {
    Variant::SetUp();
    if (!is_gles()) GTEST_SKIP() << "OpenGL ES only (backend egl-gles)";
  }
};

TEST_F(Gles, WithoutTheDescriptionApplyFailsNamingTheFieldAndChangesNothing) {
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  GLuint color = 0, depth = 0;
  const std::vector<float> rgba = flat_frame(&color, &depth);
  EXPECT_EQ(sss_apply(sss_, color, depth, nullptr), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("frame->color_format"), std::string::npos) << sss_last_error(sss_);
  sss_frame frame = frame_of(color, depth);
  frame.color_format = GL_RGBA16F;
  frame.texture_width = frame.texture_height = 8;
  EXPECT_EQ(sss_apply_frame(sss_, &frame), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("frame->depth_format"), std::string::npos) << sss_last_error(sss_);
  // A size above GL_MAX_TEXTURE_SIZE cannot be true.
  frame.depth_format = GL_DEPTH_COMPONENT32F;
  frame.texture_width = 1 << 30;
  EXPECT_EQ(sss_apply_frame(sss_, &frame), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("GL_MAX_TEXTURE_SIZE"), std::string::npos) << sss_last_error(sss_);
  EXPECT_EQ(read_rgba(color, 8, 8), rgba);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  frame.texture_width = 8;
  EXPECT_EQ(sss_apply_frame(sss_, &frame), SSS_OK) << sss_last_error(sss_);
}

TEST_F(Gles, EveryStateOfTheEsListIsRestored) {
  // The ES list of sss.h, set to unusual values (the desktop-only states do not exist here).
  const SyntheticScene scene = make_relief_scene(32, 24, 3, perspective_matrix(40.0f, 32.0f / 24.0f, 0.1f, 10.0f));
  FilterCase c;
  c.settings.struct_size = sizeof c.settings;
  sss_default_settings(&c.settings);
  c.settings.world_units_per_mm = 0.03f;
  c.depth = DepthKind::depth24_stencil8;
  c.use_stencil = true;

  GLuint program = make_host_program(true);
  glUseProgram(program);
  GLuint vao = 0, fbos[2] = {0, 0}, rb = 0, buffer = 0, samplers[3] = {0, 0, 0};
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenFramebuffers(2, fbos);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbos[0]);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbos[1]);
  glGenRenderbuffers(1, &rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buffer);
  glBufferData(GL_PIXEL_UNPACK_BUFFER, 64, nullptr, GL_STREAM_DRAW);
  glGenSamplers(3, samplers);
  for (GLenum unit = 0; unit < 3; ++unit) {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, make_rgba16f(2, 2, std::vector<float>(16, 1.0f)));
    glBindSampler(unit, samplers[unit]);
  }
  glActiveTexture(GL_TEXTURE4);
  glViewport(3, 5, 17, 19);
  for (GLenum cap : {GL_SCISSOR_TEST, GL_DEPTH_TEST, GL_STENCIL_TEST, GL_BLEND, GL_CULL_FACE, GL_RASTERIZER_DISCARD,
                     GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_COVERAGE, GL_SAMPLE_MASK, GL_POLYGON_OFFSET_FILL}) {
    glEnable(cap);
  }
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
  glStencilFuncSeparate(GL_FRONT, GL_GREATER, 7, 0x3C);
  glStencilOpSeparate(GL_FRONT, GL_INCR, GL_DECR, GL_INVERT);
  glStencilMaskSeparate(GL_FRONT, 0x0F);
  glStencilFuncSeparate(GL_BACK, GL_LESS, 3, 0xF0);
  glStencilOpSeparate(GL_BACK, GL_ZERO, GL_REPLACE, GL_INCR_WRAP);
  glStencilMaskSeparate(GL_BACK, 0xF0);
  ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));

  const Snapshot before = take_snapshot(true);
  ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << "the snapshot asked for a state ES does not have";
  const FilterOutcome o = run_case(scene, c);  // reads back through its own framebuffer, restoring it
  ASSERT_EQ(o.result, SSS_OK);
  const Snapshot after = take_snapshot(true);
  EXPECT_EQ(describe_differences(before, after), "");
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  // The state did not change the result either.
  EXPECT_LE(largest_relative_difference(o.gpu, o.cpu), 3e-3f);  // as matches_cpu_model_test.cpp

  glUseProgram(0);
  glDeleteProgram(program);
  glBindVertexArray(0);
  glDeleteVertexArrays(1, &vao);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(2, fbos);
  glDeleteRenderbuffers(1, &rb);
  glDeleteBuffers(1, &buffer);
  glDeleteSamplers(3, samplers);
}

}  // namespace
}  // namespace sss_test
