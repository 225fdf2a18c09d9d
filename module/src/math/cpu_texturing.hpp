// The texturing modes (sss.h sss_texturing) on the CPU: what the module's colour copy divides the
// host's colour by (A_post: the albedo, or its square root, floored as module/shaders/albedo.glsl
// floors it) and the copy itself, for the CPU model of the passes (CpuFilterImage::albedo_post and
// original) and for the exact references, which are A_post ⊙ (R ∗ (colour / A_post)). Math layer:
// no GL.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sss::math {

// albedo.glsl's kSssAlbedoFloor: a channel below it counts as it (sss.h documents the rule).
inline constexpr float kAlbedoFloor = 1.0f / 256.0f;

// A_post of one albedo channel in mode `mode` (sss_texturing: 0 pre-scatter gives 1, 1 the floored
// albedo, 2 its square root).
float albedo_post(float albedo, unsigned mode);

// A_post per pixel (rgb, count·3) from an RGBA albedo image, each pixel in modes[pixel's profile]:
// `profile_of` null means every pixel is in modes[0]; else it gives each pixel's profile (a value
// of modes.size() or more: 1, as the copy leaves a pixel of no profile undivided).
std::vector<float> albedo_post_plane(const float* albedo_rgba, std::size_t count, const std::vector<unsigned>& modes,
                                     const std::uint16_t* profile_of = nullptr);

// The module's copy: the colour (RGBA) with its rgb over A_post, rounded to half float where the
// copy is RGBA16F (`half`), alpha as it is.
std::vector<float> colour_over_albedo(const float* colour_rgba, const std::vector<float>& post, bool half);


}  // namespace sss::math
