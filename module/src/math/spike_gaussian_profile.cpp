#include "spike_gaussian_profile.hpp"

#include <cmath>

#include "fitters.hpp"
#include "radial_profile.hpp"

namespace sss::math {

SpikeGaussianProfile mikkelsen_profile() {
  SpikeGaussianProfile p;
  p.name = "mikkelsen-2010";
  p.spike = {0.15, 0.18, 0.20};
  // One broad Gaussian per channel: each term carries one channel's whole broad share.
  p.terms = {{2.3, {0.85, 0.0, 0.0}}, {1.4, {0.0, 0.82, 0.0}}, {1.1, {0.0, 0.0, 0.80}}};
  return p;
}

SpikeGaussianProfile skin_spike_gaussian_profile() {
  SpikeGaussianProfile p;
  p.name = "deon-skin";
  const auto& g = skin_gaussians();
  p.spike = g[0].weight;
  p.spike_variance_mm2 = g[0].variance_mm2;
  p.terms.assign(g.begin() + 1, g.end());
  return p;
}

bool is_spike_gaussian_profile_id(unsigned id) {
  return id == kMikkelsenProfileId || id <= static_cast<unsigned>(kMaterialCount);
}

SpikeGaussianProfile spike_gaussian_profile(unsigned id) {
  if (id == kMikkelsenProfileId) return mikkelsen_profile();
  if (id == 0) return skin_spike_gaussian_profile();
  const MaterialCoefficients& m = measured_materials().at(id - 1);
  SpikeGaussianProfile p;
  p.name = m.name;
  p.terms = fitters("a measured material's Gaussians (its dipole fitted)").fit_gaussian_sum(DipoleProfile(m), kFittedGaussians);
  return p;
}

SpikeGaussianProfile spike_gaussian_profile(const RadialProfile& profile, const std::string& name) {
  SpikeGaussianProfile p;
  p.name = name;
  const std::vector<GaussianTerm>* terms = profile.gaussian_terms();
  p.terms = terms != nullptr ? *terms
                             : fitters("the Gaussians fitted to a profile").fit_gaussian_sum(profile, kFittedGaussians);
  return p;
}

bool is_cbf_profile_id(unsigned id) { return id == kKernelProfileId || is_spike_gaussian_profile_id(id); }

SpikeGaussianProfile cbf_profile(unsigned id, const ProfileRequest& kernel_profile) {
  if (id != kKernelProfileId) return spike_gaussian_profile(id);
  return spike_gaussian_profile(*make_profile(kernel_profile), "kernel profile");
}

std::vector<GaussianTerm> transmittance_terms(const SpikeGaussianProfile& p) {
  std::vector<GaussianTerm> terms;
  if (p.spike_variance_mm2 > 0.0) terms.push_back({p.spike_variance_mm2, p.spike});
  terms.insert(terms.end(), p.terms.begin(), p.terms.end());
  return terms;
}

double transmittance(const std::vector<GaussianTerm>& terms, int channel, double s) {
  double sum = 0.0;
  for (const GaussianTerm& t : terms) sum += t.weight[static_cast<std::size_t>(channel)] * std::exp(-s * s / t.variance_mm2);
  return sum;
}

double broad_variance_mm2(const SpikeGaussianProfile& p, int channel) {
  double weight = 0.0, moment = 0.0;
  for (const GaussianTerm& t : p.terms) {
    weight += t.weight[static_cast<std::size_t>(channel)];
    moment += t.weight[static_cast<std::size_t>(channel)] * t.variance_mm2;
  }
  return weight > 0.0 ? moment / weight : 0.0;
}

double broad_marginal_integral(const SpikeGaussianProfile& p, int channel, double a_mm, double b_mm) {
  double sum = 0.0;
  for (const GaussianTerm& t : p.terms) {
    const double w = t.weight[static_cast<std::size_t>(channel)];
    if (w == 0.0) continue;
    const double k = std::sqrt(2.0 * t.variance_mm2);
    sum += w * 0.5 * (std::erf(b_mm / k) - std::erf(a_mm / k));
  }
  return sum;
}

double broad_profile_2d(const SpikeGaussianProfile& p, int channel, double r_mm) {
  double sum = 0.0;
  for (const GaussianTerm& t : p.terms) sum += t.weight[static_cast<std::size_t>(channel)] * gaussian_2d(t.variance_mm2, r_mm);
  return sum;
}

}  // namespace sss::math
