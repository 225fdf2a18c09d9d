// The render targets of one frame size. The lighting pass writes diffuse, specular and
// depth-stencil; the library reads diffuse and depth-stencil and writes `after`; the composite
// writes `output`.
#pragma once

#include "gl_functions.hpp"

namespace demo {

struct FrameTargets {
  GLsizei width = 0;
  GLsizei height = 0;
  GLuint diffuse = 0;        // RGBA16F: linear lit diffuse (albedo x irradiance), alpha = SSS strength ("before")
  GLuint specular = 0;       // RGBA16F: linear specular radiance, kept out of the blur
  GLuint depth_stencil = 0;  // DEPTH24_STENCIL8: stencil 1 where a translucent material is the visible surface
  GLuint after = 0;          // RGBA16F: the library's output (sss_apply_frame's output_texture)
  GLuint output = 0;         // RGBA8: tone-mapped and sRGB-encoded, what is shown and saved
  GLuint lighting_framebuffer = 0;  // diffuse + specular + depth_stencil
  GLuint output_framebuffer = 0;    // output
};

// Returns false (after printing why) when a framebuffer is incomplete or GL fails.
bool create_frame_targets(FrameTargets *targets, GLsizei width, GLsizei height);
void destroy_frame_targets(FrameTargets *targets);

}  // namespace demo
