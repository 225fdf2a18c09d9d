/*
 * Runs one of the two host examples as a host would: the README's (readme_example.c; the target
 * sss_readme_example) or, built with SSS_HEADER_EXAMPLE, the one at the top of <sss/sss.h> (extracted
 * from the header's comment at build time by cmake/SssExtractHeaderExample.cmake, compiled as strict
 * C99 and linked against the runtime library alone: sss_header_example). A headless GL context
 * (EGL surfaceless, else OSMesa: docs_gl.c), a lit diffuse target in RGBA16F with alpha = strength
 * holding a bright dot on a dim plane 12 cm from the camera, a depth-stencil texture, one frame.
 * Exit status 0 when the example's calls succeeded, the dot's light spread and the light was
 * conserved.
 */
#include <math.h>
#include <stdio.h>

#include <sss/sss.h>

#include "docs_gl.h"

#ifdef SSS_HEADER_EXAMPLE
/* The header example's three functions (its comment has no prototypes to include). */
sss_context *engine_sss_init(sss_get_proc_address_fn load, void *load_user, int w, int h);
int engine_sss_frame(sss_context *sss, const float projection[16], uint32_t diffuse, uint32_t depth, int w, int h);
void engine_sss_shutdown(sss_context *sss);
#define EXAMPLE "sss.h example"
#define CREATE(h) engine_sss_init(sss_headless_get_proc_address, (h), W, H)
#define FRAME(sss, p, c, d) engine_sss_frame((sss), (p), (c), (d), W, H)
#define DESTROY(sss) engine_sss_shutdown(sss)
#else
sss_context *engine_sss_create(sss_get_proc_address_fn get_proc_address, void *loader_user);
int engine_sss_frame(sss_context *sss, const float projection[16], uint32_t diffuse, uint32_t depth);
#define EXAMPLE "README example"
#define CREATE(h) engine_sss_create(sss_headless_get_proc_address, (h))
#define FRAME(sss, p, c, d) engine_sss_frame((sss), (p), (c), (d))
#define DESTROY(sss) sss_destroy(sss)
#endif

enum { W = 64, H = 64, DOT = (H / 2) * W + W / 2 };

static float diffuse[W * H * 4];
static unsigned depth_stencil[W * H];
static float result[W * H * 4];

int main(void) {
  docs_gl gl;
  sss_context *sss;
  /* Column-major perspective: 20° vertical field of view, near 0.01 m, far 10 m; the plane at 0.12 m
   * spans about 0.66 mm per pixel, so d'Eon's skin spreads the dot over several pixels. */
  const double n = 0.01, f = 10.0, distance = 0.12, focal = 1.0 / tan(10.0 * 3.14159265358979 / 180.0);
  const double z_ndc = (f + n) / (f - n) - 2.0 * f * n / ((f - n) * distance);
  const float projection[16] = {(float)focal, 0, 0, 0, 0, (float)focal, 0, 0, 0, 0, (float)((f + n) / (n - f)), -1,
                                0, 0, (float)(2.0 * f * n / (n - f)), 0};
  GLuint color, depth;
  double before = 0.0, after = 0.0;
  int i, ok;

  if (docs_gl_open(&gl) != 0) return 1;

  for (i = 0; i < W * H; ++i) {
    diffuse[i * 4 + 0] = diffuse[i * 4 + 1] = diffuse[i * 4 + 2] = 0.05f;
    diffuse[i * 4 + 3] = 1.0f;
    depth_stencil[i] = ((unsigned)((z_ndc + 1.0) * 0.5 * 16777215.0) << 8) | 1u;
  }
  diffuse[DOT * 4 + 0] = diffuse[DOT * 4 + 1] = diffuse[DOT * 4 + 2] = 50.0f;
  color = docs_gl_texture(&gl, GL_RGBA16F, W, H, GL_RGBA, GL_FLOAT, diffuse);
  depth = docs_gl_texture(&gl, GL_DEPTH24_STENCIL8, W, H, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, depth_stencil);

  sss = CREATE(gl.headless);
  if (sss == NULL) {
    fprintf(stderr, "%s: creating: %s\n", EXAMPLE, sss_last_error(NULL));
    docs_gl_close(&gl);
    return 1;
  }
  ok = FRAME(sss, projection, color, depth);
  if (!ok) fprintf(stderr, "engine_sss_frame: %s\n", sss_last_error(sss));
  DESTROY(sss);

  docs_gl_read_rgba(&gl, color, result);
  docs_gl_close(&gl);
  for (i = 0; i < W * H; ++i) {
    before += diffuse[i * 4];
    after += result[i * 4];
  }
  printf(EXAMPLE ": dot %.2f -> %.2f, energy %.3f -> %.3f\n", diffuse[DOT * 4], result[DOT * 4], before, after);
  return ok && result[DOT * 4] < 45.0f && fabs(after - before) < 0.01 * before ? 0 : 1;
}
