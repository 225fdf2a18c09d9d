#include "timing.hpp"

#include <algorithm>
#include <chrono>
#include <utility>

#include "host_gl.hpp"

using namespace host_gl;

namespace sss_bench {

Clock clock_for_renderer(const std::string& renderer) {
  const bool software = renderer.find("llvmpipe") != std::string::npos ||
                        renderer.find("softpipe") != std::string::npos ||
                        renderer.find("swrast") != std::string::npos;
  return software ? Clock::wall_with_finish : Clock::timer_query;
}

const char* clock_name(Clock clock) {
  return clock == Clock::wall_with_finish ? "wall clock around glFinish" : "GL_TIME_ELAPSED timer queries";
}

namespace {
std::function<void()> g_timer_preamble;
}

void set_timer_preamble(std::function<void()> preamble) { g_timer_preamble = std::move(preamble); }

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

Timing time_frames(Clock clock, int warmup, int repetitions, const std::function<bool()>& frame,
                   const std::function<void()>& before, const std::function<void()>& after) {
  Timing t;
  for (int i = 0; i < warmup; ++i) {
    if (before) before();
    if (!frame()) return t;
    if (after) after();
  }
  glFinish();
  std::vector<double> samples;
  GLuint query = 0;
  if (clock == Clock::timer_query) glGenQueries(1, &query);
  for (int i = 0; i < repetitions; ++i) {
    if (before) {
      before();
      glFinish();
    }
    if (clock == Clock::timer_query) {
      if (g_timer_preamble) g_timer_preamble();
      glBeginQuery(GL_TIME_ELAPSED, query);
      const bool ok = frame();
      glEndQuery(GL_TIME_ELAPSED);
      if (!ok) break;
      GLuint64 ns = 0;
      glGetQueryObjectui64v(query, GL_QUERY_RESULT, &ns);  // waits for the result
      samples.push_back(static_cast<double>(ns) * 1e-6);
    } else {
      const auto start = std::chrono::steady_clock::now();
      const bool ok = frame();
      glFinish();
      const auto end = std::chrono::steady_clock::now();
      if (!ok) break;
      samples.push_back(std::chrono::duration<double, std::milli>(end - start).count());
    }
    if (after) after();
  }
  if (query != 0) glDeleteQueries(1, &query);
  if (samples.empty()) return t;
  t.samples = static_cast<int>(samples.size());
  t.min_ms = *std::min_element(samples.begin(), samples.end());
  t.max_ms = *std::max_element(samples.begin(), samples.end());
  t.median_ms = median(samples);
  return t;
}

}  // namespace sss_bench
