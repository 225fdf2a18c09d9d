// The ways the passes can run (sss_settings.path): the compute path (SSS_PATH_COMPUTE,
// separable_blur.comp) and the masked fragment path (SSS_PATH_FRAGMENT_MASKED: a stencil marked from
// alpha) against the CPU model and the plain fragment path; where each gives way to the plain
// fragment path; and SSS_PATH_AUTO's choice.
//
// Tolerance: matches_cpu_model_test's 3e-3 against the CPU model (one fp16 half-ulp flip of the
// intermediate and one of the output). The compute path against the fragment path: bit for bit on
// llvmpipe, which filters textures in fp32 just as the compute path interpolates its cached taps
// (measured: no difference at all on any scene here, OSMesa and EGL), and wherever the compute
// path gives way to the fragment passes. On a GPU the texture unit filters with a fixed-point
// fraction (8 bits on many), so an fp16 rounding of the intermediate or of the output may flip
// by one step: within the same 3e-3 there, not bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "../support/kernel_of.hpp"
#include "fault_loader.hpp"
#include "filter_case.hpp"
#include "host_gl_util.hpp"

using namespace host_gl;

namespace sss_test {
namespace {

constexpr float kTolerance = 3e-3f;

SyntheticScene relief(int width = 64, int height = 48) {
  return make_relief_scene(width, height, 3,
                           perspective_matrix(40.0f, static_cast<float>(width) / static_cast<float>(height), 0.1f, 10.0f));
}

// Frames the compute path used to give to the fragment passes: the host's stencil mask, and
// kernels of two and three terms (three: the sum of terms ping-pongs between the accumulators).
FilterCase stencil_case() {
  FilterCase c;
  c.settings = visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f);
  c.depth = DepthKind::depth24_stencil8;
  c.use_stencil = true;
  return c;
}
FilterCase terms_case(uint32_t terms) {
  FilterCase c;
  c.settings = visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f);
  sss_test::kernel_of(c.settings).family = SSS_KERNEL_SUM_OF_GAUSSIANS;
  sss_test::kernel_of(c.settings).rank = terms;
  return c;
}

// The relief scene with alpha 0 (not translucent) outside the rectangle x, y, w, h: most of the
// compute path's work groups then have no pixel to blur.
SyntheticScene translucent_only_in(SyntheticScene scene, int x, int y, int w, int h) {
  for (int py = 0; py < scene.height; ++py) {
    for (int px = 0; px < scene.width; ++px) {
      if (px < x || px >= x + w || py < y || py >= y + h) {
        scene.color[4 * (static_cast<std::size_t>(py) * static_cast<std::size_t>(scene.width) + px) + 3] = 0.0f;
      }
    }
  }
  return scene;
}

class ComputePath : public FilterCaseTest {
 protected:
  // The GL can run compute shaders (desktop 4.3+): else every frame must take the fragment path.
  bool has_compute() { return !is_gles() && host_gl::has_compute_shaders(); }
  // sss_ with SSS_CREATE_STATS, the tests' settings on `path` and the scene's camera.
  bool create_measured(const SyntheticScene& scene, uint32_t path) {
    sss_ = create_sss(SSS_CREATE_STATS);
    if (sss_ == nullptr) return false;
    sss_settings s = visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f);
    s.path = path;
    return sss_set_settings(sss_, &s) == SSS_OK && sss_set_camera(sss_, scene.projection.data()) == SSS_OK;
  }
  // Runs `c` on the plain fragment path and on `path`; checks both against the CPU model, which path
  // ran (`expected` for the second: `path`, or SSS_PATH_FRAGMENT where it cannot run), and the two
  // results against each other: within kTolerance, or bit for bit when `exact`.
  // `wide`: a kernel so wide that a few taps may land one pixel from the CPU model's
  // (expect_matches_model_up_to_tap_flips); else every value within kTolerance.
  void expect_paths_match(const SyntheticScene& scene, FilterCase c, uint32_t path, uint32_t expected, bool exact,
                          bool wide = false) {
    std::vector<float> results[2];
    for (int second = 0; second < 2; ++second) {
      SCOPED_TRACE(second ? "the path under test" : "the plain fragment path");
      c.settings.path = second ? path : uint32_t{SSS_PATH_FRAGMENT};
      const FilterOutcome o = run_case(scene, c);
      ASSERT_EQ(o.result, SSS_OK);
      const float difference = largest_relative_difference(o.gpu, o.cpu);
      RecordProperty(second ? "path_vs_cpu" : "fragment_vs_cpu", std::to_string(difference));
      if (wide) {
        expect_matches_model_up_to_tap_flips(o, kTolerance, second ? "the path under test" : "the fragment path");
      } else {
        EXPECT_LE(difference, kTolerance);
      }
      EXPECT_GT(largest_relative_difference(o.gpu, o.input), 0.02f);  // the case blurs something
      EXPECT_EQ(last_path(), second ? expected : uint32_t{SSS_PATH_FRAGMENT});
      results[second] = o.gpu;
      TearDown();
      SetUp();
    }
    const float between = largest_relative_difference(results[1], results[0]);
    std::printf("path %u vs the fragment path: largest relative difference %.3g (tolerance %.3g)\n", path, between,
                exact ? 0.0 : kTolerance);
    if (exact) {
      EXPECT_EQ(results[1], results[0]);
    } else {
      EXPECT_LE(between, kTolerance);
    }
  }
  // Mesa's software rasteriser: its texture filtering is fp32 arithmetic, as the compute path's.
  static bool llvmpipe() {
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return renderer != nullptr && std::string(renderer).find("llvmpipe") != std::string::npos;
  }
  // The compute path against the plain one; `runs`: the frame can take it (and the GL has compute).
  // Bit for bit on llvmpipe and where the fragment passes run both times (see the top of the file).
  void expect_paths_agree(const SyntheticScene& scene, const FilterCase& c, bool runs, bool wide = false) {
    const bool compute = runs && has_compute();
    expect_paths_match(scene, c, SSS_PATH_COMPUTE, compute ? SSS_PATH_COMPUTE : SSS_PATH_FRAGMENT,
                       !compute || llvmpipe(), wide);
  }
};

TEST_F(ComputePath, MatchesTheCpuModelInPlaceAndIntoAnOutput) {
  for (bool separate : {false, true}) {
    for (bool half : {false, true}) {
      SCOPED_TRACE(std::string(separate ? "separate output" : "in place") + (half ? ", RGBA16F" : ", RGBA32F"));
      FilterCase c;
      c.settings = visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f);
      c.separate_output = separate;
      c.half_color = half;
      expect_paths_agree(relief(), c, true);
    }
  }
}

// As MatchesCpuModel.HalfFloatTargetsRoundToNearest, through imageStore into rgba16f images (the
// intermediate and the host's colour): rounded to nearest in the shader, as the CPU model does.
TEST_F(ComputePath, HalfFloatImagesRoundToNearest) {
  if (!has_compute()) GTEST_SKIP() << "no compute shaders on this GL";
  FilterCase c;
  c.settings = visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f);
  c.settings.path = SSS_PATH_COMPUTE;
  c.half_color = true;
  const FilterOutcome o = run_case(relief(), c);
  EXPECT_EQ(last_path(), SSS_PATH_COMPUTE);
  expect_half_rounding_like_the_cpu_model(o, "compute path, RGBA16F in place", true);
}

TEST_F(ComputePath, EveryVariantOfTheShader) {
  struct Variant {
    const char* name;
    uint32_t flags;
    DepthKind depth;
    float jitter;
    uint32_t family;
  };
  const Variant variants[] = {
      {"no follow-surface", 0u, DepthKind::depth32f, 0.0f, SSS_KERNEL_SEPARABLE},
      {"linear depth", SSS_FOLLOW_SURFACE, DepthKind::linear_r32f, 0.0f, SSS_KERNEL_SEPARABLE},
      {"jitter", SSS_FOLLOW_SURFACE, DepthKind::depth32f, 0.33f, SSS_KERNEL_SEPARABLE},
      // One Gaussian term with the exact depth correction (SSS_FOLLOW_SURFACE 2 in the shader).
      {"artist kernel", SSS_FOLLOW_SURFACE, DepthKind::depth32f, 0.0f, SSS_KERNEL_ARTIST},
  };
  for (const Variant& v : variants) {
    SCOPED_TRACE(v.name);
    FilterCase c;
    c.settings = visible_settings(17, v.flags, 0.045f);
    c.settings.jitter = v.jitter;
    sss_test::kernel_of(c.settings).family = v.family;
    c.depth = v.depth;
    expect_paths_agree(relief(), c, true);
  }
}

TEST_F(ComputePath, AKernelWiderThanTheCachedSpanReadsTheTextures) {
  // A work group caches a bounded apron on either end of a row or column (shader_constants.hpp
  // kComputeTiles: today 64 pixels in both passes), and fills only as far as its widest kernel
  // reaches. 300 px wide at about 40 px per profile mm: the 17-tap kernel reaches ~80 px each way,
  // past the apron; 600 px at twice the scale ~160 px, past any apron the path has had (96 at
  // most): the outer taps read the textures, and the image must not change. Against the CPU model
  // up to the few taps that land a pixel over at such a reach (expect_matches_model_up_to_tap_flips);
  // the two paths bit for bit on llvmpipe all the same.
  struct Wide {
    int width;
    float scale;
  };
  for (const Wide wide : {Wide{300, 0.9f}, Wide{600, 1.8f}}) {
    FilterCase c;
    c.settings = visible_settings(17, SSS_FOLLOW_SURFACE, wide.scale);
    for (bool separate : {false, true}) {
      SCOPED_TRACE(std::to_string(wide.width) + (separate ? " px, separate output" : " px, in place"));
      c.separate_output = separate;
      expect_paths_agree(relief(wide.width, 40), c, true, true);
    }
  }
}

TEST_F(ComputePath, GroupsWithoutATranslucentPixelLeaveTheirPixels) {
  // Translucent pixels in a 60x40 patch of a 400x300 frame: most work groups of both passes have
  // none, write what the pass leaves there and do no taps; the image is the fragment path's. A
  // frame with no translucent pixel at all comes back exactly as it went in.
  const SyntheticScene patch = translucent_only_in(relief(400, 300), 170, 130, 60, 40);
  for (bool separate : {false, true}) {
    SCOPED_TRACE(separate ? "separate output" : "in place");
    FilterCase c;
    c.settings = visible_settings(17, SSS_FOLLOW_SURFACE, 0.3f);
    c.separate_output = separate;
    expect_paths_agree(patch, c, true);
    c.settings.path = SSS_PATH_COMPUTE;
    const FilterOutcome o = run_case(translucent_only_in(relief(400, 300), 0, 0, 0, 0), c);
    ASSERT_EQ(o.result, SSS_OK);
    EXPECT_EQ(last_path(), has_compute() ? SSS_PATH_COMPUTE : SSS_PATH_FRAGMENT);
    EXPECT_EQ(o.gpu, o.input) << "a frame without a translucent pixel changed";
  }
}

TEST_F(ComputePath, RegionAndViewport) {
  FilterCase c;
  c.settings = visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f);
  c.use_region = true;
  c.region = {9, 7, 40, 30};
  for (bool separate : {false, true}) {
    SCOPED_TRACE(separate ? "region, separate output" : "region, in place");
    c.separate_output = separate;
    expect_paths_agree(relief(), c, true);
  }
  FilterCase v;
  v.settings = visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f);
  v.viewport = {5, 4, 50, 36};
  SCOPED_TRACE("viewport inside the texture");
  expect_paths_agree(relief(), v, true);
}

TEST_F(ComputePath, TakesTheHostsStencilAndKernelsOfSeveralTerms) {
  // The host's stencil (marked into the intermediate for the dispatches) and kernels of two and
  // three terms (their sum in the accumulators, SSS_ACCUMULATE), and both at once, in place and
  // into an output, with and without a region: the compute path runs them (last_frame_path) and
  // gives the fragment path's image.
  for (bool separate : {false, true}) {
    for (bool region : {false, true}) {
      SCOPED_TRACE(std::string(separate ? "separate output" : "in place") + (region ? ", region" : ""));
      FilterCase stencil = stencil_case();
      FilterCase two = terms_case(2);
      FilterCase both = stencil_case();
      both.settings = terms_case(3).settings;
      for (FilterCase* c : {&stencil, &two, &both}) {
        c->separate_output = separate;
        c->use_region = region;
        c->region = {9, 7, 40, 30};
      }
      {
        SCOPED_TRACE("stencil");
        expect_paths_agree(relief(), stencil, true);
      }
      {
        SCOPED_TRACE("two terms");
        expect_paths_agree(relief(), two, true);
      }
      SCOPED_TRACE("stencil and three terms");
      expect_paths_agree(relief(), both, true);
    }
  }
}

TEST_F(ComputePath, GivesWayToTheFragmentPathWhereItCannotRun) {
  // The cross-bilateral mode runs as fragment passes, with the same result.
  FilterCase c;
  c.settings = visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f);
  c.settings.mode = SSS_MODE_CROSS_BILATERAL;
  expect_paths_agree(relief(), c, false);
}

TEST_F(ComputePath, KeepsTheHostsAlphaExactly) {
  // Written back in place, the image store writes all four channels: the compute path reads the
  // host's own alpha back from the target (the fragment path masks alpha off). Strengths that fp16
  // cannot hold must come back bit for bit in an RGBA32F colour.
  SyntheticScene scene = relief();
  for (std::size_t i = 3; i < scene.color.size(); i += 4) {
    if (scene.color[i] > 0.0f) scene.color[i] = 0.6f + 0.3f * static_cast<float>(i % 7) / 7.0f + 1e-5f;
  }
  FilterCase c;
  c.settings = visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f);
  c.settings.path = SSS_PATH_COMPUTE;
  const FilterOutcome o = run_case(scene, c);
  ASSERT_EQ(o.result, SSS_OK);
  EXPECT_EQ(last_path(), has_compute() ? SSS_PATH_COMPUTE : SSS_PATH_FRAGMENT);
  EXPECT_LE(largest_relative_difference(o.gpu, o.cpu), kTolerance);
  for (std::size_t i = 3; i < o.gpu.size(); i += 4) ASSERT_EQ(o.gpu[i], o.input[i]) << "alpha of pixel " << i / 4;
}

TEST_F(ComputePath, AutoDecidesOnceAndEveryFrameMatches) {
  // SSS_PATH_AUTO: frames alternate while it times the paths (GPUs with timer queries), or it keeps
  // the fragment path (software rasterisers, OpenGL ES, GL before 4.3). Either way it logs one
  // decision for an unchanged configuration, and a new one once the configuration changes, and
  // every frame gives the same image within tolerance. Twelve frames a configuration leave room for
  // the timed trials: at most three paths, three frames each, every result there by the next frame
  // (glFinish), so the decision comes by the tenth.
  constexpr int kFrames = 12;
  constexpr const char* kDecision = "SSS_PATH_AUTO chose the ";
  LogRecord log;
  log_ = &log;
  const SyntheticScene scene = relief();
  const int w = scene.width, h = scene.height;
  FilterCase c;
  c.settings = visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f);
  c.settings.path = SSS_PATH_AUTO;
  const FilterOutcome first = run_case(scene, c);  // the reference frame (CPU model checked here)
  ASSERT_EQ(first.result, SSS_OK);
  EXPECT_LE(largest_relative_difference(first.gpu, first.cpu), kTolerance);
  // More frames on the same context: the input refilled each time, the result compared.
  const GLuint color = make_rgba32f(w, h, scene.color);
  const GLuint depth = make_depth32f(w, h, scene.window_depth);
  sss_frame frame = frame_of(color, depth);
  if (is_gles()) describe_frame(c, w, h, &frame);  // ES 3.0 cannot be asked
  int computed = 0, masked = 0;
  std::vector<uint32_t> paths;  // of the frames with the host's region
  for (int region = 0; region < 2; ++region) {
    if (region == 1) {
      // With the host's region the untimed choice is the plain fragment path (the region already
      // leaves out what the mask would): a new configuration, so a new decision.
      frame.flags |= SSS_FRAME_REGION;
      frame.region[2] = w;
      frame.region[3] = h;
    }
    for (int i = 0; i < kFrames; ++i) {
      glBindTexture(GL_TEXTURE_2D, color);
      glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, scene.color.data());
      glBindTexture(GL_TEXTURE_2D, 0);
      ASSERT_EQ(sss_apply_frame(sss_, &frame), SSS_OK) << sss_last_error(sss_);
      glFinish();  // lets the timer results arrive between frames
      const uint32_t path = last_path();
      if (region == 1) {
        paths.push_back(path);
      } else {
        computed += path == SSS_PATH_COMPUTE ? 1 : 0;
        masked += path == SSS_PATH_FRAGMENT_MASKED ? 1 : 0;
      }
      EXPECT_LE(largest_relative_difference(read_rgba(color, w, h), first.gpu), kTolerance)
          << (region ? "region " : "") << "frame " << i;
    }
    // The first configuration's frames (run_case's and these) decided once; the region's once more.
    EXPECT_EQ(log.count(SSS_LOG_INFO, kDecision), region + 1) << "after the frames " << (region ? "with" : "without")
                                                              << " a region";
  }
  for (const auto& m : log.messages) {
    if (m.second.find(kDecision) != std::string::npos) std::printf("logged: %s\n", m.second.c_str());
  }
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (llvmpipe() || is_gles()) {  // no trustworthy timer: decided at once, and kept every frame
    EXPECT_EQ(masked, kFrames);
    EXPECT_EQ(paths, std::vector<uint32_t>(kFrames, SSS_PATH_FRAGMENT));
    EXPECT_TRUE(log.has(SSS_LOG_INFO, std::string(kDecision) + "masked fragment path (no trustworthy timer"));
    EXPECT_TRUE(log.has(SSS_LOG_INFO, std::string(kDecision) + "fragment path (no trustworthy timer"));
  }
  if (!has_compute()) {
    EXPECT_EQ(computed, 0);
  }
  std::printf("SSS_PATH_AUTO on %s: of %d frames, %d on the compute path, %d on the masked fragment path\n",
              renderer ? renderer : "?", kFrames, computed, masked);
}

TEST_F(ComputePath, StatsCountNoPixelsForAComputeFrame) {
  // SSS_CREATE_STATS: a dispatch has no samples to count, so SSS_STATS_PIXELS stays clear for a
  // compute frame; the same frames on the fragment path count them (desktop GL).
  if (is_gles()) GTEST_SKIP() << "OpenGL ES counts no pixels on either path";
  const SyntheticScene scene = relief();
  const GLuint color = make_rgba32f(scene.width, scene.height, scene.color);
  const GLuint depth = make_depth32f(scene.width, scene.height, scene.window_depth);
  for (uint32_t path : {SSS_PATH_FRAGMENT, SSS_PATH_COMPUTE}) {
    SCOPED_TRACE(path == SSS_PATH_COMPUTE ? "compute path" : "fragment path");
    ASSERT_TRUE(create_measured(scene, path));
    const sss_frame frame = frame_of(color, depth);
    sss_stats stats = {};
    stats.struct_size = sizeof stats;
    for (int i = 0; i < 4; ++i) {
      ASSERT_EQ(sss_apply_frame(sss_, &frame), SSS_OK) << sss_last_error(sss_);
      glFinish();
    }
    ASSERT_EQ(sss_get_stats(sss_, &stats), SSS_OK);
    const bool compute_ran = stats.last_frame_path == SSS_PATH_COMPUTE;
    EXPECT_EQ(compute_ran, path == SSS_PATH_COMPUTE && has_compute());
    // A compute frame has only its GPU time to report, where the timer is trustworthy (on llvmpipe
    // nothing at all: measured stays 0); a fragment frame always has its pixel count.
    EXPECT_EQ((stats.measured & SSS_STATS_PIXELS) != 0, !compute_ran);
    if (!compute_ran) {
      EXPECT_NE(stats.measured_frame, 0u);
    }
    sss_destroy(sss_);
    sss_ = nullptr;
  }
}

// The compute path writes its target through image unit 0, and image stores to an incomplete
// texture are undefined (a silent no-op on some drivers). A host texture left on the default
// minification filter (GL_NEAREST_MIPMAP_LINEAR) with level 0 alone is incomplete: such a frame
// takes the fragment path, says so in the log and in last_frame_path, and gives the fragment path's
// image; the host's promise (SSS_FRAME_TARGET_COMPLETE) or the GL's answer that the filter needs no
// mipmaps lets the compute path run. Mesa's llvmpipe stores into such a texture all the same (it
// checks the bound level alone), so there what gives the trap away is the path, not the pixels.
TEST_F(ComputePath, AnIncompleteTargetTakesTheFragmentPath) {
  if (!has_compute()) GTEST_SKIP() << "no compute shaders on this GL";
  reset_faults();
  loader_override_ = fault_get_proc_address;  // counts glGetTexParameteriv
  LogRecord log;
  log_ = &log;
  const SyntheticScene scene = relief();
  const int w = scene.width, h = scene.height;
  const GLuint depth = make_depth32f(w, h, scene.window_depth);
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  ASSERT_EQ(sss_set_camera(sss_, scene.projection.data()), SSS_OK);
  const auto use_path = [&](uint32_t path) {
    sss_settings s = visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f);
    s.path = path;
    ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK);
  };
  // A colour (or output) texture, complete (GL_NEAREST) or on the default filter with one level.
  const auto texture = [&](const std::vector<float>& rgba, bool complete) {
    const GLuint t = make_rgba32f(w, h, rgba);
    glBindTexture(GL_TEXTURE_2D, t);
    if (!complete) glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_LINEAR);
    glBindTexture(GL_TEXTURE_2D, 0);
    return t;
  };
  const std::vector<float> blank(static_cast<std::size_t>(w * h * 4), -1.0f);
  for (const bool separate : {false, true}) {
    SCOPED_TRACE(separate ? "into a separate output" : "in place");
    // Returns the image, with the path and the queries the frame took.
    const auto run = [&](bool complete, uint32_t flags, bool describe, uint32_t* path, int* queries) {
      const GLuint color = texture(scene.color, complete || separate);
      const GLuint output = separate ? texture(blank, complete) : 0u;
      sss_frame f = frame_of(color, depth, output);
      f.flags = flags;
      if (describe) describe_frame(&f, GL_RGBA32F, GL_RGBA32F, GL_DEPTH_COMPONENT32F, w, h);
      reset_faults();
      EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
      EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
      *queries = faults().texture_parameter_queries;
      *path = last_path();
      return read_rgba(separate ? output : color, w, h);
    };
    uint32_t path = 0;
    int queries = 0;
    use_path(SSS_PATH_FRAGMENT);
    const std::vector<float> fragment = run(true, 0, false, &path, &queries);
    use_path(SSS_PATH_COMPUTE);
    // The trap: the default filter, one level.
    EXPECT_EQ(run(false, 0, false, &path, &queries), fragment);
    EXPECT_EQ(path, SSS_PATH_FRAGMENT) << "image stores into an incomplete texture";
    EXPECT_TRUE(log.has(SSS_LOG_INFO, "may be incomplete")) << "the log does not say why";
    // Complete by its filter: asked, and the compute path runs (bit for bit on llvmpipe).
    const std::vector<float> asked = run(true, 0, false, &path, &queries);
    EXPECT_EQ(path, SSS_PATH_COMPUTE);
    EXPECT_GT(queries, 0);
    EXPECT_LE(largest_relative_difference(asked, fragment), llvmpipe() ? 0.0f : kTolerance);
    // The host's promise in a described frame: no question, the compute path.
    run(true, SSS_FRAME_TARGET_COMPLETE, true, &path, &queries);
    EXPECT_EQ(path, SSS_PATH_COMPUTE);
    EXPECT_EQ(queries, 0);
    // A described frame without the promise: the default filter is assumed, nothing asked.
    run(true, 0, true, &path, &queries);
    EXPECT_EQ(path, SSS_PATH_FRAGMENT);
    EXPECT_EQ(queries, 0);
  }
  reset_faults();
}

TEST_F(ComputePath, AnUnknownPathIsRefusedByName) {
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  sss_settings s;
  sss_default_settings(&s);
  EXPECT_EQ(s.path, SSS_PATH_AUTO);  // the default: the fastest path here (sss.h, SSS_PATH_AUTO)
  s.path = SSS_PATH_HALF_RESOLUTION + 1;
  EXPECT_EQ(sss_set_settings(sss_, &s), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("settings->path = 5"), std::string::npos) << sss_last_error(sss_);
  sss_settings back;
  back.struct_size = sizeof back;
  ASSERT_EQ(sss_get_settings(sss_, &back), SSS_OK);
  EXPECT_EQ(back.path, SSS_PATH_AUTO);  // nothing changed
  s.path = SSS_PATH_FRAGMENT;
  ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK);
  ASSERT_EQ(sss_get_settings(sss_, &back), SSS_OK);
  EXPECT_EQ(back.path, SSS_PATH_FRAGMENT);
}

// ---- The masked fragment path (SSS_PATH_FRAGMENT_MASKED).

class MaskedPath : public ComputePath {
 protected:
  // The plain and the masked fragment path: the same shader on the same pixels, the rest copied or
  // left alone either way, so bit for bit the same image.
  void expect_bit_identical(const SyntheticScene& scene, const FilterCase& c, uint32_t expected) {
    expect_paths_match(scene, c, SSS_PATH_FRAGMENT_MASKED, expected, true);
  }
};

TEST_F(MaskedPath, GivesThePlainFragmentResultBitForBit) {
  // The relief scene has pixels that are not translucent (alpha 0) among translucent ones.
  for (bool separate : {false, true}) {
    SCOPED_TRACE(separate ? "separate output" : "in place");
    FilterCase c;
    c.settings = visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f);
    c.separate_output = separate;
    expect_bit_identical(relief(), c, SSS_PATH_FRAGMENT_MASKED);
    FilterCase r = c;
    r.use_region = true;
    r.region = {9, 7, 40, 30};
    SCOPED_TRACE("a region");
    expect_bit_identical(relief(), r, SSS_PATH_FRAGMENT_MASKED);
  }
  SCOPED_TRACE("two terms");
  expect_bit_identical(relief(), terms_case(2), SSS_PATH_FRAGMENT_MASKED);
}

TEST_F(MaskedPath, AHostStencilKeepsThePlainPath) {
  expect_bit_identical(relief(), stencil_case(), SSS_PATH_FRAGMENT);
}

// Both fragment paths cull by the depth the inputs draw marks (issue 24): three draws (the inputs,
// the two passes), and on the masked path two more before them, the tile marks and their columns
// (tile_culling.cpp); and the last pass shades translucent pixels only, which its samples-passed
// count shows: into a separate output too, where the plain passes once shaded every pixel (the
// culled ones are copied by a draw outside the count).
TEST_F(MaskedPath, BothFragmentPathsShadeOnlyTranslucentPixels) {
  const SyntheticScene scene = relief();
  const GLuint depth = make_depth32f(scene.width, scene.height, scene.window_depth);
  std::uint64_t translucent = 0;
  for (std::size_t i = 3; i < scene.color.size(); i += 4) translucent += scene.color[i] > 0.0f ? 1 : 0;
  ASSERT_GT(translucent, 0u);
  ASSERT_LT(translucent, static_cast<std::uint64_t>(scene.width) * scene.height) << "the scene must have both";
  for (const bool separate : {false, true}) {
    for (uint32_t path : {SSS_PATH_FRAGMENT, SSS_PATH_FRAGMENT_MASKED}) {
      SCOPED_TRACE(std::string(separate ? "separate output, " : "in place, ") +
                   (path == SSS_PATH_FRAGMENT ? "plain" : "masked"));
      const GLuint color = make_rgba32f(scene.width, scene.height, scene.color);
      const GLuint output = separate ? make_rgba32f(scene.width, scene.height, scene.color) : 0u;
      ASSERT_TRUE(create_measured(scene, path));
      sss_frame frame = frame_of(color, depth);
      frame.output_texture = output;
      if (is_gles()) {
        FilterCase description;
        description.separate_output = separate;
        describe_frame(description, scene.width, scene.height, &frame);
      }
      for (int i = 0; i < 2; ++i) {
        ASSERT_EQ(sss_apply_frame(sss_, &frame), SSS_OK) << sss_last_error(sss_);
        glFinish();
      }
      sss_stats stats = {};
      stats.struct_size = sizeof stats;
      ASSERT_EQ(sss_get_stats(sss_, &stats), SSS_OK);
      // (the tile marks,) the inputs, the passes (, the copy of the rest)
      EXPECT_EQ(stats.last_frame_passes, (separate ? 4u : 3u) + (path == SSS_PATH_FRAGMENT_MASKED ? 2u : 0u));
      if (!is_gles()) {
        ASSERT_NE(stats.measured & SSS_STATS_PIXELS, 0u);
        // In place the untouched pixels discard, so the count is the blurred ones: at most the translucent.
        if (separate) {
          EXPECT_EQ(stats.pixels_touched, translucent);
        } else {
          EXPECT_GT(stats.pixels_touched, 0u);
          EXPECT_LE(stats.pixels_touched, translucent);
        }
      }
      sss_destroy(sss_);
      sss_ = nullptr;
    }
  }
}

}  // namespace
}  // namespace sss_test
