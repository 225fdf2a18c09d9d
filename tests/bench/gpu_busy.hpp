// GPU time without the CPU's gaps. Timing one frame with GL_TIME_ELAPSED after glFinish starts an
// idle GPU on each command as the CPU issues it, so the query spans the CPU's issue time too (the
// library's state save, uniforms and bindings: tens of microseconds, the whole of a 0.1 ms frame
// on a fast GPU). In a host's frame the GPU runs behind the CPU and sees the commands queued. This
// keeps the GPU busy for a while (one small compute dispatch spinning, flushed) right before the
// timed frame, so that its commands are all queued when the GPU reaches the query.
#pragma once

#include <memory>

#include "host_gl.hpp"

namespace sss_bench {

class GpuBusy {
 public:
  // nullptr below OpenGL 4.3 (no compute shaders). The spin is calibrated to about `busy_ms`.
  static std::unique_ptr<GpuBusy> create(double busy_ms);
  ~GpuBusy();
  GpuBusy(const GpuBusy&) = delete;
  GpuBusy& operator=(const GpuBusy&) = delete;

  void run();  // queues the spin and flushes; leaves no binding behind
  double calibrated_ms() const { return calibrated_ms_; }

 private:
  GpuBusy(GLuint program, GLuint sink);
  double time_once();

  GLuint program_, sink_;
  GLint iterations_location_;
  int iterations_ = 4096;
  double calibrated_ms_ = 0.0;
};

}  // namespace sss_bench
