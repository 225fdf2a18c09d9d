#include "mc_slab.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <random>
#include <thread>

namespace sss::mc {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRouletteThreshold = 1e-4;
constexpr double kRouletteSurvival = 0.1;
constexpr std::uint64_t kChunk = 4096;

// Unpolarised Fresnel reflectance from the slab (index n1) into the ambient (n2) at incidence cosine
// cos_i; 1 beyond the critical angle.
double fresnel(double n1, double n2, double cos_i) {
  const double sin_i2 = std::max(0.0, 1.0 - cos_i * cos_i);
  const double sin_t2 = (n1 / n2) * (n1 / n2) * sin_i2;
  if (sin_t2 >= 1.0) return 1.0;
  const double cos_t = std::sqrt(1.0 - sin_t2);
  const double rs = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
  const double rp = (n1 * cos_t - n2 * cos_i) / (n1 * cos_t + n2 * cos_i);
  return 0.5 * (rs * rs + rp * rp);
}

struct Photon {
  double x = 0, y = 0, z = 0, ux = 0, uy = 0, uz = 1, w = 1;
};

void run_chunk(const SlabMedium& m, const RadialGrid& grid, std::uint64_t count, std::uint64_t seed, SlabTally& t) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  auto xi = [&] {  // (0, 1]: safe for log
    return 1.0 - uni(rng);
  };
  const double mu_t = m.sigma_a + m.sigma_s;
  const double absorb_fraction = m.sigma_a / mu_t;
  const double r_spec = std::pow((m.eta - 1.0) / (m.eta + 1.0), 2);
  const bool finite = m.thickness_mm > 0.0;
  for (std::uint64_t n = 0; n < count; ++n) {
    Photon p;
    p.w = 1.0 - r_spec;
    t.specular += r_spec;
    ++t.photons;
    double step_left = 0.0;  // dimensionless optical depth still to travel
    while (true) {
      if (step_left <= 0.0) step_left = -std::log(xi());
      double s = step_left / mu_t;
      // Distance to the boundary the photon is heading for.
      double to_boundary = INFINITY;
      if (p.uz < 0.0) to_boundary = -p.z / p.uz;
      if (p.uz > 0.0 && finite) to_boundary = (m.thickness_mm - p.z) / p.uz;
      if (s >= to_boundary) {
        p.x += p.ux * to_boundary;
        p.y += p.uy * to_boundary;
        p.z = p.uz < 0.0 ? 0.0 : m.thickness_mm;
        step_left -= to_boundary * mu_t;
        if (uni(rng) < fresnel(m.eta, 1.0, std::fabs(p.uz))) {
          p.uz = -p.uz;  // internal reflection; the rest of the step goes on
          continue;
        }
        if (p.uz < 0.0) {
          t.diffuse_reflected += p.w;
          const double bin = std::hypot(p.x, p.y) / grid.dr_mm;
          // Compared as a double first: converting an out-of-range double to an integer is undefined.
          if (bin < static_cast<double>(t.reflected_by_bin.size())) t.reflected_by_bin[static_cast<std::size_t>(bin)] += p.w;
        } else {
          t.transmitted += p.w;
        }
        break;
      }
      p.x += p.ux * s;
      p.y += p.uy * s;
      p.z += p.uz * s;
      step_left = 0.0;
      // Interaction: deposit the absorbed share, scatter isotropically.
      const double dw = p.w * absorb_fraction;
      t.absorbed += dw;
      p.w -= dw;
      const double cos_t = 2.0 * uni(rng) - 1.0;
      const double sin_t = std::sqrt(std::max(0.0, 1.0 - cos_t * cos_t));
      const double phi = 2.0 * kPi * uni(rng);
      p.ux = sin_t * std::cos(phi);
      p.uy = sin_t * std::sin(phi);
      p.uz = cos_t;
      if (p.w < kRouletteThreshold) {
        if (uni(rng) < kRouletteSurvival) {
          t.roulette += p.w * (1.0 / kRouletteSurvival - 1.0);
          p.w /= kRouletteSurvival;
        } else {
          t.roulette -= p.w;
          break;
        }
      }
    }
  }
}

void add(SlabTally& into, const SlabTally& t) {
  into.photons += t.photons;
  into.specular += t.specular;
  into.diffuse_reflected += t.diffuse_reflected;
  into.transmitted += t.transmitted;
  into.absorbed += t.absorbed;
  into.roulette += t.roulette;
  for (std::size_t i = 0; i < into.reflected_by_bin.size(); ++i) into.reflected_by_bin[i] += t.reflected_by_bin[i];
}

}  // namespace

std::vector<double> SlabTally::profile(const RadialGrid& grid) const {
  std::vector<double> out(reflected_by_bin.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double area = kPi * grid.dr_mm * grid.dr_mm * (2.0 * static_cast<double>(i) + 1.0);
    out[i] = photons ? reflected_by_bin[i] / (static_cast<double>(photons) * area) : 0.0;
  }
  return out;
}

SlabTally simulate_slab(const SlabMedium& medium, const RadialGrid& grid, std::uint64_t photons, int threads,
                        std::uint64_t seed) {
  const std::uint64_t chunks = (photons + kChunk - 1) / kChunk;
  std::vector<SlabTally> per_chunk(chunks);
  std::atomic<std::uint64_t> next{0};
  auto worker = [&] {
    for (std::uint64_t c = next++; c < chunks; c = next++) {
      SlabTally& t = per_chunk[c];
      t.reflected_by_bin.assign(static_cast<std::size_t>(grid.bins), 0.0);
      const std::uint64_t count = std::min(kChunk, photons - c * kChunk);
      // SplitMix-style mixing keeps neighbouring chunk seeds unrelated.
      std::uint64_t s = seed + 0x9E3779B97F4A7C15ull * (c + 1);
      s = (s ^ (s >> 30)) * 0xBF58476D1CE4E5B9ull;
      s = (s ^ (s >> 27)) * 0x94D049BB133111EBull;
      run_chunk(medium, grid, count, s ^ (s >> 31), t);
    }
  };
  std::vector<std::thread> pool;
  for (int i = 1; i < std::max(1, threads); ++i) pool.emplace_back(worker);
  worker();
  for (auto& th : pool) th.join();
  SlabTally total;
  total.reflected_by_bin.assign(static_cast<std::size_t>(grid.bins), 0.0);
  for (const auto& t : per_chunk) add(total, t);
  return total;
}

RadialGrid supplementary_grid(const double sigma_a[3], const double sigma_s[3]) {
  double lo = INFINITY, hi = 0.0;
  for (int c = 0; c < 3; ++c) {
    const double mfp = 1.0 / (sigma_a[c] + sigma_s[c]);
    lo = std::min(lo, mfp);
    hi = std::max(hi, mfp);
  }
  const double dr = lo / 20.0;
  return RadialGrid{dr, static_cast<int>(std::ceil(32.0 * hi / dr))};
}

}  // namespace sss::mc
