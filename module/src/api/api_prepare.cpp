// sss_prepare: the programs and targets of the frames a host describes, built and allocated at a
// moment of its choosing (load, resize) instead of inside the first such frame, where a shader
// compile or a texture allocation is a visible hitch. The description is checked in full before
// anything is built; the GPU side is gl::SeparableFilter::prewarm (gl/prewarm.cpp).
#include <cstddef>
#include <cstring>

#include "../gl/debug_label.hpp"
#include "../gl/state_guard.hpp"
#include "../gl/texture_query.hpp"
#include "context.hpp"
#include "gl_session.hpp"
#include "profiles.hpp"
#include "versioned_structs.hpp"

namespace {

using sss::api::fail;
namespace gl = sss::gl;

// The largest sample count the module takes (one 32-bit sample mask word), as sss_apply_frame.
constexpr int32_t kMaxSamples = 32;

sss_result bad_format(sss_context* ctx, const char* field, std::uint32_t value, const char* expected) {
  return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "desc->%s = 0x%04X (%s): expected %s", field, value,
              gl::format_name(static_cast<gl::GLint>(value)).c_str(), expected);
}

// strength_format: its list, and a colour and sample count sss_apply_frame takes a strength texture with.
sss_result check_strength(sss_context* ctx, const sss_prepare_desc& d) {
  if (d.strength_format == 0) return SSS_OK;
  if (!gl::is_strength_format(static_cast<gl::GLint>(d.strength_format))) {
    return bad_format(ctx, "strength_format", d.strength_format,
                      "0 (none), GL_R8 (0x8229), GL_R16F (0x822D) or GL_R32F (0x822E)");
  }
  if (d.samples > 1) {
    return fail(ctx, SSS_ERROR_UNSUPPORTED, "desc->strength_format = %s with samples = %d: the MSAA path reads the "
                "strength from the colour's alpha", gl::format_name(static_cast<gl::GLint>(d.strength_format)).c_str(),
                d.samples);
  }
  if (d.output_format == 0 && gl::is_color_format(static_cast<gl::GLint>(d.color_format))) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "desc->strength_format with color_format = %s written back "
                "(output_format 0): sss_apply_frame refuses it (the colour's alpha would become the strength)",
                gl::format_name(static_cast<gl::GLint>(d.color_format)).c_str());
  }
  return SSS_OK;
}

// profile_format: its list, single-sample, the separable mode (as sss_apply_frame takes it).
sss_result check_profile_format(sss_context* ctx, const sss_prepare_desc& d) {
  if (d.profile_format == 0) return SSS_OK;
  if (!gl::is_profile_format(static_cast<gl::GLint>(d.profile_format))) {
    return bad_format(ctx, "profile_format", d.profile_format, "0 (none), GL_R8UI (0x8232) or GL_R16UI (0x8234)");
  }
  if (d.samples > 1) {
    return fail(ctx, SSS_ERROR_UNSUPPORTED, "desc->profile_format with samples = %d: per-pixel profiles take "
                "single-sample textures", d.samples);
  }
  if (ctx->settings.cross_bilateral) {
    return fail(ctx, SSS_ERROR_UNSUPPORTED, "desc->profile_format in the cross-bilateral mode: per-pixel profiles "
                "run the separable mode");
  }
  return SSS_OK;
}

// The caller's desc in today's layout (0.3's ends before profile_format, which is then 0) into
// *out, and every field against its list or range, without the GL.
sss_result check_fields(sss_context* ctx, const sss_prepare_desc* desc, sss_prepare_desc* out) {
  if (desc == nullptr) return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "desc is NULL");
  // New in 0.3 (main between 0.2 and 0.3 had the same layout); 0.4 added profile_format.
  const sss_result size =
      sss::api::check_struct_size(ctx, "desc->struct_size", "sss_prepare_desc", desc->struct_size,
                                  {{"0.3", static_cast<uint32_t>(offsetof(sss_prepare_desc, profile_format))},
                                   {"0.4, 0.5", static_cast<uint32_t>(offsetof(sss_prepare_desc, albedo_format))},
                                   {"0.6", static_cast<uint32_t>(sizeof(sss_prepare_desc))}});
  if (size != SSS_OK) return size;
  *out = sss_prepare_desc{};
  std::memcpy(out, desc, desc->struct_size);
  const sss_prepare_desc& d = *out;
  if (d.width < 1 || d.height < 1) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "desc->width = %d, height = %d: both must be >= 1", d.width,
                d.height);
  }
  const auto format = [](std::uint32_t f) { return static_cast<gl::GLint>(f); };
  if (!gl::is_color_format(format(d.color_format)) &&
      !(gl::is_alpha_free_color_format(format(d.color_format)) && d.strength_format != 0)) {
    return bad_format(ctx, "color_format", d.color_format,
                      "GL_RGBA16F (0x881A) or GL_RGBA32F (0x8814); GL_R11F_G11F_B10F (0x8C3A) with strength_format");
  }
  if (d.output_format != 0 && !gl::is_color_format(format(d.output_format))) {
    return bad_format(ctx, "output_format", d.output_format,
                      "0 (in place), GL_RGBA16F (0x881A) or GL_RGBA32F (0x8814)");
  }
  if (!gl::is_hardware_depth_format(format(d.depth_format)) && !gl::is_linear_depth_format(format(d.depth_format))) {
    return bad_format(ctx, "depth_format", d.depth_format,
                      "a GL_DEPTH_COMPONENT* or GL_DEPTH*_STENCIL8 format, or GL_R16F/GL_R32F");
  }
  if (d.samples < 0 || d.samples > kMaxSamples) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "desc->samples = %d: must be 0 or 1 (single-sample) or in [2, %d]",
                d.samples, kMaxSamples);
  }
  if (d.stencil_format != 0 && !gl::is_depth_stencil_format(format(d.stencil_format))) {
    return bad_format(ctx, "stencil_format", d.stencil_format,
                      "0 (no stencil), GL_DEPTH24_STENCIL8 (0x88F0) or GL_DEPTH32F_STENCIL8 (0x8CAD)");
  }
  if (d.albedo_format != 0 && !gl::is_albedo_format(format(d.albedo_format))) {
    return bad_format(ctx, "albedo_format", d.albedo_format,
                      "0 (no albedo), GL_SRGB8_ALPHA8 (0x8C43), GL_RGBA8 (0x8058) or GL_RGBA16F (0x881A)");
  }
  sss_result r = check_strength(ctx, d);
  if (r == SSS_OK) r = check_profile_format(ctx, d);
  if (r != SSS_OK) return r;
  if ((d.flags & ~SSS_PREPARE_ALL_FLAGS) != 0) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "desc->flags = 0x%x has unknown bits 0x%x", d.flags,
                d.flags & ~SSS_PREPARE_ALL_FLAGS);
  }
  return SSS_OK;
}

// What the context can do with such frames: the size and sample count against its limits, the
// formats against OpenGL ES's extensions (as sss_apply_frame checks the textures themselves).
sss_result check_limits(sss_context* ctx, const sss_prepare_desc& d) {
  const gl::Functions& f = ctx->gl;
  gl::GLint max_size = 0;
  f.GetIntegerv(gl::MAX_TEXTURE_SIZE, &max_size);
  if (d.width > max_size || d.height > max_size) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "desc->width = %d, height = %d: above GL_MAX_TEXTURE_SIZE = %d",
                d.width, d.height, max_size);
  }
  if (d.samples > 1) {
    if (!f.has_msaa_path()) {
      return fail(ctx, SSS_ERROR_UNSUPPORTED, "desc->samples = %d: the MSAA path needs desktop OpenGL", d.samples);
    }
    const bool linear = gl::is_linear_depth_format(static_cast<gl::GLint>(d.depth_format));
    gl::GLint max_color = 0, max_depth = 0;
    f.GetIntegerv(gl::MAX_COLOR_TEXTURE_SAMPLES, &max_color);
    f.GetIntegerv(linear ? gl::MAX_COLOR_TEXTURE_SAMPLES : gl::MAX_DEPTH_TEXTURE_SAMPLES, &max_depth);
    if (d.samples > max_color || d.samples > max_depth) {
      return fail(ctx, SSS_ERROR_UNSUPPORTED, "desc->samples = %d: this context supports at most %d for the colour "
                  "and %d for the depth format", d.samples, max_color, max_depth);
    }
  }
  if (f.api.es) {
    const auto rgba32f = [](std::uint32_t format) { return format == static_cast<std::uint32_t>(gl::RGBA32F); };
    const bool r11f = gl::is_alpha_free_color_format(static_cast<gl::GLint>(d.color_format));
    const char* field = rgba32f(d.color_format) || r11f ? "color_format"
                        : rgba32f(d.output_format)      ? "output_format"
                                                        : nullptr;
    if (field != nullptr && !ctx->es_float_render) {
      return fail(ctx, SSS_ERROR_UNSUPPORTED, "desc->%s = %s: rendering to it on OpenGL ES needs "
                  "GL_EXT_color_buffer_float", field, r11f ? "GL_R11F_G11F_B10F" : "GL_RGBA32F");
    }
    if (rgba32f(d.color_format) && !ctx->es_float_linear) {
      return fail(ctx, SSS_ERROR_UNSUPPORTED, "desc->color_format = GL_RGBA32F: filtering it on OpenGL ES needs "
                  "GL_OES_texture_float_linear");
    }
  }
  return SSS_OK;
}

gl::TextureInfo described(const sss_prepare_desc& d, std::uint32_t format, bool multisampled) {
  gl::TextureInfo t;
  t.internal_format = static_cast<gl::GLint>(format);
  t.width = d.width;
  t.height = d.height;
  if (multisampled) {
    t.target = gl::TEXTURE_2D_MULTISAMPLE;
    t.samples = d.samples;
    t.fixed_locations = (d.flags & SSS_PREPARE_UNFIXED_SAMPLE_LOCATIONS) != 0 ? 0 : 1;
  }
  return t;
}

// The FilterRun of such a frame with the current settings, as sss_apply_frame fills it: textures by
// format, size and samples; the kernels, mode and path of the settings.
gl::FilterRun described_run(const sss_context& ctx, const sss_prepare_desc& d, gl::StencilInput* stencil) {
  gl::FilterRun run;
  const bool multisampled = d.samples > 1;
  run.color = described(d, d.color_format, multisampled);
  // A frame's colour is a texture: a path that copies it (a strength texture, a texturing mode, the
  // colour copy of any path) then writes back into it as the passes' output, which a nameless
  // colour would read as "written back" and plan another last pass.
  run.color.name = gl::kPrewarmColourPlaceholder;
  run.depth = described(d, d.depth_format, multisampled);
  if (d.output_format != 0) {
    run.output = described(d, d.output_format, false);
    run.output.name = gl::kPrewarmPlaceholder;
  }
  if ((d.flags & SSS_PREPARE_NORMALS) != 0) {
    run.normals = described(d, static_cast<std::uint32_t>(gl::RGBA16F), false);
    run.normals.name = gl::kPrewarmPlaceholder;
  }
  if (d.strength_format != 0) {
    run.strength = described(d, d.strength_format, false);
    run.strength.name = gl::kPrewarmPlaceholder;
  }
  if (d.albedo_format != 0) {
    run.albedo = described(d, d.albedo_format, multisampled);  // multisampled like the colour
    run.albedo.name = gl::kPrewarmPlaceholder;
  }
  if (d.stencil_format != 0) {
    stencil->texture = described(d, d.stencil_format, multisampled);
    run.stencil = stencil;
  }
  run.viewport = {0, 0, d.width, d.height};
  run.draw_rect = run.viewport;
  run.region = (d.flags & SSS_PREPARE_REGION) != 0;
  const bool linear = gl::is_linear_depth_format(static_cast<gl::GLint>(d.depth_format));
  // The MSAA path's resolve reads the host's depth; its passes read the resolved linear distance.
  run.resolve_constants.linear_depth = linear;
  run.constants.linear_depth = linear || multisampled;
  run.kernel = &ctx.kernel;
  run.kernel_revision = ctx.kernel_revision;
  run.follow_surface = ctx.settings.follow_surface;
  run.path = ctx.settings.path;
  run.auto_half_resolution = ctx.settings.auto_half_resolution;
  run.cross_bilateral = ctx.settings.cross_bilateral;
  run.cbf_kernel = &ctx.cbf_kernel;
  run.cbf_kernel_revision = ctx.cbf_kernel_revision;
  if (d.profile_format != 0) {
    run.profile_ids = described(d, d.profile_format, false);
    run.profile_ids.name = gl::kPrewarmPlaceholder;
    sss::api::fill_profiles(ctx, ctx.projection, nullptr, &run);  // the kernels; their constants are per frame
  }
  run.texturing[0] = static_cast<std::uint8_t>(ctx.settings.texturing);
  return run;
}

}  // namespace

extern "C" {

SSS_API sss_result sss_prepare(sss_context* ctx, const sss_prepare_desc* given) {
  if (ctx == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "ctx is NULL");
  sss_prepare_desc current;
  sss_result r = check_fields(ctx, given, &current);
  if (r != SSS_OK) return r;
  const sss_prepare_desc* desc = &current;
  const gl::Functions& f = ctx->gl;
  r = sss::api::require_current_context(ctx, f);
  if (r != SSS_OK) return r;

  sss::api::drain_host_errors(ctx, f);
  gl::StateGuard guard(f, (ctx->create_flags & SSS_CREATE_NO_STATE_RESTORE) == 0);
  gl::DebugGroup group(f, (ctx->create_flags & SSS_CREATE_NO_DEBUG_LABELS) == 0, "sss_prepare");
  r = check_limits(ctx, *desc);
  if (r == SSS_OK) r = sss::api::require_module_objects(ctx);
  if (r != SSS_OK) return r;

  gl::StencilInput stencil;
  const gl::FilterRun run = described_run(*ctx, *desc, &stencil);
  std::string message;
  r = ctx->filter.prewarm(run, &message);
  if (r != SSS_OK) {
    sss::api::drain_host_errors(nullptr, f);
    return fail(ctx, r, message);
  }
  return sss::api::check_gl_errors(ctx, f, "preparing the passes");
}

}  // extern "C"
