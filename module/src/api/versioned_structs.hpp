// Versioned structs (sss.h, "struct_size"): each public struct's size in every release, the checks
// that accept those sizes and refuse any other, and the conversions of the layouts that changed.
// A size from an earlier release whose fields are a prefix of today's is read as that prefix (the
// later fields take their defaults); sss_settings changed its fields (0.2: width became
// world_units_per_mm; 0.3: the embedded kernel desc became a pointer, samples became taps, the
// profile ids one space), so its 0.1 and 0.2 layouts are converted field by field.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>

#include "context.hpp"
#include "sss/sss_tools.h"

namespace sss::api {

// The x86-64 sizes (LP64; the layouts are the same fields elsewhere, so the sizes are computed from
// the legacy structs below where they differ).
struct StructRelease {
  const char* release;
  std::uint32_t size;
};

// SSS_OK when `size` is one of `known` (the last one being the current sizeof); else
// SSS_ERROR_INVALID_ARGUMENT naming `field` ("frame->struct_size"), the struct and the sizes it accepts.
sss_result check_struct_size(sss_context* ctx, const char* field, const char* type, std::uint32_t size,
                             std::initializer_list<StructRelease> known);

// The settings as this release reads them, converted from whatever release's layout `in` has
// (its struct_size says which). `kernel` holds the desc a 0.1 or 0.2 layout embedded; the converted
// settings point at it when its family is not eq. (1).
// The size of 0.3's to 0.5's sss_settings: today's fields before texturing (0.6), rounded up to
// the struct's alignment as their compilers padded it.
inline constexpr auto kSettingsSize05 = static_cast<std::uint32_t>(
    (offsetof(sss_settings, texturing) + alignof(sss_settings) - 1) / alignof(sss_settings) * alignof(sss_settings));

struct CurrentSettings {
  sss_settings settings{};
  sss_kernel_desc kernel{};
};
sss_result settings_from_caller(sss_context* ctx, const sss_settings* in, CurrentSettings* out);
// Writes `current` into *out in the layout out->struct_size names (this or an earlier release's);
// `kernel` is the current kernel desc (NULL: eq. (1)).
sss_result settings_to_caller(sss_context* ctx, const sss_settings& current, sss_settings* out);

// The frame in this release's layout, converted field by field from an earlier release's (0.1-0.4:
// prefixes of legacy_structs.hpp's Frame04; 0.5 put each texture beside its format).
sss_result frame_from_caller(sss_context* ctx, const sss_frame* in, sss_frame* out);

// What 0.1 and 0.2 called the profile ids of sss_settings.cbf_profile: sss_material 0..11 (today's
// values), 0x100 SSS_PROFILE_MIKKELSEN_2010 and 0x101 SSS_PROFILE_KERNEL.
std::uint32_t profile_from_legacy(std::uint32_t legacy);
std::uint32_t profile_to_legacy(std::uint32_t profile);

}  // namespace sss::api
