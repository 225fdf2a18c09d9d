// The layouts of sss_settings in the releases before 0.3 (from their sss.h, field for field), for
// the conversions of versioned_structs.cpp (tests/gl/versioned_structs_test.cpp writes its own copies,
// from the old headers, and passes them).
// sss_kernel_desc and sss_profile_desc kept 0.1's layout up to 0.3 (profile_desc's `material` is
// `profile`); 0.4 appended the burley fields to sss_profile_desc, and so to sss_kernel_desc.
#pragma once

#include <cstddef>
#include <cstdint>

#include "sss/sss_tools.h"

namespace sss::legacy {

// sss_profile_desc and sss_kernel_desc of 0.1 to 0.3: today's without the burley fields.
struct ProfileDesc03 {
  std::uint32_t struct_size;
  std::int32_t profile, gaussian_count, table_size;
  const float* table_radius_mm;
  const float* table_rgb;
};
struct KernelDesc03 {
  std::uint32_t struct_size;
  std::int32_t family, taps, rank;
  std::uint32_t flags;
  float guide_k, radius_mm;
  float strength[3], falloff[3], near_variance_mm2[3], far_variance_mm2[3], near_weight[3];
  ProfileDesc03 profile;
};
static_assert(offsetof(sss_profile_desc, burley_albedo) == sizeof(ProfileDesc03), "0.4 appended the burley fields");
static_assert(offsetof(sss_kernel_desc, profile) == offsetof(KernelDesc03, profile), "the fields before the profile kept");

// sss 0.1 (git 4cb68e3): the paper's width, Table 1 defaults, the kernel desc embedded.
struct Settings01 {
  std::uint32_t struct_size;
  float width;  // one profile millimetre spans (2/3)·width world units
  float strength[3];
  float falloff[3];
  std::int32_t samples;
  std::uint32_t flags;  // SSS_FOLLOW_SURFACE 0x1, SSS_ADAPTIVE_TAPS 0x2
  std::uint32_t mode;
  std::int32_t cbf_taps;
  float cbf_r_max_mm;
  std::uint32_t cbf_profile;  // sss_material 0..11, 0x100 Mikkelsen, 0x101 the kernel's profile
  KernelDesc03 kernel;
  float jitter;
  std::uint32_t path;
};

// sss 0.2 (git 5646dcc, and main up to 0.3): world units per millimetre and the look apart.
struct Settings02 {
  std::uint32_t struct_size;
  float world_units_per_mm;
  float scale;
  float strength[3];
  float falloff[3];
  float separable_scale;
  std::int32_t samples;
  std::uint32_t flags;  // SSS_FOLLOW_SURFACE 0x1, SSS_ADAPTIVE_TAPS 0x2 (ignored)
  std::uint32_t mode;
  std::int32_t cbf_taps;
  float cbf_r_max_mm;
  std::uint32_t cbf_profile;
  KernelDesc03 kernel;
  float jitter;
  std::uint32_t path;
};

inline constexpr std::uint32_t kLegacyAdaptiveTaps = 0x2u;
inline constexpr std::uint32_t kLegacyMikkelsen = 0x100u;
inline constexpr std::uint32_t kLegacyKernelProfile = 0x101u;
// 0.4's sss_frame. Each earlier release's is a prefix of it: 0.1's and 0.2's end before
// depth_stencil_mode, 0.3's before profile_texture (their sizes: frame_size_ending_at). 0.5 put each
// texture beside its format and added the projection and the noise index.
struct Frame04 {
  std::uint32_t struct_size, color_texture, depth_texture, output_texture;
  const sss_stencil* stencil;
  std::int32_t viewport[4];
  std::uint32_t flags, color_format, depth_format, output_format, stencil_format;
  std::int32_t texture_width, texture_height;
  std::uint32_t normal_texture, normal_format, msaa_depth_resolve;
  std::int32_t region[4];
  std::uint32_t depth_stencil_mode;
  std::uint32_t strength_texture, strength_format;
  std::uint32_t profile_texture, profile_format;
};
inline constexpr auto kFrameSize04 = static_cast<std::uint32_t>(sizeof(Frame04));
// The size of a release's frame whose fields end at byte `end` of Frame04: rounded up to the
// struct's alignment, as its compiler padded it. From the layout, not a number: 0.1's and 0.2's are
// 96 bytes with 64-bit pointers and 92 on wasm32 (the WebAssembly build).
constexpr std::uint32_t frame_size_ending_at(std::size_t end) {
  return static_cast<std::uint32_t>((end + alignof(Frame04) - 1) / alignof(Frame04) * alignof(Frame04));
}
inline constexpr std::uint32_t kFrameSize02 = frame_size_ending_at(offsetof(Frame04, depth_stencil_mode));

// 0.1-0.4's sss_stats: today's without gpu_memory_bytes (0.5).
struct Stats04 {
  std::uint32_t struct_size, glsl_variant;
  std::uint64_t frames, passes;
  std::uint32_t last_frame_passes, measured;
  std::uint64_t measured_frame, pixels_touched;
  double gpu_time_ms[2];
  std::uint32_t last_frame_path;
};
inline constexpr auto kStatsSize04 = static_cast<std::uint32_t>(sizeof(Stats04));
static_assert(offsetof(sss_stats, gpu_memory_bytes) >= offsetof(Stats04, last_frame_path) + sizeof(std::uint32_t),
              "0.5 appended gpu_memory_bytes");

}  // namespace sss::legacy

namespace sss::api {
// 0.1-0.3's kernel desc as today's (the burley fields their defaults) and back (kernel_desc.cpp).
void kernel_desc_from_legacy(const legacy::KernelDesc03& old, sss_kernel_desc* out);
void kernel_desc_to_legacy(const sss_kernel_desc& current, legacy::KernelDesc03* old);
}  // namespace sss::api
