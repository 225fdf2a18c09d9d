// sss_apply and sss_apply_frame: validate everything (arguments first, then the textures as the GL
// describes them, or for a steady frame as the last successful frame found them: steady_frame.hpp)
// before the first draw, so that a failure leaves the host's textures untouched;
// the runners build and allocate everything before their first draw too. The one failure found
// after the draws began is a GL error they raised: its message says the target may be partly written.
#include <cstdio>

#include "../gl/debug_label.hpp"
#include "../gl/host_texture_state.hpp"
#include "../gl/state_guard.hpp"
#include "../gl/texture_query.hpp"
#include "context.hpp"
#include "gl_session.hpp"
#include "host_texture_params.hpp"
#include "profiles.hpp"
#include "validation.hpp"
#include "versioned_structs.hpp"

namespace {

using sss::api::fail;
namespace gl = sss::gl;

// The GL's view of one texture, or (OpenGL ES 3.0, which cannot be asked) the frame's description.
// `format_field` names the sss_frame field that describes it; `described` is its value (0: none).
sss_result query(sss_context* ctx, const sss_frame& frame, gl::GLuint name, const char* role, const char* format_field,
                 std::uint32_t described, gl::TextureInfo* info) {
  std::string message;
  const bool can_ask = ctx->gl.has_texture_query;
  const sss_result r = gl::query_texture(ctx->gl, name, role, can_ask, info, &message);
  if (r != SSS_OK) return fail(ctx, r, message);
  if (info->multisampled() && !ctx->gl.has_msaa_path()) {  // OpenGL ES 3.1+ (ES 3.0 has no such textures)
    return fail(ctx, SSS_ERROR_UNSUPPORTED,
                "%s = %u is GL_TEXTURE_2D_MULTISAMPLE: the MSAA path needs desktop OpenGL; on OpenGL ES resolve "
                "it to a GL_TEXTURE_2D first (colour by glBlitFramebuffer, depth as linear view distance)",
                role, name);
  }
  const bool has_size = frame.texture_width != 0;
  if (!can_ask) {
    if (described == 0 || !has_size) {
      return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                  "frame->%s = %u, texture_width = %d, texture_height = %d: OpenGL ES 3.0 cannot be asked for a "
                  "texture's format and size (no glGetTexLevelParameteriv), so the frame must give them for %s = %u",
                  format_field, described, frame.texture_width, frame.texture_height, role, name);
    }
    const int max_size = ctx->max_texture_size;
    if (frame.texture_width > max_size || frame.texture_height > max_size) {
      return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "frame->texture_width, texture_height = %dx%d: above GL_MAX_TEXTURE_SIZE = %d",
                  frame.texture_width, frame.texture_height, max_size);
    }
    info->internal_format = static_cast<gl::GLint>(described);
    info->width = frame.texture_width;
    info->height = frame.texture_height;
    return SSS_OK;
  }
  if (described != 0 && static_cast<gl::GLint>(described) != info->internal_format) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "frame->%s = %s but %s = %u has format %s", format_field,
                gl::format_name(static_cast<gl::GLint>(described)).c_str(), role, name,
                gl::format_name(info->internal_format).c_str());
  }
  if (has_size && (frame.texture_width != info->width || frame.texture_height != info->height)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "frame->texture_width, texture_height = %dx%d but %s = %u is %dx%d",
                frame.texture_width, frame.texture_height, role, name, info->width, info->height);
  }
  return SSS_OK;
}

// OpenGL ES: what the formats need beyond ES 3.0 (the intermediate's EXT_color_buffer_half_float
// or _float is checked at create). RGBA32F colour is read through the module's GL_LINEAR sampler
// (a texture that format cannot filter would be incomplete, even for texelFetch) and rendered to;
// RGBA32F output is rendered to; depth is only fetched, through a GL_NEAREST sampler.
sss_result check_es_format(sss_context* ctx, const char* role, const gl::TextureInfo& t, bool sampled_linear) {
  if (ctx->gl.api.es && gl::is_alpha_free_color_format(t.internal_format) && !ctx->es_float_render) {
    return fail(ctx, SSS_ERROR_UNSUPPORTED,
                "%s = %u is GL_R11F_G11F_B10F: rendering to it on OpenGL ES needs GL_EXT_color_buffer_float", role,
                t.name);
  }
  if (!ctx->gl.api.es || t.internal_format != static_cast<gl::GLint>(gl::RGBA32F)) return SSS_OK;
  if (!ctx->es_float_render) {
    return fail(ctx, SSS_ERROR_UNSUPPORTED, "%s = %u is GL_RGBA32F: rendering to it on OpenGL ES needs GL_EXT_color_buffer_float",
                role, t.name);
  }
  if (sampled_linear && !ctx->es_float_linear) {
    return fail(ctx, SSS_ERROR_UNSUPPORTED, "%s = %u is GL_RGBA32F: filtering it on OpenGL ES needs GL_OES_texture_float_linear",
                role, t.name);
  }
  return SSS_OK;
}

sss_result wrong_format(sss_context* ctx, const char* role, const gl::TextureInfo& t, const char* expected) {
  return fail(ctx, SSS_ERROR_INVALID_TEXTURE, "%s = %u has format %s: expected %s", role, t.name,
              gl::format_name(t.internal_format).c_str(), expected);
}

sss_result same_size(sss_context* ctx, const char* role, const gl::TextureInfo& t, const gl::TextureInfo& color) {
  if (t.width == color.width && t.height == color.height) return SSS_OK;
  return fail(ctx, SSS_ERROR_INVALID_TEXTURE, "%s = %u is %dx%d but the colour texture is %dx%d", role, t.name,
              t.width, t.height, color.width, color.height);
}

// Colour, depth and stencil must agree in target and sample count (an MSAA path needs every
// sample of every input; a mix has no meaning).
sss_result same_samples(sss_context* ctx, const char* role, const gl::TextureInfo& t, const gl::TextureInfo& color) {
  if (t.multisampled() == color.multisampled() && t.samples == color.samples) return SSS_OK;
  return fail(ctx, SSS_ERROR_INVALID_TEXTURE, "%s = %u is %s but color_texture = %u is %s: both must have the same "
              "target and sample count", role, t.name, gl::describe_target(t).c_str(), color.name,
              gl::describe_target(color).c_str());
}

// A multisampled texture's count against the module's limit (one 32-bit sample mask word) and the
// context's limits.
sss_result supported_samples(sss_context* ctx, const char* role, const gl::TextureInfo& t, int max_samples,
                             const char* limit_name) {
  if (!t.multisampled()) return SSS_OK;
  if (t.samples <= 32 && t.samples <= max_samples) return SSS_OK;
  return fail(ctx, SSS_ERROR_UNSUPPORTED, "%s = %u has %d samples: this context supports at most %d (%s), the "
              "module at most 32", role, t.name, t.samples, max_samples, limit_name);
}

// SSS_PATH_AUTO times the paths again when this changes: what decides their relative cost (the
// size, the kernel, follow-surface, where the result goes and in which format, the frame's flags).
std::uint64_t path_key(const sss_context& ctx, const gl::FilterRun& run, std::uint32_t frame_flags) {
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the fields
  const auto mix = [&h](std::uint64_t v) {
    for (int i = 0; i < 8; ++i) {
      h ^= (v >> (8 * i)) & 0xFFu;
      h *= 1099511628211ull;
    }
  };
  mix(static_cast<std::uint64_t>(run.color.width));
  mix(static_cast<std::uint64_t>(run.color.height));
  mix(ctx.kernel_revision);
  mix(run.has_profiles() ? ctx.profiles_revision : 0u);
  mix(ctx.settings.follow_surface ? 1u : 0u);
  mix(run.output.name != 0 ? static_cast<std::uint64_t>(run.output.internal_format) : 0u);
  mix(static_cast<std::uint64_t>(run.color.internal_format));
  mix(frame_flags);
  mix(run.albedo.name != 0 ? 1u + ctx.settings.texturing : 0u);  // the texturing mode adds the colour copy
  return h;
}

// The colour and depth textures, as the GL describes them, against the lists in sss.h.
sss_result query_color_and_depth(sss_context* ctx, const sss_frame& frame, gl::FilterRun* run) {
  sss_result r = query(ctx, frame, frame.color_texture, "color_texture", "color_format", frame.color_format, &run->color);
  if (r != SSS_OK) return r;
  if (gl::is_alpha_free_color_format(run->color.internal_format) && frame.strength_texture == 0) {
    return wrong_format(ctx, "color_texture", run->color,
                        "GL_RGBA16F or GL_RGBA32F: GL_R11F_G11F_B10F has no alpha for the strength, so it needs a "
                        "strength_texture (GL_R8, GL_R16F or GL_R32F; see sss_frame)");
  }
  if (!gl::is_color_format(run->color.internal_format) && !gl::is_alpha_free_color_format(run->color.internal_format)) {
    return wrong_format(ctx, "color_texture", run->color, "GL_RGBA16F or GL_RGBA32F (GL_R11F_G11F_B10F with a strength_texture)");
  }
  r = check_es_format(ctx, "color_texture", run->color, true);
  if (r != SSS_OK) return r;
  r = supported_samples(ctx, "color_texture", run->color, ctx->max_color_texture_samples,
                        "GL_MAX_COLOR_TEXTURE_SAMPLES");
  if (r != SSS_OK) return r;
  r = query(ctx, frame, frame.depth_texture, "depth_texture", "depth_format", frame.depth_format, &run->depth);
  if (r != SSS_OK) return r;
  if (!gl::is_hardware_depth_format(run->depth.internal_format) && !gl::is_linear_depth_format(run->depth.internal_format)) {
    return wrong_format(ctx, "depth_texture", run->depth, "a GL_DEPTH_COMPONENT* or GL_DEPTH*_STENCIL8 format, or GL_R16F/GL_R32F");
  }
  r = same_size(ctx, "depth_texture", run->depth, run->color);
  if (r == SSS_OK) r = same_samples(ctx, "depth_texture", run->depth, run->color);
  if (r != SSS_OK) return r;
  // Linear depth (R16F/R32F) is a colour format to the GL.
  const bool linear = gl::is_linear_depth_format(run->depth.internal_format);
  return supported_samples(ctx, "depth_texture", run->depth,
                           linear ? ctx->max_color_texture_samples : ctx->max_depth_texture_samples,
                           linear ? "GL_MAX_COLOR_TEXTURE_SAMPLES" : "GL_MAX_DEPTH_TEXTURE_SAMPLES");
}

// sss_frame.strength_texture: single-sample R8, R16F or R32F of the colour's size, with a colour
// the passes can take it with (gl/colour_copy.cpp).
sss_result query_strength(sss_context* ctx, const sss_frame& frame, gl::FilterRun* run) {
  sss_result r = query(ctx, frame, frame.strength_texture, "strength_texture", "strength_format",
                       frame.strength_format, &run->strength);
  if (r != SSS_OK) return r;
  if (!gl::is_strength_format(run->strength.internal_format)) {
    return wrong_format(ctx, "strength_texture", run->strength, "GL_R8, GL_R16F or GL_R32F");
  }
  if (run->strength.multisampled()) {
    return fail(ctx, SSS_ERROR_INVALID_TEXTURE, "strength_texture = %u is %s: it must be a single-sample GL_TEXTURE_2D",
                run->strength.name, gl::describe_target(run->strength).c_str());
  }
  r = same_size(ctx, "strength_texture", run->strength, run->color);
  if (r != SSS_OK) return r;
  if (run->color.multisampled()) {
    return fail(ctx, SSS_ERROR_UNSUPPORTED,
                "strength_texture = %u with color_texture = %u %s: the MSAA path reads the strength from the colour's "
                "samples' alpha; resolve the colour first, or put the strength in its alpha",
                run->strength.name, run->color.name, gl::describe_target(run->color).c_str());
  }
  if (frame.output_texture == 0 && gl::is_color_format(run->color.internal_format)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                "strength_texture = %u with color_texture = %u (%s) written back: the colour's alpha would be "
                "overwritten with the strength; give an output_texture, or put the strength in the colour's alpha",
                run->strength.name, run->color.name, gl::format_name(run->color.internal_format).c_str());
  }
  return SSS_OK;
}

// Whether a texturing mode of a profile the frame can use reads the albedo (sss.h sss_texturing);
// the first such profile's index in *which (-1: the settings, without per-pixel profiles).
bool needs_albedo(const sss_context& ctx, const sss_frame& frame, int* which, unsigned* mode) {
  *which = -1;
  *mode = ctx.settings.texturing;
  if (*mode != SSS_TEXTURING_PRE_SCATTER) return true;
  if (frame.profile_texture == 0) return false;
  for (std::size_t i = 0; i < ctx.extra_profiles.size(); ++i) {
    *mode = ctx.extra_profiles[i].settings.texturing;
    if (*mode != SSS_TEXTURING_PRE_SCATTER) {
      *which = static_cast<int>(i + 1);
      return true;
    }
  }
  return false;
}

// A texturing mode other than pre-scatter needs the albedo, and one of the colour's size, target and
// sample count (a multisampled colour: an albedo multisampled alike, whose samples the resolve
// divides one by one; a single-sample albedo has no value per sample, so it is refused rather than
// guessed at: docs/integration.md "Texturing modes").
sss_result query_albedo(sss_context* ctx, const sss_frame& frame, gl::FilterRun* run) {
  int which = -1;
  unsigned mode = 0;
  if (!needs_albedo(*ctx, frame, &which, &mode)) return SSS_OK;  // given or not, it is not read
  char field[48];
  if (which < 0) {
    std::snprintf(field, sizeof field, "settings->texturing");
  } else {
    std::snprintf(field, sizeof field, "profiles[%d].texturing", which);
  }
  if (frame.albedo_texture == 0) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                "%s = %u (%s) with frame->albedo_texture = 0: the mode divides the colour by the albedo; give the "
                "albedo texture, or SSS_TEXTURING_PRE_SCATTER", field, mode,
                mode == SSS_TEXTURING_POST_SCATTER ? "SSS_TEXTURING_POST_SCATTER" : "SSS_TEXTURING_PRE_AND_POST_SCATTER");
  }
  sss_result r = query(ctx, frame, frame.albedo_texture, "albedo_texture", "albedo_format", frame.albedo_format,
                       &run->albedo);
  if (r != SSS_OK) return r;
  if (!gl::is_albedo_format(run->albedo.internal_format)) {
    return wrong_format(ctx, "albedo_texture", run->albedo, "GL_SRGB8_ALPHA8, GL_RGBA8 or GL_RGBA16F");
  }
  r = same_samples(ctx, "albedo_texture", run->albedo, run->color);
  if (r == SSS_OK) r = same_size(ctx, "albedo_texture", run->albedo, run->color);
  return r;
}

// The optional textures: a separate output, the host's stencil, the normals, the strength, the albedo.
sss_result query_optional_textures(sss_context* ctx, const sss_frame& frame, gl::FilterRun* run,
                                   gl::StencilInput* stencil) {
  sss_result r = SSS_OK;
  if (frame.output_texture != 0) {
    r = query(ctx, frame, frame.output_texture, "output_texture", "output_format", frame.output_format, &run->output);
    if (r != SSS_OK) return r;
    if (!gl::is_color_format(run->output.internal_format)) {
      return wrong_format(ctx, "output_texture", run->output, "GL_RGBA16F or GL_RGBA32F");
    }
    if (run->output.multisampled()) {
      return fail(ctx, SSS_ERROR_INVALID_TEXTURE,
                  "output_texture = %u is %s: the output is single-sample (pass 0 to write back into the "
                  "multisampled colour)", run->output.name, gl::describe_target(run->output).c_str());
    }
    r = check_es_format(ctx, "output_texture", run->output, false);
    if (r == SSS_OK) r = same_size(ctx, "output_texture", run->output, run->color);
    if (r != SSS_OK) return r;
  }
  if (frame.stencil != nullptr) {
    r = query(ctx, frame, frame.stencil->depth_stencil_texture, "stencil->depth_stencil_texture", "stencil_format",
              frame.stencil_format, &stencil->texture);
    if (r != SSS_OK) return r;
    if (!gl::is_depth_stencil_format(stencil->texture.internal_format)) {
      return wrong_format(ctx, "stencil->depth_stencil_texture", stencil->texture,
                          "GL_DEPTH24_STENCIL8 or GL_DEPTH32F_STENCIL8");
    }
    r = same_size(ctx, "stencil->depth_stencil_texture", stencil->texture, run->color);
    if (r == SSS_OK) r = same_samples(ctx, "stencil->depth_stencil_texture", stencil->texture, run->color);
    if (r != SSS_OK) return r;
    stencil->ref = frame.stencil->ref;
    stencil->mask = frame.stencil->mask;
    run->stencil = stencil;
  }
  if (frame.strength_texture != 0) {
    r = query_strength(ctx, frame, run);
    if (r != SSS_OK) return r;
  }
  if (frame.profile_texture != 0) {
    r = query(ctx, frame, frame.profile_texture, "profile_texture", "profile_format", frame.profile_format,
              &run->profile_ids);
    if (r == SSS_OK) r = sss::api::check_profile_texture(ctx, *run);
    if (r != SSS_OK) return r;
  }
  r = query_albedo(ctx, frame, run);
  if (r != SSS_OK) return r;
  if (frame.normal_texture != 0) {
    r = query(ctx, frame, frame.normal_texture, "normal_texture", "normal_format", frame.normal_format, &run->normals);
    if (r != SSS_OK) return r;
    if (!gl::is_color_format(run->normals.internal_format)) {
      return wrong_format(ctx, "normal_texture", run->normals, "GL_RGBA16F or GL_RGBA32F");
    }
    r = check_es_format(ctx, "normal_texture", run->normals, false);
    if (r == SSS_OK) r = same_size(ctx, "normal_texture", run->normals, run->color);
  }
  return r;
}

// The textures, as the GL describes them, against the lists in sss.h (a steady frame takes them
// from the last frame instead: steady_frame.hpp), and the frame's rectangles.
sss_result describe_textures(sss_context* ctx, const sss_frame& frame, bool steady, gl::FilterRun* run,
                             gl::StencilInput* stencil) {
  sss_result r = SSS_OK;
  if (steady) {
    sss::api::steady_textures(*ctx, frame, run, stencil);
  } else {
    r = query_color_and_depth(ctx, frame, run);
    if (r == SSS_OK) r = query_optional_textures(ctx, frame, run, stencil);
  }
  return r == SSS_OK ? sss::api::frame_rectangles(ctx, frame, run) : r;
}

sss::math::DepthEncoding depth_encoding(const gl::TextureInfo& depth, std::uint32_t frame_flags) {
  if (gl::is_linear_depth_format(depth.internal_format)) return sss::math::DepthEncoding::linear_distance;
  return (frame_flags & SSS_FRAME_DEPTH_ZERO_TO_ONE) != 0 ? sss::math::DepthEncoding::hardware_zero_to_one
                                                          : sss::math::DepthEncoding::hardware_minus_one_to_one;
}

// Everything of the run but the textures and rectangles: the constants from the settings, the
// frame's camera (`projection`) and geometry; the kernel; the path; the noise index.
void fill_run(const sss_context& ctx, const sss_frame& frame, const sss::math::Matrix4& projection, gl::FilterRun* run) {
  sss::math::FrameGeometry geometry;
  geometry.texture_width = run->color.width;
  geometry.texture_height = run->color.height;
  geometry.viewport = run->viewport;
  geometry.depth = depth_encoding(run->depth, frame.flags);
  if (run->color.multisampled()) {
    // The resolve reads the host's encoding; the passes read the resolved linear distance.
    run->resolve_constants =
        sss::math::compute_pass_constants(ctx.settings, projection, geometry, ctx.kernel.reach_mm);
    geometry.depth = sss::math::DepthEncoding::linear_distance;
    run->depth_resolve = static_cast<gl::DepthResolve>(frame.msaa_depth_resolve);
  }
  run->constants = sss::math::compute_pass_constants(ctx.settings, projection, geometry, ctx.kernel.reach_mm);
  run->kernel = &ctx.kernel;
  run->kernel_revision = ctx.kernel_revision;
  run->follow_surface = ctx.settings.follow_surface;
  run->noise_index = frame.noise_index;
  run->debug_view = frame.debug_view;
  run->texturing[0] = static_cast<std::uint8_t>(ctx.settings.texturing);
  // Nothing drawn (unless an output needs the copy) where every profile the frame can use is the identity.
  run->identity = sss::api::is_identity_settings(ctx.settings) &&
                  (!run->has_profiles() || sss::api::extra_profiles_are_identity(ctx));
  run->frame = ctx.frames + 1;
  run->path = ctx.settings.path;
  run->auto_half_resolution = ctx.settings.auto_half_resolution;
  if (run->path == SSS_PATH_AUTO) run->path_key = path_key(ctx, *run, frame.flags);  // only AUTO reads it
  if (ctx.settings.cross_bilateral) {
    run->cross_bilateral = true;
    run->identity = ctx.settings.world_units_per_mm == 0.0f || ctx.settings.scale == 0.0f;  // strength does not apply here
    run->cbf_kernel = &ctx.cbf_kernel;
    run->cbf_kernel_revision = ctx.cbf_kernel_revision;
  }
  if (run->region) {
    // The host's promise: nothing translucent outside draw_rect. An empty one means nothing is;
    // otherwise the passes draw there alone and their taps stay inside it, like at the viewport's
    // edge (the projection is still the viewport's: only the clamp and the drawn rectangle change).
    if (run->draw_rect[2] == 0 || run->draw_rect[3] == 0) {
      run->identity = true;
    } else {
      sss::math::clamp_to_rect(&run->constants, run->draw_rect);
    }
  }
  // A view shows the passes as they run even where they change nothing (scale, strength or the
  // scene scale 0: a zero step, no taps).
  if (frame.debug_view != 0) run->identity = false;
  if (run->has_profiles()) sss::api::fill_profiles(ctx, projection, &geometry, run);
}

// The runner, with the depth texture sampled as depth (gl/host_texture_state.hpp: put back before
// the error check, on failure too), then the GL errors, except in a steady frame (steady_frame.hpp:
// reading the error flag is a round trip, and the frame it repeats found none). Every check,
// program build and allocation came before the first draw; an error the GL raised while drawing is
// found only now, when the target may hold part of the result, and the message says so.
sss_result run_passes(sss_context* ctx, const sss_frame& frame, bool steady, gl::FilterRun* run) {
  const gl::Functions& f = ctx->gl;
  gl::GLenum depth_mode = gl::DEPTH_COMPONENT;
  sss_result r = sss::api::host_texture_params(ctx, frame, run, &depth_mode);
  if (r != SSS_OK) return r;
  std::string message;
  {
    const gl::DepthSamplingOverride depth_sampling(f, run->depth, depth_mode);
    r = ctx->filter.run(*run, &message);
  }
  if (r != SSS_OK) {
    sss::api::drain_host_errors(nullptr, f);
    return fail(ctx, r, message);
  }
  if (steady) return SSS_OK;
  char passes[200];
  std::snprintf(passes, sizeof passes,
                "the separable passes (they had begun drawing: %s = %u may be partly written, its content is "
                "undefined until a frame succeeds; the GL state is restored)",
                run->writes_back() ? "color_texture" : "output_texture", run->target().name);
  return sss::api::check_gl_errors(ctx, f, passes);
}

}  // namespace

extern "C" {

SSS_API sss_result sss_apply(sss_context* ctx, uint32_t color_texture, uint32_t depth_texture,
                             const sss_stencil* stencil) {
  sss_frame frame = {};
  frame.struct_size = sizeof frame;
  frame.color_texture = color_texture;
  frame.depth_texture = depth_texture;
  frame.stencil = stencil;
  return sss_apply_frame(ctx, &frame);
}

SSS_API sss_result sss_apply_frame(sss_context* ctx, const sss_frame* given) {
  if (ctx == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "ctx is NULL");
  sss_frame current;  // an earlier release's frame read into today's layout (versioned_structs.cpp)
  sss_result r = sss::api::frame_from_caller(ctx, given, &current);
  if (r != SSS_OK) return r;
  const sss_frame* frame = &current;
  r = sss::api::check_frame(ctx, frame);
  if (r != SSS_OK) return r;
  // The frame's own camera, or the context's (sss_set_camera). A frame's is checked every time (a
  // few float comparisons): two views may take turns.
  sss::math::Matrix4 projection = ctx->projection;
  if (frame->projection != nullptr) {
    r = sss::api::take_projection(ctx, frame->projection, "frame->", &projection);
    if (r != SSS_OK) return r;
  } else if (!ctx->has_camera) {
    return fail(ctx, SSS_ERROR_INVALID_OPERATION,
                "frame->projection is NULL and no camera is set: give the frame a projection or call sss_set_camera");
  }
  const gl::Functions& f = ctx->gl;
  // A steady frame trusts the last successful one and asks the GL nothing (steady_frame.hpp);
  // every other frame checks the context, the host's errors and the textures first.
  bool steady = (ctx->create_flags & SSS_CREATE_DEBUG_CHECKS) == 0 && sss::api::is_steady(*ctx, *frame);
  ctx->steady.valid = false;  // until this frame succeeds
  if (!steady) {
    r = sss::api::require_current_context(ctx, f);
    if (r != SSS_OK) return r;
    sss::api::drain_host_errors(ctx, f);
  }
  gl::StateGuard guard(f, (ctx->create_flags & SSS_CREATE_NO_STATE_RESTORE) == 0,
                       sss::api::guard_scope(*ctx, *frame, steady));
  gl::DebugGroup group(f, (ctx->create_flags & SSS_CREATE_NO_DEBUG_LABELS) == 0, "sss_apply");
  if (!steady) {
    r = sss::api::require_module_objects(ctx);
    if (r != SSS_OK) return r;
  }

  gl::FilterRun run;
  gl::StencilInput stencil;
  r = describe_textures(ctx, *frame, steady, &run, &stencil);
  if (r != SSS_OK) {
    if (!steady) sss::api::drain_host_errors(nullptr, f);  // a failed query may have raised one
    return r;
  }
  fill_run(*ctx, *frame, projection, &run);
  if (frame->debug_view != 0 && (run.cross_bilateral || run.color.multisampled())) {
    if (!steady) sss::api::drain_host_errors(nullptr, f);
    return fail(ctx, SSS_ERROR_UNSUPPORTED, "frame->debug_view = %u: the views show the separable passes on "
                "single-sample textures (%s)", frame->debug_view,
                run.cross_bilateral ? "the settings are in the cross-bilateral mode" : "the colour is multisampled");
  }
  if (steady && run.identity != ctx->steady.identity) {
    // Drawing after drawing nothing may allocate the targets, whose check reads the error flag.
    steady = false;
    sss::api::drain_host_errors(ctx, f);
  }
  run.verify = !steady;
  if (run.has_profiles() && !run.identity && (ctx->create_flags & SSS_CREATE_DEBUG_CHECKS) != 0) {
    r = sss::api::check_profile_indices(ctx, run);
    if (r != SSS_OK) return r;
  }

  r = run_passes(ctx, *frame, steady, &run);
  if (r == SSS_OK) {
    ++ctx->frames;
    ctx->last_frame_passes = static_cast<std::uint32_t>(ctx->filter.last_draws());
    ctx->last_frame_path = ctx->filter.last_run_path();
    ctx->passes += ctx->last_frame_passes;
    sss::api::remember_steady(ctx, *frame, run);
  }
  return r;
}

}  // extern "C"
