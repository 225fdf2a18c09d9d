// The Monte Carlo slab simulator (tools/mc) and the committed profiles it made (data/profiles):
// energy conservation of a tiny run, and the agreement of dipole and Monte Carlo where the
// diffusion approximation holds.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "math/radial_profile.hpp"
#include "mc_slab.hpp"

namespace {

using sss::mc::RadialGrid;
using sss::mc::SlabMedium;
using sss::mc::SlabTally;

TEST(MonteCarloSlab, FiniteSlabConservesEnergy) {
  const SlabMedium slab{0.1, 1.0, 1.4, 1.0};  // 1 mm thick: light leaves through both sides
  const RadialGrid grid{0.05, 100};
  const std::uint64_t n = 3000;
  const SlabTally t = sss::mc::simulate_slab(slab, grid, n, 2, 1);
  ASSERT_EQ(t.photons, n);
  const double total = (t.specular + t.diffuse_reflected + t.transmitted + t.absorbed) / n;
  // Bookkeeping: every unit of weight is either specular, reflected, transmitted, absorbed, or the
  // net weight roulette added; exact up to rounding of ~1e5 additions.
  EXPECT_NEAR(total - t.roulette / n, 1.0, 1e-12);
  // Physics: roulette is zero-mean and only acts on packets below 1e-4, each event moving at most
  // 9e-4 of one photon: over 3000 photons the sum is far inside 1e-3 of 1.
  EXPECT_NEAR(total, 1.0, 1e-3);
  EXPECT_GT(t.transmitted / n, 0.05);
  EXPECT_GT(t.diffuse_reflected / n, 0.05);
  EXPECT_GT(t.absorbed / n, 0.05);
  EXPECT_NEAR(t.specular / n, std::pow(0.4 / 2.4, 2), 1e-12);  // normal incidence Fresnel
  double binned = 0.0;
  for (double w : t.reflected_by_bin) binned += w;
  EXPECT_LE(binned, t.diffuse_reflected + 1e-9);
}

TEST(MonteCarloSlab, SemiInfiniteTransmitsNothingAndThreadsDoNotChangeTheResult) {
  const SlabMedium m{0.05, 2.0, 1.3, 0.0};
  const RadialGrid grid{0.02, 200};
  const SlabTally one = sss::mc::simulate_slab(m, grid, 5000, 1, 9);
  const SlabTally three = sss::mc::simulate_slab(m, grid, 5000, 3, 9);
  EXPECT_EQ(one.transmitted, 0.0);
  EXPECT_EQ(one.diffuse_reflected, three.diffuse_reflected);
  EXPECT_EQ(one.reflected_by_bin, three.reflected_by_bin);
  EXPECT_NEAR((one.specular + one.diffuse_reflected + one.absorbed - one.roulette) / 5000.0, 1.0, 1e-12);
}

TEST(MonteCarloSlab, SupplementaryGrid) {
  const double a[3] = {0.0030, 0.0034, 0.0460}, s[3] = {2.29, 2.39, 1.97};  // apple
  const RadialGrid g = sss::mc::supplementary_grid(a, s);
  EXPECT_NEAR(g.dr_mm, 1.0 / (2.39 + 0.0034) / 20.0, 1e-15);
  EXPECT_EQ(g.bins, static_cast<int>(std::ceil(32.0 / (1.97 + 0.046) / g.dr_mm)));
}

// ---- The committed data.

struct ProfileCsv {
  std::vector<double> r;
  std::vector<std::array<double, 3>> mc;
};

ProfileCsv load_profile(const std::string& path) {
  ProfileCsv p;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'r') continue;
    std::stringstream ss(line);
    std::string cell;
    std::vector<double> v;
    while (std::getline(ss, cell, ',')) v.push_back(std::stod(cell));
    if (v.size() < 4) continue;
    p.r.push_back(v[0]);
    p.mc.push_back({v[1], v[2], v[3]});
  }
  return p;
}

std::map<std::string, std::array<double, 3>> load_summary_mc(const std::string& path) {
  std::map<std::string, std::array<double, 3>> out;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("material", 0) == 0) continue;
    std::stringstream ss(line);
    std::string name, cell;
    std::getline(ss, name, ',');
    std::array<double, 3> v{};
    for (double& x : v) {
      std::getline(ss, cell, ',');
      x = std::stod(cell);
    }
    out[name] = v;
  }
  return out;
}

const std::string kData = SSS_SOURCE_DIR "/data/profiles/";

// The diffusion approximation (and so the dipole) needs scattering to dominate: reduced albedo
// ≥ 0.95 (Jensen et al. 2001 §2.3). Below, e.g. ketchup's green at 0.07, the dipole is not expected
// to hold and is not tested.
constexpr double kMinAlbedo = 0.95;

TEST(CommittedProfiles, TotalDiffuseReflectanceMatchesTheDipole) {
  const auto mc = load_summary_mc(kData + "summary.csv");
  ASSERT_EQ(mc.size(), 11u) << "run scripts/generate-profiles.sh";
  int tested = 0;
  for (const auto& m : sss::math::measured_materials()) {
    const sss::math::DipoleProfile dipole(m);
    for (std::size_t c = 0; c < 3; ++c) {
      const double albedo = m.sigma_s_per_mm[c] / (m.sigma_a_per_mm[c] + m.sigma_s_per_mm[c]);
      if (albedo < kMinAlbedo) continue;
      ++tested;
      // Monte Carlo noise at 1e5 photons: σ(R)/R ≈ sqrt((1 − R)/(N R)) < 0.3%. The dipole's own
      // error on the total for index-mismatched boundaries is a few percent (largest for marble,
      // η = 1.5); 5% holds them both.
      EXPECT_NEAR(mc.at(m.name)[c] / dipole.integral()[c], 1.0, 0.05) << m.name << " channel " << c;
    }
  }
  EXPECT_GE(tested, 20);
}

TEST(CommittedProfiles, ProfilesAgreeAwayFromTheCentre) {
  int tested = 0;
  for (const auto& m : sss::math::measured_materials()) {
    const ProfileCsv p = load_profile(kData + m.name + ".csv");
    ASSERT_GT(p.r.size(), 100u) << m.name;
    const double dr = p.r[1] - p.r[0];
    const sss::math::DipoleProfile dipole(m);
    for (std::size_t c = 0; c < 3; ++c) {
      const double albedo = m.sigma_s_per_mm[c] / (m.sigma_a_per_mm[c] + m.sigma_s_per_mm[c]);
      if (albedo < kMinAlbedo) continue;
      const double mfp = 1.0 / (m.sigma_a_per_mm[c] + m.sigma_s_per_mm[c]);
      const double total = dipole.integral()[c];
      // Annuli of doubling radius from 2 mean free paths: the dipole misplaces light within about
      // one mean free path of the entry point (its source sits one MFP deep, the real photons
      // start at the surface), so the centre is left out.
      for (double a = 2.0 * mfp; a < p.r.back() / 2.0; a *= 2.0) {
        const double b = 2.0 * a;
        double mc_energy = 0.0;
        for (std::size_t i = 0; i < p.r.size(); ++i) {
          if (p.r[i] >= a && p.r[i] < b) mc_energy += p.mc[i][c] * 2.0 * 3.14159265358979323846 * p.r[i] * dr;
        }
        const double dip_energy = dipole.encircled(b)[c] - dipole.encircled(a)[c];
        // Only annuli with ≥ 2% of the reflectance: ≥ 2000 photons of 1e5, so ≤ 2.5% noise.
        if (dip_energy < 0.02 * total) continue;
        ++tested;
        // The dipole against transport: within 15% per annulus in the diffusive range. Measured with
        // the committed 1e5-photon data: worst 12% (marble, η = 1.5, whose boundary the dipole's
        // extrapolated-boundary term models least well); typically 1-7%. For comparison, in
        // [0, 1 MFP) the Monte Carlo has about 20-25% more light than the dipole (η = 1.3): the
        // single scattering and the surface entry the dipole leaves out.
        EXPECT_NEAR(mc_energy / dip_energy, 1.0, 0.15) << m.name << " c=" << c << " annulus [" << a << ", " << b << ") mm";
      }
    }
  }
  EXPECT_GE(tested, 40);
}

}  // namespace
