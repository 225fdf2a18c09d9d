// The kernel families as the demo shows them (sss_tools.h sss_kernel_family): the name --kernel
// takes, the panel's and the report's labels, whether a family blurs with the chosen material's
// profile and whether it takes a term count. The demo's one list of families: a new family is a row
// of kernel_family.cpp.
#pragma once

namespace demo {

struct KernelFamilyInfo {
  const char *option;  // --kernel NAME[:N]
  const char *label;   // the panel's list
  const char *report;  // the report's kernel line
  bool from_profile;   // built from the chosen material's profile (else from its own parameters)
  bool ranked;         // takes a term count (sss_kernel_desc.rank, the panel's "terms")
};

// The row of `family`, a sss_kernel_family; nullptr outside [0, SSS_KERNEL_FAMILY_COUNT).
const KernelFamilyInfo *kernel_family_info(int family);

}  // namespace demo
