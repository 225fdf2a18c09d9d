// How many pixels the library was asked to filter and how many it changed, counted on the GPU with
// occlusion queries (GL_SAMPLES_PASSED) over full-screen draws that write no colour:
//   marked   stencil == 1 in the lighting pass's depth-stencil (what sss_stencil selects)
//   touched  after != before, bit for bit (the library leaves every other pixel exactly as it was)
#pragma once

#include "frame_targets.hpp"
#include "gl_functions.hpp"

#include <cstdint>

namespace demo {

struct PixelCounts {
  std::uint64_t marked = 0;
  std::uint64_t touched = 0;
  std::uint64_t total = 0;
};

struct PixelCountPass {
  GLuint marked_program = 0;
  GLuint touched_program = 0;
  GLuint vao = 0;
  GLuint query = 0;
};

bool create_pixel_count_pass(PixelCountPass *pass);
// `after` == `before` (SSS off) counts no touched pixel without drawing.
PixelCounts count_pixels(const PixelCountPass &pass, const FrameTargets &targets, GLuint before, GLuint after);
void destroy_pixel_count_pass(PixelCountPass *pass);

}  // namespace demo
