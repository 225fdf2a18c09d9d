// The checks and conversions of sss_profile_desc and sss_kernel_desc, shared by the GL-free kernel
// API (sss_kernel_plan, sss_profile_*) and sss_set_settings (its embedded kernel). No GL.
#include <cmath>
#include <cstdio>
#include <initializer_list>

#include "validation.hpp"

namespace sss::api {

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

}  // namespace

sss_result check_profile(sss_context* ctx, const sss_profile_desc* p, const char* name) {
  if (p == nullptr) return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%s is NULL", name);
  if (p->struct_size != sizeof(sss_profile_desc)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%s->struct_size = %u: expected sizeof(sss_profile_desc) = %u",
                name, p->struct_size, static_cast<unsigned>(sizeof(sss_profile_desc)));
  }
  if (p->material < 0 || p->material >= SSS_MATERIAL_COUNT) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%s->material = %d: must be in [0, %d)", name, p->material,
                SSS_MATERIAL_COUNT);
  }
  if (p->material == SSS_MATERIAL_SKIN && (p->gaussian_count < 1 || p->gaussian_count > 6)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%s->gaussian_count = %d: must be in [1, 6]", name,
                p->gaussian_count);
  }
  if (p->material != SSS_MATERIAL_TABULATED) return SSS_OK;
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

sss::math::ProfileRequest to_request(const sss_profile_desc& p) {
  sss::math::ProfileRequest r;
  if (p.material == SSS_MATERIAL_SKIN) {
    r.material = sss::math::kProfileSkin;
    r.gaussian_count = p.gaussian_count;
  } else if (p.material == SSS_MATERIAL_TABULATED) {
    r.material = sss::math::kProfileTable;
    for (int32_t i = 0; i < p.table_size; ++i) {
      r.table_radii_mm.push_back(p.table_radius_mm[i]);
      r.table_values.push_back({p.table_rgb[i * 3], p.table_rgb[i * 3 + 1], p.table_rgb[i * 3 + 2]});
    }
  } else {
    r.material = p.material - SSS_MATERIAL_APPLE;  // the math table starts at apple
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
  // In sss_settings, taps, strength and falloff are the settings' own (samples, strength, falloff).
  if (!in_settings && (d->taps < SSS_MIN_SAMPLES || d->taps > SSS_MAX_SAMPLES || d->taps % 2 == 0)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%staps = %d: must be odd and in [%d, %d]", name, d->taps,
                SSS_MIN_SAMPLES, SSS_MAX_SAMPLES);
  }
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
  if (reads({SSS_KERNEL_SEPARABLE, SSS_KERNEL_ARTIST}) && !in_settings) return SSS_OK;
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
  if (d.family != SSS_KERNEL_SEPARABLE && d.family != SSS_KERNEL_ARTIST) q.profile = to_request(d.profile);
  return q;
}

}  // namespace sss::api
