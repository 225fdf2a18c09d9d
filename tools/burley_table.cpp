// The table of Burley parameters for the measured materials in docs/burley.md, computed here
// (never typed): A = the dipole's total diffuse reflectance R_d and ℓ_d = 1/σtr from Jensen et al.
// 2001's σa, σs' and η (module/src/math/burley_profile.hpp, what sss_profile_burley_from_measured
// returns), d = ℓ_d / s(A), and how Burley's shape compares with the committed Monte Carlo
// simulation of the same material (data/profiles/, docs/profiles.md) and with the dipole: the radii
// holding half and 90 % of each channel's energy.
//
//   sss_burley_table                  the table on stdout
//   sss_burley_table --update FILE    replaces what lies between FILE's table markers
//   sss_burley_table --check FILE     exit 1 if FILE's table differs from this one (ctest
//                                     docs.burley_table_is_current)
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "math/burley_profile.hpp"
#include "math/radial_profile.hpp"

using namespace sss::math;

namespace {

const char* const kBegin = "<!-- burley-table:begin (tools/burley_table.cpp writes this; do not edit) -->\n";
const char* const kEnd = "<!-- burley-table:end -->\n";

std::string three(const Rgb& v, const char* f) {
  std::string s;
  for (std::size_t c = 0; c < 3; ++c) {
    char b[32];
    std::snprintf(b, sizeof b, f, v[c]);
    s += (c ? " " : "") + std::string(b);
  }
  return s;
}

// The radius holding `fraction` of channel c's energy (bisection on the profile's encircled()).
double radius_holding(const RadialProfile& p, std::size_t c, double fraction) {
  const double total = p.integral()[c];
  double lo = 0.0, hi = p.support_mm(1e-6);
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (p.encircled(mid)[c] < fraction * total ? lo : hi) = mid;
  }
  return hi;
}

// The committed Monte Carlo profile of a material (data/profiles/<name>.csv, scripts/generate-profiles.sh):
// R_d at bin centres per channel, and the total diffuse reflectance (data/profiles/summary.csv), which
// counts the photons that left beyond the grid too.
struct MonteCarlo {
  std::vector<double> r;
  std::vector<Rgb> value;
  Rgb total{};
};

MonteCarlo read_monte_carlo(const std::string& name) {
  MonteCarlo mc;
  std::ifstream in(std::string(SSS_SOURCE_DIR) + "/data/profiles/" + name + ".csv");
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#' || line[0] == 'r') continue;
    double r = 0.0;
    Rgb v{};
    if (std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf", &r, &v[0], &v[1], &v[2]) == 4) mc.r.push_back(r), mc.value.push_back(v);
  }
  std::ifstream summary(std::string(SSS_SOURCE_DIR) + "/data/profiles/summary.csv");
  for (std::string line; std::getline(summary, line);) {
    if (line.rfind(name + ",", 0) == 0) {
      std::sscanf(line.c_str() + name.size() + 1, "%lf,%lf,%lf", &mc.total[0], &mc.total[1], &mc.total[2]);
    }
  }
  if (mc.r.size() < 2 || !(mc.total[0] > 0.0)) throw std::runtime_error("no Monte Carlo data for " + name);
  return mc;
}

// The radius where the Monte Carlo profile's energy reaches `fraction` of its total (linear within the
// bin; the bins are uniform, centred at (i + ½) dr); NaN when the grid ends first.
double radius_holding(const MonteCarlo& mc, std::size_t c, double fraction) {
  const double dr = 2.0 * mc.r[0];
  double inside = 0.0;
  for (std::size_t i = 0; i < mc.r.size(); ++i) {
    const double bin = 2.0 * 3.14159265358979323846 * mc.r[i] * mc.value[i][c] * dr;
    if (inside + bin >= fraction * mc.total[c]) return (static_cast<double>(i) + (fraction * mc.total[c] - inside) / bin) * dr;
    inside += bin;
  }
  return std::nan("");
}

std::string radii(const MonteCarlo& mc, const RadialProfile& dipole, const RadialProfile& burley, double fraction) {
  std::string s;
  for (std::size_t c = 0; c < 3; ++c) {
    char b[64];
    std::snprintf(b, sizeof b, "%s%.2f / %.2f / %.2f", c ? ", " : "", radius_holding(mc, c, fraction),
                  radius_holding(dipole, c, fraction), radius_holding(burley, c, fraction));
    s += b;
  }
  return s;
}

std::string table() {
  std::ostringstream md;
  md << kBegin << "\n"
     << "| material (`sss_profile`) | A (r g b) | ℓ_d mm (r g b) | d mm (r g b) | 50 % radius mm, Monte Carlo / "
        "dipole / Burley (r, g, b) | 90 % radius mm, Monte Carlo / dipole / Burley (r, g, b) |\n"
        "|---|---|---|---|---|---|\n";
  for (const MaterialCoefficients& m : measured_materials()) {
    const BurleyParameters b = burley_from_material(m);
    const BurleyProfile burley(b);
    const DipoleProfile dipole(m);
    const MonteCarlo mc = read_monte_carlo(m.name);
    md << "| " << m.name << " | " << three(b.albedo, "%.3f") << " | " << three(b.dmfp_mm, "%.3g") << " | "
       << three(burley.shape_mm(), "%.3g") << " | " << radii(mc, dipole, burley, 0.5) << " | "
       << radii(mc, dipole, burley, 0.9) << " |\n";
  }
  md << "\n" << kEnd;
  return md.str();
}

bool read(const char* path, std::string* text) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream s;
  s << in.rdbuf();
  *text = s.str();
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  std::string fresh;
  try {
    fresh = table();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", argv[0], e.what());
    return 2;
  }
  if (argc == 1) {
    std::cout << fresh;
    return 0;
  }
  const bool update = argc == 3 && std::strcmp(argv[1], "--update") == 0;
  const bool check = argc == 3 && std::strcmp(argv[1], "--check") == 0;
  if (!update && !check) {
    std::fprintf(stderr, "usage: %s [--update FILE | --check FILE]\n", argv[0]);
    return 2;
  }
  std::string text;
  if (!read(argv[2], &text)) {
    std::fprintf(stderr, "%s: cannot read %s\n", argv[0], argv[2]);
    return 2;
  }
  const std::size_t begin = text.find(kBegin), end = text.find(kEnd);
  if (begin == std::string::npos || end == std::string::npos || end < begin) {
    std::fprintf(stderr, "%s: %s has no table markers (%s ... %s)\n", argv[0], argv[2], kBegin, kEnd);
    return 2;
  }
  const std::string current = text.substr(begin, end + std::strlen(kEnd) - begin);
  if (check) {
    if (current == fresh) return 0;
    std::fprintf(stderr, "%s: the table in %s is not current; run %s --update %s (scripts/generate-profiles.sh)\n",
                 argv[0], argv[2], argv[0], argv[2]);
    return 1;
  }
  text.replace(begin, current.size(), fresh);
  std::ofstream(argv[2], std::ios::binary) << text;
  return 0;
}
