#include "versioned_structs.hpp"

#include <cstddef>
#include <cstdio>
#include <cstring>
#include <string>

#include "legacy_structs.hpp"
#include "validation.hpp"

namespace sss::api {

namespace {

using legacy::Settings01;
using legacy::Settings02;

static_assert(offsetof(legacy::Frame04, depth_stencil_mode) == legacy::kFrameSize02,
              "0.1's and 0.2's sss_frame are 0.4's up to depth_stencil_mode");

// The 0.1 and 0.2 layouts embedded a kernel desc whose eq. (1) family meant "the settings' own
// strength and falloff": today that is settings.kernel = NULL.
template <typename Legacy>
void take_legacy_kernel(const Legacy& in, CurrentSettings* out) {
  kernel_desc_from_legacy(in.kernel, &out->kernel);
  out->settings.kernel = in.kernel.family == SSS_KERNEL_SEPARABLE ? nullptr : &out->kernel;
}

// The fields 0.1, 0.2 and 0.3 share by name and meaning.
template <typename Legacy>
void take_common(const Legacy& in, CurrentSettings* out) {
  sss_settings& s = out->settings;
  for (int c = 0; c < 3; ++c) {
    s.strength[c] = in.strength[c];
    s.falloff[c] = in.falloff[c];
  }
  s.taps = in.samples;
  s.flags = in.flags & ~legacy::kLegacyAdaptiveTaps;  // accepted and ignored since 0.2
  s.mode = in.mode;
  s.cbf_taps = in.cbf_taps;
  s.cbf_r_max_mm = in.cbf_r_max_mm;
  s.cbf_profile = profile_from_legacy(in.cbf_profile);
  s.jitter = in.jitter;
  s.path = in.path;
  take_legacy_kernel(in, out);
}

template <typename Legacy>
void give_common(const sss_settings& s, Legacy* out) {
  for (int c = 0; c < 3; ++c) {
    out->strength[c] = s.strength[c];
    out->falloff[c] = s.falloff[c];
  }
  out->samples = s.taps;
  out->flags = s.flags;
  out->mode = s.mode;
  out->cbf_taps = s.cbf_taps;
  out->cbf_r_max_mm = s.cbf_r_max_mm;
  out->cbf_profile = profile_to_legacy(s.cbf_profile);
  sss_kernel_desc eq1;
  default_kernel_desc(&eq1);
  kernel_desc_to_legacy(s.kernel != nullptr ? *s.kernel : eq1, &out->kernel);
  out->jitter = s.jitter;
  out->path = s.path;
}

constexpr auto kSettings01 = static_cast<std::uint32_t>(sizeof(Settings01));
constexpr auto kSettings02 = static_cast<std::uint32_t>(sizeof(Settings02));
constexpr auto kSettings03 = kSettingsSize05;  // 0.3 to 0.5
constexpr auto kSettings06 = static_cast<std::uint32_t>(sizeof(sss_settings));
static_assert(kSettings06 != kSettings03 && kSettings06 != kSettings02 && kSettings06 != kSettings01,
              "a new sss_settings layout needs a size of its own");

}  // namespace

sss_result check_struct_size(sss_context* ctx, const char* field, const char* type, std::uint32_t size,
                             std::initializer_list<StructRelease> known) {
  for (const StructRelease& k : known) {
    if (k.size == size) return SSS_OK;
  }
  std::string sizes;  // only for the message: a frame of a known size allocates nothing
  for (const StructRelease& k : known) {
    if (!sizes.empty()) sizes += ", ";
    sizes += std::to_string(k.size) + " (" + k.release + ")";
  }
  return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%s = %u: no release of sss defined %s with that size; accepted: %s",
              field, size, type, sizes.c_str());
}

std::uint32_t profile_from_legacy(std::uint32_t legacy) {
  if (legacy == legacy::kLegacyMikkelsen) return SSS_PROFILE_MIKKELSEN_2010;
  if (legacy == legacy::kLegacyKernelProfile) return SSS_PROFILE_KERNEL;
  // 0..11 kept their values; anything else stays out of range for check_settings to name.
  return legacy <= SSS_PROFILE_WHOLEMILK ? legacy : 0xFFFFFFFFu;
}

std::uint32_t profile_to_legacy(std::uint32_t profile) {
  if (profile == SSS_PROFILE_MIKKELSEN_2010) return legacy::kLegacyMikkelsen;
  if (profile == SSS_PROFILE_KERNEL) return legacy::kLegacyKernelProfile;
  return profile;
}

sss_result settings_from_caller(sss_context* ctx, const sss_settings* in, CurrentSettings* out) {
  if (in == nullptr) return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "settings is NULL");
  const sss_result r = check_struct_size(ctx, "settings->struct_size", "sss_settings", in->struct_size,
                                         {{"0.1", kSettings01},
                                          {"0.2", kSettings02},
                                          {"0.3 to 0.5", kSettings03},
                                          {"0.6", kSettings06}});
  if (r != SSS_OK) return r;
  if (in->struct_size == kSettings03 || in->struct_size == kSettings06) {
    // 0.3 to 0.5 are today's fields before texturing, which keeps its default (pre-scatter).
    sss_default_settings(&out->settings);
    std::memcpy(static_cast<void*>(&out->settings), in, in->struct_size == kSettings03 ? offsetof(sss_settings, texturing)
                                                                                        : sizeof(sss_settings));
    out->settings.struct_size = kSettings06;
    // Its kernel desc may be 0.1-0.3's (a host built against 0.3): read as today's.
    if (in->kernel == nullptr) return SSS_OK;
    out->settings.kernel = &out->kernel;
    return kernel_desc_from_caller(ctx, in->kernel, "settings->kernel", &out->kernel);
  }
  sss_default_settings(&out->settings);
  if (in->struct_size == kSettings02) {
    Settings02 old;
    std::memcpy(&old, in, sizeof old);
    out->settings.world_units_per_mm = old.world_units_per_mm;
    out->settings.scale = old.scale;
    out->settings.separable_scale = old.separable_scale;
    take_common(old, out);
    return SSS_OK;
  }
  // 0.1: one millimetre of the eq. (1) kernel spanned (2/3)·width world units, in the kernel's own
  // millimetres (separable_scale 1: 0.1's image footprint, docs/migration.md); every other family's
  // millimetres are the profile's, which the same conversion keeps.
  Settings01 old;
  std::memcpy(&old, in, sizeof old);
  out->settings.world_units_per_mm = old.width * (2.0f / 3.0f);
  out->settings.scale = 1.0f;
  out->settings.separable_scale = 1.0f;
  take_common(old, out);
  return SSS_OK;
}

sss_result settings_to_caller(sss_context* ctx, const sss_settings& current, sss_settings* out) {
  const sss_result r = check_struct_size(ctx, "settings->struct_size", "sss_settings", out->struct_size,
                                         {{"0.1", kSettings01},
                                          {"0.2", kSettings02},
                                          {"0.3 to 0.5", kSettings03},
                                          {"0.6", kSettings06}});
  if (r != SSS_OK) return r;
  if (out->struct_size == kSettings06) {
    *out = current;
    return SSS_OK;
  }
  if (out->struct_size == kSettings03) {  // today's fields before texturing
    const std::uint32_t size = out->struct_size;
    std::memcpy(static_cast<void*>(out), &current, offsetof(sss_settings, texturing));
    out->struct_size = size;
    return SSS_OK;
  }
  if (out->struct_size == kSettings02) {
    Settings02 old{};
    old.struct_size = kSettings02;
    old.world_units_per_mm = current.world_units_per_mm;
    old.scale = current.scale;
    old.separable_scale = current.separable_scale;
    give_common(current, &old);
    std::memcpy(static_cast<void*>(out), &old, sizeof old);
    return SSS_OK;
  }
  // 0.1 has no scale or separable_scale: its width is the one that gives today's world_units_per_mm
  // · scale (the eq. (1) kernel's own size is not expressible there).
  Settings01 old{};
  old.struct_size = kSettings01;
  old.width = current.world_units_per_mm * current.scale * 1.5f;
  give_common(current, &old);
  std::memcpy(static_cast<void*>(out), &old, sizeof old);
  return SSS_OK;
}

// 0.3's sss_frame: 0.4's fields up to profile_texture, its size rounded up to the struct's
// alignment (112 bytes on LP64, where the bytes after strength_format are padding; 108 on wasm32).
constexpr auto kFrameFields03 = static_cast<std::uint32_t>(offsetof(legacy::Frame04, profile_texture));
constexpr std::uint32_t kFrameSize03 = legacy::frame_size_ending_at(kFrameFields03);
// 0.5's sss_frame: today's fields before albedo_texture (0.6).
constexpr auto kFrameFields05 = static_cast<std::uint32_t>(offsetof(sss_frame, albedo_texture));
constexpr auto kFrameSize05 = static_cast<std::uint32_t>((kFrameFields05 + alignof(sss_frame) - 1) / alignof(sss_frame) *
                                                         alignof(sss_frame));
// Every release's frame has its own size, on every ABI, so the size alone says the layout.
static_assert(sizeof(sss_frame) != legacy::kFrameSize02 && sizeof(sss_frame) != kFrameSize03 &&
                  sizeof(sss_frame) != legacy::kFrameSize04 && legacy::kFrameSize04 != kFrameSize03 &&
                  sizeof(sss_frame) != kFrameSize05 && kFrameSize05 != legacy::kFrameSize04 &&
                  kFrameSize05 != kFrameSize03 && kFrameSize05 != legacy::kFrameSize02,
              "a new sss_frame layout needs a size of its own");

sss_result frame_from_caller(sss_context* ctx, const sss_frame* in, sss_frame* out) {
  if (in == nullptr) return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "frame is NULL");
  const sss_result r = check_struct_size(ctx, "frame->struct_size", "sss_frame", in->struct_size,
                                         {{"0.1, 0.2", legacy::kFrameSize02},
                                          {"0.3", kFrameSize03},
                                          {"0.4", legacy::kFrameSize04},
                                          {"0.5", kFrameSize05},
                                          {"0.6", static_cast<std::uint32_t>(sizeof(sss_frame))}});
  if (r != SSS_OK) return r;
  if (in->struct_size == sizeof(sss_frame)) {
    *out = *in;
    return SSS_OK;
  }
  if (in->struct_size == kFrameSize05) {  // today's fields before the albedo, which stays 0 (none)
    *out = sss_frame{};
    std::memcpy(static_cast<void*>(out), in, kFrameFields05);
    out->struct_size = sizeof(sss_frame);
    return SSS_OK;
  }
  // An earlier release's fields only (its padding is not a field), read into 0.4's layout with the
  // later fields zero (their defaults), then moved field by field.
  legacy::Frame04 old{};
  std::memcpy(static_cast<void*>(&old), in, in->struct_size == kFrameSize03 ? kFrameFields03 : in->struct_size);
  *out = sss_frame{};
  out->struct_size = sizeof(sss_frame);
  out->color_texture = old.color_texture;
  out->color_format = old.color_format;
  out->depth_texture = old.depth_texture;
  out->depth_format = old.depth_format;
  out->depth_stencil_mode = old.depth_stencil_mode;
  out->msaa_depth_resolve = old.msaa_depth_resolve;
  out->output_texture = old.output_texture;
  out->output_format = old.output_format;
  out->texture_width = old.texture_width;
  out->texture_height = old.texture_height;
  out->flags = old.flags;
  std::memcpy(out->viewport, old.viewport, sizeof out->viewport);
  std::memcpy(out->region, old.region, sizeof out->region);
  out->stencil = old.stencil;
  out->stencil_format = old.stencil_format;
  out->strength_texture = old.strength_texture;
  out->strength_format = old.strength_format;
  out->profile_texture = old.profile_texture;
  out->profile_format = old.profile_format;
  out->normal_texture = old.normal_texture;
  out->normal_format = old.normal_format;
  return SSS_OK;
}

}  // namespace sss::api
