// The per-pixel profiles' kernel tables (sss_set_profiles) in a uniform buffer: one block per pass
// axis, each holding every profile's table for that pass (math/profile_set.hpp's layout), bound to
// binding point 0 for the pass that reads it. Rewritten only when the profiles change, never per
// frame; the per-frame numbers (pixels per millimetre) are plain uniforms (blur_pass.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "filter_run.hpp"
#include "gl_functions.hpp"

namespace sss::gl {

class ProfileTables {
 public:
  // Reads the limits once (GL_MAX_UNIFORM_BLOCK_SIZE, the offset alignment): how many profiles one
  // block holds (at most SSS_MAX_PROFILES; 7 at OpenGL ES 3.0's minimum of 16 KB).
  void init(const Functions* gl, bool labels);
  int capacity() const { return capacity_; }
  // The tables of run's profiles in the buffer (made on first use), unless revision
  // run.profiles_revision is already there (then no GL call).
  sss_result upload(const FilterRun& run, std::string* message);
  // Binding point 0 on the block of the pass along `axis` (0 horizontal, 1 vertical).
  void bind(int axis) const;
  // The buffer's storage (both passes' blocks), 0 before the first upload (sss_stats.gpu_memory_bytes).
  std::uint64_t memory_bytes() const {
    return buffer_ != 0 ? static_cast<std::uint64_t>(stride_ + block_bytes()) : 0;
  }
  void destroy();  // deletes the buffer (in the current context)
  void forget();   // drops the name (context lost)

 private:
  std::ptrdiff_t block_bytes() const;

  const Functions* gl_ = nullptr;
  bool labels_ = false;
  int capacity_ = 0;
  std::ptrdiff_t stride_ = 0;  // bytes from the horizontal block to the vertical one (aligned)
  GLuint buffer_ = 0;
  std::uint64_t revision_ = 0;  // of the profiles the buffer holds (0: none yet)
};

}  // namespace sss::gl
