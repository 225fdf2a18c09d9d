// The checks and conversions of sss_profile_desc and sss_kernel_desc, and the tap and unit-range
// checks, shared by the tools API (sss_kernel_plan, sss_profile_*; the tools library) and
// sss_set_settings (settings->kernel; the runtime library). No GL: compiled into both libraries.
#include <cmath>
#include <cstdio>
#include <initializer_list>

#include "legacy_structs.hpp"
#include "validation.hpp"

#include <cstring>

namespace sss::api {

sss_result check_taps(sss_context* ctx, const char* name, int32_t taps) {
  if (taps < SSS_MIN_TAPS || taps > SSS_MAX_TAPS || taps % 2 == 0) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%s = %d: must be odd and in [%d, %d]", name, taps, SSS_MIN_TAPS,
                SSS_MAX_TAPS);
  }
  return SSS_OK;
}

sss_result check_unit_range(sss_context* ctx, const char* name, const float values[3]) {
  if (values == nullptr) return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%s is NULL", name);
  for (int c = 0; c < 3; ++c) {
    const float v = values[c];
    if (!(v >= 0.0f && v <= 1.0f)) {  // also rejects NaN
      return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%s[%d] = %g: must be in [0, 1]", name, c,
                  static_cast<double>(v));
    }
  }
  return SSS_OK;
}

void set_burley(const sss::math::BurleyParameters& b, sss_profile_desc* p) {
  for (std::size_t c = 0; c < 3; ++c) {
    p->burley_albedo[c] = static_cast<float>(b.albedo[c]);
    p->burley_dmfp_mm[c] = static_cast<float>(b.dmfp_mm[c]);
  }
}

void default_profile_desc(sss_profile_desc* p) {
  std::memset(p, 0, sizeof *p);
  p->struct_size = sizeof *p;
  p->profile = SSS_PROFILE_SKIN_DEON;
  p->gaussian_count = 6;
  set_burley(sss::math::burley_default_parameters(), p);
}

void default_kernel_desc(sss_kernel_desc* d) {
  const sss::math::KernelRequest r;
  std::memset(d, 0, sizeof *d);
  d->struct_size = sizeof *d;
  d->family = SSS_KERNEL_SEPARABLE;
  d->taps = r.taps;
  d->rank = r.rank;
  d->guide_k = static_cast<float>(r.guide_k);
  for (std::size_t c = 0; c < 3; ++c) {
    d->strength[c] = r.strength[c];
    d->falloff[c] = r.falloff[c];
    d->near_variance_mm2[c] = static_cast<float>(r.artist.near_variance_mm2[c]);
    d->far_variance_mm2[c] = static_cast<float>(r.artist.far_variance_mm2[c]);
    d->near_weight[c] = static_cast<float>(r.artist.near_weight[c]);
  }
  default_profile_desc(&d->profile);
}

namespace {
bool finite_in(float v, float lo, float hi) { return std::isfinite(v) && v >= lo && v <= hi; }

sss_result check_positive3(sss_context* ctx, const char* prefix, const char* name, const float v[3]) {
  for (int c = 0; c < 3; ++c) {
    if (!(finite_in(v[c], 0.0f, 1e4f) && v[c] > 0.0f)) {
      return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%s%s[%d] = %g: must be in (0, 1e4]", prefix, name, c,
                  static_cast<double>(v[c]));
    }
  }
  return SSS_OK;
}

sss_result check_burley(sss_context* ctx, const sss_profile_desc* p, const char* name) {
  for (int c = 0; c < 3; ++c) {
    const float a = p->burley_albedo[c];
    if (!(finite_in(a, 0.0f, 1.0f) && a > 0.0f)) {
      return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%s->burley_albedo[%d] = %g: must be in (0, 1]", name, c,
                  static_cast<double>(a));
    }
  }
  for (int c = 0; c < 3; ++c) {
    const float l = p->burley_dmfp_mm[c];
    if (!finite_in(l, SSS_BURLEY_MIN_DMFP_MM, SSS_BURLEY_MAX_DMFP_MM)) {
      return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%s->burley_dmfp_mm[%d] = %g: must be in [%g, %g] mm", name, c,
                  static_cast<double>(l), static_cast<double>(SSS_BURLEY_MIN_DMFP_MM),
                  static_cast<double>(SSS_BURLEY_MAX_DMFP_MM));
    }
  }
  return SSS_OK;
}

}  // namespace

sss_result check_profile(sss_context* ctx, const sss_profile_desc* p, const char* name) {
  if (p == nullptr) return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%s is NULL", name);
  if (p->struct_size != sizeof(sss_profile_desc)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%s->struct_size = %u: expected sizeof(sss_profile_desc) = %u",
                name, p->struct_size, static_cast<unsigned>(sizeof(sss_profile_desc)));
  }
  if ((p->profile < SSS_PROFILE_SKIN_DEON || p->profile > SSS_PROFILE_TABULATED) && p->profile != SSS_PROFILE_BURLEY) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                "%s->profile = %d: must be an sss_profile in [SSS_PROFILE_SKIN_DEON (0), SSS_PROFILE_TABULATED (%d)] "
                "or SSS_PROFILE_BURLEY (%d)",
                name, p->profile, SSS_PROFILE_TABULATED, SSS_PROFILE_BURLEY);
  }
  if (p->profile == SSS_PROFILE_SKIN_DEON && (p->gaussian_count < 1 || p->gaussian_count > 6)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%s->gaussian_count = %d: must be in [1, 6]", name,
                p->gaussian_count);
  }
  if (p->profile == SSS_PROFILE_BURLEY) return check_burley(ctx, p, name);
  if (p->profile != SSS_PROFILE_TABULATED) return SSS_OK;
  if (p->table_size < 1 || p->table_size > SSS_PROFILE_MAX_TABLE) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%s->table_size = %d: must be in [1, %d]", name, p->table_size,
                SSS_PROFILE_MAX_TABLE);
  }
  if (p->table_radius_mm == nullptr) return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%s->table_radius_mm is NULL", name);
  if (p->table_rgb == nullptr) return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%s->table_rgb is NULL", name);
  for (int32_t i = 0; i < p->table_size; ++i) {
    const float r = p->table_radius_mm[i];
    if (!finite_in(r, 0.0f, 1e30f) || (i > 0 && !(r > p->table_radius_mm[i - 1]))) {
      return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                  "%s->table_radius_mm[%d] = %g: must be finite, >= 0 and above the previous radius", name, i,
                  static_cast<double>(r));
    }
    for (int c = 0; c < 3; ++c) {
      const float v = p->table_rgb[i * 3 + c];
      if (!finite_in(v, 0.0f, 1e30f)) {
        return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%s->table_rgb[%d] = %g: must be finite and >= 0", name,
                    i * 3 + c, static_cast<double>(v));
      }
    }
  }
  return SSS_OK;
}

// ---- Earlier releases' layouts (legacy_structs.hpp): read as the prefix they are, the burley
// fields taking their defaults.

void kernel_desc_from_legacy(const legacy::KernelDesc03& old, sss_kernel_desc* out) {
  default_kernel_desc(out);
  std::memcpy(static_cast<void*>(out), &old, offsetof(legacy::KernelDesc03, profile));
  std::memcpy(static_cast<void*>(&out->profile), &old.profile, sizeof old.profile);
  out->struct_size = sizeof *out;
  // An embedded 0.1-0.3 profile desc becomes today's; any other size stays for check_profile to name.
  if (old.profile.struct_size == sizeof(legacy::ProfileDesc03)) out->profile.struct_size = sizeof(sss_profile_desc);
}

void kernel_desc_to_legacy(const sss_kernel_desc& current, legacy::KernelDesc03* old) {
  std::memcpy(old, &current, offsetof(legacy::KernelDesc03, profile));
  std::memcpy(&old->profile, &current.profile, sizeof old->profile);
  old->struct_size = sizeof *old;
  old->profile.struct_size = sizeof old->profile;
}

sss_result profile_desc_from_caller(sss_context* ctx, const sss_profile_desc* in, const char* name,
                                    sss_profile_desc* out) {
  if (in == nullptr) return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%s is NULL", name);
  if (in->struct_size == sizeof(legacy::ProfileDesc03)) {
    default_profile_desc(out);
    std::memcpy(static_cast<void*>(out), in, sizeof(legacy::ProfileDesc03));
    out->struct_size = sizeof *out;
    return SSS_OK;
  }
  if (in->struct_size != sizeof(sss_profile_desc)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                "%s->struct_size = %u: expected sizeof(sss_profile_desc) = %u (or 0.1-0.3's %u)", name,
                in->struct_size, static_cast<unsigned>(sizeof(sss_profile_desc)),
                static_cast<unsigned>(sizeof(legacy::ProfileDesc03)));
  }
  *out = *in;
  return SSS_OK;
}

sss_result kernel_desc_from_caller(sss_context* ctx, const sss_kernel_desc* in, const char* name,
                                   sss_kernel_desc* out) {
  if (in == nullptr) return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%s is NULL", name);
  if (in->struct_size == sizeof(legacy::KernelDesc03)) {
    legacy::KernelDesc03 old;
    std::memcpy(&old, in, sizeof old);
    if (old.profile.struct_size != sizeof(legacy::ProfileDesc03)) {
      return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                  "%s->profile.struct_size = %u: a 0.1-0.3 sss_kernel_desc (%u bytes) holds 0.1-0.3's "
                  "sss_profile_desc (%u)",
                  name, old.profile.struct_size, static_cast<unsigned>(sizeof old),
                  static_cast<unsigned>(sizeof old.profile));
    }
    kernel_desc_from_legacy(old, out);
    return SSS_OK;
  }
  if (in->struct_size != sizeof(sss_kernel_desc)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                "%s->struct_size = %u: expected sizeof(sss_kernel_desc) = %u (or 0.1-0.3's %u)", name,
                in->struct_size, static_cast<unsigned>(sizeof(sss_kernel_desc)),
                static_cast<unsigned>(sizeof(legacy::KernelDesc03)));
  }
  *out = *in;
  return SSS_OK;
}

sss::math::ProfileRequest to_request(const sss_profile_desc& p) {
  sss::math::ProfileRequest r;
  if (p.profile == SSS_PROFILE_SKIN_DEON) {
    r.material = sss::math::kProfileSkin;
    r.gaussian_count = p.gaussian_count;
  } else if (p.profile == SSS_PROFILE_TABULATED) {
    r.material = sss::math::kProfileTable;
    for (int32_t i = 0; i < p.table_size; ++i) {
      r.table_radii_mm.push_back(p.table_radius_mm[i]);
      r.table_values.push_back({p.table_rgb[i * 3], p.table_rgb[i * 3 + 1], p.table_rgb[i * 3 + 2]});
    }
  } else if (p.profile == SSS_PROFILE_BURLEY) {
    r.material = sss::math::kProfileBurley;
    for (std::size_t c = 0; c < 3; ++c) {
      r.burley.albedo[c] = p.burley_albedo[c];
      r.burley.dmfp_mm[c] = p.burley_dmfp_mm[c];
    }
  } else {
    r.material = p.profile - SSS_PROFILE_APPLE;  // the math table starts at apple
  }
  return r;
}


sss_result check_kernel_desc(sss_context* ctx, const sss_kernel_desc* d, const char* name, bool in_settings) {
  // name: how the fields are reached in messages ("desc->", "settings->kernel.").
  char field[96];
  auto named = [&](const char* member) {
    std::snprintf(field, sizeof field, "%s%s", name, member);
    return field;
  };
  if (d == nullptr) return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "desc is NULL");
  if (d->struct_size != sizeof(sss_kernel_desc)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%sstruct_size = %u: expected sizeof(sss_kernel_desc) = %u",
                name, d->struct_size, static_cast<unsigned>(sizeof(sss_kernel_desc)));
  }
  if (d->family < 0 || d->family >= SSS_KERNEL_FAMILY_COUNT) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%sfamily = %d: must be in [0, %d)", name, d->family,
                SSS_KERNEL_FAMILY_COUNT);
  }
  // In sss_settings, taps, strength and falloff are the settings' own.
  if (!in_settings && check_taps(ctx, named("taps"), d->taps) != SSS_OK) return SSS_ERROR_INVALID_ARGUMENT;
  if ((d->flags & ~SSS_KERNEL_ALL_FLAGS) != 0u) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%sflags = 0x%x: unknown bits 0x%x", name, d->flags,
                d->flags & ~SSS_KERNEL_ALL_FLAGS);
  }
  // sss_kernel_plan checks the fields its family reads; sss_set_settings every field whatever the
  // family (as it checks every field whatever the mode), so a later switch of family cannot fail.
  const int32_t family = d->family;
  auto reads = [&](std::initializer_list<int32_t> families) {
    if (in_settings) return true;
    for (int32_t f : families) {
      if (f == family) return true;
    }
    return false;
  };
  sss_result r = SSS_OK;
  if (!in_settings && family == SSS_KERNEL_SEPARABLE) {
    r = check_unit_range(ctx, named("strength"), d->strength);
    if (r == SSS_OK) r = check_unit_range(ctx, named("falloff"), d->falloff);
  }
  if (r == SSS_OK && reads({SSS_KERNEL_ARTIST})) {
    r = check_positive3(ctx, name, "near_variance_mm2", d->near_variance_mm2);
    if (r == SSS_OK) r = check_positive3(ctx, name, "far_variance_mm2", d->far_variance_mm2);
    if (r == SSS_OK) r = check_unit_range(ctx, named("near_weight"), d->near_weight);
  }
  if (r != SSS_OK) return r;
  if (!in_settings && !sss::math::builds_from_profile(static_cast<sss::math::KernelFamily>(family))) return SSS_OK;
  if (reads({SSS_KERNEL_SUM_OF_GAUSSIANS, SSS_KERNEL_SVD}) && (d->rank < 1 || d->rank > 6)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%srank = %d: must be in [1, 6]", name, d->rank);
  }
  if (reads({SSS_KERNEL_GUIDED}) && !finite_in(d->guide_k, 0.0f, 4.0f)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%sguide_k = %g: must be in [0, 4]", name,
                static_cast<double>(d->guide_k));
  }
  if (!finite_in(d->radius_mm, 0.0f, 1e4f)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%sradius_mm = %g: must be 0 or in (0, 1e4]", name,
                static_cast<double>(d->radius_mm));
  }
  return check_profile(ctx, &d->profile, named("profile"));
}

sss::math::KernelRequest to_kernel_request(const sss_kernel_desc& d) {
  sss::math::KernelRequest q;
  q.family = static_cast<sss::math::KernelFamily>(d.family);
  q.taps = d.taps;
  q.rank = d.rank;
  q.rescale_energy = (d.flags & SSS_KERNEL_SVD_NO_RESCALE) == 0u;
  q.guide_k = d.guide_k;
  q.radius_mm = d.radius_mm;
  for (std::size_t c = 0; c < 3; ++c) {
    q.strength[c] = d.strength[c];
    q.falloff[c] = d.falloff[c];
    q.artist.near_variance_mm2[c] = d.near_variance_mm2[c];
    q.artist.far_variance_mm2[c] = d.far_variance_mm2[c];
    q.artist.near_weight[c] = d.near_weight[c];
  }
  // Only the families that read a profile get one (an unread tabulated profile copies nothing).
  if (sss::math::builds_from_profile(q.family)) q.profile = to_request(d.profile);
  return q;
}

}  // namespace sss::api
