// SSS_PATH_AUTO: which of the fragment and compute paths runs a frame. Where timer queries are
// trustworthy, the first frames of a configuration alternate the two paths, each timed with one
// GL_TIME_ELAPSED query around the whole pair of passes and read back only once available (never
// stalling); when both have kTrials results the lower median wins until the configuration changes.
// Without a trustworthy timer (Mesa's software rasterisers, where GL_TIME_ELAPSED covers one tile)
// it keeps the fragment path, the faster one there by the benchmark (docs/benchmarks.md).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "gl_functions.hpp"

namespace sss::gl {

class PathChooser {
 public:
  static constexpr int kTrials = 3;  // timed frames of each path before deciding

  // trustworthy_timer: GL_TIME_ELAPSED measures whole passes here (not a software rasteriser, and
  // GL_QUERY_COUNTER_BITS > 0). Query objects are made on first use.
  void init(const Functions* gl, bool trustworthy_timer);
  void destroy();  // deletes the query objects (they must exist in the current context)
  void forget();   // drops the names (context lost)

  // Whether the frame of configuration `key` (size, settings, frame flags) runs the compute path.
  // A trial frame is timed: call begin() before its passes and end() after them.
  struct Choice {
    bool compute = false;
    bool trial = false;
  };
  Choice choose(std::uint64_t key);
  void begin(const Choice& choice);
  void end();
  // Set when a decision was made during the last choose() (for the log): "compute path: 0.41 ms
  // against 0.62 ms for the fragment path" and the like; "" otherwise.
  const char* decision() const { return decision_.data(); }

 private:
  struct Pending {
    GLuint query = 0;
    bool compute = false;
    bool waiting = false;
  };
  void collect();
  void reset(std::uint64_t key);

  const Functions* gl_ = nullptr;
  bool timer_ = false;
  std::uint64_t key_ = 0;
  bool has_key_ = false, decided_ = false, compute_ = false;
  int trials_started_ = 0;
  std::array<std::vector<double>, 2> samples_;  // [0] fragment, [1] compute, milliseconds (capacity kept)
  std::array<Pending, 2 * kTrials + 2> pending_{};
  int active_ = -1;  // index into pending_ of the query begun for this frame
  std::array<char, 192> decision_{};  // fixed storage: a steady frame allocates nothing
};

}  // namespace sss::gl
