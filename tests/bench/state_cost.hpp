// What SSS_CREATE_NO_STATE_RESTORE saves: the CPU-side cost of one sss_apply_frame with and without
// the module's GL state save and restore, on a call that draws nothing (width 0, in place), so the
// difference is the save and restore alone.
#pragma once

#include "method.hpp"

namespace sss_bench {

struct StateCost {
  double with_restore_us = 0.0;     // per call, median over batches
  double without_restore_us = 0.0;  // the same with SSS_CREATE_NO_STATE_RESTORE
  int calls_per_batch = 0, batches = 0;
};

// Times batches of in-place sss_apply_frame calls with width 0 on a 16x16 frame (glFinish after each
// batch) for a context that restores state and one that does not.
StateCost measure_state_cost(const GlLoader& loader);

// What a context created with SSS_CREATE_NO_STATE_RESTORE leaves behind, as that flag promises, put
// back to the defaults the rest of the benchmark's own passes rely on (and `viewport`).
void reset_pass_state(const int viewport[4]);

}  // namespace sss_bench
