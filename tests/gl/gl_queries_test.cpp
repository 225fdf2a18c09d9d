// No stall (issue 22): a steady frame makes no GL query. Each glGet*, glIs*, glGetError or
// glCheckFramebufferStatus is a round trip that stalls a threaded driver (Mesa's glthread, NVIDIA's
// threaded optimisation), so a frame whose textures the frame describes (formats and size) and that
// repeats the last successful one asks the GL nothing with SSS_CREATE_NO_STATE_RESTORE, and with
// state restore only reads the part of the state list that its path can change. Counted through the
// loader (support/counting_loader.hpp): every query and creation function the module loads is
// wrapped, and only the module's calls go through it.
//   GlQueries.*  every backend, egl-gles included (the ES 3.0 path, whose frames are described anyway)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "counting_loader.hpp"
#include "filter_case.hpp"
#include "gl_state_snapshot.hpp"

using namespace host_gl;

namespace sss_test {
namespace {

constexpr int kWidth = 32, kHeight = 24;
constexpr int kSteadyFrames = 5;

class GlQueries : public FilterCaseTest {
 protected:
  void SetUp() override {
    FilterCaseTest::SetUp();
    scene_ = make_relief_scene(kWidth, kHeight, 5, perspective_matrix(40.0f, 32.0f / 24.0f, 0.1f, 10.0f));
    color_ = make_rgba16f(kWidth, kHeight, scene_.color);
    depth_ = make_depth32f(kWidth, kHeight, scene_.window_depth);
  }

  // A context whose GL goes through the counting loader (on ES through the ES 3.0 loader, like
  // every other test there).
  void start(uint32_t flags) {
    loader_override_ = counting_loader(is_gles() ? es30_get_proc_address : sss_headless_get_proc_address);
    sss_ = create_sss(flags);
    loader_override_ = nullptr;
    ASSERT_NE(sss_, nullptr);
    settings_ = visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f);
    // The plain fragment path unless a case names another: the counts below are its own. The
    // default, SSS_PATH_AUTO, reads more (ADescribedSteadyFrameWithStateRestore... says what).
    settings_.path = SSS_PATH_FRAGMENT;
    ASSERT_EQ(sss_set_settings(sss_, &settings_), SSS_OK) << sss_last_error(sss_);
    ASSERT_EQ(sss_set_camera(sss_, scene_.projection.data()), SSS_OK);
  }

  // The colour and depth of the scene, in place, described (formats and size).
  sss_frame described_frame() const {
    sss_frame f = frame_of(color_, depth_);
    FilterCase c;
    c.half_color = true;
    describe_frame(c, kWidth, kHeight, &f);
    return f;
  }

  // The calls of `frames` frames after two that make the objects and set the steady state.
  GlCallCounts steady_counts(const sss_frame& f, int frames = kSteadyFrames) {
    EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
    EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
    reset_call_counts();
    for (int i = 0; i < frames; ++i) EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
    return call_counts();
  }

  // A DEPTH24_STENCIL8 of the scene's depth, stencil 1 where the scene is translucent.
  GLuint make_depth_stencil() {
    std::vector<uint32_t> packed(scene_.window_depth.size());
    for (std::size_t i = 0; i < packed.size(); ++i) {
      const auto d24 = static_cast<uint32_t>(std::lround(scene_.window_depth[i] * 16777215.0));
      packed[i] = (d24 << 8) | (scene_.stencil[i] ? 1u : 0u);
    }
    return make_texture(GL_DEPTH24_STENCIL8, kWidth, kHeight, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, packed.data());
  }

  SyntheticScene scene_;
  sss_settings settings_{};
  GLuint color_ = 0, depth_ = 0;
};

// Per frame, "glGetIntegerv 15, glIsEnabled 21" for messages.
std::string per_frame(const std::map<std::string, long>& calls, int frames) {
  std::string out;
  for (const auto& [name, n] : calls) {
    out += (out.empty() ? "" : ", ") + name + " " + std::to_string(n / frames) + (n % frames != 0 ? "+" : "");
  }
  return out.empty() ? "none" : out;
}

// Two views in one context, each frame carrying its own projection (sss_frame.projection), and the
// jitter's noise index moving every frame: the frames stay steady, the module asks the GL nothing.
TEST_F(GlQueries, TwoViewsTakingTurnsWithTheirOwnProjectionsMakeNone) {
  start(SSS_CREATE_NO_STATE_RESTORE);
  if (HasFatalFailure()) return;
  sss_settings s = settings_;
  s.jitter = 0.5f;
  ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK) << sss_last_error(sss_);
  const sss::math::Matrix4 left = perspective_matrix(40.0f, 32.0f / 24.0f, 0.1f, 10.0f);
  const sss::math::Matrix4 right = perspective_matrix(44.0f, 32.0f / 24.0f, 0.1f, 10.0f);
  sss_frame f = described_frame();
  for (int i = 0; i < 2; ++i) {
    f.projection = (i % 2 == 0 ? left : right).data();
    ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
  }
  reset_call_counts();
  for (uint32_t i = 0; i < 2 * kSteadyFrames; ++i) {
    f.projection = (i % 2 == 0 ? left : right).data();
    f.noise_index = i;
    ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
  }
  const GlCallCounts n = call_counts();
  EXPECT_EQ(n.total_queries(), 0) << n.describe_queries();
  EXPECT_EQ(n.total_creations(), 0) << n.describe_creations();
}

TEST_F(GlQueries, ADescribedSteadyFrameWithoutStateRestoreMakesNone) {
  start(SSS_CREATE_NO_STATE_RESTORE);
  if (HasFatalFailure()) return;
  const GLuint output = make_rgba32f(kWidth, kHeight, scene_.color);
  const GLuint depth_stencil = make_depth_stencil();
  sss_stencil stencil = {depth_stencil, 1, 0xFF};
  struct Case {
    const char* name;
    uint32_t path = SSS_PATH_FRAGMENT, mode = SSS_MODE_SEPARABLE;
    GLuint output = 0;
    bool region = false, stencil = false, two_terms = false;
    bool stencil_sampling = false;  // the depth-stencil texture on GL_STENCIL_INDEX, stated in the frame
  };
  std::vector<Case> cases = {
      {"in place"},
      {"separate output", SSS_PATH_FRAGMENT, SSS_MODE_SEPARABLE, output},
      {"region, separate output", SSS_PATH_FRAGMENT, SSS_MODE_SEPARABLE, output, true},
      {"host stencil", SSS_PATH_FRAGMENT, SSS_MODE_SEPARABLE, 0, false, true},
      {"kernel of two terms (SVD rank 2)", SSS_PATH_FRAGMENT, SSS_MODE_SEPARABLE, 0, false, false, true},
      {"masked fragment path", SSS_PATH_FRAGMENT_MASKED},
      {"half-resolution path", SSS_PATH_HALF_RESOLUTION},
      {"cross-bilateral mode", SSS_PATH_FRAGMENT, SSS_MODE_CROSS_BILATERAL},
      // A described frame's target counts as incomplete unless SSS_FRAME_TARGET_COMPLETE says
      // otherwise: without the flag this would silently count the fragment path.
      {"compute path (where the context has it)", SSS_PATH_COMPUTE},
      // The module switches the texture to depth sampling and back: no query either.
      {"host stencil on stencil sampling (GL 4.3+, ES 3.1+)", SSS_PATH_FRAGMENT, SSS_MODE_SEPARABLE, 0, false, true,
       false, true},
  };
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  const int version = major * 10 + minor;
  const bool has_compute = !is_gles() && version >= 43;
  const bool has_stencil_sampling = version >= (is_gles() ? 31 : 43);
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    if (c.stencil_sampling && !has_stencil_sampling) continue;
    const sss_settings s = path_case_settings(settings_, c.path, c.mode, c.two_terms);
    ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK) << sss_last_error(sss_);
    sss_frame f = frame_of(color_, c.stencil ? depth_stencil : depth_, c.output);
    f.stencil = c.stencil ? &stencil : nullptr;
    if (c.region) {
      f.flags = SSS_FRAME_REGION;
      f.region[0] = 3;
      f.region[1] = 2;
      f.region[2] = 20;
      f.region[3] = 18;
    }
    if (c.path == SSS_PATH_COMPUTE) f.flags |= SSS_FRAME_TARGET_COMPLETE;
    if (c.stencil_sampling) {
      f.depth_stencil_mode = GL_STENCIL_INDEX;
      glBindTexture(GL_TEXTURE_2D, depth_stencil);
      glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_STENCIL_TEXTURE_MODE, GL_STENCIL_INDEX);
      glBindTexture(GL_TEXTURE_2D, 0);
    }
    FilterCase description;
    description.half_color = true;
    description.depth = c.stencil ? DepthKind::depth24_stencil8 : DepthKind::depth32f;
    describe_frame(description, kWidth, kHeight, &f);
    const GlCallCounts n = steady_counts(f);
    sss_stats stats = {};
    stats.struct_size = sizeof stats;
    ASSERT_EQ(sss_get_stats(sss_, &stats), SSS_OK);
    if (c.path == SSS_PATH_COMPUTE) {
      EXPECT_EQ(stats.last_frame_path, has_compute ? SSS_PATH_COMPUTE : SSS_PATH_FRAGMENT);
    }
    if (c.stencil_sampling) {
      GLint mode = 0;
      glBindTexture(GL_TEXTURE_2D, depth_stencil);
      glGetTexParameteriv(GL_TEXTURE_2D, GL_DEPTH_STENCIL_TEXTURE_MODE, &mode);
      glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_STENCIL_TEXTURE_MODE, GL_DEPTH_COMPONENT);
      glBindTexture(GL_TEXTURE_2D, 0);
      EXPECT_EQ(mode, GL_STENCIL_INDEX) << "the host's sampling mode is put back";
    }
    std::printf("[ counts   ] %-40s queries per steady frame: %s\n", c.name, per_frame(n.queries, kSteadyFrames).c_str());
    EXPECT_EQ(n.total_queries(), 0) << "queries in " << kSteadyFrames << " steady frames: " << n.describe_queries();
    EXPECT_EQ(n.total_creations(), 0) << "creations in " << kSteadyFrames << " steady frames: " << n.describe_creations();
  }
}

// An R11F_G11F_B10F colour with its strength in an R8 texture (sss_frame.strength_texture): the
// colour and strength are drawn into the module's copy every frame, with no query either.
TEST_F(GlQueries, ASteadyFrameWithAStrengthTextureMakesNone) {
  start(SSS_CREATE_NO_STATE_RESTORE);
  if (HasFatalFailure()) return;
  std::vector<float> rgb;
  std::vector<uint8_t> strength;
  for (std::size_t i = 0; i < scene_.color.size(); ++i) {
    if (i % 4 != 3) rgb.push_back(scene_.color[i]);
    if (i % 4 == 3) strength.push_back(static_cast<uint8_t>(std::lround(scene_.color[i] * 255.0f)));
  }
  const GLuint color = make_texture(GL_R11F_G11F_B10F, kWidth, kHeight, GL_RGB, GL_FLOAT, rgb.data());
  const GLuint mask = make_texture(GL_R8, kWidth, kHeight, GL_RED, GL_UNSIGNED_BYTE, strength.data());
  for (uint32_t path : {SSS_PATH_FRAGMENT, SSS_PATH_FRAGMENT_MASKED, SSS_PATH_COMPUTE}) {
    SCOPED_TRACE(path);
    const sss_settings s = path_case_settings(settings_, path, SSS_MODE_SEPARABLE, false);
    ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK) << sss_last_error(sss_);
    sss_frame f = frame_of(color, depth_);
    FilterCase description;
    describe_frame(description, kWidth, kHeight, &f);
    f.color_format = GL_R11F_G11F_B10F;
    f.strength_texture = mask;
    f.strength_format = GL_R8;
    f.flags = SSS_FRAME_TARGET_COMPLETE;
    const GlCallCounts n = steady_counts(f);
    std::printf("[ counts   ] strength texture, path %u: queries per steady frame: %s\n", path,
                per_frame(n.queries, kSteadyFrames).c_str());
    EXPECT_EQ(n.total_queries(), 0) << "queries in " << kSteadyFrames << " steady frames: " << n.describe_queries();
    EXPECT_EQ(n.total_creations(), 0) << "creations in " << kSteadyFrames << " steady frames: " << n.describe_creations();
  }
}

// What the state guard reads in a steady in-place frame of the plain fragment path with one kernel
// term and no stencil, on this context: the list in sss.h less what that frame cannot change (stencil
// func, ref, masks and ops: only a stencil mask; the multisample bindings, GL_SAMPLE_MASK_VALUE and
// GL_MULTISAMPLE: only the MSAA path, whose write-back alone draws into a multisampled target;
// texture unit 3: only normals and kernels of several terms), with the host's program 0 (a current
// one adds its glIsProgram). `image_units`: the context has them (desktop GL 4.3+), where the
// fragment passes read their taps through image unit 0, so its name, level, layer, access and
// format and whether it is layered are read too.
std::map<std::string, long> expected_guard_reads(bool es, int es_minor, bool image_units) {
  long integers = 7;   // program, vertex array, draw and read framebuffer, renderbuffer, unpack buffer, active texture
  integers += 3 * 2;   // units 0-2: GL_TEXTURE_BINDING_2D and GL_SAMPLER_BINDING
  integers += 1;       // GL_VIEWPORT
  long enables = 9;    // scissor, depth, stencil, blend, cull face, rasterizer discard, alpha to coverage,
                       // sample coverage, polygon offset fill
  if (!es || es_minor >= 1) enables += 1;  // GL_SAMPLE_MASK (GL 3.2+, ES 3.1+)
  if (!es) {
    enables += 3 + 8;  // sRGB, depth clamp, logic op; clip distances 0-7
    integers += 1;     // GL_POLYGON_MODE
  }
  integers += 1;       // GL_DEPTH_FUNC: the fragment passes cull by the module's depth (issue 24)
  // GL_COLOR_WRITEMASK and GL_DEPTH_WRITEMASK; GL_DEPTH_RANGE.
  std::map<std::string, long> reads = {
      {"glGetBooleanv", 2}, {"glGetFloatv", 1}, {"glGetIntegerv", integers}, {"glIsEnabled", enables}};
  if (image_units) {  // image units 0 (the taps) and 1 (the strength): name, level, layer, access, format; layered
    reads["glGetIntegeri_v"] = 2 * 5;
    reads["glGetBooleani_v"] = 2 * 1;
  }
  return reads;
}

TEST_F(GlQueries, ADescribedSteadyFrameWithStateRestoreReadsOnlyTheStateItCanChange) {
  start(0);
  if (HasFatalFailure()) return;
  const GlCallCounts n = steady_counts(described_frame());
  const int es_minor = is_gles() ? std::atoi(reinterpret_cast<const char*>(glGetString(GL_VERSION)) + 12) : 0;
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  const bool image_units = !is_gles() && major * 10 + minor >= 43;
  std::map<std::string, long> expected = expected_guard_reads(is_gles(), es_minor, image_units);
  long per_frame_total = 0;
  for (auto& [name, count] : expected) {
    per_frame_total += count;
    count *= kSteadyFrames;
  }
  std::printf("[ counts   ] with state restore: %ld queries per steady frame (%s)\n",
              n.total_queries() / kSteadyFrames, per_frame(n.queries, kSteadyFrames).c_str());
  EXPECT_EQ(n.queries, expected) << "per frame: " << per_frame(n.queries, kSteadyFrames) << "; expected "
                                 << per_frame(expected, kSteadyFrames) << " (" << per_frame_total << ")";
  EXPECT_EQ(n.total_creations(), 0) << n.describe_creations();

  // The default path, SSS_PATH_AUTO, may take the masked path too, whose tile marks go on texture
  // unit 5 (its texture and sampler). (The masked path marks no stencil: it culls by depth, as the
  // plain one; image unit 0 is read for both, as for the compute path.)
  sss_settings s = settings_;
  s.path = SSS_PATH_AUTO;
  ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK) << sss_last_error(sss_);
  const sss_frame f = described_frame();
  // Past the choice: where the timer is trusted (a GPU) the first frames time each path, each
  // result read once the GPU is done with it.
  for (int i = 0; i < 3 * 3 + 2; ++i) {  // three timed frames of each of up to three paths
    ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
    glFinish();
  }
  const GlCallCounts a = steady_counts(f);
  std::map<std::string, long> expected_auto = expected_guard_reads(is_gles(), es_minor, image_units);
  expected_auto["glGetIntegerv"] += 2;  // unit 5: GL_TEXTURE_BINDING_2D and GL_SAMPLER_BINDING
  per_frame_total = 0;
  for (auto& [name, count] : expected_auto) {
    per_frame_total += count;
    count *= kSteadyFrames;
  }
  std::printf("[ counts   ] the default path, with state restore: %ld queries per steady frame (%s)\n",
              a.total_queries() / kSteadyFrames, per_frame(a.queries, kSteadyFrames).c_str());
  EXPECT_EQ(a.queries, expected_auto) << "per frame: " << per_frame(a.queries, kSteadyFrames) << "; expected "
                                      << per_frame(expected_auto, kSteadyFrames) << " (" << per_frame_total << ")";
  EXPECT_EQ(a.total_creations(), 0) << a.describe_creations();
}

TEST_F(GlQueries, DebugChecksCheckEverySteadyFrame) {
  start(SSS_CREATE_NO_STATE_RESTORE | SSS_CREATE_DEBUG_CHECKS);
  if (HasFatalFailure()) return;
  const GlCallCounts n = steady_counts(described_frame(), 1);
  std::printf("[ counts   ] with SSS_CREATE_DEBUG_CHECKS: %ld queries per steady frame (%s)\n", n.total_queries(),
              n.describe_queries().c_str());
  const auto calls = [&n](const char* name) { return n.queries.count(name) != 0 ? n.queries.at(name) : 0L; };
  EXPECT_GE(calls("glGetError"), 2) << "the host's errors on entry, the passes' after";
  EXPECT_EQ(calls("glGetString"), 1) << "a context is current";
  EXPECT_GE(calls("glIsFramebuffer"), 3) << "the module's objects are in it";
  EXPECT_EQ(calls("glIsTexture"), 2) << "colour and depth are textures";
  EXPECT_EQ(calls("glCheckFramebufferStatus"), 3) << "the inputs', the horizontal and the vertical pass's framebuffers";
  if (!is_gles()) {
    EXPECT_EQ(calls("glGetTexLevelParameteriv"), 6) << "the description against the GL";
  }

  // And the host's pending error is cleared and logged, as on every frame that checks.
  LogRecord log;
  log_ = &log;
  loader_override_ = counting_loader(is_gles() ? es30_get_proc_address : sss_headless_get_proc_address);
  sss_context* logged = create_sss(SSS_CREATE_DEBUG_CHECKS);
  log_ = nullptr;
  loader_override_ = nullptr;
  ASSERT_NE(logged, nullptr);
  ASSERT_EQ(sss_set_camera(logged, scene_.projection.data()), SSS_OK);
  const sss_frame f = described_frame();
  ASSERT_EQ(sss_apply_frame(logged, &f), SSS_OK) << sss_last_error(logged);
  glEnable(0x1234);  // GL_INVALID_ENUM, left pending by the "host" before a steady frame
  EXPECT_EQ(sss_apply_frame(logged, &f), SSS_OK) << sss_last_error(logged);
  EXPECT_TRUE(log.has(SSS_LOG_WARNING, "the host left GL_INVALID_ENUM pending"));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  sss_destroy(logged);
}

TEST_F(GlQueries, WithoutDebugChecksTheHostsPendingErrorStaysTheHosts) {
  LogRecord log;
  log_ = &log;
  start(0);
  log_ = nullptr;
  if (HasFatalFailure()) return;
  const sss_frame f = described_frame();
  ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
  glEnable(0x1234);  // GL_INVALID_ENUM, left pending by the "host" before a steady frame
  EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
  EXPECT_EQ(log.count(SSS_LOG_WARNING), 0) << "a steady frame read the error flag";
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM)) << "the host's error is the host's to read";
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  // A frame that is not steady (here: another description) reads the flag: it clears and logs.
  sss_frame moved = f;
  moved.output_texture = make_rgba16f(kWidth, kHeight, scene_.color);
  moved.output_format = GL_RGBA16F;
  glEnable(0x1234);
  EXPECT_EQ(sss_apply_frame(sss_, &moved), SSS_OK) << sss_last_error(sss_);
  EXPECT_TRUE(log.has(SSS_LOG_WARNING, "the host left GL_INVALID_ENUM pending"));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(GlQueries, AFrameThatIsNotSteadyAsksAndGivesTheSameImage) {
  start(SSS_CREATE_NO_STATE_RESTORE);
  if (HasFatalFailure()) return;
  const GLuint copy = make_rgba16f(kWidth, kHeight, read_rgba(color_, kWidth, kHeight));
  const GlCallCounts steady = steady_counts(described_frame(), 1);  // three frames on color_
  EXPECT_EQ(steady.total_queries(), 0) << steady.describe_queries();

  // Undescribed (the GL is asked every frame; OpenGL ES 3.0 cannot be asked, so there: a frame on
  // another texture, described): queries, and the same image after as many frames.
  sss_frame other = described_frame();
  other.color_texture = copy;
  if (!is_gles()) other = frame_of(copy, depth_);
  for (int i = 0; i < 3; ++i) {
    reset_call_counts();
    ASSERT_EQ(sss_apply_frame(sss_, &other), SSS_OK) << sss_last_error(sss_);
    const GlCallCounts asked = call_counts();
    if (i == 0 || !is_gles()) {
      std::printf("[ counts   ] %s, frame %d: %ld queries (%s)\n",
                  is_gles() ? "another colour texture, described" : "undescribed", i + 1, asked.total_queries(),
                  asked.describe_queries().c_str());
      EXPECT_GT(asked.total_queries(), 0);
    }
  }
  EXPECT_EQ(read_rgba(copy, kWidth, kHeight), read_rgba(color_, kWidth, kHeight));
}

TEST_F(GlQueries, AChangedContextIsCheckedAfterSssGlContextChanged) {
  start(SSS_CREATE_NO_STATE_RESTORE);
  if (HasFatalFailure()) return;
  const sss_frame f = described_frame();
  steady_counts(f, 1);
  ASSERT_EQ(sss_gl_context_changed(sss_), SSS_OK);
  reset_call_counts();
  ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
  const GlCallCounts n = call_counts();
  EXPECT_EQ(n.queries.count("glGetString"), 1u) << n.describe_queries();
  EXPECT_EQ(n.queries.count("glIsProgram"), 1u) << n.describe_queries();
  reset_call_counts();
  ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
  EXPECT_EQ(call_counts().total_queries(), 0) << call_counts().describe_queries();
  EXPECT_EQ(sss_gl_context_changed(nullptr), SSS_ERROR_INVALID_ARGUMENT);
}

}  // namespace
}  // namespace sss_test
