// What the benchmark's in-place library methods share (in_place_method.cpp, profiles_method.cpp):
// a context of their own, a work copy of the scene's lit colour that the frame writes back into
// (refilled before each timed frame, copied out after it, both untimed), and the path that ran.
#pragma once

#include <string>

#include "method.hpp"
#include "sss/sss.h"

namespace sss_bench {

class LibraryFrameMethod : public Method {
 public:
  explicit LibraryFrameMethod(const GlLoader& loader);
  ~LibraryFrameMethod() override;

  void after_run(const GpuScene& scene, GLuint output) override { blit(work_, output, scene.width, scene.height); }
  // "compute", "masked" or "fragment": sss_stats.last_frame_path of the last frame.
  std::string path_ran() const override;

 protected:
  // The RGBA16F work texture at the scene's size; true when it was (re)allocated.
  bool ensure_work(const GpuScene& scene);
  // A float colour texture into another of the same size (GL_NEAREST: texel for texel).
  void blit(GLuint from, GLuint to, int width, int height);

  sss_context* ctx_ = nullptr;
  GLuint work_ = 0;

 private:
  GLuint framebuffers_[2] = {0, 0};
  int work_width_ = 0, work_height_ = 0;
};

}  // namespace sss_bench
