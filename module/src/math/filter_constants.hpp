// One function from settings + projection + frame geometry to the numbers both passes use (the
// shader's uniforms and the CPU model's inputs), so the two can never disagree. Math layer: no GL.
#pragma once

#include <array>

#include "default_kernel_fit.hpp"
#include "kernel_request.hpp"
#include "projection.hpp"

namespace sss::math {

inline constexpr float kCbfMaxRMaxMm = 50.0f;  // the largest sss_settings.cbf_r_max_mm

struct FilterSettings {
  // The scene scale and the look, apart: one millimetre of surface is world_units_per_mm world
  // units (0.001: a scene in metres), and `scale` multiplies every scattering distance (1: the
  // profile at its physical size).
  float world_units_per_mm = 0.001f;
  float scale = 1.0f;
  // Eq. (1) (the separable family): strength, falloff and the kernel millimetres per millimetre of
  // surface, calibrated against d'Eon's skin (default_kernel_fit.hpp, docs/kernel-fits.md).
  std::array<float, 3> strength = kCalibratedStrength;
  std::array<float, 3> falloff = kCalibratedFalloff;
  float separable_scale = kCalibratedSeparableScale;
  int samples = 17;
  bool follow_surface = true;
  // The cross-bilateral mode (sss_settings.mode and cbf_*; see spike_gaussian_profile.hpp, cbf_kernel.hpp).
  bool cross_bilateral = false;
  int cbf_taps = 13;
  float cbf_r_max_mm = 4.5f;  // Mikkelsen's r_max for skin, (0, kCbfMaxRMaxMm]
  unsigned cbf_profile = 13u;  // an sss_profile: SSS_PROFILE_MIKKELSEN_2010 (spike_gaussian_profile.hpp)
  // The kernel family of the separable mode (sss_settings.kernel): kernel.family separable is eq. (1)
  // from samples, strength and falloff above; every other family is built by build_kernel_plan with
  // `samples` taps (kernel.taps, .strength and .falloff are not read).
  KernelRequest kernel;
  float jitter = 0.0f;  // share of each pass's taps jittered per pixel (supplementary Fig. S.6-S.7)
  unsigned path = 2;  // SSS_PATH_AUTO (SSS_PATH_*: fragment passes, masked ones, compute dispatches, or the fastest)
  bool auto_half_resolution = false;  // SSS_AUTO_HALF_RESOLUTION: AUTO may time SSS_PATH_HALF_RESOLUTION too
  // sss_settings.texturing (sss.h sss_texturing): 0 pre-scatter, 1 post-scatter, 2 pre- and
  // post-scatter; where the albedo goes, not what the kernel is (no kernel input).
  unsigned texturing = 0;
};

enum class DepthEncoding {
  hardware_minus_one_to_one,  // window depth d = (z_ndc + 1) / 2 (GL default)
  hardware_zero_to_one,       // glClipControl(GL_ZERO_TO_ONE): d = z_ndc
  linear_distance             // the texture holds -z_view directly
};

struct FrameGeometry {
  int texture_width = 0, texture_height = 0;
  std::array<int, 4> viewport = {0, 0, 0, 0};  // x, y, w, h in texels (never empty here)
  DepthEncoding depth = DepthEncoding::hardware_minus_one_to_one;
};

struct PassConstants {
  // Pixels per profile millimetre at clip w = 1 and alpha = 1, for the x and the y pass:
  // projection scale × half the viewport × world units per mm.
  std::array<float, 2> pixels_per_mm = {0.0f, 0.0f};
  // Follow-surface factor: 1 / (kernel reach in world units); the blend towards the centre colour
  // is min(1, factor · |depth difference| / alpha). 0 when off.
  float follow_surface_factor = 0.0f;
  // z_ndc = raw_depth · ndc_scale + ndc_bias (hardware depth only).
  float ndc_scale = 2.0f, ndc_bias = -1.0f;
  // Profile millimetres per world unit at alpha 1 (1 / (world_units_per_mm · scale), FLT_MAX for 0): the
  // depth correction of supplementary §E measures depth differences in profile millimetres.
  float mm_per_world = 0.0f;
  // Projection elements the depth linearisation uses: m10, m11, m14, m15.
  std::array<float, 4> depth_terms = {0.0f, 0.0f, 0.0f, 0.0f};
  // Tap positions (pixel coordinates, texel centres at +0.5) are clamped to this box, so taps never
  // read outside the viewport.
  std::array<float, 2> clamp_min = {0.0f, 0.0f}, clamp_max = {0.0f, 0.0f};
  bool linear_depth = false;
  // The view-space offsets between pixels (pass_surface.hpp), x then y: the world width of one
  // window pixel per unit of clip w, s = 2 / (m[0] · viewport width) and 2 / (m[5] · height), signed
  // as the projection is; and the view ray's lateral slope at window position p, p · slope_scale +
  // slope_bias (slope_scale = -m11 · s; slope_bias = (m[8] + m11 · (1 + 2 · viewport x / width)) /
  // m[0], likewise for y). Zero where the projection scale is not finite or zero.
  std::array<float, 2> pixel_span = {0.0f, 0.0f};
  std::array<float, 2> slope_scale = {0.0f, 0.0f}, slope_bias = {0.0f, 0.0f};
};

// World units per profile millimetre: world_units_per_mm · scale.
double world_units_per_profile_mm(const FilterSettings& settings);

// reach_mm: the kernel's reach in profile millimetres (PassKernel::reach_mm), where the
// follow-surface ramp reaches a full blend; below 0: eq. (1)'s range for settings.samples in
// surface millimetres (its kernel range over separable_scale).
PassConstants compute_pass_constants(const FilterSettings& settings, const Matrix4& projection,
                                     const FrameGeometry& geometry, double reach_mm = -1.0);

// The view offsets of PassConstants (pixel_span, slope_scale, slope_bias) for `projection` and a
// viewport (x, y, width, height in pixels; not empty). compute_pass_constants sets them; the
// half-resolution passes set their own for the half-size grid.
void set_view_offsets(PassConstants* k, const Matrix4& projection, const std::array<int, 4>& viewport);

// Keeps tap positions (and the pixels the CPU model filters) inside `rect` (x, y, width, height in
// pixels; not empty): texel centres from rect.xy + 0.5 to rect.xy + size - 0.5. compute_pass_constants
// uses the viewport; a host's region (SSS_FRAME_REGION) narrows it.
void clamp_to_rect(PassConstants* k, const std::array<int, 4>& rect);

// The linear view distance for a raw depth value, in float as the shader computes it.
float linearise_depth(const PassConstants& k, float raw_depth);

// Clip w at a view distance, in float as the shader computes it.
float clip_w(const PassConstants& k, float distance);

}  // namespace sss::math
