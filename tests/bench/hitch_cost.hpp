// No hitch and no stall, measured (issue 22): the wall-clock time of the first sss_apply_frame
// after a settings change that needs new programs and targets, with and without sss_prepare called
// in between, and the GL queries a steady frame makes, counted through the tests' counting loader
// (tests/support/counting_loader.hpp). Not a pass/fail test: the numbers go to the results files.
#pragma once

#include "method.hpp"
#include "results.hpp"

namespace sss_bench {

struct HitchCost {
  int width = 0, height = 0, repeats = 0;
  // Medians over `repeats` fresh contexts, glFinish around each timed call.
  double first_frame_unprepared_ms = 0.0;  // the first frame after the change, no sss_prepare
  double prepare_ms = 0.0;                 // sss_prepare after the change
  double first_frame_prepared_ms = 0.0;    // the first frame after sss_prepare
  double steady_frame_ms = 0.0;            // a later frame of the same settings
  // GL queries (glGet*, glIs*, glGetError, glCheckFramebufferStatus) per steady described frame.
  double steady_queries_restore = 0.0, steady_queries_no_restore = 0.0;
  const char* change = "";  // what the settings change is
};

// On a width x height frame of a plane (RGBA16F colour, DEPTH_COMPONENT32F), in place.
HitchCost measure_hitch_cost(const GlLoader& loader, int width, int height);
// Measures it into `info` (the results files' run section) and prints it.
void record_hitch_cost(const GlLoader& loader, int width, int height, RunInfo* info);

}  // namespace sss_bench
