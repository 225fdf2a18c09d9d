// Simulates the diffuse reflectance profile of every measured material (supplementary §G) per RGB
// channel with the Monte Carlo slab (mc_slab.hpp) on the §F grid, and writes one CSV per material
// with the dipole profile beside it, plus summary.csv with the total diffuse reflectances.
//
//   sss_mc_profiles --out DIR [--photons N] [--threads T] [--seed S] [--materials a,b,...]
//
// Defaults: 10^7 photons as in §F would take hours on two cores; scripts/generate-profiles.sh passes
// the count the committed data was made with (docs/profiles.md says which and why).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "math/radial_profile.hpp"
#include "mc_slab.hpp"

namespace {

void usage() {
  std::cerr << "usage: sss_mc_profiles --out DIR [--photons N] [--threads T] [--seed S] [--materials a,b,...]\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::string out_dir;
  std::uint64_t photons = 10000000;
  int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::uint64_t seed = 20261121;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> const char* {
      if (i + 1 >= argc) {
        usage();
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--out") {
      out_dir = value();
    } else if (a == "--photons") {
      photons = std::strtoull(value(), nullptr, 10);
    } else if (a == "--threads") {
      threads = std::atoi(value());
    } else if (a == "--seed") {
      seed = std::strtoull(value(), nullptr, 10);
    } else if (a == "--materials") {
      only = std::string(",") + value() + ",";
    } else {
      usage();
      return 2;
    }
  }
  if (out_dir.empty() || photons == 0 || threads < 1) {
    usage();
    return 2;
  }

  const std::string summary_path = out_dir + "/summary.csv";
  FILE* summary = std::fopen(summary_path.c_str(), only.empty() ? "w" : "a");
  if (!summary) {
    std::perror(summary_path.c_str());
    return 1;
  }
  if (only.empty()) {
    std::fprintf(summary, "# Total diffuse reflectance (specular excluded): Monte Carlo (%llu photons per channel) and dipole\n",
                 static_cast<unsigned long long>(photons));
    std::fprintf(summary, "material,mc_r,mc_g,mc_b,dipole_r,dipole_g,dipole_b,albedo_r,albedo_g,albedo_b\n");
  }
  for (const auto& m : sss::math::measured_materials()) {
    if (!only.empty() && only.find(std::string(",") + m.name + ",") == std::string::npos) continue;
    const auto start = std::chrono::steady_clock::now();
    const sss::mc::RadialGrid grid = sss::mc::supplementary_grid(m.sigma_a_per_mm.data(), m.sigma_s_per_mm.data());
    std::vector<std::vector<double>> mc(3);
    double total[3];
    for (std::size_t c = 0; c < 3; ++c) {
      const sss::mc::SlabMedium medium{m.sigma_a_per_mm[c], m.sigma_s_per_mm[c], m.eta, 0.0};
      const auto tally = sss::mc::simulate_slab(medium, grid, photons, threads, seed + 7 * c);
      mc[c] = tally.profile(grid);
      total[c] = tally.diffuse_reflected / static_cast<double>(photons);
    }
    const sss::math::DipoleProfile dipole(m);
    const std::string path = out_dir + "/" + m.name + ".csv";
    FILE* f = std::fopen(path.c_str(), "w");
    if (!f) {
      std::perror(path.c_str());
      return 1;
    }
    std::fprintf(f, "# %s: sigma_a %g %g %g /mm, sigma_s %g %g %g /mm, eta %g, g 0 (supplementary §G)\n", m.name,
                 m.sigma_a_per_mm[0], m.sigma_a_per_mm[1], m.sigma_a_per_mm[2], m.sigma_s_per_mm[0],
                 m.sigma_s_per_mm[1], m.sigma_s_per_mm[2], m.eta);
    std::fprintf(f, "# Monte Carlo: %llu photons per channel, seed %llu, grid dr %.6g mm x %d bins (supplementary §F)\n",
                 static_cast<unsigned long long>(photons), static_cast<unsigned long long>(seed), grid.dr_mm, grid.bins);
    std::fprintf(f, "# R_d(r) in 1/mm^2 at bin centres; dipole (Jensen et al. 2001) at the same radii\n");
    std::fprintf(f, "r_mm,mc_r,mc_g,mc_b,dipole_r,dipole_g,dipole_b\n");
    for (int i = 0; i < grid.bins; ++i) {
      const double r = (i + 0.5) * grid.dr_mm;
      const auto d = dipole.evaluate(r);
      std::fprintf(f, "%.6g,%.5g,%.5g,%.5g,%.5g,%.5g,%.5g\n", r, mc[0][static_cast<std::size_t>(i)],
                   mc[1][static_cast<std::size_t>(i)], mc[2][static_cast<std::size_t>(i)], d[0], d[1], d[2]);
    }
    std::fclose(f);
    const auto dt = dipole.integral();
    double albedo[3];
    for (std::size_t c = 0; c < 3; ++c) albedo[c] = m.sigma_s_per_mm[c] / (m.sigma_a_per_mm[c] + m.sigma_s_per_mm[c]);
    std::fprintf(summary, "%s,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f\n", m.name, total[0], total[1], total[2],
                 dt[0], dt[1], dt[2], albedo[0], albedo[1], albedo[2]);
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cerr << m.name << ": " << grid.bins << " bins, " << secs << " s\n";
  }
  std::fclose(summary);
  return 0;
}
