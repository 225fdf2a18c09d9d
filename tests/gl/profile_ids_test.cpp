// Per-pixel profiles (issue 23): sss_set_profiles and sss_frame.profile_texture run several materials
// in one pass pair, and a tap whose index (profile and object) differs from its centre's is not
// taken, so no light crosses between materials or objects.
//
// The reference for "the selection costs no accuracy": a tap of another index counts as the
// centre's colour, which is exactly what the follow-surface blend does to a tap beyond the kernel's
// reach in depth (mix(tap, centre, 1) is the centre, bit for bit). So each material's pixels, run
// with its neighbours' indices, must equal the same profile run alone on a frame where every other
// material's pixels are pushed far behind: bit for bit, on every pixel of the material, its border
// included (a neighbour of another index does not serve the surface's tangent either, as a pushed
// one does not: pass_surface.hpp). Its interior (the pixels the push does not change) must equal the
// plain single-profile run of the unchanged frame too. With R8UI indices the module carries the
// index in the low byte of each pixel's blue colour word (pass_inputs.frag: one fetch per tap),
// which an RGBA16F colour leaves at 0 (its float bits end in 13 zeros), so R8UI and R16UI indices
// give the same image bit for bit too: the distances, and with them the surface's tangents, stay
// whole. (Until 2026-11 the index rode in the distance's low byte, which cost it 3e-5 of itself;
// once the tangents came from the distances, that moved sheared taps by a column.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>

#include "api/profiles.hpp"
#include "filter_case.hpp"
#include "math/cpu_separable_filter.hpp"
#include "host_gl_util.hpp"
#include "multisample_textures.hpp"

using namespace host_gl;

namespace sss_test {
namespace {

constexpr int kW = 64, kH = 48;
constexpr int kBoundary = 30;  // pixels x < kBoundary are the first material, the rest the second

// A second look: other strength and falloff, twice the scattering distance.
sss_settings second_look(sss_settings s) {
  s.scale = 2.0f;
  s.strength[0] = 0.5f;
  s.strength[1] = 0.95f;
  s.strength[2] = 0.3f;
  s.falloff[0] = 0.7f;
  s.falloff[1] = 1.0f;
  s.falloff[2] = 0.2f;
  return s;
}

class ProfileIds : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    scene_ = make_relief_scene(kW, kH, 5, perspective_matrix(40.0f, 64.0f / 48.0f, 0.1f, 10.0f));
    first_ = visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f);
    first_.path = SSS_PATH_FRAGMENT;
  }
  // An R8UI (or R16UI) texture of per-pixel values.
  GLuint make_ids(const std::function<unsigned(int x, int y)>& value, bool sixteen = false) {
    std::vector<uint16_t> v16(static_cast<std::size_t>(kW) * kH);
    std::vector<uint8_t> v8(v16.size());
    for (int y = 0; y < kH; ++y) {
      for (int x = 0; x < kW; ++x) {
        v16[static_cast<std::size_t>(y) * kW + x] = static_cast<uint16_t>(value(x, y));
        v8[static_cast<std::size_t>(y) * kW + x] = static_cast<uint8_t>(value(x, y));
      }
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    const GLuint t = sixteen ? make_texture(GL_R16UI, kW, kH, GL_RED_INTEGER, GL_UNSIGNED_SHORT, v16.data())
                             : make_texture(GL_R8UI, kW, kH, GL_RED_INTEGER, GL_UNSIGNED_BYTE, v8.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    return t;
  }
  void fresh(uint32_t flags = 0) {
    if (sss_ != nullptr) sss_destroy(sss_);
    sss_ = create_sss(flags);
    ASSERT_NE(sss_, nullptr);
    ASSERT_EQ(sss_set_camera(sss_, scene_.projection.data()), SSS_OK);
  }
  // The scene's colour and depth, with the pixels `far(x, y)` selects pushed far behind.
  struct Inputs {
    GLuint color = 0, depth = 0;
  };
  Inputs make_inputs(const std::function<bool(int x, int y)>& far = nullptr) {
    SyntheticScene s = scene_;
    if (far) {
      for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
          if (far(x, y)) s.distance[static_cast<std::size_t>(y) * kW + x] = 9.0f;
        }
      }
      compute_window_depth(&s);
    }
    if (linear_depth_) {  // the view distance itself, R32F
      return {make_rgba16f(kW, kH, s.color), make_texture(GL_R32F, kW, kH, GL_RED, GL_FLOAT, s.distance.data())};
    }
    return {make_rgba16f(kW, kH, s.color), make_depth32f(kW, kH, s.window_depth)};
  }
  // The frame, described (OpenGL ES 3.0 cannot be asked), written back.
  sss_result apply(const Inputs& in, GLuint ids, GLenum ids_format = GL_R8UI) {
    sss_frame f = frame_of(in.color, in.depth);
    f.texture_width = kW;
    f.texture_height = kH;
    f.color_format = GL_RGBA16F;
    f.depth_format = linear_depth_ ? GL_R32F : GL_DEPTH_COMPONENT32F;
    f.profile_texture = ids;
    f.profile_format = ids != 0 ? ids_format : 0;
    return sss_apply_frame(sss_, &f);
  }
  std::vector<float> run_profiles(const sss_settings* profiles, uint32_t count, const std::function<unsigned(int, int)>& id,
                                  bool sixteen = false) {
    fresh();
    EXPECT_EQ(sss_set_profiles(sss_, profiles, count), SSS_OK) << sss_last_error(sss_);
    const Inputs in = make_inputs();
    EXPECT_EQ(apply(in, make_ids(id, sixteen), sixteen ? GL_R16UI : GL_R8UI), SSS_OK) << sss_last_error(sss_);
    return read_rgba(in.color, kW, kH);
  }
  std::vector<float> run_single(const sss_settings& s, const std::function<bool(int, int)>& far = nullptr) {
    fresh();
    EXPECT_EQ(sss_set_settings(sss_, &s), SSS_OK) << sss_last_error(sss_);
    const Inputs in = make_inputs(far);
    EXPECT_EQ(apply(in, 0), SSS_OK) << sss_last_error(sss_);
    return read_rgba(in.color, kW, kH);
  }

  // Two materials in one frame (one pass pair), the second's pixels holding `second_value`,
  // against each run alone with the other pushed away (see the top of this file).
  // `sixteen`: R16UI indices, else R8UI (both bit for bit).
  void expect_each_material_alone(const sss_settings profiles[2], unsigned second_value, bool sixteen);

  SyntheticScene scene_;
  sss_settings first_{};
  bool linear_depth_ = false;  // the host's depth is linear view distance (R32F), not hardware depth
};

// rgb of pixel (x, y) equal in a and b, bit for bit (alpha is the host's in both).
bool same_rgb(const std::vector<float>& a, const std::vector<float>& b, int x, int y) {
  const std::size_t i = (static_cast<std::size_t>(y) * kW + x) * 4;
  return std::memcmp(&a[i], &b[i], 3 * sizeof(float)) == 0;
}

void ProfileIds::expect_each_material_alone(const sss_settings profiles[2], unsigned second_value, bool sixteen) {
  const auto left = [](int x, int) { return x < kBoundary; };
  const auto right = [](int x, int) { return x >= kBoundary; };
  const auto agree = same_rgb;
  const std::vector<float> mixed =
      run_profiles(profiles, 2, [&](int x, int) { return x < kBoundary ? 0u : second_value; }, sixteen);
  const std::vector<float> first_alone = run_single(profiles[0], right);
  const std::vector<float> second_alone = run_single(profiles[1], left);
  const std::vector<float> first_plain = run_single(profiles[0]);
  const std::vector<float> second_plain = run_single(profiles[1]);
  int mismatches = 0, interior[2] = {0, 0}, interior_mismatches = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const bool first = x < kBoundary;
      const std::vector<float>& alone = first ? first_alone : second_alone;
      const std::vector<float>& plain = first ? first_plain : second_plain;
      if (!agree(mixed, alone, x, y)) ++mismatches;
      if (same_rgb(alone, plain, x, y)) {  // the other material out of reach: the interior
        ++interior[first ? 0 : 1];
        if (!agree(mixed, plain, x, y)) ++interior_mismatches;
      }
    }
  }
  std::printf("interior pixels: %d of %d and %d of %d\n", interior[0], kBoundary * kH, interior[1],
              (kW - kBoundary) * kH);
  EXPECT_EQ(mismatches, 0) << "pixels whose result differs from their profile run alone";
  EXPECT_EQ(interior_mismatches, 0);
  // The comparison is not empty: much of each material is interior, and the mixed frame blurs.
  EXPECT_GT(interior[0], kBoundary * kH / 4);
  EXPECT_GT(interior[1], (kW - kBoundary) * kH / 4);
  EXPECT_NE(mixed, first_plain);
  EXPECT_NE(mixed, second_plain);
}

}  // namespace

TEST_F(ProfileIds, EachMaterialMatchesItsProfileRunAlone) {
  const sss_settings profiles[2] = {first_, second_look(first_)};
  expect_each_material_alone(profiles, 1u, false);
}

TEST_F(ProfileIds, EachMaterialMatchesItsProfileRunAloneBitForBitWithR16UI) {
  const sss_settings profiles[2] = {first_, second_look(first_)};
  expect_each_material_alone(profiles, 1u, true);
}

TEST_F(ProfileIds, EachMaterialMatchesItsProfileRunAloneOnLinearDepth) {
  linear_depth_ = true;
  const sss_settings profiles[2] = {first_, second_look(first_)};
  expect_each_material_alone(profiles, 1u, false);
  expect_each_material_alone(profiles, 1u, true);
}

// Against the CPU model of the per-pixel variant (math::cpu_profile_filter): two profiles and two
// objects in one frame. Tolerance 3e-3 relative, as MatchesCpuModel.* (tests/gl/matches_cpu_model_test.cpp
// explains it: a few float ulps of difference may flip the RGBA16F intermediate's rounding once, and
// the output's once more); a wrong tap, weight, profile or index test moves values by 1e-2 or more.
TEST_F(ProfileIds, MatchesTheCpuModel) {
  const sss_settings profiles[2] = {first_, second_look(first_)};
  const auto id = [](int x, int y) { return x < kBoundary ? (y < kH / 2 ? 0u : 0x10u) : (y < 20 ? 1u : 7u); };
  const std::vector<float> gpu = run_profiles(profiles, 2, id);
  std::vector<uint16_t> ids(static_cast<std::size_t>(kW) * kH);
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) ids[static_cast<std::size_t>(y) * kW + x] = static_cast<uint16_t>(id(x, y));
  }
  const ProfileModels models = profile_models(profiles, 2, scene_.projection, kW, kH);
  const std::vector<float> input = read_rgba(make_rgba16f(kW, kH, scene_.color), kW, kH);
  sss::math::CpuFilterImage image;
  image.width = kW;
  image.height = kH;
  image.color = input.data();
  image.depth = scene_.window_depth.data();
  image.output_is_half = true;  // written back into the RGBA16F colour
  std::vector<float> cpu(input.size());
  // R8UI indices: the model reads the blue colour word's low byte as 0, as the passes do.
  sss::math::cpu_profile_filter(models.kernel_pointers(), models.constants, ids.data(), image, cpu.data(), true);
  const float difference = largest_relative_difference(gpu, cpu);
  std::printf("GPU vs CPU model: largest relative difference %.3g\n", difference);
  EXPECT_LE(difference, 3e-3f);
  EXPECT_GT(largest_relative_difference(gpu, input), 0.02f);  // it blurred
  // Pixels of index 7 (no such profile) kept their value on both.
  EXPECT_EQ(gpu[(static_cast<std::size_t>(30) * kW + 50) * 4], input[(static_cast<std::size_t>(30) * kW + 50) * 4]);
}

// The profile view (SSS_DEBUG_VIEW_PROFILE): each pixel's profile and object, (0, 0, 0, 1) where its
// index has no profile, into an output; the colour untouched.
TEST_F(ProfileIds, TheProfileViewShowsEachPixelsIndex) {
  const sss_settings profiles[2] = {first_, second_look(first_)};
  const auto id = [](int x, int y) { return x < kBoundary ? (y < kH / 2 ? 0u : 0x10u) : (y < 20 ? 1u : 0x27u); };
  fresh();
  ASSERT_EQ(sss_set_profiles(sss_, profiles, 2), SSS_OK) << sss_last_error(sss_);
  const Inputs in = make_inputs();
  const GLuint output = make_rgba16f(kW, kH, std::vector<float>(static_cast<std::size_t>(kW) * kH * 4, -1.0f));
  sss_frame f = frame_of(in.color, in.depth, output);
  describe_frame(&f, GL_RGBA16F, GL_RGBA16F, GL_DEPTH_COMPONENT32F, kW, kH);
  f.profile_texture = make_ids(id);
  f.profile_format = GL_R8UI;
  f.debug_view = SSS_DEBUG_VIEW_PROFILE;
  const std::vector<float> before = read_rgba(in.color, kW, kH);
  ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
  EXPECT_EQ(read_rgba(in.color, kW, kH), before);
  const std::vector<float> view = read_rgba(output, kW, kH);
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const unsigned v = id(x, y);
      const bool has_profile = (v & 15u) < 2u;
      const float* p = &view[(static_cast<std::size_t>(y) * kW + x) * 4];
      ASSERT_EQ(p[0], has_profile ? static_cast<float>(v & 15u) : 0.0f) << x << ", " << y;
      ASSERT_EQ(p[1], has_profile ? static_cast<float>(v >> 4) : 0.0f) << x << ", " << y;
      ASSERT_EQ(p[2], has_profile ? 1.0f : 0.0f);  // 1 wherever the passes run
      ASSERT_EQ(p[3], 1.0f);
    }
  }
}

TEST_F(ProfileIds, EachObjectOfOneMaterialMatchesItsRunAlone) {
  // One profile, two objects (index 0 and 0x10: profile 0, object 1): the object ID alone separates them.
  const sss_settings profiles[2] = {first_, first_};
  expect_each_material_alone(profiles, 0x10u, false);
  expect_each_material_alone(profiles, 0x10u, true);
}

TEST_F(ProfileIds, NoLightCrossesBetweenIndicesAtTheSameDepth) {
  // A plane facing the camera: the left half lit, the right half black, every pixel translucent at
  // the same depth, so the follow-surface blend lets every tap through. Only the index stops light.
  scene_ = make_flat_scene(kW, kH, {1.0f, 0.5f, 0.25f, 1.0f}, 1.0f, scene_.projection);
  for (int y = 0; y < kH; ++y) {
    for (int x = kBoundary; x < kW; ++x) {
      for (int c = 0; c < 3; ++c) scene_.color[(static_cast<std::size_t>(y) * kW + x) * 4 + c] = 0.0f;
    }
  }
  const std::vector<float> input = read_rgba(make_rgba16f(kW, kH, scene_.color), kW, kH);
  // The largest relative change of a left-half channel: the weight of the rejected taps stays on
  // the centre, so the lit half loses no light at the border (within the weights' float sum).
  const auto left_change = [&](const std::vector<float>& out) {
    float most = 0.0f;
    for (int y = 0; y < kH; ++y) {
      for (int x = 0; x < kBoundary; ++x) {
        for (int c = 0; c < 3; ++c) {
          const std::size_t i = (static_cast<std::size_t>(y) * kW + x) * 4 + c;
          most = std::max(most, std::fabs(out[i] - input[i]) / input[i]);
        }
      }
    }
    return most;
  };
  const auto light_on_the_right = [&](const std::vector<float>& out) {
    float most = 0.0f;
    for (int y = 0; y < kH; ++y) {
      for (int x = kBoundary; x < kW; ++x) {
        for (int c = 0; c < 3; ++c) most = std::max(most, out[(static_cast<std::size_t>(y) * kW + x) * 4 + c]);
      }
    }
    return most;
  };
  for (const unsigned right_value : {1u, 0x10u, 0x21u}) {  // another profile; another object; both
    const sss_settings profiles[3] = {first_, first_, second_look(first_)};
    const std::vector<float> out =
        run_profiles(profiles, 3, [&](int x, int) { return x < kBoundary ? 0u : right_value; });
    EXPECT_EQ(light_on_the_right(out), 0.0f) << "right half index " << right_value;
    EXPECT_LE(left_change(out), 1.0f / 1024.0f) << "one half-float step";
  }
  // Without indices the light crosses, and the lit half loses it at the border (what the test would
  // see if the rejection were broken).
  const std::vector<float> plain = run_single(first_);
  EXPECT_GT(light_on_the_right(plain), 0.01f);
  EXPECT_GT(left_change(plain), 0.01f);
}

TEST_F(ProfileIds, EveryPathAndR16UIGiveTheSameImage) {
  const sss_settings look = second_look(first_);
  const auto id = [](int x, int y) { return x < kBoundary ? (y < kH / 2 ? 0u : 0x30u) : 1u; };
  sss_settings profiles[2] = {first_, look};
  const std::vector<float> fragment = run_profiles(profiles, 2, id);
  for (const uint32_t path : {SSS_PATH_FRAGMENT_MASKED, SSS_PATH_COMPUTE, SSS_PATH_AUTO}) {
    profiles[0].path = profiles[1].path = path;
    EXPECT_EQ(run_profiles(profiles, 2, id), fragment) << "path " << path;
    sss_stats stats = {};
    stats.struct_size = sizeof stats;
    ASSERT_EQ(sss_get_stats(sss_, &stats), SSS_OK);
    EXPECT_NE(stats.last_frame_path, static_cast<uint32_t>(SSS_PATH_COMPUTE)) << "profiles run the fragment passes";
  }
  profiles[0].path = profiles[1].path = SSS_PATH_FRAGMENT;
  fresh();
  ASSERT_EQ(sss_set_profiles(sss_, profiles, 2), SSS_OK);
  const Inputs in = make_inputs();
  ASSERT_EQ(apply(in, make_ids(id, true), GL_R16UI), SSS_OK) << sss_last_error(sss_);
  // R16UI and R8UI indices give the same image bit for bit (see the top).
  const std::vector<float> wide = read_rgba(in.color, kW, kH);
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) EXPECT_TRUE(same_rgb(wide, fragment, x, y)) << "R16UI at " << x << ", " << y;
  }
  EXPECT_NE(wide, read_rgba(make_rgba16f(kW, kH, scene_.color), kW, kH)) << "R16UI blurs";
}

TEST_F(ProfileIds, PixelsOfAnIndexBeyondTheProfilesAreLeftAlone) {
  const sss_settings profiles[2] = {first_, second_look(first_)};
  // Index 5 on the right: no such profile. Without debug checks those pixels keep their value.
  const std::vector<float> out = run_profiles(profiles, 2, [](int x, int) { return x < kBoundary ? 0u : 5u; });
  const std::vector<float> input = read_rgba(make_rgba16f(kW, kH, scene_.color), kW, kH);
  int changed_right = 0, changed_left = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) (same_rgb(out, input, x, y) ? 0 : ++(x < kBoundary ? changed_left : changed_right));
  }
  EXPECT_EQ(changed_right, 0);
  EXPECT_GT(changed_left, 0);
}

TEST_F(ProfileIds, BadInputIsRefusedAndNothingIsDrawn) {
  const sss_settings profiles[2] = {first_, second_look(first_)};
  fresh(SSS_CREATE_DEBUG_CHECKS);
  ASSERT_EQ(sss_set_profiles(sss_, profiles, 2), SSS_OK) << sss_last_error(sss_);
  const Inputs in = make_inputs();
  const std::vector<float> before = read_rgba(in.color, kW, kH);
  const auto expect_refused = [&](sss_result got, sss_result want, const char* part) {
    EXPECT_EQ(got, want) << sss_result_string(got) << " " << sss_last_error(sss_);
    EXPECT_NE(std::string(sss_last_error(sss_)).find(part), std::string::npos) << sss_last_error(sss_);
    EXPECT_EQ(read_rgba(in.color, kW, kH), before) << part;
  };
  // An index beyond the profiles set (a missing profile), found by the debug checks' readback.
  expect_refused(apply(in, make_ids([](int x, int y) { return x == 40 && y == 7 ? 2u : 0u; })),
                 SSS_ERROR_INVALID_TEXTURE, "pixel (40, 7) holds 2, profile index 2, but 2 profiles are set");
  // A normalised R8 texture, a wrong size, a format outside the list.
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const std::vector<uint8_t> zeros(static_cast<std::size_t>(kW) * kH, 0);
  const GLuint r8 = make_texture(GL_R8, kW, kH, GL_RED, GL_UNSIGNED_BYTE, zeros.data());
  const GLuint small = make_texture(GL_R8UI, kW / 2, kH, GL_RED_INTEGER, GL_UNSIGNED_BYTE, zeros.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  if (!is_gles()) {  // ES 3.0 takes the description on trust (it cannot ask the GL)
    sss_frame f = frame_of(in.color, in.depth);
    f.profile_texture = r8;
    expect_refused(sss_apply_frame(sss_, &f), SSS_ERROR_INVALID_TEXTURE, "has format GL_R8: expected GL_R8UI or GL_R16UI");
    f.profile_texture = small;
    expect_refused(sss_apply_frame(sss_, &f), SSS_ERROR_INVALID_TEXTURE, "is 32x48 but the colour texture is 64x48");
  }
  expect_refused(apply(in, make_ids([](int, int) { return 0u; }), GL_R8), SSS_ERROR_INVALID_ARGUMENT,
                 "frame->profile_format = 0x8229 (GL_R8): expected 0 or GL_R8UI (0x8232) or GL_R16UI (0x8234)");
  // The cross-bilateral mode takes no profile texture.
  sss_settings cbf = first_;
  cbf.mode = SSS_MODE_CROSS_BILATERAL;
  ASSERT_EQ(sss_set_settings(sss_, &cbf), SSS_OK);
  expect_refused(apply(in, make_ids([](int, int) { return 0u; })), SSS_ERROR_UNSUPPORTED,
                 "in the cross-bilateral mode");
}

TEST_F(ProfileIds, SetProfilesRefusesAndKeepsTheOldSet) {
  fresh();
  sss_settings profiles[3] = {first_, second_look(first_), second_look(first_)};
  ASSERT_EQ(sss_set_profiles(sss_, profiles, 2), SSS_OK) << sss_last_error(sss_);
  const auto expect_refused = [&](uint32_t count, sss_result want, const char* part, const sss_settings* p) {
    const sss_result got = sss_set_profiles(sss_, p, count);
    EXPECT_EQ(got, want) << sss_last_error(sss_);
    EXPECT_NE(std::string(sss_last_error(sss_)).find(part), std::string::npos) << sss_last_error(sss_);
  };
  expect_refused(0, SSS_ERROR_INVALID_ARGUMENT, "count = 0: must be in [1, SSS_MAX_PROFILES = 16]", profiles);
  expect_refused(17, SSS_ERROR_INVALID_ARGUMENT, "count = 17", profiles);
  expect_refused(2, SSS_ERROR_INVALID_ARGUMENT, "profiles is NULL", nullptr);
  profiles[2].taps = 9;
  expect_refused(3, SSS_ERROR_INVALID_ARGUMENT, "profiles[2].taps = 9 differs from profiles[0].taps = 17", profiles);
  profiles[2] = second_look(first_);
  profiles[2].scale = -1.0f;
  expect_refused(3, SSS_ERROR_INVALID_ARGUMENT, "profiles[2]: settings->scale = -1", profiles);
  profiles[2] = path_case_settings(second_look(first_), SSS_PATH_FRAGMENT, SSS_MODE_SEPARABLE, true);
  expect_refused(3, SSS_ERROR_UNSUPPORTED, "profiles[2].kernel (family", profiles);
  sss_settings cbf[2] = {first_, first_};
  cbf[0].mode = cbf[1].mode = SSS_MODE_CROSS_BILATERAL;
  expect_refused(2, SSS_ERROR_UNSUPPORTED, "SSS_MODE_CROSS_BILATERAL", cbf);
  // The set of two is still there: index 1 pixels blur with the second look.
  const Inputs in = make_inputs();
  ASSERT_EQ(apply(in, make_ids([](int x, int) { return x < kBoundary ? 0u : 1u; })), SSS_OK) << sss_last_error(sss_);
  const std::vector<float> kept = read_rgba(in.color, kW, kH);
  const sss_settings two[2] = {first_, second_look(first_)};
  EXPECT_EQ(kept, run_profiles(two, 2, [](int x, int) { return x < kBoundary ? 0u : 1u; }));
  // sss_set_settings is a set of one: index 1 is then beyond the profiles (left alone).
  fresh();
  ASSERT_EQ(sss_set_profiles(sss_, two, 2), SSS_OK);
  ASSERT_EQ(sss_set_settings(sss_, &first_), SSS_OK);
  const Inputs again = make_inputs();
  ASSERT_EQ(apply(again, make_ids([](int, int) { return 1u; })), SSS_OK);
  EXPECT_EQ(read_rgba(again.color, kW, kH), read_rgba(make_rgba16f(kW, kH, scene_.color), kW, kH));
}

TEST_F(ProfileIds, MultisampledColourIsRefused) {
  if (is_gles()) GTEST_SKIP() << "the MSAA path is desktop OpenGL";
  fresh();
  const sss_settings profiles[2] = {first_, second_look(first_)};
  ASSERT_EQ(sss_set_profiles(sss_, profiles, 2), SSS_OK);
  const SyntheticScene fine = upsample_2x2(scene_);
  const GLuint color = make_multisample_texture(GL_RGBA16F, kW, kH, 4, fine.color);
  const GLuint depth = make_multisample_texture(GL_DEPTH_COMPONENT32F, kW, kH, 4, fine.window_depth);
  ASSERT_NE(color, 0u);
  ASSERT_NE(depth, 0u);
  sss_frame f = frame_of(color, depth);
  f.profile_texture = make_ids([](int, int) { return 0u; });
  EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_ERROR_UNSUPPORTED) << sss_last_error(sss_);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("single-sample"), std::string::npos) << sss_last_error(sss_);
}

}  // namespace sss_test
