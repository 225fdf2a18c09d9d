#include "pass_queries.hpp"

namespace sss::gl {

void PassQueries::init(const Functions* gl, bool es_timer_extension, bool software_renderer) {
  gl_ = gl;
  const Functions& f = *gl_;
  // Timer queries are trusted only where the GL counts time with some bits (a counter of 0 bits is
  // the spec's way to say "no timer"); on ES only through EXT_disjoint_timer_query.
  const bool timer_api = (f.api.es ? es_timer_extension && f.GetQueryObjectui64vEXT != nullptr : true) &&
                         !software_renderer;
  GLint bits = 0;
  if (timer_api) f.GetQueryiv(TIME_ELAPSED, QUERY_COUNTER_BITS, &bits);
  for (int i = 0; i < 8 && f.GetError() != NO_ERROR; ++i) {  // a driver that rejects the target
  }
  timing_ = timer_api && bits > 0 && !software_renderer;
  pixels_ = !f.api.es;  // ES has only "any samples passed"
  for (Slot& s : slots_) {
    if (timing_) f.GenQueries(2, s.time.data());
    if (pixels_) f.GenQueries(1, &s.samples);
  }
}

void PassQueries::destroy() {
  if (gl_ == nullptr) return;
  for (Slot& s : slots_) {
    if (s.time[0] != 0) gl_->DeleteQueries(2, s.time.data());
    if (s.samples != 0) gl_->DeleteQueries(1, &s.samples);
  }
  forget();
}

void PassQueries::forget() {
  slots_ = {};
  current_ = -1;
  timing_now_ = pixels_now_ = false;
}

bool PassQueries::target_free(GLenum target) const {
  GLint active = 0;
  gl_->GetQueryiv(target, CURRENT_QUERY, &active);
  return active == 0;
}

void PassQueries::collect() {
  const Functions& f = *gl_;
  // A disjoint event (ES: the GPU clock jumped, e.g. a power state change) voids every time
  // measured since it was last asked; reading the flag clears it.
  GLint disjoint = 0;
  if (f.api.es && timing_) f.GetIntegerv(GPU_DISJOINT, &disjoint);
  for (Slot& s : slots_) {
    if (!s.pending) continue;
    GLuint last = s.counted ? s.samples : s.timed ? s.time[1] : 0;
    GLuint available = 1;
    if (last != 0) f.GetQueryObjectuiv(last, QUERY_RESULT_AVAILABLE, &available);
    if (!available) continue;  // later: reading now would stall
    s.pending = false;
    if (s.frame < latest_.frame) continue;  // an older frame than the one already reported
    PassMeasurement m;
    m.frame = s.frame;
    if (s.timed && disjoint == 0) {
      for (int p = 0; p < 2; ++p) {
        std::uint64_t ns = 0;
        if (f.api.es) {
          f.GetQueryObjectui64vEXT(s.time[static_cast<std::size_t>(p)], QUERY_RESULT, &ns);
        } else {
          f.GetQueryObjectui64v(s.time[static_cast<std::size_t>(p)], QUERY_RESULT, &ns);
        }
        m.milliseconds[static_cast<std::size_t>(p)] = static_cast<double>(ns) * 1e-6;
      }
      m.has_time = true;
    }
    if (s.counted) {
      GLuint samples = 0;
      f.GetQueryObjectuiv(s.samples, QUERY_RESULT, &samples);
      m.pixels = samples;
      m.has_pixels = true;
    }
    latest_ = m;
  }
}

bool PassQueries::begin_frame(std::uint64_t frame) {
  current_ = -1;
  if (gl_ == nullptr || (!timing_ && !pixels_)) return false;
  collect();
  for (int i = 0; i < kSlots; ++i) {
    if (!slots_[static_cast<std::size_t>(i)].pending) {
      current_ = i;
      break;
    }
  }
  if (current_ < 0) return false;
  Slot& s = slots_[static_cast<std::size_t>(current_)];
  s.frame = frame;
  s.timed = s.counted = false;
  timing_now_ = timing_ && target_free(TIME_ELAPSED);
  pixels_now_ = pixels_ && target_free(SAMPLES_PASSED);
  return true;
}

void PassQueries::begin_pass(Pass pass) {
  if (current_ < 0 || !timing_now_) return;
  gl_->BeginQuery(TIME_ELAPSED, slots_[static_cast<std::size_t>(current_)].time[static_cast<std::size_t>(pass)]);
}

void PassQueries::end_pass(Pass pass) {
  if (current_ < 0 || !timing_now_) return;
  gl_->EndQuery(TIME_ELAPSED);
  if (pass == vertical) slots_[static_cast<std::size_t>(current_)].timed = true;
}

void PassQueries::begin_pixels() {
  if (current_ < 0 || !pixels_now_) return;
  gl_->BeginQuery(SAMPLES_PASSED, slots_[static_cast<std::size_t>(current_)].samples);
}

void PassQueries::end_pixels() {
  if (current_ < 0 || !pixels_now_) return;
  gl_->EndQuery(SAMPLES_PASSED);
  slots_[static_cast<std::size_t>(current_)].counted = true;
}

void PassQueries::end_frame() {
  if (current_ < 0) return;
  Slot& s = slots_[static_cast<std::size_t>(current_)];
  s.pending = s.timed || s.counted;
  current_ = -1;
}

}  // namespace sss::gl
