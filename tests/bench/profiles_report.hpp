// The results document's section on several materials in one pass pair (issue 23): one profile
// against per-pixel profiles in the same run, per size, on the head shots and the mixed scene.
#pragma once

#include <ostream>
#include <vector>

#include "results.hpp"

namespace sss_bench {

// Writes nothing when the run has no "separable-profiles" row.
void write_profiles_section(std::ostream& out, const std::vector<ResultRow>& rows);

}  // namespace sss_bench
