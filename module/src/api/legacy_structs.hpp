// The layouts of sss_settings in the releases before 0.3 (from their sss.h, field for field), for
// the conversions of versioned_structs.cpp (tests/gl/versioned_structs_test.cpp writes its own copies,
// from the old headers, and passes them).
// sss_kernel_desc and sss_profile_desc kept their layout (profile_desc's `material` is `profile`).
#pragma once

#include <cstdint>

#include "sss/sss_tools.h"

namespace sss::legacy {

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
  sss_kernel_desc kernel;
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
  sss_kernel_desc kernel;
  float jitter;
  std::uint32_t path;
};

inline constexpr std::uint32_t kLegacyAdaptiveTaps = 0x2u;
inline constexpr std::uint32_t kLegacyMikkelsen = 0x100u;
inline constexpr std::uint32_t kLegacyKernelProfile = 0x101u;
// 0.1's and 0.2's sss_frame: today's without depth_stencil_mode (appended after 0.2).
inline constexpr std::uint32_t kFrameSize02 = 96u;

}  // namespace sss::legacy
