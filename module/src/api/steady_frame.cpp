#include "steady_frame.hpp"

#include "context.hpp"
#include "validation.hpp"

namespace sss::api {

namespace {

// Names and formats in the order of SteadyFrame: colour, depth, output, stencil, normals, strength,
// profile indices, albedo.
std::array<std::uint32_t, 8> names_of(const sss_frame& frame) {
  return {frame.color_texture, frame.depth_texture, frame.output_texture,
          frame.stencil != nullptr ? frame.stencil->depth_stencil_texture : 0u, frame.normal_texture,
          frame.strength_texture, frame.profile_texture, frame.albedo_texture};
}

std::array<std::uint32_t, 8> formats_of(const sss_frame& frame) {
  return {frame.color_format, frame.depth_format, frame.output_texture != 0 ? frame.output_format : 0u,
          frame.stencil != nullptr ? frame.stencil_format : 0u, frame.normal_texture != 0 ? frame.normal_format : 0u,
          frame.strength_texture != 0 ? frame.strength_format : 0u, frame.profile_texture != 0 ? frame.profile_format : 0u,
          frame.albedo_texture != 0 ? frame.albedo_format : 0u};
}

}  // namespace

std::array<std::uint8_t, SSS_MAX_PROFILES> texturing_of(const sss_context& ctx) {
  std::array<std::uint8_t, SSS_MAX_PROFILES> modes{};
  modes[0] = static_cast<std::uint8_t>(ctx.settings.texturing);
  for (std::size_t i = 0; i < ctx.extra_profiles.size(); ++i) {
    modes[i + 1] = static_cast<std::uint8_t>(ctx.extra_profiles[i].settings.texturing);
  }
  return modes;
}

bool is_steady(const sss_context& ctx, const sss_frame& frame) {
  const SteadyFrame& s = ctx.steady;
  if (!s.valid) return false;
  const std::array<std::uint32_t, 8> names = names_of(frame);
  const std::array<std::uint32_t, 8> formats = formats_of(frame);
  return frame_described(frame) && names == s.names && formats == s.formats &&
         frame.texture_width == s.width && frame.texture_height == s.height && frame.flags == s.frame_flags &&
         frame.msaa_depth_resolve == s.msaa_depth_resolve && frame.debug_view == s.debug_view &&
         ctx.kernel_revision == s.kernel_revision &&
         ctx.profiles_revision == s.profiles_revision &&
         ctx.cbf_kernel_revision == s.cbf_kernel_revision && ctx.settings.path == s.path &&
         ctx.settings.cross_bilateral == s.cross_bilateral && ctx.settings.follow_surface == s.follow_surface &&
         texturing_of(ctx) == s.texturing;
}

void steady_textures(const sss_context& ctx, const sss_frame& frame, gl::FilterRun* run, gl::StencilInput* stencil) {
  const SteadyFrame& s = ctx.steady;
  run->color = s.color;
  run->depth = s.depth;
  run->output = s.output;
  run->normals = s.normals;
  run->strength = s.strength;
  run->profile_ids = s.profile_ids;
  run->albedo = s.albedo;
  if (frame.stencil != nullptr) {
    stencil->texture = s.stencil;
    stencil->ref = frame.stencil->ref;
    stencil->mask = frame.stencil->mask;
    run->stencil = stencil;
  }
}

void remember_steady(sss_context* ctx, const sss_frame& frame, const gl::FilterRun& run) {
  SteadyFrame& s = ctx->steady;
  const std::array<std::uint32_t, 8> names = names_of(frame);
  const std::array<std::uint32_t, 8> formats = formats_of(frame);
  s.valid = frame_described(frame);  // an undescribed frame is asked again every time
  s.names = names;
  s.formats = formats;
  s.width = frame.texture_width;
  s.height = frame.texture_height;
  s.frame_flags = frame.flags;
  s.msaa_depth_resolve = frame.msaa_depth_resolve;
  s.debug_view = frame.debug_view;
  s.kernel_revision = ctx->kernel_revision;
  s.profiles_revision = ctx->profiles_revision;
  s.cbf_kernel_revision = ctx->cbf_kernel_revision;
  s.path = ctx->settings.path;
  s.cross_bilateral = ctx->settings.cross_bilateral;
  s.follow_surface = ctx->settings.follow_surface;
  s.texturing = texturing_of(*ctx);
  s.identity = run.identity;
  s.color = run.color;
  s.depth = run.depth;
  s.output = run.output;
  s.normals = run.normals;
  s.strength = run.strength;
  s.profile_ids = run.profile_ids;
  s.albedo = run.albedo;
  s.stencil = run.stencil != nullptr ? run.stencil->texture : gl::TextureInfo{};
}

gl::StateGuard::Scope guard_scope(const sss_context& ctx, const sss_frame& frame, bool steady) {
  const unsigned path = ctx.settings.path;
  const bool msaa = !steady || ctx.steady.color.multisampled();
  gl::StateGuard::Scope scope;
  // Image unit 0: the compute path's target, and on GL 4.3+ the fragment passes' taps
  // (BlurVariant::image_taps), which every separable frame may run (the compute path falls back to
  // them). The guard keeps it only where the context has image units.
  scope.image_unit = !ctx.settings.cross_bilateral;
  scope.multisample = msaa;
  scope.stencil = frame.stencil != nullptr || msaa;
  // The half-resolution path: the culling depth (with a host stencil too) and units 3 and 4.
  const bool half = path == SSS_PATH_HALF_RESOLUTION || (path == SSS_PATH_AUTO && ctx.settings.auto_half_resolution);
  // The fragment passes without a stencil cull by the module's depth (any separable frame may run
  // them: the compute path falls back to them).
  scope.depth = !ctx.settings.cross_bilateral && (frame.stencil == nullptr || half);
  // Unit 3: also the MSAA write-back's fourth input (a multisampled colour written back).
  scope.unit3 = ctx.settings.cross_bilateral || ctx.kernel.terms.size() > 1 || (msaa && frame.output_texture == 0) ||
                half;
  scope.profiles = frame.profile_texture != 0 || half;
  // The tile marks of the masked path (the path AUTO takes untimed, and may time), of the
  // half-resolution path and of the tiles debug view (whatever the path).
  scope.tiles = path == SSS_PATH_FRAGMENT_MASKED || path == SSS_PATH_AUTO || half ||
                frame.debug_view == SSS_DEBUG_VIEW_TILES;
  scope.albedo = frame.albedo_texture != 0;
  scope.pack = frame.profile_texture != 0 && (ctx.create_flags & SSS_CREATE_DEBUG_CHECKS) != 0;
  return scope;
}

}  // namespace sss::api

extern "C" {

SSS_API sss_result sss_gl_context_changed(sss_context* ctx) {
  if (ctx == nullptr) return sss::api::fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "ctx is NULL");
  ctx->steady.valid = false;  // the next frame checks the context, and its objects in it
  return SSS_OK;
}

}  // extern "C"
