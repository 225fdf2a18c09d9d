// Versioned structs (sss.h, "struct_size"): a struct of an earlier release is accepted and means what
// it meant then, a size no release defined is refused with a message naming the struct and the size.
// The 0.1 and 0.2 layouts of sss_settings are written out here from those releases' sss.h (git
// 4cb68e3 and 5646dcc), field for field, as a host compiled against them would pass them.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "gl_fixture.hpp"
#include "math/fitters.hpp"
#include "synthetic_scene.hpp"

namespace sss_test {
namespace {

// 0.1-0.3's sss_profile_desc and sss_kernel_desc (their sss_tools.h): 0.4 appended the burley fields.
struct ProfileDesc03 {
  uint32_t struct_size;
  int32_t profile, gaussian_count, table_size;
  const float* table_radius_mm;
  const float* table_rgb;
};
struct KernelDesc03 {
  uint32_t struct_size;
  int32_t family, taps, rank;
  uint32_t flags;
  float guide_k, radius_mm;
  float strength[3], falloff[3], near_variance_mm2[3], far_variance_mm2[3], near_weight[3];
  ProfileDesc03 profile;
};

// Today's desc as 0.3's (field for field) and 0.3's as today's reads it (the burley fields default).
KernelDesc03 as03(const sss_kernel_desc& k) {
  KernelDesc03 o{};
  o.struct_size = sizeof o;
  o.family = k.family, o.taps = k.taps, o.rank = k.rank, o.flags = k.flags, o.guide_k = k.guide_k;
  o.radius_mm = k.radius_mm;
  for (int c = 0; c < 3; ++c) {
    o.strength[c] = k.strength[c], o.falloff[c] = k.falloff[c], o.near_variance_mm2[c] = k.near_variance_mm2[c];
    o.far_variance_mm2[c] = k.far_variance_mm2[c], o.near_weight[c] = k.near_weight[c];
  }
  o.profile = {sizeof o.profile, k.profile.profile, k.profile.gaussian_count, k.profile.table_size,
               k.profile.table_radius_mm, k.profile.table_rgb};
  return o;
}
sss_kernel_desc as_current(const KernelDesc03& o) {
  sss_kernel_desc k;
  sss_default_kernel_desc(&k);
  k.family = o.family, k.taps = o.taps, k.rank = o.rank, k.flags = o.flags, k.guide_k = o.guide_k;
  k.radius_mm = o.radius_mm;
  for (int c = 0; c < 3; ++c) {
    k.strength[c] = o.strength[c], k.falloff[c] = o.falloff[c], k.near_variance_mm2[c] = o.near_variance_mm2[c];
    k.far_variance_mm2[c] = o.far_variance_mm2[c], k.near_weight[c] = o.near_weight[c];
  }
  k.profile.profile = o.profile.profile, k.profile.gaussian_count = o.profile.gaussian_count;
  k.profile.table_size = o.profile.table_size, k.profile.table_radius_mm = o.profile.table_radius_mm;
  k.profile.table_rgb = o.profile.table_rgb;
  return k;
}

// sss 0.1's sss_settings (its sss.h): the paper's width, the kernel desc embedded.
struct Settings01 {
  uint32_t struct_size;
  float width;
  float strength[3];
  float falloff[3];
  int32_t samples;
  uint32_t flags;  // SSS_FOLLOW_SURFACE 0x1, SSS_ADAPTIVE_TAPS 0x2
  uint32_t mode;
  int32_t cbf_taps;
  float cbf_r_max_mm;
  uint32_t cbf_profile;  // an sss_material 0..11, 0x100 SSS_PROFILE_MIKKELSEN_2010, 0x101 SSS_PROFILE_KERNEL
  KernelDesc03 kernel;
  float jitter;
  uint32_t path;
};

// sss 0.2's: world units per millimetre, scale and separable_scale apart.
struct Settings02 {
  uint32_t struct_size;
  float world_units_per_mm;
  float scale;
  float strength[3];
  float falloff[3];
  float separable_scale;
  int32_t samples;
  uint32_t flags;
  uint32_t mode;
  int32_t cbf_taps;
  float cbf_r_max_mm;
  uint32_t cbf_profile;
  KernelDesc03 kernel;
  float jitter;
  uint32_t path;
};

// sss 0.4's sss_frame (its sss.h): 0.1's and 0.2's are its fields up to region, 0.3's up to
// strength_format. 0.5 put each texture beside its format and added the projection and noise index.
struct Frame04 {
  uint32_t struct_size, color_texture, depth_texture, output_texture;
  const sss_stencil* stencil;
  int32_t viewport[4];
  uint32_t flags, color_format, depth_format, output_format, stencil_format;
  int32_t texture_width, texture_height;
  uint32_t normal_texture, normal_format, msaa_depth_resolve;
  int32_t region[4];
  uint32_t depth_stencil_mode;
  uint32_t strength_texture, strength_format;
  uint32_t profile_texture, profile_format;
};

#if UINTPTR_MAX == 0xFFFFFFFFFFFFFFFFu
// The sizes those releases had on x86-64 (LP64), as their sss.h compiled.
static_assert(sizeof(Settings01) == 184, "0.1's sss_settings");
static_assert(sizeof(Settings02) == 192, "0.2's sss_settings");
static_assert(sizeof(KernelDesc03) == 120 && sizeof(ProfileDesc03) == 32, "0.1-0.3's sss_kernel_desc");
static_assert(sizeof(sss_kernel_desc) == 144, "0.4: six burley floats appended to the embedded profile desc");
static_assert(sizeof(sss_create_desc) == 48, "kept 0.1's layout");
static_assert(offsetof(sss_stats, gpu_memory_bytes) == 72 && sizeof(sss_stats) == 80,
              "0.1-0.4's 72 bytes, then gpu_memory_bytes (0.5)");
static_assert(sizeof(Frame04) == 120, "0.1's and 0.2's 96 bytes, depth_stencil_mode, strength_texture and _format "
              "(0.3's 112), profile_texture and _format");
static_assert(offsetof(Frame04, depth_stencil_mode) == 96 && offsetof(Frame04, profile_texture) == 108,
              "0.3's sss_frame (112 with its padding) is 0.4's up to profile_texture");
static_assert(offsetof(sss_frame, albedo_texture) == 140 && sizeof(sss_frame) == 152,
              "0.5's sss_frame (144 bytes with its padding) is today's up to albedo_texture (0.6)");
static_assert(sizeof(sss_prepare_desc) == 48 && offsetof(sss_prepare_desc, profile_format) == 40 &&
                  offsetof(sss_prepare_desc, albedo_format) == 44,
              "0.3's sss_prepare_desc (40 bytes) and 0.4's (44) are today's up to profile_format and albedo_format");
static_assert(offsetof(sss_settings, texturing) == 80 && sizeof(sss_settings) == 88,
              "0.3-0.5's sss_settings (80 bytes) are today's up to texturing (0.6)");
#endif

const sss::math::Matrix4 kCamera = perspective_matrix(45.0f, 1.0f, 0.1f, 10.0f);

void fill_common(KernelDesc03* old) {
  sss_kernel_desc k;
  sss_default_kernel_desc(&k);
  k.family = SSS_KERNEL_SVD;
  k.rank = 2;
  k.profile.profile = SSS_PROFILE_MARBLE;  // the same value as 0.1's SSS_MATERIAL_MARBLE
  *old = as03(k);
}

// Every field sss_get_settings gives back, the kernel by content.
void expect_same_settings(const sss_settings& a, const sss_settings& b) {
  EXPECT_EQ(a.world_units_per_mm, b.world_units_per_mm);
  EXPECT_EQ(a.scale, b.scale);
  EXPECT_EQ(a.separable_scale, b.separable_scale);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(a.strength[c], b.strength[c]) << c;
    EXPECT_EQ(a.falloff[c], b.falloff[c]) << c;
  }
  EXPECT_EQ(a.taps, b.taps);
  EXPECT_EQ(a.flags, b.flags);
  EXPECT_EQ(a.mode, b.mode);
  EXPECT_EQ(a.cbf_taps, b.cbf_taps);
  EXPECT_EQ(a.cbf_r_max_mm, b.cbf_r_max_mm);
  EXPECT_EQ(a.cbf_profile, b.cbf_profile);
  EXPECT_EQ(a.jitter, b.jitter);
  EXPECT_EQ(a.path, b.path);
  ASSERT_EQ(a.kernel == nullptr, b.kernel == nullptr);
  if (a.kernel != nullptr) {
    EXPECT_EQ(std::memcmp(a.kernel, b.kernel, sizeof(sss_kernel_desc)), 0);
  }
}

class VersionedStructs : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    if (HasFatalFailure()) return;
    sss_ = create_sss();
    ASSERT_NE(sss_, nullptr);
  }

  // What the context holds, read back in today's layout.
  sss_settings current() {
    sss_settings s;
    s.struct_size = sizeof s;
    EXPECT_EQ(sss_get_settings(sss_, &s), SSS_OK) << sss_last_error(sss_);
    return s;
  }

  // `s` set on a context of its own, read back: what today's layout of the converted settings gives.
  sss_settings as_set(const sss_settings& s) {
    sss_context* other = create_sss();
    EXPECT_NE(other, nullptr);
    EXPECT_EQ(sss_set_settings(other, &s), SSS_OK) << sss_last_error(other);
    sss_settings back;
    back.struct_size = sizeof back;
    EXPECT_EQ(sss_get_settings(other, &back), SSS_OK);
    if (back.kernel != nullptr) {
      kept_ = *back.kernel;  // the other context's copy goes with it
      back.kernel = &kept_;
    }
    sss_destroy(other);
    return back;
  }

  sss_kernel_desc kept_{};
};

TEST_F(VersionedStructs, Settings01AreConvertedToWhatTheyMeant) {
  Settings01 old{};
  old.struct_size = sizeof old;
  old.width = 0.06f;
  const float strength[3] = {0.78f, 0.70f, 0.75f}, falloff[3] = {0.57f, 0.13f, 0.08f};
  std::memcpy(old.strength, strength, sizeof strength);
  std::memcpy(old.falloff, falloff, sizeof falloff);
  old.samples = 25;
  old.flags = SSS_FOLLOW_SURFACE | 0x2u;  // 0.1's SSS_ADAPTIVE_TAPS: accepted, ignored
  old.mode = SSS_MODE_SEPARABLE;
  old.cbf_taps = 15;
  old.cbf_r_max_mm = 3.5f;
  old.cbf_profile = 0x100u;  // 0.1's SSS_PROFILE_MIKKELSEN_2010
  fill_common(&old.kernel);
  old.jitter = 0.25f;
  old.path = SSS_PATH_FRAGMENT;
  ASSERT_EQ(sss_set_settings(sss_, reinterpret_cast<const sss_settings*>(&old)), SSS_OK) << sss_last_error(sss_);

  // What 0.1 meant, in 0.3's terms: one profile millimetre spanned (2/3)·width world units, in the
  // eq. (1) kernel's own millimetres (separable_scale 1), at scale 1.
  sss_settings expected;
  sss_default_settings(&expected);
  expected.world_units_per_mm = sss_world_units_per_mm_from_legacy_width(old.width);
  expected.scale = 1.0f;
  expected.separable_scale = 1.0f;
  std::memcpy(expected.strength, strength, sizeof strength);
  std::memcpy(expected.falloff, falloff, sizeof falloff);
  expected.taps = 25;
  expected.flags = SSS_FOLLOW_SURFACE;
  expected.cbf_taps = 15;
  expected.cbf_r_max_mm = 3.5f;
  expected.cbf_profile = SSS_PROFILE_MIKKELSEN_2010;
  const sss_kernel_desc kernel = as_current(old.kernel);
  expected.kernel = &kernel;
  expected.jitter = 0.25f;
  expected.path = SSS_PATH_FRAGMENT;  // the old struct's path, not today's default (SSS_PATH_AUTO)
  expect_same_settings(current(), as_set(expected));
}

TEST_F(VersionedStructs, Settings02AreConvertedToWhatTheyMeant) {
  Settings02 old{};
  old.struct_size = sizeof old;
  old.world_units_per_mm = 0.01f;
  old.scale = 1.5f;
  sss_settings defaults;
  sss_default_settings(&defaults);
  std::memcpy(old.strength, defaults.strength, sizeof old.strength);
  std::memcpy(old.falloff, defaults.falloff, sizeof old.falloff);
  old.separable_scale = defaults.separable_scale;
  old.samples = 11;
  old.flags = 0u;
  old.mode = SSS_MODE_CROSS_BILATERAL;
  old.cbf_taps = 13;
  old.cbf_r_max_mm = 4.5f;
  old.cbf_profile = 0x101u;  // 0.2's SSS_PROFILE_KERNEL: the kernel desc's profile
  sss_kernel_desc artist;
  sss_default_kernel_desc(&artist);
  artist.family = SSS_KERNEL_ARTIST;
  old.kernel = as03(artist);
  old.jitter = 0.0f;
  old.path = SSS_PATH_AUTO;
  ASSERT_EQ(sss_set_settings(sss_, reinterpret_cast<const sss_settings*>(&old)), SSS_OK) << sss_last_error(sss_);

  sss_settings expected = defaults;
  expected.world_units_per_mm = 0.01f;
  expected.scale = 1.5f;
  expected.taps = 11;
  expected.flags = 0u;
  expected.mode = SSS_MODE_CROSS_BILATERAL;
  expected.cbf_profile = SSS_PROFILE_KERNEL;
  expected.kernel = &artist;
  expected.path = SSS_PATH_AUTO;
  expect_same_settings(current(), as_set(expected));

  // 0.2's eq. (1) family meant the settings' own strength and falloff: today's NULL kernel.
  old.kernel.family = SSS_KERNEL_SEPARABLE;
  ASSERT_EQ(sss_set_settings(sss_, reinterpret_cast<const sss_settings*>(&old)), SSS_OK);
  EXPECT_EQ(current().kernel, nullptr);
}

TEST_F(VersionedStructs, GetSettingsWritesTheLayoutItIsGiven) {
  sss_settings s;
  sss_default_settings(&s);
  s.world_units_per_mm = 0.002f;
  s.scale = 2.0f;
  s.taps = 21;
  s.cbf_profile = SSS_PROFILE_MIKKELSEN_2010;
  ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK);
  Settings02 two{};
  two.struct_size = sizeof two;
  ASSERT_EQ(sss_get_settings(sss_, reinterpret_cast<sss_settings*>(&two)), SSS_OK) << sss_last_error(sss_);
  EXPECT_EQ(two.struct_size, sizeof two);
  EXPECT_EQ(two.world_units_per_mm, 0.002f);
  EXPECT_EQ(two.scale, 2.0f);
  EXPECT_EQ(two.samples, 21);
  EXPECT_EQ(two.cbf_profile, 0x100u);
  EXPECT_EQ(two.kernel.family, SSS_KERNEL_SEPARABLE);
  EXPECT_EQ(two.kernel.struct_size, sizeof(KernelDesc03));  // 0.2's layout, its size
  EXPECT_EQ(two.kernel.profile.struct_size, sizeof(ProfileDesc03));
  Settings01 one{};
  one.struct_size = sizeof one;
  ASSERT_EQ(sss_get_settings(sss_, reinterpret_cast<sss_settings*>(&one)), SSS_OK) << sss_last_error(sss_);
  EXPECT_FLOAT_EQ(sss_world_units_per_mm_from_legacy_width(one.width), 0.002f * 2.0f);  // scale folded in
  EXPECT_EQ(one.samples, 21);
  EXPECT_EQ(one.cbf_profile, 0x100u);
}

TEST_F(VersionedStructs, SizesNoReleaseDefinedAreRefusedByName) {
  sss_settings good;
  sss_default_settings(&good);
  good.taps = 9;
  ASSERT_EQ(sss_set_settings(sss_, &good), SSS_OK);
  // Larger than today's, between the releases' sizes, smaller than any.
  for (uint32_t size : {static_cast<uint32_t>(sizeof(sss_settings)) + 8u, 188u, 100u, 4u, 0u}) {
    SCOPED_TRACE(size);
    sss_settings s = good;
    s.taps = 11;
    s.struct_size = size;
    EXPECT_EQ(sss_set_settings(sss_, &s), SSS_ERROR_INVALID_ARGUMENT);
    const std::string message = sss_last_error(sss_);
    EXPECT_NE(message.find("settings->struct_size = " + std::to_string(size)), std::string::npos) << message;
    EXPECT_NE(message.find("sss_settings"), std::string::npos) << message;
    EXPECT_EQ(current().taps, 9);  // the old settings stay
  }
  sss_create_desc desc{};
  desc.struct_size = sizeof desc + 4;
  desc.get_proc_address = sss_headless_get_proc_address;
  sss_context* none = nullptr;
  EXPECT_EQ(sss_create(&desc, &none), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(nullptr)).find("sss_create_desc"), std::string::npos) << sss_last_error(nullptr);
  sss_stats stats{};
  stats.struct_size = 64;
  EXPECT_EQ(sss_get_stats(sss_, &stats), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("stats->struct_size = 64"), std::string::npos);
}

// A host built against 0.3 passes today's sss_settings pointing at 0.3's kernel desc (no burley
// fields): read as today's with those fields at their defaults; a size no release had is refused.
TEST_F(VersionedStructs, KernelDescsOfEarlierReleasesAreRead) {
  KernelDesc03 old{};
  fill_common(&old);
  sss_settings s;
  sss_default_settings(&s);
  s.kernel = reinterpret_cast<const sss_kernel_desc*>(&old);
  ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK) << sss_last_error(sss_);
  const sss_kernel_desc expected = as_current(old);
  s.kernel = &expected;
  expect_same_settings(current(), as_set(s));
  sss_kernel_desc odd = expected;
  odd.struct_size = 124u;
  s.kernel = &odd;
  EXPECT_EQ(sss_set_settings(sss_, &s), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("settings->kernel->struct_size = 124"), std::string::npos)
      << sss_last_error(sss_);
  // The same 0.3 desc on a per-pixel profile other than the first (sss_set_profiles reads each as
  // sss_set_settings does).
  // At rank 1: several profiles take one-term kernels.
  KernelDesc03 old_rank1 = old;
  old_rank1.rank = 1;
  sss_settings two[2];
  sss_default_settings(&two[0]);
  two[1] = two[0];
  two[1].kernel = reinterpret_cast<const sss_kernel_desc*>(&old_rank1);
  EXPECT_EQ(sss_set_profiles(sss_, two, 2), SSS_OK) << sss_last_error(sss_);
  old.profile.struct_size = sizeof(sss_profile_desc);  // 0.3's kernel desc cannot hold today's profile desc
  s.kernel = reinterpret_cast<const sss_kernel_desc*>(&old);
  EXPECT_EQ(sss_set_settings(sss_, &s), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("settings->kernel->profile.struct_size"), std::string::npos)
      << sss_last_error(sss_);
}

// An 8x8 RGBA32F frame into an output, every format, the size and the viewport given, in a
// release's layout (the fields have the same names in all of them).
template <typename Frame>
Frame described_frame(uint32_t struct_size, GLuint color, GLuint depth, GLuint output) {
  Frame f{};
  f.struct_size = struct_size;
  f.color_texture = color;
  f.color_format = GL_RGBA32F;
  f.depth_texture = depth;
  f.depth_format = GL_DEPTH_COMPONENT32F;
  f.output_texture = output;
  f.output_format = GL_RGBA32F;
  f.texture_width = f.texture_height = 8;
  const int32_t viewport[4] = {0, 0, 8, 8};
  std::memcpy(f.viewport, viewport, sizeof viewport);
  return f;
}

TEST_F(VersionedStructs, FramesOfEveryReleaseRunAndOthersAreRefused) {
  if (is_gles()) GTEST_SKIP() << "OpenGL ES 3.0 needs described frames; the sizes are the same there";
  ASSERT_EQ(sss_set_camera(sss_, kCamera.data()), SSS_OK);
  // A world unit of a millimetre, so that the kernel spans pixels of this small frame (at the default
  // metres it stays inside each pixel and, with the RGBA32F intermediate of an RGBA32F colour, the
  // frame comes back exactly unchanged, which would not show that the frame ran).
  sss_settings settings;
  sss_default_settings(&settings);
  settings.world_units_per_mm = 1.0f;
  // One path for all the frames: on a GPU SSS_PATH_AUTO times a different path in each of its
  // first frames, and the paths agree to rounding, not bit for bit.
  settings.path = SSS_PATH_FRAGMENT;
  ASSERT_EQ(sss_set_settings(sss_, &settings), SSS_OK) << sss_last_error(sss_);
  const SyntheticScene scene = make_relief_scene(8, 8, 1, kCamera);
  const GLuint depth = make_depth32f(8, 8, scene.window_depth);
  // 0.1-0.4 in 0.4's layout, with a separate output, a viewport of the whole frame and described
  // formats (every field moved in 0.5), then 0.5's own frame with the same fields.
  const uint32_t sizes[3] = {sizeof(Frame04) == 120 ? 96u : 92u, sizeof(Frame04) == 120 ? 112u : 108u,
                             static_cast<uint32_t>(sizeof(Frame04))};  // 0.1 and 0.2; 0.3; 0.4
  std::vector<float> results[4];
  for (int i = 0; i < 4; ++i) {
    SCOPED_TRACE(i < 3 ? sizes[i] : sizeof(sss_frame));
    const GLuint color = make_rgba32f(8, 8, scene.color);
    const GLuint output = make_rgba32f(8, 8, std::vector<float>(8 * 8 * 4, -1.0f));
    if (i < 3) {
      Frame04 f = described_frame<Frame04>(sizes[i], color, depth, output);
      // 0.3's 112 bytes end in 4 bytes of padding where 0.4 has profile_texture: whatever a 0.3 host
      // left there is not read as a texture name.
      if (sizes[i] == 112u) f.profile_texture = 0xDEADu;
      ASSERT_EQ(sss_apply_frame(sss_, reinterpret_cast<const sss_frame*>(&f)), SSS_OK) << sss_last_error(sss_);
    } else {
      const sss_frame f = described_frame<sss_frame>(sizeof(sss_frame), color, depth, output);
      ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
    }
    EXPECT_EQ(read_rgba(color, 8, 8), scene.color);  // the output was written, not the colour
    results[i] = read_rgba(output, 8, 8);
  }
  EXPECT_EQ(results[0], results[1]);  // depth_stencil_mode's default: the same frame
  EXPECT_EQ(results[0], results[2]);  // no profile texture: the same frame
  EXPECT_EQ(results[0], results[3]);  // 0.4's fields where 0.5 has them
  EXPECT_NE(results[0], scene.color);
  sss_frame f{};
  f.struct_size = 100u;
  f.color_texture = make_rgba32f(8, 8, scene.color);
  f.depth_texture = depth;
  EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_ERROR_INVALID_ARGUMENT);
  const std::string message = sss_last_error(sss_);
  EXPECT_NE(message.find("frame->struct_size = 100"), std::string::npos) << message;
  EXPECT_NE(message.find("sss_frame"), std::string::npos) << message;
}

// 0.5's structs (issue 48): its sss_settings, sss_frame and sss_set_profiles array end before the
// texturing fields 0.6 appended, so a 0.5 host gets pre-scatter whatever lies past its structs: the
// bytes where 0.6 has texturing and albedo_texture are never read.
TEST_F(VersionedStructs, Release05StructsGetPreScatter) {
  const uint32_t settings05 = static_cast<uint32_t>(
      (offsetof(sss_settings, texturing) + alignof(sss_settings) - 1) / alignof(sss_settings) * alignof(sss_settings));
  const uint32_t frame05 = static_cast<uint32_t>(
      (offsetof(sss_frame, albedo_texture) + alignof(sss_frame) - 1) / alignof(sss_frame) * alignof(sss_frame));
  ASSERT_LT(settings05, sizeof(sss_settings));
  ASSERT_LT(frame05, sizeof(sss_frame));
  sss_settings s;
  sss_default_settings(&s);
  s.world_units_per_mm = 1.0f;
  s.path = SSS_PATH_FRAGMENT;
  s.texturing = SSS_TEXTURING_POST_SCATTER;  // past 0.5's struct: not read
  s.struct_size = settings05;
  ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK) << sss_last_error(sss_);
  EXPECT_EQ(current().texturing, static_cast<uint32_t>(SSS_TEXTURING_PRE_SCATTER));
  // sss_set_profiles: an array of 0.5's structs, read at 0.5's stride.
  std::vector<unsigned char> profiles(2 * settings05);
  sss_settings second = s;
  second.scale = 2.0f;
  std::memcpy(profiles.data(), &s, settings05);
  std::memcpy(profiles.data() + settings05, &second, settings05);
  ASSERT_EQ(sss_set_profiles(sss_, reinterpret_cast<const sss_settings*>(profiles.data()), 2), SSS_OK)
      << sss_last_error(sss_);
  EXPECT_EQ(current().texturing, static_cast<uint32_t>(SSS_TEXTURING_PRE_SCATTER));
  EXPECT_EQ(current().scale, 1.0f);
  // Today's settings in post-scatter, then a 0.5 frame: its albedo fields are past its end, so the
  // frame has no albedo texture, which the mode needs (refused by name, nothing drawn).
  s.struct_size = sizeof s;
  ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK) << sss_last_error(sss_);
  ASSERT_EQ(sss_set_camera(sss_, kCamera.data()), SSS_OK);
  const SyntheticScene scene = make_relief_scene(8, 8, 1, kCamera);
  const GLuint color = make_rgba32f(8, 8, scene.color);
  sss_frame f = described_frame<sss_frame>(frame05, color, make_depth32f(8, 8, scene.window_depth),
                                           make_rgba32f(8, 8, std::vector<float>(8 * 8 * 4, -1.0f)));
  if (is_gles()) f.depth_format = GL_DEPTH_COMPONENT32F;
  f.albedo_texture = color;  // past 0.5's frame: not read
  f.albedo_format = GL_RGBA16F;
  EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("frame->albedo_texture = 0"), std::string::npos)
      << sss_last_error(sss_);
  EXPECT_EQ(read_rgba(color, 8, 8), scene.color);
}

// 0.1-0.4's sss_stats (72 bytes on LP64) get their fields and nothing past them; 0.5's get the memory.
TEST_F(VersionedStructs, StatsOfEveryReleaseAreFilledToTheirSize) {
  unsigned char bytes[sizeof(sss_stats) + 8];
  std::memset(bytes, 0xAB, sizeof bytes);
  sss_stats* old = reinterpret_cast<sss_stats*>(bytes);
  old->struct_size = static_cast<uint32_t>(offsetof(sss_stats, gpu_memory_bytes));
  ASSERT_EQ(sss_get_stats(sss_, old), SSS_OK) << sss_last_error(sss_);
  EXPECT_EQ(old->struct_size, offsetof(sss_stats, gpu_memory_bytes));
  EXPECT_EQ(old->frames, 0u);
  for (std::size_t i = offsetof(sss_stats, last_frame_path) + sizeof(uint32_t); i < sizeof bytes; ++i) {
    EXPECT_EQ(bytes[i], 0xAB) << "byte " << i << " past 0.4's fields was written";
  }
  sss_stats now{};
  now.struct_size = sizeof now;
  ASSERT_EQ(sss_get_stats(sss_, &now), SSS_OK);
  EXPECT_EQ(now.struct_size, sizeof now);
  now.struct_size = 76u;
  EXPECT_EQ(sss_get_stats(sss_, &now), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("stats->struct_size = 76"), std::string::npos);
}

// The runtime builds no fitted kernel by itself (it links neither NLopt nor Eigen): without the tools'
// fitters registered, settings that need one are refused by name and the old settings stay; after
// sss_tools_init they are taken. (This binary registers them before main through sss_math: the test
// takes them away for its span and puts them back.)
TEST_F(VersionedStructs, FittedKernelsNeedTheToolsRegistered) {
  struct Reregister {  // whatever happens below, the next tests find the fitters registered
    ~Reregister() { sss::math::set_fitters(&sss::math::tool_fitters()); }
  } reregister;
  sss::math::set_fitters(nullptr);
  sss_kernel_desc guided;
  sss_default_kernel_desc(&guided);  // registers the fitters (every sss_tools.h function does) ...
  sss::math::set_fitters(nullptr);    // ... which this test takes away again
  guided.family = SSS_KERNEL_GUIDED;
  sss_settings s;
  sss_default_settings(&s);
  s.taps = 9;
  ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK);
  s.kernel = &guided;
  EXPECT_EQ(sss_set_settings(sss_, &s), SSS_ERROR_UNSUPPORTED);
  const std::string message = sss_last_error(sss_);
  EXPECT_NE(message.find("settings->kernel->family = 4"), std::string::npos) << message;
  EXPECT_NE(message.find("sss_tools_init"), std::string::npos) << message;
  EXPECT_EQ(current().kernel, nullptr);  // the old settings stay
  sss_settings cbf;
  sss_default_settings(&cbf);
  cbf.mode = SSS_MODE_CROSS_BILATERAL;
  cbf.cbf_profile = SSS_PROFILE_APPLE;  // a measured material: its Gaussians are fitted
  EXPECT_EQ(sss_set_settings(sss_, &cbf), SSS_ERROR_UNSUPPORTED);
  cbf.cbf_profile = SSS_PROFILE_SKIN_DEON;  // closed form: the runtime builds it alone
  EXPECT_EQ(sss_set_settings(sss_, &cbf), SSS_OK) << sss_last_error(sss_);
  sss_tools_init();
  EXPECT_EQ(sss_set_settings(sss_, &s), SSS_OK) << sss_last_error(sss_);
  ASSERT_NE(current().kernel, nullptr);
  EXPECT_EQ(current().kernel->family, SSS_KERNEL_GUIDED);
}

}  // namespace
}  // namespace sss_test
