// Writes docs/kernel-fits.md: the numbers behind the kernel families, computed here (never typed):
// the eq. (2-3) fit of the separable kernel to d'Eon's skin next to the paper's Table 1, the share of
// the first singular value per channel (paper Fig. 2), the guided fit against the pre-integrated
// kernel, the sum-of-Gaussians fits of the measured materials, and the calibrated default (the rank-1
// kernels fitted on the benchmark's footprint sweep by sss_fit_default, read from its committed
// expectation, tests/bench/default_kernel_fit.json).
//
//   sss_kernel_report [--out FILE]     (default: stdout)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "math/filter_constants.hpp"
#include "math/kernel_families.hpp"
#include "math/kernel_fits.hpp"
#include "math/kernel_request.hpp"

using namespace sss::math;

namespace {

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

// Σ|a − b| / Σ|b|.
double relative_l1(const std::vector<double>& a, const std::vector<double>& b) {
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) num += std::fabs(a[i] - b[i]), den += std::fabs(b[i]);
  return num / den;
}

// One fit of tests/bench/default_kernel_fit.json: its objective and the interior miss it scores.
void fit_row(std::ostringstream& md, const char* name, const nlohmann::json& fit, const std::string& values) {
  std::vector<double> miss;
  double worst_channel = 0.0;
  for (const auto& s : fit.at("scores")) {
    miss.push_back(s.at("miss").get<double>());
    for (const auto& c : s.at("miss_rgb")) worst_channel = std::max(worst_channel, c.get<double>());
  }
  std::sort(miss.begin(), miss.end());
  const double median = miss.size() % 2 ? miss[miss.size() / 2] : 0.5 * (miss[miss.size() / 2 - 1] + miss[miss.size() / 2]);
  md << "| " << name << " | " << values << " | " << fmt("%.4f", fit.at("objective").get<double>()) << " | "
     << fmt("%.3f", miss.back()) << " | " << fmt("%.3f", median) << " | " << fmt("%.3f", worst_channel) << " | "
     << fit.at("evaluations").get<int>() << " |\n";
}

std::string triple(const nlohmann::json& v, const char* f) {
  return fmt(f, v.at(0).get<double>()) + " " + fmt(f, v.at(1).get<double>()) + " " + fmt(f, v.at(2).get<double>());
}

void calibrated_default_section(std::ostringstream& md) {
  std::ifstream in(SSS_DEFAULT_FIT_JSON);
  if (!in) throw std::runtime_error("cannot read " SSS_DEFAULT_FIT_JSON);
  const nlohmann::json j = nlohmann::json::parse(in);
  const FilterSettings defaults;
  md << "\n## The calibrated default (footprint sweep)\n\n"
     << "`sss_fit_default` (tests/bench/fit_default_main.cpp, scripts/fit-default-kernel.sh) fits rank-1 kernels to\n"
        "d'Eon's skin at its physical size, on the benchmark's footprint sweep: the six planes facing the camera\n"
        "(shadow edges at 0, 20 and 45 degrees, a 0.5 mm spot, a 3 mm disk, per-pixel albedo) at "
     << j.at("footprints_mm").size() << " footprints from " << fmt("%.3g", j.at("footprints_mm").front().get<double>())
     << " to " << fmt("%.3g", j.at("footprints_mm").back().get<double>())
     << " mm per pixel,\neach filtered by the CPU model of the passes (footprint-aware taps, 17 per pass) and scored by "
        "the interior\n`miss` against the exact plane convolution (tests/bench/calibration.hpp). The objective: "
     << j.at("objective_definition").get<std::string>() << ".\n"
        "NLopt Subplex, bounded (eq. (1): separable_scale in [0.1, 2], strength and falloff in [0, 1]; artist model:\n"
        "variances in [0.001, 2] and [0.01, 20] mm², fitted in log space, weights in [0, 1]), started from Table 1 at\n"
        "the eq. (3) scale and from d'Eon's Gaussians split into a narrow and a broad half.\n\n"
     << "| kernel | fitted values | objective | largest miss | median miss | worst channel | evaluations |\n"
        "|---|---|---:|---:|---:|---:|---:|\n";
  const auto& s = j.at("separable");
  fit_row(md, "eq. (1), calibrated", s,
          "separable_scale " + fmt("%.4f", s.at("separable_scale").get<double>()) + "; strength " +
              triple(s.at("strength"), "%.4f") + "; falloff " + triple(s.at("falloff"), "%.4f"));
  const auto& t = j.at("table1");
  fit_row(md, "eq. (1), Table 1", t,
          "separable_scale " + fmt("%.4f", t.at("separable_scale").get<double>()) +
              " (strength .78 .70 .75, falloff .57 .13 .08 kept)");
  const auto& a = j.at("artist");
  fit_row(md, "artist model", a,
          "near variance " + triple(a.at("near_variance_mm2"), "%.4g") + " mm²; far variance " +
              triple(a.at("far_variance_mm2"), "%.4g") + " mm²; near weight " + triple(a.at("near_weight"), "%.4f"));
  fit_row(md, "pre-integrated (d'Eon's marginal)", j.at("marginal"), "none: Σ w_i N(0, v_i) both ways");
  md << "\nThe library's default (`sss_default_settings`) is the "
     << (defaults.kernel.family == KernelFamily::artist          ? "artist model"
         : defaults.kernel.family == KernelFamily::preintegrated ? "pre-integrated (d'Eon's marginal)"
                                                                 : "calibrated eq. (1)")
     << " row: its kernel family, and eq. (1)'s strength, falloff and\nseparable_scale, are these values "
        "(module/src/math/default_kernel_fit.hpp, generated with the expectation;\nbench.default_kernel_fit "
        "re-scores the default on every test run and fails if a score moves). Table 1 is\n"
        "`sss_settings_separable_table1`; the artist model's row is that family's defaults (`sss_kernel_desc`'s\n"
        "near and far variance and near weight). 'separable_scale' is kernel millimetres per millimetre of skin: the eq. (3)\n"
        "fits at the top of this page move it with their grid; this one is measured where it matters, on what the\n"
        "filter outputs.\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::string out_path;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--out") == 0 && i + 1 < argc) {
      out_path = argv[++i];
    } else {
      std::cerr << "usage: sss_kernel_report [--out FILE]\n";
      return 2;
    }
  }
  std::ostringstream md;
  const auto skin = GaussianSumProfile::skin(6);
  md << "# Kernel fits and decompositions\n\n"
     << "The numbers behind each kernel family (fits, decompositions, their errors against the profile), for anyone\n"
     << "choosing a family or changing one; the families themselves: [kernels.md](kernels.md).\n\n"
     << "Written by `build/tools/sss_kernel_report --out docs/kernel-fits.md` (scripts/generate-profiles.sh runs it);\n"
     << "do not edit by hand. Profile: d'Eon–Luebke six-Gaussian skin (DESIGN.md §5) unless stated.\n\n";

  // ---- Separable fit, on several sample grids: eq. (3)'s optimum depends on where it samples.
  md << "## Separable kernel (eq. 1) fitted by eq. (2-3)\n\n"
     << "NLopt BOBYQA (bounded, derivative-free; the bounds scale ∈ [0.05, 20], strength and falloff ∈ [0, 1]\n"
     << "are the constraints of the 'constrained nonlinear optimisation'), started from the reference defaults,\n"
     << "minimising eq. (3): Σ over channels and over the n×n cells of a grid on ±R mm of (K − s sᵀ)², K the\n"
     << "profile's cell integrals normalised to 1 and s the eq. (1) kernel integrated over the same cells\n"
     << "(its delta on the centre cell). 'scale' is kernel millimetres per millimetre of skin. The last column\n"
     << "is eq. (3) at the paper's Table 1 strength and falloff (with the fitted scale) on the same grid.\n\n"
     << "| grid | n | R mm | scale | strength R G B | falloff R G B | residual | Table 1 residual | evals |\n"
     << "|---|---|---|---|---|---|---|---|---|\n";
  struct GridCase { TapSpacing spacing; int n; double radius; };
  for (const GridCase g : {GridCase{TapSpacing::uniform, 17, 3.0}, GridCase{TapSpacing::uniform, 33, 6.0},
                           GridCase{TapSpacing::uniform, 33, 3.0}, GridCase{TapSpacing::quadratic, 17, 3.0},
                           GridCase{TapSpacing::quadratic, 33, 3.0}}) {
    const SeparableFit fit = fit_separable(skin, g.n, g.radius, g.spacing);
    const ProfileMatrix target = discretise_profile(skin, make_tap_grid(g.n, g.radius, g.spacing));
    const double table1 = separable_residual(target, fit.scale, {0.78, 0.70, 0.75}, {0.57, 0.13, 0.08});
    md << "| " << (g.spacing == TapSpacing::uniform ? "uniform" : "quadratic") << " | " << g.n << " | "
       << fmt("%.0f", g.radius) << " | " << fmt("%.3f", fit.scale) << " | " << fmt("%.2f", fit.strength[0]) << " "
       << fmt("%.2f", fit.strength[1]) << " " << fmt("%.2f", fit.strength[2]) << " | " << fmt("%.2f", fit.falloff[0])
       << " " << fmt("%.2f", fit.falloff[1]) << " " << fmt("%.2f", fit.falloff[2]) << " | "
       << fmt("%.2e", fit.residual) << " | " << fmt("%.2e", table1) << " | " << fit.evaluations << " |\n";
  }
  md << "| paper Table 1 | | | (width 0.014) | 0.78 0.70 0.75 | 0.57 0.13 0.08 | | | |\n\n"
     << "Why they differ: eq. (3) is a sum over a sample set the paper does not list, and the optimum moves\n"
     << "with it. The delta of eq. (1) can only stand for what lies inside the centre sample: on a coarse\n"
     << "uniform grid (cells of 0.35 mm on ±3 mm) the narrowest skin Gaussian (σ = 0.08 mm) falls inside the\n"
     << "centre cell and the fit lands near Table 1 (strength below 1, green and blue falloff near 0.1); on\n"
     << "grids with fine centre cells the narrow Gaussian is resolved, the delta is not needed and strength\n"
     << "goes to its bound 1. Red falloff stays near 1 in every fit: the base profile p is the red channel\n"
     << "itself, so only the scale separates red falloff from width. Width: with DESIGN.md §4 (one kernel\n"
     << "millimetre spans 2/3·width world units) the matching width is 1.5·(world units per mm)/scale; the\n"
     << "paper's 0.014 is in the units of its head model, whose scale it does not give, so it cannot be\n"
     << "checked directly.\n\n";

  // ---- SVD energy.
  const ProfileMatrix m = profile_matrix_for(skin, 33, 0.0);
  const auto svd = decompose_profile(m);
  const Rgb share = first_singular_energy_fraction(svd);
  md << "## SVD of the discretised profile\n\n"
     << "33×33 quadratic grid on ±" << fmt("%.2f", m.grid.edges_mm.back()) << " mm (the profile's 1e-4 extent).\n\n"
     << "| channel | σ1²/Σσ² | σ1/Σσ | σ2/σ1 | σ3/σ1 |\n|---|---|---|---|---|\n";
  const char* names[3] = {"red", "green", "blue"};
  for (std::size_t c = 0; c < 3; ++c) {
    double sum = 0.0;
    for (double s : svd[c].singular_values) sum += s;
    const auto& sv = svd[c].singular_values;
    md << "| " << names[c] << " | " << fmt("%.3f", share[c]) << " | " << fmt("%.3f", sv[0] / sum) << " | "
       << fmt("%.3f", sv[1] / sv[0]) << " | " << fmt("%.3f", sv[2] / sv[0]) << " |\n";
  }
  md << "\nThe first singular value's share σ1²/Σσ² on other grids (uniform grids: the plain 'discrete profile'):\n\n"
     << "| grid | red | green | blue |\n|---|---|---|---|\n";
  struct SvdGrid { TapSpacing spacing; int n; double radius; };
  for (const SvdGrid g : {SvdGrid{TapSpacing::uniform, 65, 3.0}, SvdGrid{TapSpacing::uniform, 65, 6.0},
                          SvdGrid{TapSpacing::quadratic, 65, 6.0}}) {
    const ProfileMatrix mg = discretise_profile(skin, make_tap_grid(g.n, g.radius, g.spacing));
    const Rgb sg = first_singular_energy_fraction(decompose_profile(mg));
    md << "| " << (g.spacing == TapSpacing::uniform ? "uniform " : "quadratic ") << g.n << "×" << g.n << " on ±"
       << fmt("%.0f", g.radius) << " mm | " << fmt("%.3f", sg[0]) << " | " << fmt("%.3f", sg[1]) << " | "
       << fmt("%.3f", sg[2]) << " |\n";
  }
  md << "\nThe paper's Figure 2 reports about 80% of the energy in the first eigenvalue. The share depends on\n"
     << "the discretisation: entries are cell integrals, and on a uniform grid the narrow peak (the\n"
     << "0.0064 mm² Gaussian) sits in a few cells whose squares dominate the Frobenius norm and are nearly\n"
     << "rank 1; the centre-dense quadratic grid spreads it and comes closest to the paper's figure in red.\n\n";

  // ---- Pre-integrated kernel against the full matrix on straight shadow edges.
  {
    const ProfileMatrix pm = profile_matrix_for(skin, 33, 0.0);
    const KernelPlan plan = preintegrated_plan(pm);
    md << "## Pre-integrated kernel on straight shadow edges\n\n"
       << "Largest difference, as a fraction of the edge's contrast, between the pre-integrated plan and the full\n"
       << "33×33 profile matrix applied to the edge H(x cos θ + y sin θ − 0.05 mm), sampled across it (red channel):\n\n"
       << "| θ (degrees) | max difference |\n|---|---|\n";
    for (double deg : {0.0, 30.0, 45.0, 71.0, 90.0}) {
      const double th = deg * 3.14159265358979323846 / 180.0, nx = std::cos(th), ny = std::sin(th);
      auto edge = [&](double x, double y) { return nx * x + ny * y > 0.05 ? 1.0 : 0.0; };
      double worst = 0.0;
      for (double t = -1.0; t <= 1.0; t += 0.0625) {
        const double px = t * nx, py = t * ny;
        double full = 0.0, sep = 0.0;
        for (int i = 0; i < pm.n(); ++i) {
          for (int j = 0; j < pm.n(); ++j) {
            full += pm.at(0, i, j) * edge(px - pm.grid.offsets_mm[static_cast<std::size_t>(i)],
                                         py - pm.grid.offsets_mm[static_cast<std::size_t>(j)]);
          }
        }
        for (const auto& h : plan.terms[0].horizontal) {
          for (const auto& v : plan.terms[0].vertical) sep += double(h.weight[0]) * v.weight[0] * edge(px - h.offset_mm, py - v.offset_mm);
        }
        worst = std::max(worst, std::fabs(full - sep));
      }
      md << "| " << fmt("%.0f", deg) << " | " << fmt("%.2e", worst) << " |\n";
    }
    md << "\nExact (to float rounding) on the axes, where the edge is additively separable; not at other angles.\n\n";
  }

  // ---- Guided vs pre-integrated.
  md << "## Guided rank-1 fit against the pre-integrated kernel (S.8)\n\n"
     << "Relative L1 distance Σ|a − a_p| / Σ a_p of the guided taps from the pre-integrated ones, 33 uniform taps\n"
     << "on ±" << fmt("%.2f", guided_radius_mm(skin)) << " mm (the radius holding 90% of every channel's energy), mapped to [-1, 1] for the guide:\n\n"
     << "| k | red | green | blue | SLSQP evaluations |\n|---|---|---|---|---|\n";
  for (double k : {0.0, 1.0, kGuideDefaultK, 2.0, 3.0, 4.0}) {
    const GuidedFit g = guided_fit(skin, 33, guided_radius_mm(skin), k);
    const auto ap = preintegrated_taps(g.matrix);
    md << "| " << fmt("%.2f", k);
    for (std::size_t c = 0; c < 3; ++c) md << " | " << fmt("%.3f", relative_l1(g.taps[c], ap[c]));
    md << " | " << g.evaluations << " |\n";
  }
  md << "\nWhat the table says: every k stays close to a_p (a kernel unrelated to the profile, a box or a delta, is\n"
        "above 0.8), and the distance grows with k in every channel, so k = 0 is the guided fit nearest to a_p in\n"
        "this discretisation, not k = " << fmt("%.2f", kGuideDefaultK) << ". That is what S.7-S.9 lead to: the parametrised guide copies Γ_p\n"
        "only on the diagonals, and its polynomial term weights the far field more as k grows, so k moves the fit\n"
        "from a_p's near-field detail (k = 0) towards far scattering (k = 4; Fig. S.3 shows the same trade between\n"
        "k = 0 and k = 2). The default " << fmt("%.2f", kGuideDefaultK) << " is the value of the supplementary's Fig. S.1b, kept as the\n"
        "middle of the artist's range; a host that wants the fit nearest a_p sets k = 0 (`sss_kernel_desc.guide_k`).\n"
        "`GuidedFit.DistanceToThePreintegratedKernelGrowsWithK` holds this order.\n";

  // ---- Sum of Gaussians fits.
  md << "\n## Sum-of-Gaussians fits of the dipole profiles\n\n"
     << "Variances (mm²) of N = 4 Gaussians fitted to each material's dipole profile (weights per channel sum to 1):\n\n"
     << "| material | v1 | v2 | v3 | v4 |\n|---|---|---|---|---|\n";
  for (const auto& mat : measured_materials()) {
    const DipoleProfile p(mat);
    const auto terms = fit_gaussian_sum(p, 4);
    md << "| " << mat.name;
    for (const auto& t : terms) md << " | " << fmt("%.4g", t.variance_mm2);
    md << " |\n";
  }

  calibrated_default_section(md);

  if (out_path.empty()) {
    std::cout << md.str();
  } else {
    std::ofstream(out_path) << md.str();
  }
  return 0;
}
