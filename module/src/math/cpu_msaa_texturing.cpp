#include "cpu_msaa_texturing.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "cpu_texturing.hpp"
#include "half_float.hpp"

namespace sss::math {

namespace {

bool finite4(const float* v) {
  for (int c = 0; c < 4; ++c) {
    if (!(std::fabs(v[c]) <= std::numeric_limits<float>::max())) return false;
  }
  return true;
}

// msaa_resolve.frag's test: a sample the write-back changes has strength and nothing infinite or NaN.
bool translucent(const float* c) { return c[3] > 0.0f && finite4(c); }

// What msaa_write.frag gives one channel of a translucent sample of quotient q (colour s = A · q) for
// the pixel's change x, its lowest translucent quotient m and their mean t: A · a + b · s.
float written(float s, float post, float x, float m, float t) {
  float add = x, scale = 1.0f;
  if (!(m + x >= 0.0f)) {  // pulled towards m, which lands on 0 (the shader's floor of b to 2^-11)
    float pulled = std::clamp((t + x) / std::max(t - m, 1e-30f), 0.0f, 1.0f);
    pulled = t + x <= 0.0f ? 0.0f : std::floor(pulled * 2048.0f) / 2048.0f;
    scale = pulled;
    add = -(m * pulled);
  }
  return post * add + scale * s;
}

}  // namespace

std::vector<std::vector<float>> samples_over_albedo(const std::vector<std::vector<float>>& colour,
                                                    const std::vector<std::vector<float>>& albedo, unsigned mode) {
  std::vector<std::vector<float>> q = colour;
  for (std::size_t s = 0; s < q.size(); ++s) {
    for (std::size_t i = 0; i < q[s].size(); ++i) {
      if (i % 4 != 3) q[s][i] = colour[s][i] / albedo_post(albedo[s][i], mode);
    }
  }
  return q;
}

MsaaQuotientResolve resolve_over_albedo(const std::vector<std::vector<float>>& colour,
                                        const std::vector<std::vector<float>>& albedo, unsigned mode, bool half) {
  const std::vector<std::vector<float>> q = samples_over_albedo(colour, albedo, mode);
  const std::size_t values = colour.front().size();
  const auto n = static_cast<float>(colour.size());
  MsaaQuotientResolve r;
  r.quotient.assign(values, 0.0f);
  r.original.assign(values, 0.0f);
  r.albedo_post.assign(values / 4 * 3, 0.0f);
  for (std::size_t i = 0; i < values; ++i) {
    float sum = 0.0f, original = 0.0f, post = 0.0f;
    for (std::size_t s = 0; s < colour.size(); ++s) {  // in the shader's order, sample by sample
      sum += q[s][i];
      original += colour[s][i];
      if (i % 4 != 3) post += albedo_post(albedo[s][i], mode);
    }
    r.quotient[i] = half ? round_to_half(sum / n) : sum / n;
    r.original[i] = half ? round_to_half(original / n) : original / n;
    if (i % 4 != 3) r.albedo_post[i / 4 * 3 + i % 4] = post / n;
  }
  return r;
}

std::vector<std::vector<float>> write_back_over_albedo(const std::vector<std::vector<float>>& colour,
                                                       const std::vector<std::vector<float>>& albedo, unsigned mode,
                                                       const MsaaQuotientResolve& resolved,
                                                       const std::vector<float>& blurred) {
  const std::vector<std::vector<float>> q = samples_over_albedo(colour, albedo, mode);
  std::vector<std::vector<float>> out = colour;
  const std::size_t pixels = colour.front().size() / 4;
  const std::size_t n = colour.size();
  for (std::size_t p = 0; p < pixels; ++p) {
    std::array<float, 4> delta{};
    for (std::size_t c = 0; c < 3; ++c) delta[c] = blurred[p * 4 + c] - resolved.quotient[p * 4 + c];
    delta[3] = resolved.quotient[p * 4 + 3];
    const bool unchanged = delta[0] == 0.0f && delta[1] == 0.0f && delta[2] == 0.0f;
    if (!(resolved.quotient[p * 4 + 3] > 0.0f) || !finite4(delta.data()) || unchanged) continue;
    std::size_t count = 0;
    std::array<float, 3> lowest{}, mean{};
    lowest.fill(std::numeric_limits<float>::max());
    for (std::size_t s = 0; s < n; ++s) {
      if (!translucent(&q[s][p * 4])) continue;
      ++count;
      for (std::size_t c = 0; c < 3; ++c) {
        lowest[c] = std::min(lowest[c], q[s][p * 4 + c]);
        mean[c] += q[s][p * 4 + c];
      }
    }
    if (count == 0) continue;
    for (std::size_t s = 0; s < n; ++s) {
      if (!translucent(&q[s][p * 4])) continue;
      for (std::size_t c = 0; c < 3; ++c) {
        const float x = delta[c] * (static_cast<float>(n) / static_cast<float>(count));
        const float t = mean[c] / static_cast<float>(count);
        const float post = albedo_post(albedo[s][p * 4 + c], mode);
        out[s][p * 4 + c] = written(colour[s][p * 4 + c], post, x, lowest[c], t);
      }
    }
  }
  return out;
}

}  // namespace sss::math
