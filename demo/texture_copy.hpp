// Copies one colour texture into another of the same size (glBlitFramebuffer, GL 3.3).
#pragma once

#include "gl_functions.hpp"

namespace demo {

// Returns false (after printing why) when a framebuffer could not be built on the textures.
bool copy_color_texture(GLuint source, GLuint destination, GLsizei width, GLsizei height);

}  // namespace demo
