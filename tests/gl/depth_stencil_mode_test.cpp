// A host that samples the stencil of its depth-stencil texture leaves that texture's
// GL_DEPTH_STENCIL_TEXTURE_MODE on GL_STENCIL_INDEX (GL 4.3+, ES 3.1+); the module's depth fetches
// would then read stencil indices. The module reads the mode (the frame's word, sss_frame
// depth_stencil_mode, or the GL's answer for a frame that does not describe its textures), switches
// it to GL_DEPTH_COMPONENT for its passes and puts the host's value back: the result is the one the
// default mode gives, and the texture's mode is as the host left it, with or without state restore.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "fault_loader.hpp"
#include "filter_case.hpp"
#include "gl_state_snapshot.hpp"
#include "multisample_textures.hpp"

using namespace host_gl;

namespace sss_test {
namespace {

constexpr int kW = 40, kH = 32;
const sss::math::Matrix4 kCamera = perspective_matrix(40.0f, float(kW) / float(kH), 0.1f, 10.0f);

class DepthStencilMode : public GlTest {
 protected:
  void SetUp() override {
    reset_faults();
    GlTest::SetUp();
    if (HasFatalFailure()) return;
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    if (major * 10 + minor < (is_gles() ? 31 : 43)) GTEST_SKIP() << "no GL_DEPTH_STENCIL_TEXTURE_MODE on this GL";
    scene_ = make_relief_scene(kW, kH, 5, kCamera);
    std::vector<uint32_t> packed(scene_.window_depth.size());
    for (std::size_t i = 0; i < packed.size(); ++i) {
      packed[i] = (static_cast<uint32_t>(scene_.window_depth[i] * 16777215.0f) << 8) | (scene_.stencil[i] ? 0xC8u : 0u);
    }
    depth_ = make_texture(GL_DEPTH24_STENCIL8, kW, kH, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, packed.data());
  }
  void TearDown() override {
    reset_faults();
    GlTest::TearDown();
  }

  void start(uint32_t flags) {
    sss_ = create_sss(flags);
    ASSERT_NE(sss_, nullptr);
    sss_settings s;
    sss_default_settings(&s);
    s.world_units_per_mm = 0.05f;
    s.flags = SSS_FOLLOW_SURFACE;  // the depth decides which taps count
    ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK);
    ASSERT_EQ(sss_set_camera(sss_, kCamera.data()), SSS_OK);
  }
  void set_mode(GLint mode) {
    glBindTexture(GL_TEXTURE_2D, depth_);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_STENCIL_TEXTURE_MODE, mode);
    glBindTexture(GL_TEXTURE_2D, 0);
  }
  GLint mode() {
    glBindTexture(GL_TEXTURE_2D, depth_);
    GLint m = 0;
    glGetTexParameteriv(GL_TEXTURE_2D, GL_DEPTH_STENCIL_TEXTURE_MODE, &m);
    glBindTexture(GL_TEXTURE_2D, 0);
    return m;
  }
  // The filter of the scene into a fresh output; `stated`: sss_frame.depth_stencil_mode (with the
  // frame described, as OpenGL ES 3.0 requires: the module then asks the GL nothing).
  std::vector<float> apply(uint32_t stated, bool describe) {
    const GLuint color = make_rgba32f(kW, kH, scene_.color);
    const GLuint output = make_rgba32f(kW, kH, std::vector<float>(kW * kH * 4, -1.0f));
    sss_frame f = frame_of(color, depth_, output);
    f.depth_stencil_mode = stated;
    if (describe) {
      f.color_format = f.output_format = GL_RGBA32F;
      f.depth_format = GL_DEPTH24_STENCIL8;
      f.texture_width = kW;
      f.texture_height = kH;
    }
    EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    return read_rgba(output, kW, kH);
  }

  SyntheticScene scene_;
  GLuint depth_ = 0;
};

TEST_F(DepthStencilMode, StencilSamplingIsReadAsDepthAndPutBack) {
  start(0);
  ASSERT_FALSE(HasFatalFailure());
  const bool can_ask = !is_gles();  // the ES fixture loads the module as on ES 3.0: frames are described
  const std::vector<float> expected = apply(0, !can_ask);
  ASSERT_EQ(mode(), GL_DEPTH_COMPONENT);
  for (const bool stated : {false, true}) {
    if (!stated && !can_ask) continue;
    SCOPED_TRACE(stated ? "the frame states GL_STENCIL_INDEX" : "the module asks the GL");
    set_mode(GL_STENCIL_INDEX);
    const Snapshot state = take_snapshot(is_gles());
    const std::vector<float> got = apply(stated ? GL_STENCIL_INDEX : 0, stated);
    EXPECT_EQ(mode(), GL_STENCIL_INDEX) << "the host's mode was not put back";
    EXPECT_EQ(describe_differences(state, take_snapshot(is_gles())), "");
    EXPECT_EQ(got, expected) << "the passes read the stencil as depth";
  }
}

TEST_F(DepthStencilMode, ItIsPutBackWithoutStateRestoreToo) {
  start(SSS_CREATE_NO_STATE_RESTORE);
  ASSERT_FALSE(HasFatalFailure());
  const std::vector<float> expected = apply(0, is_gles());
  set_mode(GL_STENCIL_INDEX);
  EXPECT_EQ(apply(GL_STENCIL_INDEX, true), expected);
  EXPECT_EQ(mode(), GL_STENCIL_INDEX);
}

// A described frame whose mode is stated needs no question; an undescribed one is asked once.
TEST_F(DepthStencilMode, OnlyAnUndescribedFrameAsksTheGl) {
  if (is_gles()) GTEST_SKIP() << "the ES fixture's frames are always described";
  loader_override_ = fault_get_proc_address;
  start(0);
  ASSERT_FALSE(HasFatalFailure());
  set_mode(GL_STENCIL_INDEX);
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  // On GL 4.3+ an undescribed frame's colour is also asked whether it is complete (its min filter
  // and base level: the passes' inputs then read it through an image unit), and with the default
  // SSS_PATH_AUTO its target too (the compute path, one of its candidates, may write it): here the
  // separate output (in place one answer would serve both).
  const int completeness = major * 10 + minor >= 43 ? 2 : 0;
  for (const uint32_t path : {static_cast<uint32_t>(SSS_PATH_FRAGMENT), static_cast<uint32_t>(SSS_PATH_AUTO)}) {
    SCOPED_TRACE(path == SSS_PATH_AUTO ? "automatic path (the default)" : "plain fragment path");
    sss_settings s;
    s.struct_size = sizeof s;
    ASSERT_EQ(sss_get_settings(sss_, &s), SSS_OK);
    s.path = path;
    ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK) << sss_last_error(sss_);
    reset_faults();
    apply(GL_STENCIL_INDEX, true);
    EXPECT_EQ(faults().texture_parameter_queries, 0);
    apply(0, false);
    EXPECT_EQ(faults().texture_parameter_queries, 1 + completeness + (path == SSS_PATH_AUTO ? completeness : 0));
  }
}

// The MSAA path's resolve fetches every sample of a multisampled depth-stencil texture: the same.
TEST_F(DepthStencilMode, AMultisampledDepthStencilTextureToo) {
  GLint max_samples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  if (is_gles() || max_samples < 4) GTEST_SKIP() << "the MSAA path is desktop OpenGL only";
  start(0);
  ASSERT_FALSE(HasFatalFailure());
  const SyntheticScene fine = make_relief_scene(2 * kW, 2 * kH, 6, kCamera);
  const GLuint color = make_multisample_texture(GL_RGBA32F, kW, kH, 4, fine.color);
  const GLuint depth = make_multisample_depth_stencil(kW, kH, 4, fine.window_depth, fine.stencil);
  textures_.insert(textures_.end(), {color, depth});
  const auto filtered = [&] {
    const GLuint output = make_rgba32f(kW, kH, std::vector<float>(kW * kH * 4, -1.0f));
    const sss_frame f = frame_of(color, depth, output);
    EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    return read_rgba(output, kW, kH);
  };
  const std::vector<float> expected = filtered();
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, depth);
  glTexParameteri(GL_TEXTURE_2D_MULTISAMPLE, GL_DEPTH_STENCIL_TEXTURE_MODE, GL_STENCIL_INDEX);
  EXPECT_EQ(filtered(), expected);
  GLint m = 0;
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, depth);
  glGetTexParameteriv(GL_TEXTURE_2D_MULTISAMPLE, GL_DEPTH_STENCIL_TEXTURE_MODE, &m);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
  EXPECT_EQ(m, GL_STENCIL_INDEX);
}

TEST_F(DepthStencilMode, AValueOutsideTheListIsRefused) {
  start(0);
  ASSERT_FALSE(HasFatalFailure());
  const GLuint color = make_rgba32f(kW, kH, scene_.color);
  sss_frame f = frame_of(color, depth_);
  f.color_format = GL_RGBA32F;
  f.depth_format = GL_DEPTH24_STENCIL8;
  f.texture_width = kW;
  f.texture_height = kH;
  f.depth_stencil_mode = GL_DEPTH_STENCIL;
  EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("depth_stencil_mode"), std::string::npos) << sss_last_error(sss_);
}

}  // namespace
}  // namespace sss_test
