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
  GLuint profile = 0;        // R8UI: profile | object << 4 per pixel (sss_frame.profile_texture), 0 the background;
                             // single-sample only (the library refuses a profile texture with MSAA colour)
  GLuint albedo = 0;         // RGBA16F: the linear albedo the diffuse light was multiplied by (1 on the background),
                             // sss_frame.albedo_texture for the texturing modes (albedo_ms with MSAA)
  GLuint output = 0;         // RGBA8: tone-mapped and sRGB-encoded, what is shown and saved
  GLuint lighting_framebuffer = 0;  // diffuse + specular + profile + albedo + depth_stencil
  GLuint output_framebuffer = 0;    // output
  // MSAA (samples > 0): the lighting pass renders into multisampled copies of diffuse, specular,
  // albedo and depth-stencil (the profile byte has none: the library refuses it with MSAA colour);
  // the library reads those, the albedo as the texturing modes' multisampled albedo; diffuse,
  // specular and albedo above get their box resolve (for the "before" view, the composite and the counts).
  int samples = 0;
  GLuint diffuse_ms = 0, specular_ms = 0, albedo_ms = 0, depth_stencil_ms = 0;
  GLuint lighting_framebuffer_ms = 0;
};

// The framebuffer the lighting pass draws into.
inline GLuint lighting_target(const FrameTargets &t) { return t.samples > 0 ? t.lighting_framebuffer_ms : t.lighting_framebuffer; }
// MSAA: resolves diffuse, specular and albedo (box filter), depth and stencil (one sample) into the
// single-sample targets. A no-op without MSAA.
void resolve_lighting(const FrameTargets &t);

// Returns false (after printing why) when a framebuffer is incomplete or GL fails.
bool create_frame_targets(FrameTargets *targets, GLsizei width, GLsizei height, int samples = 0);
void destroy_frame_targets(FrameTargets *targets);

}  // namespace demo
