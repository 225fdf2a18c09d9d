// The MSAA path's texturing modes on the CPU (sss.h sss_texturing on a multisampled colour): the
// resolve's per-sample divide (module/shaders/msaa_resolve.frag with SSS_ALBEDO) and the
// write-back's per-sample multiply (msaa_write.frag), so that the tests can hand the module's own
// filter of the quotient to this model and compare its samples with the GL's. Math layer: no GL.
//
// Samples are laid out as the tests read them back: samples[s][pixel * 4 + channel], RGBA.
#pragma once

#include <cstddef>
#include <vector>

namespace sss::math {

// What the resolve keeps of one frame of `count` pixels with a texturing mode.
struct MsaaQuotientResolve {
  std::vector<float> quotient;     // RGBA: the mean of colour_s / A_post_s (alpha: the mean alpha)
  std::vector<float> original;     // RGBA: the mean of the undivided colour (a separate output's untouched pixels)
  std::vector<float> albedo_post;  // rgb: the mean A_post_s (what the last pass into an output multiplies by)
};

// Each sample's colour over its A_post (alpha as it is), in float as the shader divides.
std::vector<std::vector<float>> samples_over_albedo(const std::vector<std::vector<float>>& colour,
                                                    const std::vector<std::vector<float>>& albedo, unsigned mode);

// The resolve of `colour` over `albedo` in `mode` (1 post-scatter, 2 pre- and post-scatter); the
// quotient and the undivided mean rounded to half float where the host's colour is RGBA16F (`half`).
MsaaQuotientResolve resolve_over_albedo(const std::vector<std::vector<float>>& colour,
                                        const std::vector<std::vector<float>>& albedo, unsigned mode, bool half);

// The write-back: every translucent sample (alpha above 0, all finite) of a pixel with alpha whose
// blurred quotient `blurred` (RGBA per pixel) differs from the resolved one gets A_post_s times the
// pixel's change of quotient (x = (blurred − resolved) · samples / translucent samples), pulled
// towards the pixel's lowest translucent quotient where one would go below 0, as msaa_write.frag
// does; every other sample is returned as it is. In float (the GL then stores in the host's format).
std::vector<std::vector<float>> write_back_over_albedo(const std::vector<std::vector<float>>& colour,
                                                       const std::vector<std::vector<float>>& albedo, unsigned mode,
                                                       const MsaaQuotientResolve& resolved,
                                                       const std::vector<float>& blurred);

}  // namespace sss::math
