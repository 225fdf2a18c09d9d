// SSS_PATH_AUTO: which way of running the passes a frame takes: the plain fragment passes, the
// masked ones (the same passes with every draw kept to the tiles holding translucent pixels, after
// two small draws that find them), the compute dispatches, or (with SSS_AUTO_HALF_RESOLUTION) the
// half-resolution passes. Where timer queries are trustworthy, the first frames of a configuration
// cycle through the paths that can run it, each timed with one GL_TIME_ELAPSED query around the
// whole frame and read back only once available (never stalling); when each has kTrials results
// the lowest median wins until the configuration changes. Without a trustworthy timer (Mesa's
// software rasterisers, where GL_TIME_ELAPSED covers one tile) it takes what the benchmark
// measured fastest there (docs/benchmarks-passes.md): the masked fragment path, or the plain one
// when the host gave its region (which already keeps the draws to the skin) or the mask cannot be
// used; never the half-resolution path there, which only a timer can show to be faster for the
// frames at hand (it costs more than the full-size passes where few pixels' kernels are wide).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "gl_functions.hpp"

namespace sss::gl {

class PathChooser {
 public:
  static constexpr int kTrials = 3;  // timed frames of each path before deciding
  // The candidates, as bits of choose()'s `available` and values of Choice::path.
  enum Path : int { fragment = 0, masked = 1, compute = 2, half = 3, kPaths = 4 };

  // trustworthy_timer: GL_TIME_ELAPSED measures whole passes here (not a software rasteriser, and
  // GL_QUERY_COUNTER_BITS > 0). Query objects are made on first use.
  void init(const Functions* gl, bool trustworthy_timer);
  void destroy();  // deletes the query objects (they must exist in the current context)
  void forget();   // drops the names (context lost)
  // Makes the query objects the trials will use now rather than during the first frames
  // (sss_prepare); nothing where nothing is timed.
  void prewarm();

  struct Choice {
    int path = fragment;
    bool trial = false;  // timed: call begin() before the frame's passes and end() after them
  };
  // The path for a frame of configuration `key` (size, settings, formats, frame flags) that can run
  // the paths whose bits are set in `available` (fragment always is). `region`: the host gave the
  // region of translucent pixels (it decides between the fragment paths where nothing is timed).
  Choice choose(std::uint64_t key, unsigned available, bool region);
  void begin(const Choice& choice);
  void end();
  // Set when a decision was made during the last choose() (for the log); "" otherwise.
  const char* decision() const { return decision_.data(); }

 private:
  struct Pending {
    GLuint query = 0;
    int path = fragment;
    bool waiting = false;
  };
  void collect();
  void reset(std::uint64_t key);

  const Functions* gl_ = nullptr;
  bool timer_ = false;
  std::uint64_t key_ = 0;
  bool has_key_ = false, decided_ = false;
  int chosen_ = fragment;
  int trials_started_ = 0;
  std::array<std::vector<double>, kPaths> samples_;  // milliseconds per path (capacity kept)
  std::array<Pending, kPaths * kTrials + 2> pending_{};
  int active_ = -1;  // index into pending_ of the query begun for this frame
  std::array<char, 256> decision_{};  // fixed storage: a steady frame allocates nothing
};

}  // namespace sss::gl
