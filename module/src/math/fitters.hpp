// The kernels the runtime library cannot build by itself: the families that decompose the profile
// matrix (Eigen's SVD) or run an optimiser (NLopt), and the Gaussians fitted to a measured profile.
// The tools library (sss_tools.h, sss_tools_init) registers them here; the runtime library links
// neither Eigen nor NLopt, and a call that needs one of them without the tools fails with
// FittersMissing (sss_set_settings: SSS_ERROR_UNSUPPORTED naming sss_tools_init). Math layer: no GL.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "kernel_plan.hpp"
#include "radial_profile.hpp"

namespace sss::math {

struct KernelRequest;

struct Fitters {
  // The plan of a family build_kernel_plan does not build in closed form (SVD, pre-integrated, guided,
  // a sum of Gaussians fitted to a profile that is not the skin Gaussians).
  KernelPlan (*build_plan)(const KernelRequest& request);
  // `count` Gaussians fitted to `profile` (fit_gaussian_sum).
  std::vector<GaussianTerm> (*fit_gaussian_sum)(const RadialProfile& profile, int count);
};

struct FittersMissing : std::runtime_error {
  explicit FittersMissing(const std::string& what) : std::runtime_error(what) {}
};

// The fitters registered in this copy of the math layer; throws FittersMissing naming `what` when
// none are.
const Fitters& fitters(const char* what);
bool have_fitters();
void set_fitters(const Fitters* f);

// The tools' fitters (fitted_kernels.cpp, in the tools library and sss_math).
const Fitters& tool_fitters();

}  // namespace sss::math
