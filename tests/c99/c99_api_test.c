/* The public header compiles as strict C99 and the library links from C. Exercises the GL-free
 * entry points; exit status 0 on success. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "sss/sss_lut.h" /* includes sss.h */
#include "sss/sss_tools.h"

static int failures = 0;
#define CHECK(cond)                                                     \
  do {                                                                  \
    if (!(cond)) {                                                      \
      fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
      ++failures;                                                       \
    }                                                                   \
  } while (0)

int main(void) {
  sss_settings settings;
  float taps[SSS_MAX_TAPS * 4];
  float sum[3] = {0.0f, 0.0f, 0.0f};
  int i;
  sss_context *ctx = NULL;
  sss_create_desc desc;
  sss_lut_desc lut;
  float lut_rgba[4 * 4 * 2];
  sss_stats stats;
  sss_frame frame;
  sss_kernel_desc kd;
  sss_profile_desc pd;
  float plan[SSS_KERNEL_MAX_TERMS * 2 * SSS_MAX_TAPS * 4];
  float depth_variance[SSS_KERNEL_MAX_TERMS];
  float radius = 1.0f, rgb[3], reach = 0.0f;
  int32_t terms = 0;

  sss_default_settings(&settings);
  CHECK(settings.struct_size == sizeof settings);
  CHECK(settings.taps == SSS_TAPS_MEDIUM);
  CHECK(sss_kernel_separable(settings.taps, settings.strength, settings.falloff, taps) == SSS_OK);
  for (i = 0; i < settings.taps; ++i) {
    sum[0] += taps[i * 4 + 0];
    sum[1] += taps[i * 4 + 1];
    sum[2] += taps[i * 4 + 2];
  }
  CHECK(fabs(sum[0] - 1.0) < 1e-5 && fabs(sum[1] - 1.0) < 1e-5 && fabs(sum[2] - 1.0) < 1e-5);
  CHECK(taps[3] == 0.0f); /* centre first */
  CHECK(sss_kernel_separable(4, settings.strength, settings.falloff, taps) == SSS_ERROR_INVALID_ARGUMENT);
  CHECK(strstr(sss_last_error(NULL), "taps = 4") != NULL);
  CHECK(strcmp(sss_result_string(SSS_ERROR_GL), "SSS_ERROR_GL") == 0);
  CHECK(settings.mode == SSS_MODE_SEPARABLE && settings.cbf_taps == 13);
  {
    float transmittance[SSS_PROFILE_MAX_TERMS * 4];
    int32_t count = 0;
    CHECK(sss_profile_transmittance_terms(SSS_PROFILE_SKIN_DEON, transmittance, SSS_PROFILE_MAX_TERMS, &count) == SSS_OK);
    CHECK(count == 6 && transmittance[0] > 0.0f);
    CHECK(settings.cbf_profile == SSS_PROFILE_MIKKELSEN_2010);
    /* The same from a profile desc: the default one is d'Eon's six Gaussians. */
    CHECK(settings.kernel == NULL);
    sss_default_profile_desc(&pd);
    CHECK(sss_profile_desc_transmittance_terms(&pd, transmittance, SSS_PROFILE_MAX_TERMS, &count) == SSS_OK);
    CHECK(count == 6);
    CHECK(sss_profile_desc_transmittance_terms(NULL, transmittance, SSS_PROFILE_MAX_TERMS, &count) ==
          SSS_ERROR_INVALID_ARGUMENT);
    CHECK(settings.flags == SSS_FOLLOW_SURFACE);
  }
  memset(&desc, 0, sizeof desc);
  desc.struct_size = sizeof desc;
  CHECK(sss_create(&desc, &ctx) == SSS_ERROR_INVALID_ARGUMENT && ctx == NULL);
  sss_destroy(NULL);

  /* Pre-integrated LUTs, GL-free. */
  sss_lut_default_desc(&lut);
  CHECK(lut.struct_size == sizeof lut && lut.width == 256 && lut.profile == SSS_PROFILE_SKIN_DEON);
  lut.width = 4;
  lut.height = 2;
  CHECK(sss_lut_diffuse_fill(&lut, lut_rgba, 4 * 4 * 2) == SSS_OK);
  CHECK(lut_rgba[0] == 0.0f && lut_rgba[3] == 1.0f); /* N.L = -1 on a flat row: dark */
  CHECK(fabs(lut_rgba[12] - 1.0) < 1e-6);            /* N.L = 1 on a flat row: lit */
  CHECK(sss_lut_shadow_fill(&lut, lut_rgba, 4 * 4 * 2) == SSS_OK);
  CHECK(lut_rgba[0] == 0.0f && lut_rgba[12] == 1.0f);
  lut.profile = SSS_PROFILE_MARBLE; /* one sss_profile space */
  CHECK(sss_lut_diffuse_fill(&lut, lut_rgba, 4 * 4 * 2) == SSS_OK && fabs(lut_rgba[12] - 1.0) < 1e-6);
  lut.profile = SSS_PROFILE_TABULATED;
  CHECK(sss_lut_diffuse_fill(&lut, lut_rgba, 4 * 4 * 2) == SSS_ERROR_INVALID_ARGUMENT);
  lut.profile = SSS_PROFILE_SKIN_DEON;
  CHECK(sss_lut_shadow_fill(&lut, lut_rgba, 31) == SSS_ERROR_INVALID_ARGUMENT);
  CHECK(strstr(sss_last_error(NULL), "out_floats = 31") != NULL);
  CHECK(sss_lut_create_texture(NULL, SSS_LUT_DIFFUSE, &lut, NULL) == SSS_ERROR_INVALID_ARGUMENT);
  CHECK(sss_lut_generation_count(NULL) == 0);
  CHECK(sss_lut_fill_generation_count() >= 1); /* the fills above generated at least one LUT */
  /* sss_get_stats and the frame's texture description are plain C99 too. */
  memset(&stats, 0, sizeof stats);
  stats.struct_size = sizeof stats;
  CHECK(sss_get_stats(NULL, &stats) == SSS_ERROR_INVALID_ARGUMENT);
  CHECK(strstr(sss_last_error(NULL), "ctx is NULL") != NULL);
  CHECK(sss_gl_context_changed(NULL) == SSS_ERROR_INVALID_ARGUMENT);
  CHECK((SSS_CREATE_ALL_FLAGS & SSS_CREATE_DEBUG_CHECKS) != 0);
  CHECK(SSS_GLSL_330_CORE != SSS_GLSL_300_ES && (SSS_CREATE_ALL_FLAGS & SSS_CREATE_STATS) != 0);
  memset(&frame, 0, sizeof frame);
  frame.struct_size = sizeof frame;
  frame.color_format = 0x881A; /* GL_RGBA16F */
  frame.texture_width = 64;
  frame.texture_height = 48;
  CHECK(sss_apply_frame(NULL, &frame) == SSS_ERROR_INVALID_ARGUMENT);
  {
    /* sss_prepare's description (no hitch on the first frame) is plain C99 too. */
    sss_prepare_desc prepare;
    memset(&prepare, 0, sizeof prepare);
    prepare.struct_size = sizeof prepare;
    prepare.width = 64;
    prepare.height = 48;
    prepare.color_format = 0x881A; /* GL_RGBA16F */
    prepare.depth_format = 0x88F0; /* GL_DEPTH24_STENCIL8 */
    prepare.flags = SSS_PREPARE_NORMALS;
    CHECK(sss_prepare(NULL, &prepare) == SSS_ERROR_INVALID_ARGUMENT);
    CHECK(strstr(sss_last_error(NULL), "ctx is NULL") != NULL);
  }

  /* The kernel-family API (sss_tools.h). */
  sss_default_kernel_desc(&kd);
  kd.family = SSS_KERNEL_SVD;
  kd.rank = 3;
  kd.profile.profile = SSS_PROFILE_MARBLE;
  CHECK(sss_kernel_plan(&kd, SSS_KERNEL_MAX_TERMS, plan, depth_variance, &terms, &reach) == SSS_OK);
  CHECK(terms == 3 && reach > 0.0f && depth_variance[0] == 0.0f);
  kd.family = SSS_KERNEL_ARTIST;
  CHECK(sss_kernel_plan(&kd, SSS_KERNEL_MAX_TERMS, plan, depth_variance, &terms, &reach) == SSS_OK);
  CHECK(terms == 1 && depth_variance[0] > 0.0f);
  kd.family = 42;
  CHECK(sss_kernel_plan(&kd, SSS_KERNEL_MAX_TERMS, plan, NULL, &terms, NULL) == SSS_ERROR_INVALID_ARGUMENT);
  CHECK(strstr(sss_last_error(NULL), "desc->family = 42") != NULL);
  sss_default_profile_desc(&pd);
  pd.profile = SSS_PROFILE_APPLE;
  CHECK(sss_profile_evaluate(&pd, 1, &radius, rgb) == SSS_OK && rgb[0] > 0.0f);
  CHECK(sss_profile_integral(&pd, rgb) == SSS_OK && rgb[0] > 0.0f && rgb[0] < 1.0f);
  CHECK(strcmp(sss_profile_name(SSS_PROFILE_APPLE), "apple") == 0);
  printf("%d passed, %d failed\n", failures == 0 ? 1 : 0, failures == 0 ? 0 : 1);
  return failures == 0 ? 0 : 1;
}
