#include "kernel_family.hpp"

#include <sss/sss_tools.h>

#include <iterator>

namespace demo {

namespace {

// In sss_kernel_family's order.
constexpr KernelFamilyInfo kFamilies[] = {
    {"separable", "eq. (1) separable (strength, falloff)", "eq. (1)", false, false},
    {"sum-of-gaussians", "sum of Gaussians", "sum of Gaussians", true, true},
    {"svd", "SVD rank N", "SVD", true, true},
    {"preintegrated", "pre-integrated (exact for E1(x) + E2(y))", "pre-integrated", true, true},
    {"guided", "guided rank-1 fit (k = 1.55)", "guided rank-1", true, false},
    {"artist", "artist two-Gaussian, exact depth", "artist two-Gaussian", false, false},
};
static_assert(std::size(kFamilies) == SSS_KERNEL_FAMILY_COUNT, "a row for every sss_kernel_family");

}  // namespace

const KernelFamilyInfo *kernel_family_info(int family) {
  if (family < 0 || family >= SSS_KERNEL_FAMILY_COUNT) return nullptr;
  return &kFamilies[family];
}

}  // namespace demo
