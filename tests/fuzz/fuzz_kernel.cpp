// libFuzzer target: the kernel generator (math layer) over its whole documented domain, reached
// densely: the tap count from one byte, strength and falloff from 16-bit fractions (with exact 0
// and 1 and denormals reachable) or raw floats that happen to be in range. Checked: size, finite
// and non-negative weights, each channel summing to 1 within 1e-6, the centre first at offset 0,
// offsets rising and within the range R, mirror symmetry, strength 0 giving the identity.
#include <cmath>
#include <limits>

#include "fuzz_common.hpp"
#include "math/separable_kernel.hpp"

namespace {

float unit_value(sss_fuzz::Bytes& in) {
  const uint8_t mode = in.take<uint8_t>();
  switch (mode % 4) {
    case 0:
      return static_cast<float>(in.take<uint16_t>()) / 65535.0f;
    case 1: {
      const float raw = in.take<float>();
      return raw >= 0.0f && raw <= 1.0f ? raw : std::fabs(std::fmod(std::isfinite(raw) ? raw : 0.0f, 1.0f));
    }
    case 2:
      return std::numeric_limits<float>::denorm_min() * static_cast<float>(in.take<uint8_t>());
    default:
      return (mode & 4) ? 1.0f : 0.0f;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  sss_fuzz::Bytes in(data, size);
  const int samples = 3 + 2 * (in.take<uint8_t>() % 32);
  std::array<float, 3> strength, falloff;
  for (float& v : strength) v = unit_value(in);
  for (float& v : falloff) v = unit_value(in);
  const auto kernel = sss::math::separable_kernel(samples, strength, falloff);
  SSS_FUZZ_CHECK(kernel.size() == static_cast<std::size_t>(samples));
  const float range = static_cast<float>(sss::math::kSeparableKernelRangeMm);
  SSS_FUZZ_CHECK(kernel[0].offset_mm == 0.0f);
  for (int c = 0; c < 3; ++c) {
    double sum = 0.0;
    for (const auto& tap : kernel) {
      const float w = tap.weight[static_cast<std::size_t>(c)];
      SSS_FUZZ_CHECK(std::isfinite(w) && w >= 0.0f);
      sum += w;
    }
    SSS_FUZZ_CHECK(std::fabs(sum - 1.0) <= 1e-6);
    if (strength[static_cast<std::size_t>(c)] == 0.0f) {
      SSS_FUZZ_CHECK(kernel[0].weight[static_cast<std::size_t>(c)] == 1.0f);
    }
  }
  for (std::size_t i = 1; i < kernel.size(); ++i) {
    SSS_FUZZ_CHECK(std::fabs(kernel[i].offset_mm) <= range);
    if (i >= 2) SSS_FUZZ_CHECK(kernel[i - 1].offset_mm < kernel[i].offset_mm);
    const auto& mirror = kernel[kernel.size() - i];
    SSS_FUZZ_CHECK(mirror.offset_mm == -kernel[i].offset_mm);
    for (std::size_t c = 0; c < 3; ++c) SSS_FUZZ_CHECK(std::fabs(mirror.weight[c] - kernel[i].weight[c]) <= 1e-7f);
  }
  return 0;
}
