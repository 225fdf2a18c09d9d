// The last few kernels sss_set_settings built from a profile, by what each was built from, so that
// going back to earlier settings (a material per character, a quality preset, a debug toggle)
// takes the kernel kept instead of fitting it again: the fitted families and a measured material's
// cross-bilateral profile run an optimiser (NLopt) for tens to hundreds of milliseconds.
// Kernels that cost next to nothing (eq. (1), the artist model, Mikkelsen's and d'Eon's closed-form
// profiles) are not kept, so a host that animates strength every frame does not push out the
// costly ones. Math layer: no GL.
#pragma once

#include <cstddef>
#include <list>
#include <utility>

#include "cbf_kernel.hpp"
#include "filter_constants.hpp"
#include "kernel_request.hpp"
#include "pass_kernel.hpp"

namespace sss::math {

// What the cross-bilateral kernel is built from: cbf_kernel(cbf_profile(profile, request), taps,
// r_max_mm); `request` is read only for kKernelProfileId.
struct CbfKernelInputs {
  unsigned profile = 0;
  ProfileRequest request;
  int taps = 0;
  float r_max_mm = 0.0f;
};
bool same_cbf_kernel_inputs(const CbfKernelInputs& a, const CbfKernelInputs& b);

class RecentKernels {
 public:
  static constexpr std::size_t kCapacity = 4;  // of each kind

  // The separable mode's kernel built from inputs like `settings` (same_pass_kernel_inputs), which
  // becomes the most recent; nullptr when none is kept.
  const PassKernel* find(const FilterSettings& settings);
  // Keeps `kernel`, built from `settings`, when it was costly to build (dropping the least recent).
  void keep(const FilterSettings& settings, const PassKernel& kernel);
  const CbfKernel* find(const CbfKernelInputs& inputs);
  void keep(const CbfKernelInputs& inputs, const CbfKernel& kernel);

 private:
  std::list<std::pair<FilterSettings, PassKernel>> pass_;
  std::list<std::pair<CbfKernelInputs, CbfKernel>> cbf_;
};

}  // namespace sss::math
