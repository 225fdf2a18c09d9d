// A steady frame: one whose textures the frame describes (every format and the size given:
// frame_described, validation.hpp, the definition the host texture parameters use too) and
// whose textures, description and settings are those of the last frame that succeeded. Such a
// frame trusts what that frame asked the GL and checked: the textures' targets, formats, sizes and
// sample counts, that a GL context is current and holds the module's objects, that the host left
// no error pending, that the framebuffers are complete. So it makes no GL query at all (each one
// is a round trip that stalls a threaded driver: Mesa's glthread, NVIDIA's threaded optimisation),
// only the state guard's, which has to read the host's state to put it back (none with
// SSS_CREATE_NO_STATE_RESTORE).
//
// What that trust rests on (sss.h, sss_frame and SSS_CREATE_DEBUG_CHECKS): the description is the
// host's word for what it allocated (a texture re-created under the same name with the same
// description is the same to the GL for everything the module does, unless its target or sample
// count changed, which the description does not say); the GL context is the one of the last frame
// (sss_gl_context_changed says otherwise); the host's errors are its own. A frame that is not
// steady (the first, one after a failure, a change of texture, format, size or settings,
// an undescribed texture) checks everything, as does every frame with SSS_CREATE_DEBUG_CHECKS.
#pragma once

#include <array>
#include <cstdint>

#include "../gl/filter_run.hpp"
#include "../gl/state_guard.hpp"
#include "sss/sss.h"

struct sss_context;

namespace sss::api {

struct SteadyFrame {
  bool valid = false;  // cleared by a failure, a lost context, sss_gl_context_changed
  // The last successful frame as it was given: the names and formats of colour, depth, output,
  // stencil, normals, strength, profile indices and albedo (0: none), the size, the flags that pick
  // program variants.
  std::array<std::uint32_t, 8> names{}, formats{};
  std::int32_t width = 0, height = 0;
  std::uint32_t frame_flags = 0, msaa_depth_resolve = 0, debug_view = 0;
  // The settings that pick programs and targets.
  std::uint64_t kernel_revision = 0, cbf_kernel_revision = 0, profiles_revision = 0;
  unsigned path = 0;
  bool cross_bilateral = false, follow_surface = false;
  std::array<std::uint8_t, SSS_MAX_PROFILES> texturing{};  // each profile's (texturing_of)
  bool identity = false;  // nothing was drawn (width, scale or strength 0, or an empty region)
  // The textures as that frame found them (asked of the GL where it can be, else as described).
  gl::TextureInfo color, depth, output, normals, stencil, strength, profile_ids, albedo;
};

// Each profile's texturing mode ([0] the settings'; sss.h sss_texturing), which picks programs.
std::array<std::uint8_t, SSS_MAX_PROFILES> texturing_of(const sss_context& ctx);
// Whether `frame` is steady (see above), by its fields and the context's settings alone.
bool is_steady(const sss_context& ctx, const sss_frame& frame);
// The textures of a steady frame, as the last successful frame found them.
void steady_textures(const sss_context& ctx, const sss_frame& frame, gl::FilterRun* run, gl::StencilInput* stencil);
// After a successful frame: what the next one compares with.
void remember_steady(sss_context* ctx, const sss_frame& frame, const gl::FilterRun& run);
// What of the state list a frame may change (the rest the guard leaves alone, unread). A frame that
// is not steady may probe a texture's target (GL_TEXTURE_2D_MULTISAMPLE on unit 0) and take the
// MSAA path; a steady one knows its textures.
gl::StateGuard::Scope guard_scope(const sss_context& ctx, const sss_frame& frame, bool steady);

}  // namespace sss::api
