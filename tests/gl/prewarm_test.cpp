// No hitch (issue 22, item 3): after sss_prepare for a size and formats, the first sss_apply_frame
// with the prepared settings compiles no shader, links no program and creates or allocates no GL
// object, counted through the loader (counting_loader.hpp's creations: glGen*, glCreate*,
// glCompileShader, glLinkProgram, glTexImage*, glTexStorage*, glRenderbufferStorage*). Every case is
// run twice, each time in a fresh context: unprepared, where the first frame must create
// something (else the count would prove nothing), and prepared, where it must create nothing. A
// frame at another size does allocate; a bad description fails with its message and builds
// nothing. Kernel fits run in sss_set_settings only, and a kernel built lately is kept.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <cstdio>
#include <string>
#include <vector>

#include "../support/kernel_of.hpp"
#include "counting_loader.hpp"
#include "filter_case.hpp"
#include "gl_state_snapshot.hpp"
#include "multisample_textures.hpp"

using namespace host_gl;

namespace sss_test {
namespace {

constexpr int kW = 32, kH = 24;

// The creations the counting loader saw since the last reset_call_counts(), by GL function name.
using CreationCounts = std::map<std::string, long>;
CreationCounts creations() { return call_counts().creations; }
long total_creations() { return call_counts().total_creations(); }
long count_of(const std::string& function) {
  const CreationCounts c = creations();
  const auto it = c.find(function);
  return it == c.end() ? 0 : it->second;
}
std::string describe(const CreationCounts& counts) {
  GlCallCounts all;
  all.creations = counts;
  return all.describe_creations();
}
void reset_creations() { reset_call_counts(); }

struct Case {
  const char* name;
  sss_settings settings;
  GLenum color_format = GL_RGBA16F;
  GLenum output_format = 0;  // 0: in place
  GLenum depth_format = GL_DEPTH_COMPONENT32F;
  bool stencil = false;  // the host's stencil (depth is then DEPTH24_STENCIL8)
  bool normals = false;
  bool region = false;
  int samples = 0;       // > 1: multisampled colour and depth (desktop GL)
  GLenum strength_format = 0;  // a strength texture (sss_frame.strength_texture) of this format
  GLenum profile_format = 0;   // per-pixel profiles: two profiles set, a profile texture of this format
  GLenum albedo_format = 0;    // an albedo texture of this format (multisampled like the colour) for a texturing mode
};

sss_settings settings_with(uint32_t path, uint32_t mode = SSS_MODE_SEPARABLE) {
  sss_settings s = visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f);
  s.path = path;
  s.mode = mode;
  return s;
}

// Three terms: sum of three Gaussians fitted to a measured material.
sss_settings several_terms(uint32_t path) {
  sss_settings s = settings_with(path);
  sss_test::kernel_of(s).family = SSS_KERNEL_SUM_OF_GAUSSIANS;
  sss_test::kernel_of(s).rank = 3;
  sss_test::kernel_of(s).profile.profile = SSS_PROFILE_MARBLE;
  return s;
}

class Prewarm : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    loader_override_ = counting_loader(is_gles() ? es30_get_proc_address : sss_headless_get_proc_address);
    scene_ = make_relief_scene(kW * 2, kH * 2, 5, perspective_matrix(40.0f, 4.0f / 3.0f, 0.1f, 10.0f));
  }

  bool msaa_available() const { return !is_gles(); }

  // The host's textures for `c` at w x h, and the frame that names them (described on OpenGL ES).
  sss_frame frame_for(const Case& c, int w, int h);
  sss_prepare_desc desc_for(const Case& c, int w, int h) const {
    sss_prepare_desc d = {};
    d.struct_size = sizeof d;
    d.width = w;
    d.height = h;
    d.color_format = c.color_format;
    d.output_format = c.output_format;
    d.depth_format = c.stencil ? GL_DEPTH24_STENCIL8 : c.depth_format;
    d.samples = c.samples;
    d.stencil_format = c.stencil ? GL_DEPTH24_STENCIL8 : 0;
    d.flags = (c.normals ? static_cast<std::uint32_t>(SSS_PREPARE_NORMALS) : 0u) |
              (c.region ? static_cast<std::uint32_t>(SSS_PREPARE_REGION) : 0u);
    d.strength_format = c.strength_format;
    d.profile_format = c.profile_format;
    d.albedo_format = c.albedo_format;
    return d;
  }
  // A fresh context with c's settings and camera (sss_ replaced).
  void fresh_context(const Case& c) {
    if (sss_ != nullptr) sss_destroy(sss_);
    sss_ = create_sss();
    ASSERT_NE(sss_, nullptr);
    ASSERT_EQ(sss_set_settings(sss_, &c.settings), SSS_OK) << sss_last_error(sss_);
    if (c.profile_format != 0) {
      sss_settings two[2] = {c.settings, c.settings};
      two[1].scale = 2.0f;
      ASSERT_EQ(sss_set_profiles(sss_, two, 2), SSS_OK) << sss_last_error(sss_);
    }
    ASSERT_EQ(sss_set_camera(sss_, scene_.projection.data()), SSS_OK);
  }
  // What the first frame of `c` creates in a fresh context, prepared for it or not.
  CreationCounts first_frame(const Case& c, bool prepare) {
    sss_frame f = frame_for(c, kW, kH);
    fresh_context(c);
    if (sss_ == nullptr) return {};
    if (prepare) {
      const sss_prepare_desc d = desc_for(c, kW, kH);
      EXPECT_EQ(sss_prepare(sss_, &d), SSS_OK) << sss_last_error(sss_);
    }
    reset_creations();
    EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
    return creations();
  }
  void expect_no_hitch(const Case& c) {
    SCOPED_TRACE(c.name);
    const CreationCounts unprepared = first_frame(c, false);
    EXPECT_FALSE(unprepared.empty()) << "the unprepared first frame created nothing: the count proves nothing";
    const CreationCounts prepared = first_frame(c, true);
    EXPECT_TRUE(prepared.empty()) << "the prepared first frame created: " << describe(prepared)
                                  << " (unprepared: " << describe(unprepared) << ")";
  }

  SyntheticScene scene_;
  sss_stencil stencil_{0, 1, 0xFF};
};

sss_frame Prewarm::frame_for(const Case& c, int w, int h) {
  const std::vector<float> color(scene_.color.begin(), scene_.color.begin() + static_cast<long>(w) * h * 4);
  const std::vector<float> depth(scene_.window_depth.begin(), scene_.window_depth.begin() + static_cast<long>(w) * h);
  sss_frame f = {};
  f.struct_size = sizeof f;
  if (c.samples > 1) {
    f.color_texture = make_multisample_texture(c.color_format, w, h, c.samples, scene_.color);
    f.depth_texture = make_multisample_texture(c.depth_format, w, h, c.samples, scene_.window_depth);
    textures_.push_back(f.color_texture);
    textures_.push_back(f.depth_texture);
    if (c.stencil) {
      f.depth_texture = make_multisample_depth_stencil(w, h, c.samples, scene_.window_depth, scene_.stencil);
      textures_.push_back(f.depth_texture);
    }
  } else if (c.color_format == GL_R11F_G11F_B10F) {  // no alpha: RGB data (ES takes no other)
    std::vector<float> rgb;
    for (std::size_t i = 0; i < color.size(); ++i) {
      if (i % 4 != 3) rgb.push_back(color[i]);
    }
    f.color_texture = make_texture(c.color_format, w, h, GL_RGB, GL_FLOAT, rgb.data());
    f.depth_texture = make_depth32f(w, h, depth);
  } else {
    f.color_texture = make_texture(c.color_format, w, h, GL_RGBA, GL_FLOAT, color.data());
    if (c.stencil) {
      std::vector<uint32_t> packed(depth.size());
      for (std::size_t i = 0; i < packed.size(); ++i) packed[i] = (static_cast<uint32_t>(depth[i] * 16777215.0f) << 8) | 1u;
      f.depth_texture = make_texture(GL_DEPTH24_STENCIL8, w, h, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, packed.data());
    } else if (c.depth_format == GL_R32F) {
      std::vector<float> distance(depth.size(), 2.0f);
      f.depth_texture = make_texture(GL_R32F, w, h, GL_RED, GL_FLOAT, distance.data());
    } else {
      f.depth_texture = make_depth32f(w, h, depth);
    }
  }
  if (c.stencil) {
    stencil_.depth_stencil_texture = f.depth_texture;
    f.stencil = &stencil_;
  }
  if (c.output_format != 0) {
    f.output_texture = make_texture(c.output_format, w, h, GL_RGBA, GL_FLOAT, color.data());
  }
  if (c.strength_format != 0) {
    std::vector<float> strength(depth.size());
    std::vector<uint8_t> bytes(depth.size());  // R8 (ES takes no float data for it)
    for (std::size_t i = 0; i < strength.size(); ++i) {
      strength[i] = color[i * 4 + 3];
      bytes[i] = static_cast<uint8_t>(std::lround(std::clamp(strength[i], 0.0f, 1.0f) * 255.0f));
    }
    f.strength_texture = c.strength_format == GL_R8
                             ? make_texture(GL_R8, w, h, GL_RED, GL_UNSIGNED_BYTE, bytes.data())
                             : make_texture(c.strength_format, w, h, GL_RED, GL_FLOAT, strength.data());
  }
  if (c.profile_format != 0) {  // left half profile 0, right half profile 1 (object 2)
    std::vector<uint16_t> ids(static_cast<std::size_t>(w) * h);
    for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<uint16_t>(static_cast<int>(i % static_cast<std::size_t>(w)) < w / 2 ? 0 : 0x21);
    std::vector<uint8_t> bytes(ids.begin(), ids.end());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    f.profile_texture = c.profile_format == GL_R8UI
                            ? make_texture(GL_R8UI, w, h, GL_RED_INTEGER, GL_UNSIGNED_BYTE, bytes.data())
                            : make_texture(GL_R16UI, w, h, GL_RED_INTEGER, GL_UNSIGNED_SHORT, ids.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  }
  if (c.albedo_format != 0) {  // RGBA16F (what the multisampled textures take), 0.5 everywhere
    const std::vector<float> half_grey(static_cast<std::size_t>(w) * h * 4 * (c.samples > 1 ? 4 : 1), 0.5f);
    f.albedo_texture = c.samples > 1 ? make_multisample_texture(c.albedo_format, w, h, c.samples, half_grey)
                                     : make_texture(c.albedo_format, w, h, GL_RGBA, GL_FLOAT, half_grey.data());
    if (c.samples > 1) textures_.push_back(f.albedo_texture);
  }
  if (c.normals) {
    std::vector<float> normals(static_cast<std::size_t>(w) * h * 4, 0.0f);
    for (std::size_t i = 2; i < normals.size(); i += 4) normals[i] = 1.0f;
    f.normal_texture = make_texture(GL_RGBA16F, w, h, GL_RGBA, GL_FLOAT, normals.data());
  }
  if (c.region) {
    f.flags |= SSS_FRAME_REGION;
    f.region[0] = 2;
    f.region[1] = 3;
    f.region[2] = w - 6;
    f.region[3] = h - 5;
  }
  if (is_gles()) {  // ES 3.0 cannot be asked for formats and sizes
    f.color_format = c.color_format;
    f.depth_format = c.stencil ? GL_DEPTH24_STENCIL8 : c.depth_format;
    f.output_format = c.output_format;
    f.stencil_format = c.stencil ? GL_DEPTH24_STENCIL8 : 0;
    f.normal_format = c.normals ? GL_RGBA16F : 0;
    f.strength_format = c.strength_format;
    f.profile_format = c.profile_format;
    f.albedo_format = c.albedo_format;
    f.texture_width = w;
    f.texture_height = h;
  }
  return f;
}

TEST_F(Prewarm, TheFirstFragmentFrameCreatesNothing) {
  Case c{"fragment, in place", settings_with(SSS_PATH_FRAGMENT)};
  expect_no_hitch(c);
  c = Case{"fragment, RGBA32F into a separate RGBA16F output, linear depth, region", settings_with(SSS_PATH_FRAGMENT),
           GL_RGBA32F, GL_RGBA16F, GL_R32F};
  c.region = true;
  if (is_gles()) c.color_format = GL_RGBA16F;  // RGBA32F colour needs extensions on ES
  expect_no_hitch(c);
  c = Case{"fragment behind the host's stencil", settings_with(SSS_PATH_FRAGMENT)};
  c.stencil = true;
  expect_no_hitch(c);
  sss_settings jittered = settings_with(SSS_PATH_FRAGMENT);
  jittered.jitter = 0.5f;
  jittered.flags = 0;
  expect_no_hitch(Case{"jittered taps, no follow-surface", jittered});
}

TEST_F(Prewarm, TheFirstMaskedFrameCreatesNothing) {
  expect_no_hitch(Case{"masked, in place", settings_with(SSS_PATH_FRAGMENT_MASKED)});
  expect_no_hitch(Case{"masked, separate output", settings_with(SSS_PATH_FRAGMENT_MASKED), GL_RGBA16F, GL_RGBA16F});
}

TEST_F(Prewarm, TheFirstHalfResolutionFrameCreatesNothing) {
  expect_no_hitch(Case{"half resolution, in place", settings_with(SSS_PATH_HALF_RESOLUTION)});
  sss_stats stats = {};
  stats.struct_size = sizeof stats;
  ASSERT_EQ(sss_get_stats(sss_, &stats), SSS_OK);
  EXPECT_EQ(stats.last_frame_path, static_cast<uint32_t>(SSS_PATH_HALF_RESOLUTION));
  expect_no_hitch(Case{"half resolution, separate output", settings_with(SSS_PATH_HALF_RESOLUTION), GL_RGBA16F,
                       GL_RGBA16F});
}

TEST_F(Prewarm, TheFirstComputeFrameCreatesNothing) {
  // Where the GL has no compute shaders (OpenGL ES, before 4.3) the frame takes the fragment path,
  // which is what sss_prepare then prepares.
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  const bool has_compute = !is_gles() && major * 10 + minor >= 43;
  const auto last_path = [this] {
    sss_stats stats = {};
    stats.struct_size = sizeof stats;
    EXPECT_EQ(sss_get_stats(sss_, &stats), SSS_OK);
    return stats.last_frame_path;
  };
  expect_no_hitch(Case{"compute, in place", settings_with(SSS_PATH_COMPUTE)});
  EXPECT_EQ(last_path(), has_compute ? SSS_PATH_COMPUTE : SSS_PATH_FRAGMENT);
  expect_no_hitch(Case{"compute, RGBA32F separate output", settings_with(SSS_PATH_COMPUTE), GL_RGBA16F,
                       static_cast<GLenum>(is_gles() ? GL_RGBA16F : GL_RGBA32F)});
  EXPECT_EQ(last_path(), has_compute ? SSS_PATH_COMPUTE : SSS_PATH_FRAGMENT);
  Case stencil{"compute behind the host's stencil", settings_with(SSS_PATH_COMPUTE)};
  stencil.stencil = true;
  expect_no_hitch(stencil);
  EXPECT_EQ(last_path(), has_compute ? SSS_PATH_COMPUTE : SSS_PATH_FRAGMENT);
  expect_no_hitch(Case{"compute, three terms, separate output", several_terms(SSS_PATH_COMPUTE), GL_RGBA16F, GL_RGBA16F});
  EXPECT_EQ(last_path(), has_compute ? SSS_PATH_COMPUTE : SSS_PATH_FRAGMENT);
  expect_no_hitch(Case{"automatic path", settings_with(SSS_PATH_AUTO)});
  std::printf("the automatic path's first frame ran path %u\n", last_path());
}

TEST_F(Prewarm, TheFirstFrameOfSeveralKernelTermsCreatesNothing) {
  expect_no_hitch(Case{"three terms, in place", several_terms(SSS_PATH_FRAGMENT)});
  expect_no_hitch(Case{"three terms, separate output", several_terms(SSS_PATH_FRAGMENT), GL_RGBA16F, GL_RGBA16F});
  expect_no_hitch(Case{"three terms, automatic path", several_terms(SSS_PATH_AUTO)});
}

TEST_F(Prewarm, TheFirstCrossBilateralFrameCreatesNothing) {
  const sss_settings s = settings_with(SSS_PATH_FRAGMENT, SSS_MODE_CROSS_BILATERAL);
  expect_no_hitch(Case{"cross-bilateral, in place", s});
  Case c{"cross-bilateral, normals, separate output", s, GL_RGBA16F, GL_RGBA16F};
  c.normals = true;
  expect_no_hitch(c);
  c = Case{"cross-bilateral behind the host's stencil", s};
  c.stencil = true;
  expect_no_hitch(c);
}

TEST_F(Prewarm, TheFirstMultisampledFrameCreatesNothing) {
  if (!msaa_available()) GTEST_SKIP() << "the MSAA path is desktop OpenGL only";
  Case c{"MSAA, in place", settings_with(SSS_PATH_FRAGMENT)};
  c.samples = 4;
  expect_no_hitch(c);
  c = Case{"MSAA, separate output", settings_with(SSS_PATH_FRAGMENT), GL_RGBA16F, GL_RGBA16F};
  c.samples = 4;
  expect_no_hitch(c);
  c = Case{"MSAA, cross-bilateral", settings_with(SSS_PATH_FRAGMENT, SSS_MODE_CROSS_BILATERAL)};
  c.samples = 4;
  expect_no_hitch(c);
  c = Case{"MSAA behind the host's stencil, three terms", several_terms(SSS_PATH_FRAGMENT)};
  c.samples = 4;
  c.stencil = true;
  expect_no_hitch(c);
  // A texturing mode: the resolve and write-back over a multisampled albedo (sss_prepare accepts
  // albedo_format with samples > 1 since the MSAA path takes one).
  sss_settings post = settings_with(SSS_PATH_FRAGMENT);
  post.texturing = SSS_TEXTURING_POST_SCATTER;
  c = Case{"MSAA, post-scatter, in place", post};
  c.samples = 4;
  c.albedo_format = GL_RGBA16F;
  expect_no_hitch(c);
  post.texturing = SSS_TEXTURING_PRE_AND_POST_SCATTER;
  c = Case{"MSAA, pre- and post-scatter, separate output", post, GL_RGBA16F, GL_RGBA16F};
  c.samples = 4;
  c.albedo_format = GL_RGBA16F;
  expect_no_hitch(c);
}

// A texturing mode on single-sample textures: the passes divide by the albedo, so the fragment and
// compute paths copy the colour first (copies_colour) and, written back, the host's colour becomes
// the passes' output; into a separate output they keep the host's colour apart from it.
TEST_F(Prewarm, TheFirstFrameOfATexturingModeCreatesNothing) {
  for (const uint32_t path : {SSS_PATH_FRAGMENT, SSS_PATH_COMPUTE, SSS_PATH_AUTO}) {
    for (const uint32_t mode : {SSS_TEXTURING_POST_SCATTER, SSS_TEXTURING_PRE_AND_POST_SCATTER}) {
      sss_settings s = settings_with(path);
      s.texturing = mode;
      Case in_place{"a texturing mode, in place", s};
      in_place.albedo_format = GL_RGBA16F;
      expect_no_hitch(in_place);
      Case output{"a texturing mode, separate output", s, GL_RGBA16F, GL_RGBA16F};
      output.albedo_format = GL_RGBA16F;
      expect_no_hitch(output);
    }
  }
}

// An RGBA32F colour's intermediate is RGBA32F (its precision kept): sss_prepare allocates that one.
// A strength texture's frames draw the colour with it into the module's copy first: its program
// and target are prepared too.
TEST_F(Prewarm, TheFirstFrameOfAnRgba32fColourOrAStrengthTextureCreatesNothing) {
  for (uint32_t path : {SSS_PATH_FRAGMENT, SSS_PATH_FRAGMENT_MASKED, SSS_PATH_COMPUTE}) {
    if (!is_gles()) {  // RGBA32F colour needs extensions on ES
      expect_no_hitch(Case{"RGBA32F colour, in place", settings_with(path), GL_RGBA32F});
    }
    Case c{"R11F_G11F_B10F colour with an R8 strength, in place", settings_with(path), GL_R11F_G11F_B10F};
    c.strength_format = GL_R8;
    expect_no_hitch(c);
    c = Case{"RGBA16F colour with an R16F strength, separate output", settings_with(path), GL_RGBA16F, GL_RGBA16F};
    c.strength_format = GL_R16F;
    expect_no_hitch(c);
  }
  Case c{"cross-bilateral, R11F_G11F_B10F colour with an R32F strength",
         settings_with(SSS_PATH_FRAGMENT, SSS_MODE_CROSS_BILATERAL), GL_R11F_G11F_B10F};
  c.strength_format = GL_R32F;
  expect_no_hitch(c);
}

TEST_F(Prewarm, TheFirstFrameOfPerPixelProfilesCreatesNothing) {
  for (uint32_t path : {SSS_PATH_FRAGMENT, SSS_PATH_FRAGMENT_MASKED, SSS_PATH_AUTO}) {
    Case c{"two profiles, R8UI indices, in place", settings_with(path)};
    c.profile_format = GL_R8UI;
    expect_no_hitch(c);
    c = Case{"two profiles, R16UI indices, linear depth, a region, separate output", settings_with(path), GL_RGBA16F,
             GL_RGBA16F, GL_R32F};
    c.region = true;
    c.profile_format = GL_R16UI;
    expect_no_hitch(c);
  }
}

TEST_F(Prewarm, AFrameOfAnotherSizeAllocates) {
  const Case c{"fragment, in place", settings_with(SSS_PATH_FRAGMENT)};
  sss_frame f = frame_for(c, kW - 4, kH - 2);
  fresh_context(c);
  const sss_prepare_desc d = desc_for(c, kW, kH);
  ASSERT_EQ(sss_prepare(sss_, &d), SSS_OK) << sss_last_error(sss_);
  reset_creations();
  ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
  EXPECT_GT(count_of("glTexImage2D"), 0) << describe(creations());
  EXPECT_EQ(count_of("glCompileShader") + count_of("glLinkProgram"), 0) << describe(creations());
  // Prepared for that size too, the next frame there allocates nothing.
  const sss_prepare_desc smaller = desc_for(c, kW - 4, kH - 2);
  ASSERT_EQ(sss_prepare(sss_, &smaller), SSS_OK) << sss_last_error(sss_);
  reset_creations();
  ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
  EXPECT_EQ(total_creations(), 0) << describe(creations());
}

TEST_F(Prewarm, PreparingAgainCreatesNothingAndRestoresTheState) {
  const Case c{"several terms, automatic path", several_terms(SSS_PATH_AUTO)};
  fresh_context(c);
  const sss_prepare_desc d = desc_for(c, kW, kH);
  const Snapshot before = take_snapshot(is_gles());
  reset_creations();
  ASSERT_EQ(sss_prepare(sss_, &d), SSS_OK) << sss_last_error(sss_);
  EXPECT_GT(total_creations(), 0);
  EXPECT_EQ(describe_differences(before, take_snapshot(is_gles())), "");
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  reset_creations();
  ASSERT_EQ(sss_prepare(sss_, &d), SSS_OK) << sss_last_error(sss_);
  EXPECT_EQ(total_creations(), 0) << describe(creations());
}

TEST_F(Prewarm, BadDescriptionsFailWithTheirMessageAndBuildNothing) {
  const Case c{"fragment, in place", settings_with(SSS_PATH_FRAGMENT)};
  fresh_context(c);
  const sss_prepare_desc good = desc_for(c, kW, kH);
  struct Bad {
    const char* expected;  // in the message
    sss_result code;
    sss_prepare_desc desc;
  };
  std::vector<Bad> bad;
  const auto with = [&](const char* expected, sss_result code, auto change) {
    sss_prepare_desc d = good;
    change(d);
    bad.push_back({expected, code, d});
  };
  with("desc->struct_size = 4", SSS_ERROR_INVALID_ARGUMENT, [](sss_prepare_desc& d) { d.struct_size = 4; });
  with("desc->width = 0", SSS_ERROR_INVALID_ARGUMENT, [](sss_prepare_desc& d) { d.width = 0; });
  with("height = -3", SSS_ERROR_INVALID_ARGUMENT, [](sss_prepare_desc& d) { d.height = -3; });
  with("above GL_MAX_TEXTURE_SIZE", SSS_ERROR_INVALID_ARGUMENT, [](sss_prepare_desc& d) { d.width = 1 << 30; });
  with("desc->color_format = 0x0000", SSS_ERROR_INVALID_ARGUMENT, [](sss_prepare_desc& d) { d.color_format = 0; });
  with("desc->color_format = 0x8058", SSS_ERROR_INVALID_ARGUMENT, [](sss_prepare_desc& d) { d.color_format = GL_RGBA8; });
  with("desc->output_format = 0x822E", SSS_ERROR_INVALID_ARGUMENT, [](sss_prepare_desc& d) { d.output_format = GL_R32F; });
  with("desc->depth_format = 0x881A", SSS_ERROR_INVALID_ARGUMENT, [](sss_prepare_desc& d) { d.depth_format = GL_RGBA16F; });
  with("desc->samples = 33", SSS_ERROR_INVALID_ARGUMENT, [](sss_prepare_desc& d) { d.samples = 33; });
  with("desc->samples = -1", SSS_ERROR_INVALID_ARGUMENT, [](sss_prepare_desc& d) { d.samples = -1; });
  with("desc->stencil_format = 0x81A6", SSS_ERROR_INVALID_ARGUMENT,
       [](sss_prepare_desc& d) { d.stencil_format = GL_DEPTH_COMPONENT24; });
  with("desc->flags = 0x80", SSS_ERROR_INVALID_ARGUMENT, [](sss_prepare_desc& d) { d.flags = 0x80; });
  if (is_gles()) {
    with("desc->samples = 4: the MSAA path needs desktop OpenGL", SSS_ERROR_UNSUPPORTED,
         [](sss_prepare_desc& d) { d.samples = 4; });
  }
  for (const Bad& b : bad) {
    SCOPED_TRACE(b.expected);
    reset_creations();
    EXPECT_EQ(sss_prepare(sss_, &b.desc), b.code);
    EXPECT_NE(std::string(sss_last_error(sss_)).find(b.expected), std::string::npos) << sss_last_error(sss_);
    EXPECT_EQ(total_creations(), 0) << describe(creations());
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  }
  EXPECT_EQ(sss_prepare(sss_, nullptr), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("desc is NULL"), std::string::npos);
  EXPECT_EQ(sss_prepare(nullptr, &good), SSS_ERROR_INVALID_ARGUMENT);
  // Nothing was built: the first frame still builds what it needs.
  sss_frame f = frame_for(c, kW, kH);
  reset_creations();
  ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
  EXPECT_GT(total_creations(), 0);
}

// Kernel fits run in sss_set_settings and nowhere else: never in sss_set_camera, sss_prepare,
// sss_apply_frame or sss_get_stats; and settings that go back to a fitted kernel built lately
// take it without fitting again. How long a fit takes is printed (and logged at DEBUG).
TEST_F(Prewarm, FitsRunInSetSettingsOnlyAndAreKept) {
  LogRecord log;
  log_ = &log;
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  sss_settings guided = settings_with(SSS_PATH_FRAGMENT);
  sss_test::kernel_of(guided).family = SSS_KERNEL_GUIDED;
  const sss_settings marble = several_terms(SSS_PATH_FRAGMENT);
  const sss_settings plain = settings_with(SSS_PATH_FRAGMENT);
  using Clock = std::chrono::steady_clock;
  const auto timed = [&](const sss_settings& s) {
    const auto start = Clock::now();
    EXPECT_EQ(sss_set_settings(sss_, &s), SSS_OK) << sss_last_error(sss_);
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  };
  const double guided_fit = timed(guided);
  const double marble_fit = timed(marble);
  EXPECT_EQ(log.count(SSS_LOG_DEBUG, "sss_set_settings: built the kernel"), 2);
  timed(plain);
  const double guided_again = timed(guided);
  const double marble_again = timed(marble);
  EXPECT_EQ(log.count(SSS_LOG_DEBUG, "kept from earlier settings"), 2);
  std::printf("sss_set_settings: guided rank-1 fit %.1f ms, again %.3f ms; three Gaussians fitted to marble %.1f ms, "
              "again %.3f ms\n", guided_fit, guided_again, marble_fit, marble_again);
  for (const auto& m : log.messages) {
    if (m.second.find("sss_set_settings: built the") != std::string::npos) std::printf("  log: %s\n", m.second.c_str());
  }
  // The largest fit the settings allow: the guided family at 65 taps.
  sss_settings widest = guided;
  widest.taps = 65;
  std::printf("sss_set_settings: guided rank-1 fit at 65 taps %.1f ms\n", timed(widest));
  // The cross-bilateral mode's measured-material profile is fitted once as well.
  sss_settings cbf = settings_with(SSS_PATH_FRAGMENT, SSS_MODE_CROSS_BILATERAL);
  cbf.cbf_profile = SSS_PROFILE_KETCHUP;
  const double cbf_fit = timed(cbf);
  sss_settings apple = cbf;
  apple.cbf_profile = SSS_PROFILE_APPLE;
  timed(apple);
  const double cbf_again = timed(cbf);
  EXPECT_EQ(log.count(SSS_LOG_DEBUG, "the cross-bilateral kernel was kept"), 1);
  std::printf("sss_set_settings: cross-bilateral ketchup profile %.1f ms, again %.3f ms\n", cbf_fit, cbf_again);

  // The per-frame calls build no kernel.
  const int built = log.count(SSS_LOG_DEBUG, "sss_set_settings: built the");
  const Case c{"guided", guided};
  ASSERT_EQ(sss_set_settings(sss_, &guided), SSS_OK);
  sss_frame f = frame_for(c, kW, kH);
  const sss_prepare_desc d = desc_for(c, kW, kH);
  ASSERT_EQ(sss_prepare(sss_, &d), SSS_OK) << sss_last_error(sss_);
  for (int i = 0; i < 3; ++i) {
    ASSERT_EQ(sss_set_camera(sss_, scene_.projection.data()), SSS_OK);
    ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
    sss_stats stats = {};
    stats.struct_size = sizeof stats;
    ASSERT_EQ(sss_get_stats(sss_, &stats), SSS_OK);
  }
  EXPECT_EQ(log.count(SSS_LOG_DEBUG, "sss_set_settings: built the"), built);
  sss_destroy(sss_);
  sss_ = nullptr;
  log_ = nullptr;
}

}  // namespace
}  // namespace sss_test
