// Pass 4: diffuse + specular, exposure, ACES filmic fit, sRGB encode into an RGBA8 target, read back.
#pragma once

#include "gl_functions.hpp"

#include <cstdint>
#include <vector>

namespace demo {

struct CompositePass {
  GLuint program = 0;
  GLuint framebuffer = 0;
  GLuint output_texture = 0;  // RGBA8, already sRGB-encoded
  GLuint vao = 0;             // empty: the full-screen triangle comes from gl_VertexID
  GLsizei width = 0;
  GLsizei height = 0;
};

bool create_composite_pass(CompositePass *pass, GLsizei width, GLsizei height);

// Draws the composite of the two linear textures.
void run_composite_pass(const CompositePass &pass, GLuint diffuse, GLuint specular, float exposure);

// The output's pixels, RGBA8, rows bottom-up as GL stores them.
std::vector<std::uint8_t> read_composite(const CompositePass &pass);

void destroy_composite_pass(CompositePass *pass);

}  // namespace demo
