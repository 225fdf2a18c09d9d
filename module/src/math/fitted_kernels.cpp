// The fitters the tools library registers (fitters.hpp): the kernel families that decompose the
// profile matrix or run an optimiser, and the Gaussian fit of a profile. Not in the runtime library.
#include "fitters.hpp"
#include "kernel_fits.hpp"
#include "kernel_request.hpp"

namespace sss::math {

namespace {

// The grid the matrix families' footprint tables come from (the most taps a pass may have).
constexpr int kTableGridTaps = 65;
// The guided family fits its taps with an optimiser; its tables come from this grid (see below).
constexpr int kGuidedTableGridTaps = 33;

// `plan` takes the footprint tables of `fine`, the same kernel on a finer grid (term by term).
void use_tables_of(const KernelPlan& fine, KernelPlan* plan) {
  for (std::size_t t = 0; t < plan->terms.size() && t < fine.terms.size(); ++t) {
    plan->terms[t].horizontal_table = footprint_table_from_taps(fine.terms[t].horizontal);
    plan->terms[t].vertical_table = footprint_table_from_taps(fine.terms[t].vertical);
  }
  plan->reach_mm = plan_reach_mm(*plan);
}

}  // namespace

namespace {

KernelPlan build_fitted_plan(const KernelRequest& r) {
  const auto profile = make_profile(r.profile);
  switch (r.family) {
    case KernelFamily::sum_of_gaussians:
      return gaussian_sum_plan(GaussianSumProfile(fit_gaussian_sum(*profile, r.rank)), r.taps);
    case KernelFamily::svd: {
      KernelPlan plan = svd_plan(profile_matrix_for(*profile, r.taps, r.radius_mm), r.rank, r.rescale_energy);
      // The footprint tables from the same decomposition on the finest grid: the taps' cells are
      // what the fixed (jittered) passes read; the footprint-aware passes read the kernel itself.
      if (r.taps < kTableGridTaps) {
        const KernelPlan fine = svd_plan(profile_matrix_for(*profile, kTableGridTaps, r.radius_mm), r.rank, r.rescale_energy);
        use_tables_of(fine, &plan);
      }
      return plan;
    }
    case KernelFamily::preintegrated: {
      KernelPlan plan = preintegrated_plan(profile_matrix_for(*profile, r.taps, r.radius_mm), r.rank);
      if (r.taps < kTableGridTaps) {
        use_tables_of(preintegrated_plan(profile_matrix_for(*profile, kTableGridTaps, r.radius_mm), r.rank), &plan);
      }
      // A sum of Gaussians has its marginal in closed form: Σ w_i N(0, v_i) along each axis (the
      // 1D marginal of a 2D Gaussian is the 1D Gaussian of the same variance), normalised by ‖R‖₁.
      if (const auto* terms = profile->gaussian_terms()) {
        std::vector<LineGaussian> marginal;
        const Rgb total = profile->integral();
        for (const GaussianTerm& g : *terms) {
          marginal.push_back({g.variance_mm2, {g.weight[0] / total[0], g.weight[1] / total[1], g.weight[2] / total[2]}});
        }
        plan.terms[0].horizontal_table = footprint_table_gaussians(marginal);
        plan.terms[0].vertical_table = plan.terms[0].horizontal_table;
        plan.reach_mm = plan_reach_mm(plan);
      }
      return plan;
    }
    case KernelFamily::guided: {
      const double radius = r.radius_mm > 0.0 ? r.radius_mm : guided_radius_mm(*profile);
      KernelPlan plan = guided_plan(*profile, r.taps, radius, r.guide_k);
      // As for SVD, the tables come from a finer fit. The fit's cells are uniform over the 90 %
      // radius, so at 17 taps blue's and green's narrow peaks shared their centre cell with a fifth
      // of a millimetre of tail: at 2 mm per pixel that put both channels 1.1-1.3 times further from
      // the exact result than doing nothing (sss_fit_default --score-family 4 --taps 17). From the 33-cell
      // fit the worst channel on the sweep is 0.96 (blue, 1.08 mm per pixel) and the fit takes
      // ~90 ms; the 65-cell one reaches 0.90 but takes a second.
      if (r.taps < kGuidedTableGridTaps) use_tables_of(guided_plan(*profile, kGuidedTableGridTaps, radius, r.guide_k), &plan);
      return plan;
    }
    default:
      return {};
  }
}

}  // namespace

const Fitters& tool_fitters() {
  static const Fitters f{&build_fitted_plan, &fit_gaussian_sum};
  return f;
}

}  // namespace sss::math
