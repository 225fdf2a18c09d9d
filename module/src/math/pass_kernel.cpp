#include "pass_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "kernel_families.hpp"
#include "separable_kernel.hpp"

namespace sss::math {

namespace {

// The plan's taps of one pass, centre first (a zero-weight centre where the plan has none), then in
// increasing offset: what sss_kernel_plan reports; the passes read the footprint table.
PassTaps make_pass_taps(std::vector<KernelTap> taps) {
  std::stable_sort(taps.begin(), taps.end(),
                   [](const KernelTap& a, const KernelTap& b) { return a.offset_mm < b.offset_mm; });
  PassTaps out;
  auto centre = std::find_if(taps.begin(), taps.end(), [](const KernelTap& t) { return t.offset_mm == 0.0f; });
  if (centre == taps.end()) {
    out.taps.push_back(KernelTap{{0.0f, 0.0f, 0.0f}, 0.0f});
  } else {
    out.taps.push_back(*centre);
    taps.erase(centre);
  }
  out.taps.insert(out.taps.end(), taps.begin(), taps.end());
  return out;
}

// The mass of a pass per channel: what its weights sum to at any footprint.
std::array<double, 3> table_mass(const FootprintTable& t) {
  return {2.0 * t.half_cdf.back()[0] + t.delta[0], 2.0 * t.half_cdf.back()[1] + t.delta[1],
          2.0 * t.half_cdf.back()[2] + t.delta[2]};
}

// Moves a term's mass from its horizontal pass into its vertical one (the product, the term, is
// unchanged): the horizontal pass then writes a weighted average of the input, which at a pixel
// whose kernel fits inside it is the input itself, exactly representable in the RGBA16F
// intermediate. Left as it was where the horizontal mass is near 0 (an SVD term that sums to
// about nothing has no average to keep).
void normalise_horizontal(PassTerm* term) {
  const std::array<double, 3> mass = table_mass(term->horizontal.footprint);
  for (std::size_t c = 0; c < 3; ++c) {
    if (!(std::fabs(mass[c]) > 1e-3) || mass[c] == 1.0) continue;
    const auto down = static_cast<float>(1.0 / mass[c]), up = static_cast<float>(mass[c]);
    FootprintTable& h = term->horizontal.footprint;
    FootprintTable& v = term->vertical.footprint;
    h.delta[c] *= down;
    for (auto& e : h.half_cdf) e[c] *= down;
    // Exactly 1 in float: a pixel passed through keeps its value bit for bit.
    h.half_cdf.back()[c] = 0.5f * (1.0f - h.delta[c]);
    v.delta[c] *= up;
    for (auto& e : v.half_cdf) e[c] *= up;
    for (KernelTap& tap : term->horizontal.taps) tap.weight[c] *= down;
    for (KernelTap& tap : term->vertical.taps) tap.weight[c] *= up;
  }
}

}  // namespace

PassKernel make_pass_kernel(const KernelPlan& plan, float jitter) {
  PassKernel k;
  for (const SeparableTerm& term : plan.terms) {
    PassTerm t;
    t.horizontal = make_pass_taps(term.horizontal);
    t.vertical = make_pass_taps(term.vertical);
    t.horizontal.footprint =
        term.horizontal_table.empty() ? footprint_table_from_taps(term.horizontal) : term.horizontal_table;
    t.vertical.footprint = term.vertical_table.empty() ? footprint_table_from_taps(term.vertical) : term.vertical_table;
    normalise_horizontal(&t);
    t.depth_variance_mm2 = term.depth_variance_mm2;
    k.terms.push_back(std::move(t));
  }
  k.reach_mm = plan_reach_mm(plan);
  std::size_t most = 0;
  for (const SeparableTerm& term : plan.terms) most = std::max({most, term.horizontal.size(), term.vertical.size()});
  const int half = std::min(static_cast<int>(most / 2), kMaxFootprintHalfTaps);
  k.layout = plan.layout;
  k.spacing = footprint_spacing(half, plan.layout);
  k.jitter_from = first_jittered_tap(jitter, half);
  return k;
}

PassKernel build_pass_kernel(const FilterSettings& settings) {
  KernelRequest request = settings.kernel;
  request.taps = settings.samples;
  request.strength = settings.strength;
  request.falloff = settings.falloff;
  request.separable_scale = settings.separable_scale;
  return make_pass_kernel(build_kernel_plan(request), settings.jitter);
}

bool same_pass_kernel_inputs(const FilterSettings& a, const FilterSettings& b) {
  if (a.samples != b.samples || a.jitter != b.jitter || a.kernel.family != b.kernel.family) {
    return false;
  }
  const KernelRequest& x = a.kernel;
  const KernelRequest& y = b.kernel;
  switch (x.family) {
    case KernelFamily::separable:
      return a.strength == b.strength && a.falloff == b.falloff && a.separable_scale == b.separable_scale;
    case KernelFamily::artist:
      return x.artist.near_variance_mm2 == y.artist.near_variance_mm2 &&
             x.artist.far_variance_mm2 == y.artist.far_variance_mm2 && x.artist.near_weight == y.artist.near_weight;
    default: break;
  }
  return same_profile_request(x.profile, y.profile) && x.rank == y.rank && x.rescale_energy == y.rescale_energy && x.guide_k == y.guide_k &&
         x.radius_mm == y.radius_mm;
}

float jitter_noise(int x, int y, int axis, std::uint32_t noise_index) {
  // A 32-bit integer hash (xorshift-multiply rounds) of the pixel, the axis and the noise index (by
  // the golden ratio's odd multiplier, so that consecutive indices land far apart), then its top 24
  // bits as a fraction: exact in float and identical in GLSL's uint arithmetic.
  std::uint32_t h = static_cast<std::uint32_t>(x) * 0x8da6b343u ^ static_cast<std::uint32_t>(y) * 0xd8163841u ^
                    static_cast<std::uint32_t>(axis + 1) * 0xcb1ab31fu ^ noise_index * 0x9e3779b9u;
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

}  // namespace sss::math
