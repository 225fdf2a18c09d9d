// sss_set_profiles and the per-pixel profile texture of sss_apply_frame: validation and
// bookkeeping (no GL but the debug checks' readback of the indices).
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "../gl/texture_query.hpp"
#include "profiles.hpp"
#include "validation.hpp"
#include "versioned_structs.hpp"

namespace {

using sss::api::fail;
namespace gl = sss::gl;

// The fields every profile shares (one pass pair runs them all): they must equal profiles[0]'s.
sss_result check_shared_fields(sss_context* ctx, const sss_settings& first, const sss_settings& s, uint32_t i) {
  struct Shared {
    const char* name;
    double value, expected;
    bool differs;
  };
  const auto bits_differ = [](float a, float b) { return std::memcmp(&a, &b, sizeof a) != 0; };
  const Shared fields[] = {
      {"taps", static_cast<double>(s.taps), static_cast<double>(first.taps), s.taps != first.taps},
      {"flags", static_cast<double>(s.flags), static_cast<double>(first.flags), s.flags != first.flags},
      {"mode", static_cast<double>(s.mode), static_cast<double>(first.mode), s.mode != first.mode},
      {"path", static_cast<double>(s.path), static_cast<double>(first.path), s.path != first.path},
      {"jitter", static_cast<double>(s.jitter), static_cast<double>(first.jitter), bits_differ(s.jitter, first.jitter)},
      {"cbf_taps", static_cast<double>(s.cbf_taps), static_cast<double>(first.cbf_taps), s.cbf_taps != first.cbf_taps},
      {"cbf_r_max_mm", static_cast<double>(s.cbf_r_max_mm), static_cast<double>(first.cbf_r_max_mm),
       bits_differ(s.cbf_r_max_mm, first.cbf_r_max_mm)},
      {"cbf_profile", static_cast<double>(s.cbf_profile), static_cast<double>(first.cbf_profile),
       s.cbf_profile != first.cbf_profile},
  };
  for (const Shared& f : fields) {
    if (!f.differs) continue;
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                "profiles[%u].%s = %g differs from profiles[0].%s = %g: taps, flags, mode, path, jitter and the "
                "cbf_* fields are shared by every profile (one pass pair runs them all)",
                i, f.name, f.value, f.name, f.expected);
  }
  return SSS_OK;
}

// A failure of profiles[i]'s checks, its message (which names settings->field) prefixed with the index.
sss_result for_profile(sss_context* ctx, sss_result r, uint32_t i) {
  std::string why = ctx->last_error;
  const std::string code = std::string(sss_result_string(r)) + ": ";
  if (why.compare(0, code.size(), code) == 0) why.erase(0, code.size());
  return fail(ctx, r, "profiles[%u]: %s", i, why.c_str());
}

// One profile of several: valid settings sharing profiles[0]'s shared fields, the separable mode,
// and a kernel of one term (sss_set_profiles then checks that every depth rule is the first's).
sss_result build_profile(sss_context* ctx, const sss_settings* profiles, uint32_t i, sss::math::Profile* out) {
  const sss_settings& s = profiles[i];
  if (s.struct_size != sizeof(sss_settings)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                "profiles[%u].struct_size = %u: expected sizeof(sss_settings) = %u (sss_set_profiles is new in 0.4)",
                i, s.struct_size, static_cast<unsigned>(sizeof(sss_settings)));
  }
  // A kernel desc of an earlier release's size (a tools build older than the runtime) is read as
  // today's, as sss_set_settings reads it.
  sss::api::CurrentSettings current;
  sss_result r = sss::api::settings_from_caller(ctx, &s, &current);
  if (r == SSS_OK) r = sss::api::check_settings(ctx, &current.settings);
  if (r != SSS_OK) return for_profile(ctx, r, i);
  if (i > 0) {
    r = check_shared_fields(ctx, profiles[0], s, i);
    if (r != SSS_OK) return r;
  }
  if (s.mode == SSS_MODE_CROSS_BILATERAL) {
    return fail(ctx, SSS_ERROR_UNSUPPORTED, "profiles[%u].mode = SSS_MODE_CROSS_BILATERAL: several profiles run "
                "the separable mode (SSS_MODE_SEPARABLE)", i);
  }
  out->settings = sss::api::to_filter_settings(current.settings);
  r = sss::api::build_pass_kernel(ctx, out->settings, &out->kernel);
  if (r != SSS_OK) return for_profile(ctx, r, i);
  if (out->kernel.terms.size() != 1) {
    return fail(ctx, SSS_ERROR_UNSUPPORTED,
                "profiles[%u].kernel (family %d) has %zu separable terms: with several profiles each kernel must be "
                "one term (eq. (1), or a family at rank 1)", i, static_cast<int>(out->settings.kernel.family),
                out->kernel.terms.size());
  }
  return SSS_OK;
}

}  // namespace

namespace sss::api {

bool is_identity_settings(const sss::math::FilterSettings& s) {
  if (s.world_units_per_mm == 0.0f || s.scale == 0.0f) return true;
  // Strength applies to eq. (1) alone (the separable family); the others scatter what their profile does.
  return s.kernel.family == sss::math::KernelFamily::separable && s.strength[0] == 0.0f && s.strength[1] == 0.0f &&
         s.strength[2] == 0.0f;
}

sss_result check_profile_texture(sss_context* ctx, const gl::FilterRun& run) {
  const gl::TextureInfo& t = run.profile_ids;
  if (!gl::is_profile_format(t.internal_format)) {
    return fail(ctx, SSS_ERROR_INVALID_TEXTURE, "profile_texture = %u has format %s: expected GL_R8UI or GL_R16UI",
                t.name, gl::format_name(t.internal_format).c_str());
  }
  if (t.multisampled() || run.color.multisampled()) {
    return fail(ctx, SSS_ERROR_UNSUPPORTED,
                "profile_texture = %u with color_texture = %u (%s): per-pixel profiles take single-sample textures; "
                "resolve the colour first", t.name, run.color.name, gl::describe_target(run.color).c_str());
  }
  if (t.width != run.color.width || t.height != run.color.height) {
    return fail(ctx, SSS_ERROR_INVALID_TEXTURE, "profile_texture = %u is %dx%d but the colour texture is %dx%d",
                t.name, t.width, t.height, run.color.width, run.color.height);
  }
  if (ctx->settings.cross_bilateral) {
    return fail(ctx, SSS_ERROR_UNSUPPORTED, "profile_texture = %u in the cross-bilateral mode: per-pixel profiles "
                "run the separable mode", t.name);
  }
  return SSS_OK;
}

void fill_profiles(const sss_context& ctx, const sss::math::Matrix4& projection, const sss::math::FrameGeometry* geometry,
                   gl::FilterRun* run) {
  run->profile_count = 1 + static_cast<int>(ctx.extra_profiles.size());
  run->profile_kernels[0] = &ctx.kernel;
  run->profile_constants[0] = run->constants;
  run->profiles_revision = ctx.profiles_revision;
  for (std::size_t i = 0; i < ctx.extra_profiles.size(); ++i) {
    const sss::math::Profile& p = ctx.extra_profiles[i];
    run->profile_kernels[i + 1] = &p.kernel;
    run->texturing[i + 1] = static_cast<std::uint8_t>(p.settings.texturing);
    if (geometry == nullptr) continue;
    run->profile_constants[i + 1] =
        sss::math::compute_pass_constants(p.settings, projection, *geometry, p.kernel.reach_mm);
  }
}

bool extra_profiles_are_identity(const sss_context& ctx) {
  for (const sss::math::Profile& p : ctx.extra_profiles) {
    if (!is_identity_settings(p.settings)) return false;
  }
  return true;
}

sss_result check_profile_indices(sss_context* ctx, const gl::FilterRun& run) {
  const gl::Functions& f = ctx->gl;
  const std::array<int, 4>& rect = run.draw_rect;
  if (rect[2] <= 0 || rect[3] <= 0) return SSS_OK;
  gl::GLuint framebuffer = 0;
  f.GenFramebuffers(1, &framebuffer);
  f.BindFramebuffer(gl::READ_FRAMEBUFFER, framebuffer);
  f.FramebufferTexture2D(gl::READ_FRAMEBUFFER, gl::COLOR_ATTACHMENT0, gl::TEXTURE_2D, run.profile_ids.name, 0);
  f.ReadBuffer(gl::COLOR_ATTACHMENT0);
  // The guard saved the pack state (GuardScope::pack): tightly packed, into client memory.
  f.BindBuffer(gl::PIXEL_PACK_BUFFER, 0);
  f.PixelStorei(gl::PACK_ALIGNMENT, 4);
  f.PixelStorei(gl::PACK_ROW_LENGTH, 0);
  f.PixelStorei(gl::PACK_SKIP_ROWS, 0);
  f.PixelStorei(gl::PACK_SKIP_PIXELS, 0);
  // RGBA_INTEGER / UNSIGNED_INT: the one combination every GL reads an unsigned integer colour with.
  std::vector<std::uint32_t> values(static_cast<std::size_t>(rect[2]) * static_cast<std::size_t>(rect[3]) * 4);
  f.ReadPixels(rect[0], rect[1], rect[2], rect[3], gl::RGBA_INTEGER, gl::UNSIGNED_INT, values.data());
  f.FramebufferTexture2D(gl::READ_FRAMEBUFFER, gl::COLOR_ATTACHMENT0, gl::TEXTURE_2D, 0, 0);
  f.DeleteFramebuffers(1, &framebuffer);
  const auto count = static_cast<std::uint32_t>(1 + ctx->extra_profiles.size());
  for (std::size_t p = 0; p < values.size() / 4; ++p) {
    const std::uint32_t value = values[4 * p];
    if ((value & sss::math::kProfileIndexMask) < count) continue;
    const int x = rect[0] + static_cast<int>(p % static_cast<std::size_t>(rect[2]));
    const int y = rect[1] + static_cast<int>(p / static_cast<std::size_t>(rect[2]));
    return fail(ctx, SSS_ERROR_INVALID_TEXTURE,
                "profile_texture = %u: pixel (%d, %d) holds %u, profile index %u, but %u profiles are set (a missing "
                "profile: sss_set_profiles); nothing was drawn", run.profile_ids.name, x, y, value,
                value & sss::math::kProfileIndexMask, count);
  }
  return SSS_OK;
}

}  // namespace sss::api

extern "C" {

SSS_API sss_result sss_set_profiles(sss_context* ctx, const sss_settings* profiles, uint32_t count) {
  if (ctx == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "ctx is NULL");
  if (profiles == nullptr) return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "profiles is NULL");
  if (count < 1 || count > SSS_MAX_PROFILES) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "count = %u: must be in [1, SSS_MAX_PROFILES = %d]", count,
                SSS_MAX_PROFILES);
  }
  const int capacity = ctx->filter.profile_capacity();
  if (static_cast<int>(count) > capacity) {
    return fail(ctx, SSS_ERROR_UNSUPPORTED,
                "count = %u: this GL's uniform blocks (GL_MAX_UNIFORM_BLOCK_SIZE) hold the tables of %d profiles",
                count, capacity);
  }
  if (count == 1) return sss_set_settings(ctx, profiles);
  // The array's stride is the caller's sizeof(sss_settings), which profiles[0].struct_size says:
  // 0.4's and 0.5's (their profiles are pre-scatter) or today's. Read into today's layout first.
  const uint32_t stride = profiles[0].struct_size;
  if (stride != sizeof(sss_settings) && stride != sss::api::kSettingsSize05) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                "profiles[0].struct_size = %u: expected sizeof(sss_settings) = %u (0.6) or %u (0.4, 0.5; "
                "sss_set_profiles is new in 0.4)",
                stride, static_cast<unsigned>(sizeof(sss_settings)), sss::api::kSettingsSize05);
  }
  std::vector<sss::api::CurrentSettings> read(count);  // kept: each settings.kernel may point into it
  std::vector<sss_settings> current(count);
  for (uint32_t i = 0; i < count; ++i) {
    const auto* given = reinterpret_cast<const sss_settings*>(reinterpret_cast<const char*>(profiles) +
                                                              static_cast<std::size_t>(i) * stride);
    if (given->struct_size != stride) {
      return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                  "profiles[%u].struct_size = %u: expected profiles[0]'s, %u (one array of one release's structs)", i,
                  given->struct_size, stride);
    }
    const sss_result r = sss::api::settings_from_caller(ctx, given, &read[i]);
    if (r != SSS_OK) return for_profile(ctx, r, i);
    current[i] = read[i].settings;
  }
  profiles = current.data();
  // Every profile is checked and built before anything changes: a failure keeps the old set.
  std::vector<sss::math::Profile> built(count);
  // Last to first, so that profile 0's kernel is the freshest in ctx->recent_kernels.
  for (uint32_t i = count; i-- > 0;) {
    const sss_result r = build_profile(ctx, profiles, i, &built[i]);
    if (r != SSS_OK) return r;
  }
  const bool gaussian = built[0].kernel.terms[0].depth_variance_mm2 > 0.0f;
  for (uint32_t i = 1; i < count; ++i) {
    if ((built[i].kernel.terms[0].depth_variance_mm2 > 0.0f) != gaussian) {
      return fail(ctx, SSS_ERROR_UNSUPPORTED,
                  "profiles[%u].kernel: its depth rule (%s) differs from profiles[0]'s (%s); one pass pair applies one",
                  i, gaussian ? "the follow-surface ramp" : "the Gaussian depth correction",
                  gaussian ? "the Gaussian depth correction" : "the follow-surface ramp");
    }
  }
  // Profile 0 becomes the settings (its kernel is in ctx->recent_kernels now: no second fit).
  const sss_result r = sss_set_settings(ctx, &profiles[0]);
  if (r != SSS_OK) return r;
  built.erase(built.begin());
  ctx->extra_profiles = std::move(built);
  ++ctx->profiles_revision;
  return SSS_OK;
}

}  // extern "C"
