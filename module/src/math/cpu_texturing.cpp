#include "cpu_texturing.hpp"

#include <algorithm>
#include <cmath>

#include "half_float.hpp"

namespace sss::math {

float albedo_post(float albedo, unsigned mode) {
  if (mode == 0) return 1.0f;
  const float floored = std::max(albedo, kAlbedoFloor);
  return mode == 1 ? floored : std::sqrt(floored);
}

std::vector<float> albedo_post_plane(const float* albedo_rgba, std::size_t count, const std::vector<unsigned>& modes,
                                     const std::uint16_t* profile_of) {
  std::vector<float> post(count * 3, 1.0f);
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t profile = profile_of != nullptr ? (profile_of[i] & 15u) : 0u;
    if (profile >= modes.size()) continue;
    for (std::size_t c = 0; c < 3; ++c) post[i * 3 + c] = albedo_post(albedo_rgba[i * 4 + c], modes[profile]);
  }
  return post;
}

std::vector<float> colour_over_albedo(const float* colour_rgba, const std::vector<float>& post, bool half) {
  const std::size_t count = post.size() / 3;
  std::vector<float> copy(colour_rgba, colour_rgba + count * 4);
  for (std::size_t i = 0; i < count; ++i) {
    for (std::size_t c = 0; c < 3; ++c) {
      const float v = copy[i * 4 + c] / post[i * 3 + c];
      copy[i * 4 + c] = half ? round_to_half(v) : v;
    }
    if (half) copy[i * 4 + 3] = round_to_half(copy[i * 4 + 3]);
  }
  return copy;
}

}  // namespace sss::math
