// GPU measurements of the passes for sss_get_stats (opt-in: SSS_CREATE_STATS): per frame, one
// GL_TIME_ELAPSED query around each pass where timer queries are trustworthy, and one
// GL_SAMPLES_PASSED query around the vertical blur draw (desktop GL; ES has no sample counts).
// Results are read back without stalling: the queries of a frame go into one slot of a small ring,
// and a slot is read (and freed) only once the GL says its results are available. When every slot
// is still in flight the frame is not measured. A query target the host has a query active on is
// left alone (GL allows one active query per target): that measurement is skipped for the frame.
#pragma once

#include <array>
#include <cstdint>

#include "gl_functions.hpp"

namespace sss::gl {

struct PassMeasurement {
  std::uint64_t frame = 0;     // 1-based frame number the numbers come from; 0: none yet
  bool has_pixels = false, has_time = false;
  std::uint64_t pixels = 0;
  std::array<double, 2> milliseconds{};  // horizontal, vertical
};

class PassQueries {
 public:
  enum Pass : int { horizontal = 0, vertical = 1 };

  // Decides what can be measured here (timer bits, ES extension, renderer) and makes the query
  // objects. software_renderer: Mesa's llvmpipe/softpipe, whose GL_TIME_ELAPSED covers a single
  // tile of a pass (DESIGN.md §6), so its times are not reported.
  void init(const Functions* gl, bool es_timer_extension, bool software_renderer);
  void destroy();  // deletes the objects (they must exist in the current context)
  void forget();   // drops the names (context lost)
  bool timing_supported() const { return timing_; }
  bool pixels_supported() const { return pixels_; }

  // Reads the slots whose results are ready (into latest()), then picks a free slot for `frame`;
  // false when none is free (nothing is measured this frame).
  bool begin_frame(std::uint64_t frame);
  void begin_pass(Pass pass);
  void end_pass(Pass pass);
  void begin_pixels();
  void end_pixels();
  void end_frame();
  const PassMeasurement& latest() const { return latest_; }

 private:
  static constexpr int kSlots = 3;
  struct Slot {
    std::array<GLuint, 2> time{};
    GLuint samples = 0;
    bool pending = false, timed = false, counted = false;
    std::uint64_t frame = 0;
  };
  void collect();
  bool target_free(GLenum target) const;

  const Functions* gl_ = nullptr;
  bool timing_ = false, pixels_ = false;
  std::array<Slot, kSlots> slots_{};
  int current_ = -1;           // slot of the frame being recorded
  bool timing_now_ = false, pixels_now_ = false;
  PassMeasurement latest_;
};

}  // namespace sss::gl
