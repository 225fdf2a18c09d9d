// Bad input gets a specific code and a message naming the argument and its value; the host's
// textures stay as they were and no GL error is left behind.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

#include "filter_case.hpp"

using namespace host_gl;

namespace sss_test {
namespace {

const sss::math::Matrix4 kCamera = perspective_matrix(45.0f, 1.0f, 0.1f, 10.0f);

class BadInput : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    if (HasFatalFailure()) return;
    sss_ = create_sss();
    ASSERT_NE(sss_, nullptr);
    ASSERT_EQ(sss_set_camera(sss_, kCamera.data()), SSS_OK);
    scene_ = make_relief_scene(8, 8, 1, kCamera);
    color_ = make_rgba32f(8, 8, scene_.color);
    depth_ = make_depth32f(8, 8, scene_.window_depth);
  }

  // Applies, expects `code` with `fragment` in the message, and checks nothing changed.
  void expect_apply_fails(const sss_frame& frame, sss_result code, const std::string& fragment) {
    const std::vector<float> before = read_rgba(color_, 8, 8);
    EXPECT_EQ(sss_apply_frame(sss_, &frame), code) << sss_last_error(sss_);
    const std::string message = sss_last_error(sss_);
    EXPECT_NE(message.find(fragment), std::string::npos) << message;
    EXPECT_NE(message.find(sss_result_string(code)), std::string::npos) << message;
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    const std::vector<float> after = read_rgba(color_, 8, 8);
    EXPECT_EQ(0, std::memcmp(before.data(), after.data(), before.size() * sizeof(float)));
  }

  sss_frame frame(GLuint color, GLuint depth) const {
    sss_frame f = frame_of(color, depth);
    return f;
  }

  SyntheticScene scene_;
  GLuint color_ = 0, depth_ = 0;
};

TEST_F(BadInput, NullContextAndNullArguments) {
  EXPECT_EQ(sss_apply(nullptr, color_, depth_, nullptr), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(nullptr)).find("ctx is NULL"), std::string::npos);
  EXPECT_EQ(sss_apply_frame(sss_, nullptr), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("frame is NULL"), std::string::npos);
  EXPECT_EQ(sss_set_settings(nullptr, nullptr), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(sss_set_camera(sss_, nullptr), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("projection is NULL"), std::string::npos);
  sss_frame f = frame(color_, depth_);
  f.struct_size = 3;
  expect_apply_fails(f, SSS_ERROR_INVALID_ARGUMENT, "frame->struct_size = 3");
  f = frame(color_, depth_);
  f.flags = 0x80;
  expect_apply_fails(f, SSS_ERROR_INVALID_ARGUMENT, "frame->flags = 0x80");
}

TEST_F(BadInput, TextureZeroAndNamesThatAreNotTextures) {
  expect_apply_fails(frame(0, depth_), SSS_ERROR_INVALID_TEXTURE, "color_texture is 0");
  expect_apply_fails(frame(color_, 0), SSS_ERROR_INVALID_TEXTURE, "depth_texture is 0");
  expect_apply_fails(frame(424242, depth_), SSS_ERROR_INVALID_TEXTURE, "color_texture = 424242 is not a texture name");
  GLuint generated_never_bound = 0;
  glGenTextures(1, &generated_never_bound);
  textures_.push_back(generated_never_bound);
  expect_apply_fails(frame(color_, generated_never_bound), SSS_ERROR_INVALID_TEXTURE, "is not a texture name");
  EXPECT_FALSE(glIsTexture(generated_never_bound)) << "the check must not create the texture";
}

TEST_F(BadInput, WrongTarget) {
  GLuint cube = 0;
  glGenTextures(1, &cube);
  textures_.push_back(cube);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  expect_apply_fails(frame(cube, depth_), SSS_ERROR_INVALID_TEXTURE,
                     "is neither GL_TEXTURE_2D nor GL_TEXTURE_2D_MULTISAMPLE");
}

TEST_F(BadInput, WrongFormats) {
  const GLuint rgba8 = make_texture(GL_RGBA8, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  expect_apply_fails(frame(rgba8, depth_), SSS_ERROR_INVALID_TEXTURE, "color_texture = " + std::to_string(rgba8) + " has format");
  expect_apply_fails(frame(color_, color_), SSS_ERROR_INVALID_TEXTURE, "depth_texture = " + std::to_string(color_) + " has format GL_RGBA32F");
  sss_stencil stencil = {depth_, 1, 0xFF};  // DEPTH_COMPONENT32F has no stencil
  sss_frame f = frame(color_, depth_);
  f.stencil = &stencil;
  expect_apply_fails(f, SSS_ERROR_INVALID_TEXTURE, "stencil->depth_stencil_texture");
  f = frame(color_, depth_);
  f.output_texture = rgba8;
  expect_apply_fails(f, SSS_ERROR_INVALID_TEXTURE, "output_texture");
}

TEST_F(BadInput, SizeMismatch) {
  const GLuint wide_depth = make_depth32f(16, 8, std::vector<float>(128, 0.5f));
  expect_apply_fails(frame(color_, wide_depth), SSS_ERROR_INVALID_TEXTURE, "is 16x8 but the colour texture is 8x8");
  sss_frame f = frame(color_, depth_);
  f.viewport[0] = 4;
  f.viewport[2] = 8;
  f.viewport[3] = 8;
  expect_apply_fails(f, SSS_ERROR_INVALID_ARGUMENT, "reaches outside the 8x8 colour texture");
  f.viewport[2] = -1;
  expect_apply_fails(f, SSS_ERROR_INVALID_ARGUMENT, "frame->viewport = {4, 0, -1, 8}");
}

TEST_F(BadInput, OutputEqualToColourAndBadStencilValues) {
  sss_frame f = frame(color_, depth_);
  f.output_texture = color_;
  expect_apply_fails(f, SSS_ERROR_INVALID_ARGUMENT, "is the colour texture");
  sss_stencil stencil = {depth_, 300, 0xFF};
  f = frame(color_, depth_);
  f.stencil = &stencil;
  expect_apply_fails(f, SSS_ERROR_INVALID_ARGUMENT, "stencil ref = 300");
}

TEST_F(BadInput, SettingsOutOfRangeKeepThePreviousSettings) {
  sss_settings good;
  sss_default_settings(&good);
  good.world_units_per_mm = 0.01f;
  ASSERT_EQ(sss_set_settings(sss_, &good), SSS_OK);
  struct Case {
    void (*mutate)(sss_settings*);
    const char* fragment;
  };
  const Case cases[] = {
      {[](sss_settings* s) { s->taps = 16; }, "settings->taps = 16"},
      {[](sss_settings* s) { s->taps = 1; }, "settings->taps = 1"},
      {[](sss_settings* s) { s->taps = 67; }, "settings->taps = 67"},
      {[](sss_settings* s) { s->world_units_per_mm = NAN; }, "settings->world_units_per_mm = nan"},
      {[](sss_settings* s) { s->world_units_per_mm = -1.0f; }, "settings->world_units_per_mm = -1"},
      {[](sss_settings* s) { s->world_units_per_mm = INFINITY; }, "settings->world_units_per_mm = inf"},
      {[](sss_settings* s) { s->strength[2] = 1.01f; }, "settings->strength[2] = 1.01"},
      {[](sss_settings* s) { s->falloff[0] = -0.5f; }, "settings->falloff[0] = -0.5"},
      {[](sss_settings* s) { s->flags = 0x40; }, "settings->flags = 0x40"},
      {[](sss_settings* s) { s->struct_size = 8; }, "settings->struct_size = 8"},
  };
  for (const Case& c : cases) {
    sss_settings s = good;
    c.mutate(&s);
    const sss_settings now = expect_settings_refused(sss_, s, c.fragment);
    EXPECT_EQ(now.world_units_per_mm, good.world_units_per_mm);
    EXPECT_EQ(now.taps, good.taps);
  }
}

TEST_F(BadInput, SingularOrUnsupportedProjections) {
  float zero[16] = {};
  EXPECT_EQ(sss_set_camera(sss_, zero), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("singular"), std::string::npos);
  sss::math::Matrix4 m = kCamera;
  m[14] = 0.0f;
  EXPECT_EQ(sss_set_camera(sss_, m.data()), SSS_ERROR_INVALID_ARGUMENT);
  m = kCamera;
  m[10] = NAN;
  EXPECT_EQ(sss_set_camera(sss_, m.data()), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("projection[10] = nan"), std::string::npos);
  m = kCamera;
  m[3] = 0.5f;
  EXPECT_EQ(sss_set_camera(sss_, m.data()), SSS_ERROR_UNSUPPORTED);
}

TEST_F(BadInput, ApplyBeforeAnyCamera) {
  sss_context* fresh = create_sss();
  ASSERT_NE(fresh, nullptr);
  EXPECT_EQ(sss_apply(fresh, color_, depth_, nullptr), SSS_ERROR_INVALID_OPERATION);
  EXPECT_NE(std::string(sss_last_error(fresh)).find("sss_set_camera"), std::string::npos);
  sss_destroy(fresh);
}

TEST_F(BadInput, NoCurrentContext) {
  ASSERT_EQ(sss_headless_release_current(headless_), 0);
  sss_create_desc desc = {};
  desc.struct_size = sizeof desc;
  desc.get_proc_address = sss_headless_get_proc_address;
  desc.get_proc_address_user = headless_;
  sss_context* ctx = reinterpret_cast<sss_context*>(0x1);
  EXPECT_EQ(sss_create(&desc, &ctx), SSS_ERROR_NO_CONTEXT);
  EXPECT_EQ(ctx, nullptr);
  EXPECT_NE(std::string(sss_last_error(nullptr)).find("no GL context is current"), std::string::npos);
  EXPECT_EQ(sss_apply(sss_, color_, depth_, nullptr), SSS_ERROR_NO_CONTEXT);
  ASSERT_EQ(sss_headless_make_current(headless_), 0);
  EXPECT_EQ(sss_apply(sss_, color_, depth_, nullptr), SSS_OK) << sss_last_error(sss_);
}

// A loader that lies: it reports an old GL version, or withholds one function.
struct LyingLoader {
  sss_headless* headless;
  const char* withheld;
};
const GLubyte* APIENTRY old_version_string(GLenum name) {
  return reinterpret_cast<const GLubyte*>(name == GL_VERSION ? "3.0 Mesa 22.3.6" : "fake");
}
void* old_version_loader(const char* name, void* user) {
  if (std::strcmp(name, "glGetString") == 0) {
    PFNGLGETSTRINGPROC fn = old_version_string;
    void* address = nullptr;
    std::memcpy(&address, &fn, sizeof address);
    return address;
  }
  return sss_headless_get_proc_address(name, static_cast<LyingLoader*>(user)->headless);
}
void* withholding_loader(const char* name, void* user) {
  const auto* loader = static_cast<LyingLoader*>(user);
  if (std::strcmp(name, loader->withheld) == 0) return nullptr;
  return sss_headless_get_proc_address(name, loader->headless);
}

TEST_F(BadInput, VersionBelow33AndMissingFunctions) {
  LyingLoader loader = {headless_, "glGenSamplers"};
  sss_create_desc desc = {};
  desc.struct_size = sizeof desc;
  desc.get_proc_address = old_version_loader;
  desc.get_proc_address_user = &loader;
  sss_context* ctx = nullptr;
  EXPECT_EQ(sss_create(&desc, &ctx), SSS_ERROR_UNSUPPORTED);
  EXPECT_NE(std::string(sss_last_error(nullptr)).find("\"3.0 Mesa 22.3.6\": OpenGL 3.3 or newer is required"),
            std::string::npos)
      << sss_last_error(nullptr);
  desc.get_proc_address = withholding_loader;
  EXPECT_EQ(sss_create(&desc, &ctx), SSS_ERROR_GL_FUNCTION_MISSING);
  EXPECT_NE(std::string(sss_last_error(nullptr)).find("glGenSamplers"), std::string::npos);
  EXPECT_EQ(ctx, nullptr);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(BadInput, CreateDescriptorChecks) {
  sss_context* ctx = nullptr;
  EXPECT_EQ(sss_create(nullptr, &ctx), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(nullptr)).find("desc is NULL"), std::string::npos);
  sss_create_desc desc = {};
  desc.struct_size = sizeof desc;
  EXPECT_EQ(sss_create(&desc, &ctx), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(nullptr)).find("get_proc_address is NULL"), std::string::npos);
  desc.get_proc_address = sss_headless_get_proc_address;
  desc.get_proc_address_user = headless_;
  desc.flags = 0x100;
  EXPECT_EQ(sss_create(&desc, &ctx), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(nullptr)).find("desc->flags = 0x100"), std::string::npos);
  desc.flags = 0;
  desc.struct_size = 4;
  EXPECT_EQ(sss_create(&desc, &ctx), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(sss_create(&desc, nullptr), SSS_ERROR_INVALID_ARGUMENT);
}

TEST_F(BadInput, TheHostsPendingErrorIsClearedAndLogged) {
  std::string logged;
  sss_create_desc desc = {};
  desc.struct_size = sizeof desc;
  desc.get_proc_address = sss_headless_get_proc_address;
  desc.get_proc_address_user = headless_;
  desc.log = [](int level, const char* message, void* user) {
    if (level == SSS_LOG_WARNING) *static_cast<std::string*>(user) += message;
  };
  desc.log_user = &logged;
  sss_context* ctx = nullptr;
  ASSERT_EQ(sss_create(&desc, &ctx), SSS_OK);
  ASSERT_EQ(sss_set_camera(ctx, kCamera.data()), SSS_OK);
  glEnable(0x1234);  // GL_INVALID_ENUM, left pending by the "host"
  EXPECT_EQ(sss_apply(ctx, color_, depth_, nullptr), SSS_OK) << sss_last_error(ctx);
  EXPECT_NE(logged.find("GL_INVALID_ENUM"), std::string::npos) << logged;
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  sss_destroy(ctx);
}

}  // namespace
}  // namespace sss_test
