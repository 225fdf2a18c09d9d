// The texture units the module's programs read from. They are fixed per program (set once after
// linking, or by layout(binding) in GLSL 4.20: module/shaders/*), so a frame binds textures and
// never changes a sampler uniform. Units 0-6 are in the StateGuard's list (sss.h).
#pragma once

#include "gl_functions.hpp"

namespace sss::gl::unit {

// The blur passes (separable, compute and cross-bilateral) and the copy.
constexpr GLuint source = 0;       // the pass input: host colour, then the intermediate
constexpr GLuint depth = 1;        // the host's depth (or the MSAA path's resolved view distance)
constexpr GLuint original = 2;     // the host's colour, read by a pass writing a separate output
constexpr GLuint normals = 3;      // the cross-bilateral mode's host normals
constexpr GLuint accumulated = 3;  // the earlier terms' sum (separable kernels of several terms)
// The fragment blur passes' strength (pass_inputs.frag's R32UI target; the source unit holds its
// colour and distance texels).
constexpr GLuint pass_strength = 1;
// Per-pixel profiles: the host's profile and object indices (sss_frame.profile_texture), read by
// pass_inputs.frag (R8UI) or by the blur passes per tap (R16UI).
constexpr GLuint profile_ids = 4;
// The strength texture's combine (colour_copy.cpp): the host's colour on `source`, its strength here.
constexpr GLuint strength = 1;

// The masked path's tile culling (tile_culling.cpp): the tiles' marks, read by the span vertex
// stage of its inputs draw and blur passes (fullscreen.vert, SSS_TILE_SPANS) and by the columns'
// draw; the columns' marks, read by the inputs draw's vertex stage only (which reads no original).
constexpr GLuint tiles = 5;

// The texturing modes (albedo.glsl): the host's albedo, read by the colour copy and by the pass that
// writes the frame's target. In the StateGuard's list only for a frame that has one (GuardScope::albedo).
constexpr GLuint albedo = 6;
constexpr GLuint tile_columns = 2;

// The MSAA resolve, stencil mark and write-back (which never reads the host's samples).
// The half-resolution path's upsample (half_upsample.frag): source and pass_strength as above.
constexpr GLuint half_source = 2;  // half_inputs.frag's texels
constexpr GLuint half_result = 3;  // the half-size passes' result
constexpr GLuint half_tables = 4;  // every profile's two pass tables

constexpr GLuint msaa_color = 0;        // resolve: the host's samples
constexpr GLuint msaa_depth = 1;        // resolve: the host's depth samples
constexpr GLuint msaa_lowest = 0;       // write: the translucent samples' smallest values and mask
constexpr GLuint msaa_blurred = 1;      // write: the blurred image
constexpr GLuint msaa_resolved = 2;     // write: the resolved colour
constexpr GLuint msaa_translucent = 3;  // write: the translucent samples' mean and count

}  // namespace sss::gl::unit
