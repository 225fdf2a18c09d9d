// libFuzzer target: the CPU model of the two passes, and the exact reference, on tiny images built
// from raw bytes: every colour and depth value is any float bit pattern (NaN, infinities,
// denormals), the camera is sixteen raw floats (a default camera when check_projection refuses
// them), the settings come from bytes within their documented ranges.
// Checked for the CPU model (the full-size passes' and the half-resolution path's: the policies
// sss_apply_frame documents): a pixel with finite input
// comes out finite; a pixel with non-finite colour or alpha, alpha not > 0, or outside the mask
// keeps its exact value; alpha is never written; a blurred channel stays within the finite inputs'
// range (fp16 rounding and the float sum's error allowed).
// Checked for the exact reference (images up to 4x4, finite irradiance): finite output, the input
// kept where a pixel is not usable.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "colour_range.hpp"
#include "fuzz_common.hpp"
#include "math/cpu_half_resolution.hpp"
#include "math/half_resolution.hpp"
#include "math/cpu_separable_filter.hpp"
#include "math/exact_reference.hpp"
#include "math/filter_constants.hpp"
#include "math/pass_kernel.hpp"
#include "math/projection.hpp"
#include "math/separable_kernel.hpp"

namespace {

float unit_value(sss_fuzz::Bytes& in) { return static_cast<float>(in.take<uint16_t>()) / 65535.0f; }

sss::math::Matrix4 default_camera() {
  sss::math::Matrix4 m{};
  m[0] = m[5] = 2.0f;
  m[10] = -1.02f;
  m[11] = -1.0f;
  m[14] = -0.202f;
  return m;
}

void check_cpu_model(sss_fuzz::Bytes& in, int w, int h, const std::vector<float>& color,
                     const std::vector<float>& depth, const std::vector<uint8_t>& mask, const sss::math::Matrix4& m) {
  sss::math::FilterSettings s;
  s.world_units_per_mm = static_cast<float>(in.take<uint16_t>()) * (in.take<uint8_t>() % 2 ? 1e-4f : 1e-1f);
  for (float& v : s.strength) v = unit_value(in);
  for (float& v : s.falloff) v = unit_value(in);
  s.samples = 3 + 2 * (in.take<uint8_t>() % 32);
  s.follow_surface = in.take<uint8_t>() % 2 == 0;
  const uint8_t encoding = in.take<uint8_t>() % 3;
  sss::math::FrameGeometry g;
  g.texture_width = w;
  g.texture_height = h;
  g.viewport = {0, 0, w, h};
  g.depth = encoding == 0   ? sss::math::DepthEncoding::hardware_minus_one_to_one
            : encoding == 1 ? sss::math::DepthEncoding::hardware_zero_to_one
                            : sss::math::DepthEncoding::linear_distance;
  // The kernel as the library builds it (footprint-aware taps).
  const auto kernel = sss::math::build_pass_kernel(s);
  const auto constants = sss::math::compute_pass_constants(s, m, g, kernel.reach_mm);
  sss::math::CpuFilterImage image;
  image.width = w;
  image.height = h;
  image.color = color.data();
  image.depth = depth.data();
  image.mask = mask.data();
  image.output_is_half = in.take<uint8_t>() % 2 == 0;
  std::vector<float> out(color.size());
  // The full-size passes, or (a quarter of the inputs) the half-resolution path's model at its
  // threshold or at 1 pixel (every pixel with a kernel wider than itself upsampled; not 0, which
  // would hand the upsample kernels that fit in their pixel, as identity settings have, where the
  // library draws nothing): the same policies hold for both.
  const uint8_t which = in.take<uint8_t>();
  const bool half = which % 4 == 0;
  if (half) {
    sss::math::cpu_half_resolution_filter({&kernel}, {constants}, nullptr, image,
                                          which % 8 == 0 ? 1.0f : sss::math::kHalfResolutionMinReachPixels, out.data());
  } else {
    sss::math::cpu_pass_kernel_filter(kernel, constants, image, out.data());
  }

  const std::size_t n = mask.size();
  const sss_test::ColourRange range = sss_test::finite_colour_range(color.data(), n);
  for (std::size_t i = 0; i < n; ++i) {
    const float* a = &color[i * 4];
    const float* b = &out[i * 4];
    SSS_FUZZ_CHECK(std::memcmp(a + 3, b + 3, sizeof(float)) == 0);
    const bool finite = std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]) && std::isfinite(a[3]);
    if (!finite || !(a[3] > 0.0f) || mask[i] == 0) {
      SSS_FUZZ_CHECK(std::memcmp(a, b, 4 * sizeof(float)) == 0);
      continue;
    }
    for (int c = 0; c < 3; ++c) {
      // Into a half-float output, light past its range is infinite whatever the path (the GL's
      // conversion); the full-size model leaves such a pixel alone only because its intermediate
      // turned infinite first. Both keep the rest finite.
      if (image.output_is_half && std::max(std::fabs(range.least(c)), std::fabs(range.greatest(c))) >= 65504.0f) continue;
      SSS_FUZZ_CHECK(std::isfinite(b[c]));
      if (std::memcmp(&a[c], &b[c], sizeof(float)) == 0) continue;
      // The half-resolution upsample (B + near field − its half-size stand-in) is clamped to the
      // range of what it combined, which lies within the inputs' range like the passes' results.
      SSS_FUZZ_CHECK(b[c] >= range.least(c));
      SSS_FUZZ_CHECK(b[c] <= range.greatest(c));
    }
  }
}

void check_exact_reference(sss_fuzz::Bytes& in, int w, int h, const std::vector<float>& color,
                           const std::vector<float>& depth, const std::vector<uint8_t>& mask,
                           const sss::math::Matrix4& m) {
  if (w > 4 || h > 4) return;  // cheap cases only
  std::vector<float> irradiance(color);
  for (float& v : irradiance) {
    if (!std::isfinite(v)) v = 0.0f;
  }
  sss::math::ExactInput input;
  input.width = w;
  input.height = h;
  input.irradiance = irradiance.data();
  input.distance = depth.data();  // as a view distance
  input.mask = mask.data();
  input.projection = m;
  input.world_units_per_mm = std::ldexp(1.0, static_cast<int>(in.take<uint8_t>() % 41) - 30);
  sss::math::ExactOptions options;
  options.threads = 1;
  std::vector<double> out(static_cast<std::size_t>(w) * h * 3);
  sss::math::exact_surface_convolution(input, sss::math::skin_profile_terms(), sss::math::PixelRegion{0, 0, w, h},
                                       out.data(), options);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      const double d = depth[i];
      const bool usable = mask[i] != 0 && std::isfinite(d) && sss::math::clip_w_from_distance(m, d) > 0.0;
      for (int c = 0; c < 3; ++c) {
        SSS_FUZZ_CHECK(std::isfinite(out[i * 3 + c]));
        if (!usable) SSS_FUZZ_CHECK(out[i * 3 + c] == static_cast<double>(irradiance[i * 4 + c]));
      }
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  sss_fuzz::Bytes in(data, size);
  const uint8_t dims = in.take<uint8_t>();
  const int w = 1 + dims % 6, h = 1 + (dims / 6) % 6;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  sss::math::Matrix4 m;
  for (float& v : m) v = in.take<float>();
  if (sss::math::check_projection(m, nullptr) != sss::math::ProjectionCheck::ok) m = default_camera();
  std::vector<float> color(n * 4), depth(n);
  std::vector<uint8_t> mask(n);
  for (float& v : color) v = in.take<float>();
  for (float& v : depth) v = in.take<float>();
  const uint64_t mask_bits = in.take<uint64_t>();
  for (std::size_t i = 0; i < n; ++i) mask[i] = ((mask_bits >> i) & 1) ? 0 : 1;
  check_cpu_model(in, w, h, color, depth, mask, m);
  check_exact_reference(in, w, h, color, depth, mask, m);
  return 0;
}
