// Frame timing as DESIGN.md §6 asks: on a software rasteriser (llvmpipe, softpipe) wall-clock
// around glFinish, because llvmpipe's GL_TIME_ELAPSED keeps only one tile's time; on a real GPU
// GL_TIME_ELAPSED timer queries. Medians after warm-up.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace sss_bench {

enum class Clock { wall_with_finish, timer_query };

// The clock to trust for this renderer (GL_RENDERER string).
Clock clock_for_renderer(const std::string& renderer);
const char* clock_name(Clock clock);

struct Timing {
  double median_ms = 0.0;
  double min_ms = 0.0;
  double max_ms = 0.0;
  int samples = 0;
};

// Runs `frame` `warmup` times untimed, then `repetitions` times timed. `frame` returns false to
// abort (the timing then has 0 samples). `before` and `after`, when given, run around every frame
// outside the timed span (the GPU finished before the clock starts): what a method needs that a
// host's frame would not pay for, such as refilling the colour an in-place filter overwrote.
Timing time_frames(Clock clock, int warmup, int repetitions, const std::function<bool()>& frame,
                   const std::function<void()>& before = {}, const std::function<void()>& after = {});

double median(std::vector<double> values);

// Run right before each timed frame on the timer-query clock (after the untimed `before` and its
// glFinish): the benchmark installs a GpuBusy spin there on GPUs (gpu_busy.hpp). Empty: none.
void set_timer_preamble(std::function<void()> preamble);

}  // namespace sss_bench
