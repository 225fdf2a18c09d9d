// Faults: a shader that does not compile (at create, and for a variant first built in a frame),
// GL_OUT_OF_MEMORY when the module allocates its targets, and the GL context lost between frames.
// Each gives a specific error, leaves no GL object and no GL error behind, leaves the host's state
// and textures as they were, and the next call (or create) recovers. The faults come through the
// loader (support/fault_loader.hpp), so the library carries no test hook.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "fault_loader.hpp"
#include "filter_case.hpp"
#include "gl_objects.hpp"
#include "gl_state_snapshot.hpp"
#include "host_gl_util.hpp"
#include "multisample_textures.hpp"

using namespace host_gl;

namespace sss_test {
namespace {

const sss::math::Matrix4 kCamera = perspective_matrix(40.0f, 1.0f, 0.1f, 10.0f);

sss_settings wide_settings() {
  sss_settings s;
  sss_default_settings(&s);
  s.world_units_per_mm = 0.05f;
  // The path SSS_PATH_AUTO takes where there is no trustworthy timer (llvmpipe), pinned: on a GPU
  // AUTO times each path in turn, and the objects the tests count would depend on which ran.
  s.path = SSS_PATH_FRAGMENT_MASKED;
  return s;
}

class Faults : public GlTest {
 protected:
  void SetUp() override {
    reset_faults();
    GlTest::SetUp();
  }
  void TearDown() override {
    reset_faults();
    GlTest::TearDown();
  }

  sss_result create_faulty(sss_context** out, std::string* log = nullptr) {
    sss_create_desc desc = {};
    desc.struct_size = sizeof desc;
    desc.get_proc_address = fault_get_proc_address;
    desc.get_proc_address_user = headless_;
    if (log != nullptr) {
      desc.log = [](int level, const char* message, void* user) {
        if (level <= SSS_LOG_WARNING) *static_cast<std::string*>(user) += std::string(message) + "\n";
      };
      desc.log_user = log;
    }
    return sss_create(&desc, out);
  }

  GlObjectCounts objects() { return count_gl_objects(sss_headless_get_proc_address, headless_); }

  struct Textures {
    GLuint color = 0, depth = 0;
    int width = 0, height = 0;
  };
  enum class Depth { hardware, linear, stencil };

  Textures make_scene(int width, int height, Depth kind) {
    const SyntheticScene scene = make_relief_scene(width, height, 3, kCamera);
    Textures t;
    t.width = width;
    t.height = height;
    t.color = make_rgba16f(width, height, scene.color);
    switch (kind) {
      case Depth::hardware:
        t.depth = make_depth32f(width, height, scene.window_depth);
        break;
      case Depth::linear:
        t.depth = make_texture(GL_R32F, width, height, GL_RED, GL_FLOAT, scene.distance.data());
        break;
      case Depth::stencil: {
        std::vector<uint32_t> packed(scene.window_depth.size());
        for (std::size_t i = 0; i < packed.size(); ++i) {
          packed[i] = (static_cast<uint32_t>(scene.window_depth[i] * 16777215.0f) << 8) | scene.stencil[i];
        }
        t.depth =
            make_texture(GL_DEPTH24_STENCIL8, width, height, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, packed.data());
        break;
      }
    }
    return t;
  }

  sss_result apply(sss_context* ctx, const Textures& t, bool stencil) {
    sss_stencil s = {t.depth, 1, 0xFF};
    return sss_apply(ctx, t.color, t.depth, stencil ? &s : nullptr);
  }

  // The blur passes' taps and the passes' inputs' colour are read through an image unit (desktop GL
  // 4.3+), with a sampler program standing in where the driver refuses such a program.
  bool image_inputs() const { return !is_gles() && host_gl::has_compute_shaders(); }

  // A driver that refuses every program whose source holds `define` (a read through an image unit):
  // create and three frames succeed, the first with the image of a context whose driver built
  // them, such a program is refused once and not asked for again, and the log says `warning`.
  void expect_the_sampler_stands_in(const std::string& define, const std::string& warning) {
    const std::vector<float> expected = reference(20, 16, Depth::hardware, false);
    faults().break_sources_with = define;
    std::string log;
    ASSERT_EQ(create_faulty(&sss_, &log), SSS_OK) << sss_last_error(nullptr);
    EXPECT_EQ(faults().shader_sources_broken, 1) << "refused once, then no program asked for image loads";
    const sss_settings s = wide_settings();
    ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK);
    ASSERT_EQ(sss_set_camera(sss_, kCamera.data()), SSS_OK);
    const Textures t = make_scene(20, 16, Depth::hardware);
    ASSERT_EQ(apply(sss_, t, false), SSS_OK) << sss_last_error(sss_);
    const std::vector<float> got = read_rgba(t.color, 20, 16);
    EXPECT_EQ(0, std::memcmp(got.data(), expected.data(), got.size() * sizeof(float)))
        << "the sampler reads the same bits as the image unit";
    for (int frame = 0; frame < 2; ++frame) ASSERT_EQ(apply(sss_, t, false), SSS_OK) << sss_last_error(sss_);
    EXPECT_EQ(faults().shader_sources_broken, 1) << "a frame built a refused program again";
    EXPECT_NE(log.find(warning), std::string::npos) << log;
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  }

  // The image a context that never saw a fault makes from the same input.
  std::vector<float> reference(int width, int height, Depth kind, bool stencil) {
    const Textures t = make_scene(width, height, kind);
    sss_context* ctx = create_sss();
    EXPECT_NE(ctx, nullptr);
    if (ctx == nullptr) return {};
    const sss_settings s = wide_settings();
    EXPECT_EQ(sss_set_settings(ctx, &s), SSS_OK);
    EXPECT_EQ(sss_set_camera(ctx, kCamera.data()), SSS_OK);
    EXPECT_EQ(apply(ctx, t, stencil), SSS_OK) << sss_last_error(ctx);
    sss_destroy(ctx);
    return read_rgba(t.color, width, height);
  }

  // One failing apply: `code`, `fragment` in the message, the colour texture, the host's state
  // and the GL objects as they were, no GL error. Returns false on a fatal mismatch.
  void expect_failure_leaves_nothing(sss_context* ctx, const Textures& t, bool stencil, sss_result code,
                                     const std::string& fragment, const GlObjectCounts* expected_objects) {
    const std::vector<float> before = read_rgba(t.color, t.width, t.height);
    const Snapshot state = take_snapshot();
    const GlObjectCounts objects_before = objects();
    EXPECT_EQ(apply(ctx, t, stencil), code) << sss_last_error(ctx);
    const std::string message = sss_last_error(ctx);
    EXPECT_NE(message.find(fragment), std::string::npos) << message;
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    EXPECT_EQ(describe_differences(state, take_snapshot()), "");
    const std::vector<float> after = read_rgba(t.color, t.width, t.height);
    EXPECT_EQ(0, std::memcmp(before.data(), after.data(), before.size() * sizeof(float))) << "colour changed";
    const GlObjectCounts now = objects();
    EXPECT_EQ(now, expected_objects != nullptr ? *expected_objects : objects_before)
        << "before: " << objects_before.describe() << "\nafter:  " << now.describe();
  }
};

TEST_F(Faults, EveryShaderFailingAtCreateGivesShaderCompileAndLeavesNothing) {
  int failures = 0, stand_ins = 0;
  for (int k = 0; k < 32; ++k) {
    reset_faults();
    faults().skip_shader_sources = k;
    faults().break_shader_sources = 1;
    const GlObjectCounts before = objects();
    const Snapshot state = take_snapshot();
    sss_context* ctx = reinterpret_cast<sss_context*>(0x1);
    std::string log;
    const sss_result r = create_faulty(&ctx, &log);
    if (faults().shader_sources_broken == 0) {  // create compiles fewer shaders than k: done
      EXPECT_EQ(r, SSS_OK) << sss_last_error(nullptr);
      sss_destroy(ctx);
      break;
    }
    SCOPED_TRACE("shader source " + std::to_string(k));
    if (r == SSS_OK) {
      // Either stage of a preset tap count's blur program: the program with the count as a uniform
      // stands in, and says so (next test); either stage of the passes' inputs reading the colour
      // through the image unit: the sampler's stands in. No other program may be refused quietly.
      EXPECT_NE(log.find("stands in"), std::string::npos) << log;
      const std::string& source = faults().last_broken_source;
      EXPECT_TRUE(source.find("#define SSS_HALF_TAPS") != std::string::npos ||
                  source.find("#define SSS_TILE_SPANS 1") != std::string::npos ||
                  (image_inputs() && (source.find("#define SSS_COLOR_IMAGE 1") != std::string::npos ||
                                      source.find("#define SSS_TILE_SPANS 2") != std::string::npos)))
          << source.substr(0, 400);
      ++stand_ins;
      sss_destroy(ctx);
      continue;
    }
    ++failures;
    EXPECT_EQ(r, SSS_ERROR_SHADER_COMPILE);
    EXPECT_EQ(ctx, nullptr);
    const std::string message = sss_last_error(nullptr);
    EXPECT_NE(message.find("shader"), std::string::npos) << message;
    EXPECT_NE(message.find("error"), std::string::npos) << "no driver log in: " << message;
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    EXPECT_EQ(describe_differences(state, take_snapshot()), "");
    EXPECT_EQ(objects(), before) << "before: " << before.describe() << "\nafter:  " << objects().describe();
  }
  // Create builds the copy program and the default's two blur programs, of the preset count (two
  // stages each, refused in turn: stand-ins), then the passes' inputs (with image units: through
  // the image unit, two more stand-ins), then what else its prewarm needs.
  std::printf("create: %d shaders whose failure fails it, %d whose program has a stand-in\n", failures, stand_ins);
  EXPECT_GE(failures, image_inputs() ? 2 : 4);
  EXPECT_EQ(stand_ins, image_inputs() ? 6 : 4);
  reset_faults();
  sss_context* ctx = nullptr;
  EXPECT_EQ(create_faulty(&ctx), SSS_OK);  // and the next create works
  sss_destroy(ctx);
}

// A driver that refuses the blur program of a preset tap count (SSS_HALF_TAPS: NVIDIA once did)
// gets the program that reads the count as a uniform instead: the frame succeeds with the same
// image as a context whose driver built both, one warning says so, and the refused program is not
// tried again in later frames.
TEST_F(Faults, ARefusedPresetTapCountFallsBackToTheUniformCount) {
  const std::vector<float> expected = reference(20, 16, Depth::hardware, false);
  faults().break_sources_with = "#define SSS_HALF_TAPS";
  std::string log;
  ASSERT_EQ(create_faulty(&sss_, &log), SSS_OK) << sss_last_error(nullptr);
  const sss_settings s = wide_settings();
  ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK);
  ASSERT_EQ(sss_set_camera(sss_, kCamera.data()), SSS_OK);
  const Textures t = make_scene(20, 16, Depth::hardware);
  ASSERT_EQ(apply(sss_, t, false), SSS_OK) << sss_last_error(sss_);
  const int refused = faults().shader_sources_broken;
  EXPECT_GT(refused, 0);
  EXPECT_NE(log.find("17 taps as a constant"), std::string::npos) << log;
  const std::vector<float> got = read_rgba(t.color, 20, 16);
  const float difference = largest_relative_difference(got, expected);
  std::printf("uniform tap count against the preset count's program: largest relative difference %.3g\n",
              static_cast<double>(difference));
  EXPECT_LE(difference, 1e-6f);
  for (int frame = 0; frame < 2; ++frame) EXPECT_EQ(apply(sss_, t, false), SSS_OK) << sss_last_error(sss_);
  EXPECT_EQ(faults().shader_sources_broken, refused) << "a refused program was built again";
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// A driver that refuses image loads in the blur programs (SSS_IMAGE_TAPS, desktop GL 4.3+; none has
// so far) gets programs that read their taps through the sampler: the frame succeeds with the image
// of a context whose driver built them, one warning says so, and no program tries image loads again.
TEST_F(Faults, ARefusedImageTapProgramFallsBackToTheSampler) {
  if (!image_inputs()) GTEST_SKIP() << "no image units: the taps use the sampler";
  expect_the_sampler_stands_in("#define SSS_IMAGE_TAPS 1", "through a sampler stands in");
}

// The same for the passes' inputs reading the colour through the image unit
// (PassInputsVariant::color_image).
TEST_F(Faults, ARefusedImageInputsProgramFallsBackToTheSampler) {
  if (!image_inputs()) GTEST_SKIP() << "no image units: the inputs read the colour through the sampler";
  expect_the_sampler_stands_in("#define SSS_COLOR_IMAGE 1", "reads it through a sampler stands in");
}

TEST_F(Faults, AVariantFailingInAFrameGivesShaderCompileAndTheNextFrameRecovers) {
  const std::vector<float> expected = reference(20, 16, Depth::linear, false);
  ASSERT_EQ(create_faulty(&sss_), SSS_OK);
  const sss_settings s = wide_settings();
  ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK);
  ASSERT_EQ(sss_set_camera(sss_, kCamera.data()), SSS_OK);
  const Textures t = make_scene(20, 16, Depth::linear);  // linear depth: variants create did not build
  // The frame's first program create did not build: its passes' inputs on linear depth (where
  // there are image units, the one reading the colour through the image unit, then the sampler's
  // stand-in).
  faults().break_sources_with = "#define SSS_MARK_DEPTH";
  expect_failure_leaves_nothing(sss_, t, false, SSS_ERROR_SHADER_COMPILE, "pass inputs shader", nullptr);
  EXPECT_EQ(faults().shader_sources_broken, image_inputs() ? 2 : 1);
  faults().break_sources_with.clear();
  EXPECT_EQ(apply(sss_, t, false), SSS_OK) << sss_last_error(sss_);
  const std::vector<float> got = read_rgba(t.color, 20, 16);
  EXPECT_EQ(0, std::memcmp(got.data(), expected.data(), got.size() * sizeof(float)));
}

TEST_F(Faults, OutOfMemoryOnTheIntermediateTargetAndRecovery) {
  const std::vector<float> expected = reference(24, 20, Depth::hardware, false);
  ASSERT_EQ(create_faulty(&sss_), SSS_OK);
  const sss_settings s = wide_settings();
  ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK);
  ASSERT_EQ(sss_set_camera(sss_, kCamera.data()), SSS_OK);

  // First frame: the module has no target yet.
  const Textures first = make_scene(24, 20, Depth::hardware);
  faults().huge_intermediate_targets = 1;
  expect_failure_leaves_nothing(sss_, first, false, SSS_ERROR_OUT_OF_MEMORY, "pass input", nullptr);
  const GlObjectCounts without_target = objects();
  EXPECT_EQ(apply(sss_, first, false), SSS_OK) << sss_last_error(sss_);
  std::vector<float> got = read_rgba(first.color, 24, 20);
  EXPECT_EQ(0, std::memcmp(got.data(), expected.data(), got.size() * sizeof(float)));

  // A resize that fails: the old target is given up (one texture fewer), the next frame recovers.
  const Textures resized = make_scene(31, 17, Depth::hardware);
  const GlObjectCounts with_target = objects();
  faults().huge_intermediate_targets = 1;
  GlObjectCounts one_fewer = with_target;
  one_fewer.count[0] -= 1;
  expect_failure_leaves_nothing(sss_, resized, false, SSS_ERROR_OUT_OF_MEMORY, "31x17 RGBA32UI pass input",
                                &one_fewer);
  EXPECT_EQ(apply(sss_, resized, false), SSS_OK) << sss_last_error(sss_);
  EXPECT_EQ(objects(), with_target);
  // The passes' three targets (inputs, strength, intermediate), the masked path's two tile marks
  // (the default path's choice here: no timer on a software rasteriser; a GPU's timed choice makes
  // them too, as it times the masked path), and two host textures made in between.
  EXPECT_EQ(without_target.count[0] + 5, with_target.count[0] - 2);
  const int from_driver = faults().out_of_memory_from_driver, injected = faults().out_of_memory_injected;
  EXPECT_EQ(from_driver + injected, 2);
  RecordProperty("out_of_memory_from_driver", from_driver);
  std::printf("GL_OUT_OF_MEMORY: %d raised by the driver for a GL_MAX_TEXTURE_SIZE^2 target, %d injected\n",
              from_driver, injected);
}

TEST_F(Faults, OutOfMemoryOnTheStencilCopyAndRecovery) {
  const std::vector<float> expected = reference(16, 16, Depth::stencil, true);
  ASSERT_EQ(create_faulty(&sss_), SSS_OK);
  const sss_settings s = wide_settings();
  ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK);
  ASSERT_EQ(sss_set_camera(sss_, kCamera.data()), SSS_OK);
  const Textures t = make_scene(16, 16, Depth::stencil);
  faults().fail_renderbuffer_storage = 1;
  // The passes' three targets, their two framebuffers and the inputs program for a stencil (create
  // built the one that marks the culling depth) were made before the stencil copy failed (they
  // stay, for the next frame); the renderbuffer is given up.
  GlObjectCounts with_intermediate = objects();
  with_intermediate.count[0] += 3;
  with_intermediate.count[2] += 2;
  with_intermediate.count[6] += 1;
  with_intermediate.count[7] += 2;
  expect_failure_leaves_nothing(sss_, t, true, SSS_ERROR_OUT_OF_MEMORY, "stencil copy", &with_intermediate);
  EXPECT_EQ(apply(sss_, t, true), SSS_OK) << sss_last_error(sss_);
  with_intermediate.count[3] += 1;  // and now the stencil copy
  EXPECT_EQ(objects(), with_intermediate);
  const std::vector<float> got = read_rgba(t.color, 16, 16);
  EXPECT_EQ(0, std::memcmp(got.data(), expected.data(), got.size() * sizeof(float)));
}

// A GL error the draws raise (here GL_OUT_OF_MEMORY after the horizontal pass, then after the
// vertical one, which writes the host's colour) is found only after the draws began: the call fails
// with SSS_ERROR_GL and must not claim the colour untouched. The message says it may be partly
// written; the GL state is restored and no error is left; the next frame recovers.
TEST_F(Faults, AGlErrorFromTheDrawsSaysTheTargetMayBePartlyWritten) {
  ASSERT_EQ(create_faulty(&sss_), SSS_OK);
  const sss_settings s = wide_settings();
  ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK);
  ASSERT_EQ(sss_set_camera(sss_, kCamera.data()), SSS_OK);
  const Textures t = make_scene(20, 16, Depth::hardware);
  for (int skip : {0, 1}) {
    SCOPED_TRACE(skip == 0 ? "after the horizontal pass" : "after the vertical pass");
    reset_faults();
    faults().skip_draws = skip;
    faults().draw_error = GL_OUT_OF_MEMORY;
    const Snapshot state = take_snapshot();
    EXPECT_EQ(apply(sss_, t, false), SSS_ERROR_GL);
    const std::string message = sss_last_error(sss_);
    EXPECT_NE(message.find("GL_OUT_OF_MEMORY"), std::string::npos) << message;
    EXPECT_NE(message.find("color_texture = " + std::to_string(t.color) + " may be partly written"), std::string::npos)
        << message;
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    EXPECT_EQ(describe_differences(state, take_snapshot()), "");
  }
  reset_faults();
  EXPECT_EQ(apply(sss_, t, false), SSS_OK) << sss_last_error(sss_);
}

// Every allocation comes before the first draw: an out-of-memory on the MSAA path (the inputs
// target of the single-sample passes, allocated after the MSAA path's own targets and once used to
// be allocated after its resolve draw) fails with no draw made, the host's samples and state as they were.
TEST_F(Faults, TheMsaaPathAllocatesEverythingBeforeItsFirstDraw) {
  GLint max_samples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  if (is_gles() || max_samples < 4) GTEST_SKIP() << "the MSAA path is desktop OpenGL only";
  const int w = 24, h = 20;
  const SyntheticScene fine = make_relief_scene(2 * w, 2 * h, 3, kCamera);
  const GLuint color = make_multisample_texture(GL_RGBA32F, w, h, 4, fine.color);
  const GLuint depth = make_multisample_texture(GL_DEPTH_COMPONENT32F, w, h, 4, fine.window_depth);
  textures_.insert(textures_.end(), {color, depth});
  for (const bool in_place : {true, false}) {
    SCOPED_TRACE(in_place ? "written back" : "into an output");
    sss_destroy(sss_);  // a fresh context: no target allocated yet
    ASSERT_EQ(create_faulty(&sss_), SSS_OK);
    const sss_settings s = wide_settings();
    ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK);
    ASSERT_EQ(sss_set_camera(sss_, kCamera.data()), SSS_OK);
    const GLuint output = in_place ? 0u : make_rgba32f(w, h, std::vector<float>(w * h * 4, -1.0f));
    const auto samples_before = read_samples(color, w, h, 4);
    const std::vector<float> output_before = in_place ? std::vector<float>() : read_rgba(output, w, h);
    const Snapshot state = take_snapshot();
    reset_faults();
    faults().huge_intermediate_targets = 1;
    faults().huge_target_format = GL_RGBA32UI;
    const sss_frame f = frame_of(color, depth, output);
    EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_ERROR_OUT_OF_MEMORY) << sss_last_error(sss_);
    EXPECT_EQ(faults().draws, 0) << "drawn before the allocation that failed";
    const std::string message = sss_last_error(sss_);
    // Written back, the first RGBA32UI target is the write-back's (the translucent samples' lowest
    // values and mask, allocated with the resolve's), before the passes' inputs.
    EXPECT_NE(message.find(in_place ? "MSAA write-back targets" : "pass input"), std::string::npos) << message;
    EXPECT_EQ(message.find("partly written"), std::string::npos) << message;
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    EXPECT_EQ(describe_differences(state, take_snapshot()), "");
    EXPECT_EQ(read_samples(color, w, h, 4), samples_before);
    if (!in_place) {
      EXPECT_EQ(read_rgba(output, w, h), output_before);
    }
    reset_faults();
    EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
  }
}

// The host's own objects in a new context, made so that their names cover the ones the module had
// in the lost context: a linked program current, a vertex array bound, a framebuffer with a
// render target bound for drawing, samplers, textures.
struct HostObjects {
  GLuint program = 0, vertex_arrays[4] = {}, framebuffers[4] = {}, samplers[2] = {}, target = 0;
  std::vector<GLuint> empty_programs;
};

GLuint compile(GLenum type, const char* source) {
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  return shader;
}

HostObjects make_host_objects(GLuint target) {
  HostObjects h;
  h.target = target;
  const GLuint vs = compile(GL_VERTEX_SHADER, "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n");
  const GLuint fs = compile(GL_FRAGMENT_SHADER, "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n");
  h.program = glCreateProgram();
  glAttachShader(h.program, vs);
  glAttachShader(h.program, fs);
  glLinkProgram(h.program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  for (int i = 0; i < 12; ++i) h.empty_programs.push_back(glCreateProgram());
  glGenVertexArrays(4, h.vertex_arrays);
  for (GLuint vao : h.vertex_arrays) glBindVertexArray(vao);
  glGenFramebuffers(4, h.framebuffers);
  for (GLuint fb : h.framebuffers) glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glGenSamplers(2, h.samplers);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, h.framebuffers[0]);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target, 0);
  const GLfloat clear[4] = {0.25f, 0.5f, 0.75f, 1.0f};
  glClearBufferfv(GL_COLOR, 0, clear);
  glUseProgram(h.program);
  glBindVertexArray(h.vertex_arrays[0]);
  return h;
}

void delete_host_objects(HostObjects* h) {
  glUseProgram(0);
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteProgram(h->program);
  for (GLuint p : h->empty_programs) glDeleteProgram(p);
  glDeleteVertexArrays(4, h->vertex_arrays);
  glDeleteFramebuffers(4, h->framebuffers);
  glDeleteSamplers(2, h->samplers);
}

class ContextLoss : public Faults {
 protected:
  // Applies once in the test's context, then destroys that GL context (the sss context lives on)
  // and makes a new one current, as a host does after a device reset.
  void lose_the_context_after_one_frame(std::string* log = nullptr) {
    ASSERT_EQ(create_faulty(&sss_, log), SSS_OK);  // no fault armed: the loader only passes through
    const sss_settings s = wide_settings();
    ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK);
    ASSERT_EQ(sss_set_camera(sss_, kCamera.data()), SSS_OK);
    const Textures t = make_scene(16, 16, Depth::hardware);
    ASSERT_EQ(apply(sss_, t, false), SSS_OK) << sss_last_error(sss_);
    textures_.clear();  // they go with the context
    sss_headless_destroy(headless_);
    headless_ = nullptr;
    sss_headless_desc desc = {};
    desc.backend = test_backend();
    desc.major = 3;
    desc.minor = 3;
    desc.core_profile = 1;
    char error[512] = "";
    ASSERT_EQ(sss_headless_create(&desc, &headless_, error, sizeof error), 0) << error;
    std::string missing;
    ASSERT_TRUE(host_gl::load(sss_headless_get_proc_address, headless_, &missing)) << missing;
  }

  GLint draw_attachment() {
    auto get = reinterpret_cast<PFNGLGETFRAMEBUFFERATTACHMENTPARAMETERIVPROC>(
        sss_headless_get_proc_address("glGetFramebufferAttachmentParameteriv", headless_));
    GLint name = -1;
    get(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
    return name;
  }
};

TEST_F(ContextLoss, TheFirstFrameInTheNewContextFailsCleanlyAndTheNextRecovers) {
  lose_the_context_after_one_frame();
  if (HasFatalFailure()) return;
  const std::vector<float> expected = reference(16, 16, Depth::hardware, false);
  const Textures t = make_scene(16, 16, Depth::hardware);
  const GLuint target = make_rgba16f(4, 4, std::vector<float>(64, 0.0f));
  HostObjects host = make_host_objects(target);
  const std::vector<float> target_before = read_rgba(target, 4, 4);
  const GlObjectCounts objects_before = objects();

  expect_failure_leaves_nothing(sss_, t, false, SSS_ERROR_NO_CONTEXT, "not in the current GL context", nullptr);
  EXPECT_EQ(draw_attachment(), static_cast<GLint>(target)) << "the host's framebuffer lost its attachment";
  const std::vector<float> target_after = read_rgba(target, 4, 4);
  EXPECT_EQ(0, std::memcmp(target_before.data(), target_after.data(), target_before.size() * sizeof(float)))
      << "the module drew into the host's framebuffer";

  const Snapshot state = take_snapshot();
  EXPECT_EQ(apply(sss_, t, false), SSS_OK) << sss_last_error(sss_);
  EXPECT_EQ(describe_differences(state, take_snapshot()), "");
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  const std::vector<float> got = read_rgba(t.color, 16, 16);
  EXPECT_EQ(0, std::memcmp(got.data(), expected.data(), got.size() * sizeof(float)));

  sss_destroy(sss_);
  sss_ = nullptr;
  EXPECT_EQ(objects(), objects_before) << "before: " << objects_before.describe()
                                       << "\nafter:  " << objects().describe();
  EXPECT_TRUE(glIsProgram(host.program));
  EXPECT_EQ(draw_attachment(), static_cast<GLint>(target));
  delete_host_objects(&host);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(ContextLoss, DestroyAfterTheLossDeletesNothingOfTheHosts) {
  std::string log;
  lose_the_context_after_one_frame(&log);
  if (HasFatalFailure()) return;
  const GLuint target = make_rgba16f(4, 4, std::vector<float>(64, 0.0f));
  HostObjects host = make_host_objects(target);
  const GlObjectCounts objects_before = objects();
  const Snapshot state = take_snapshot();
  sss_destroy(sss_);
  sss_ = nullptr;
  EXPECT_EQ(objects(), objects_before) << "before: " << objects_before.describe()
                                       << "\nafter:  " << objects().describe();
  EXPECT_EQ(describe_differences(state, take_snapshot()), "");
  EXPECT_EQ(draw_attachment(), static_cast<GLint>(target));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_NE(log.find("nothing was deleted"), std::string::npos) << log;
  delete_host_objects(&host);
}

}  // namespace
}  // namespace sss_test
