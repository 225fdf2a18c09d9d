/*
 * Runs one of the two host examples as a host would: the README's (readme_example.c; the target
 * sss_readme_example) or, built with SSS_HEADER_EXAMPLE, the one at the top of <sss/sss.h> (extracted
 * from the header's comment at build time by cmake/SssExtractHeaderExample.cmake, compiled as strict
 * C99 and linked against the runtime library alone: sss_header_example). A headless GL context
 * (EGL surfaceless, else OSMesa), a lit diffuse target in RGBA16F with alpha = strength holding a
 * bright dot on a dim plane 12 cm from the camera, a depth-stencil texture, one frame. Exit status 0
 * when the example's calls succeeded, the dot's light spread and the light was conserved.
 */
#include <GL/glcorearb.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <sss/sss.h>
#include <sss_headless.h>

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

/* A GL entry point into a function pointer (ISO C has no cast from void * to a function pointer). */
static void load(sss_headless *h, const char *name, void *function_pointer, size_t size) {
  void *address = sss_headless_get_proc_address(name, h);
  if (size == sizeof address) memcpy(function_pointer, &address, size);
}

int main(void) {
  static const sss_headless_backend backends[] = {SSS_HEADLESS_EGL_SURFACELESS, SSS_HEADLESS_OSMESA};
  sss_headless *h = NULL;
  sss_context *sss;
  PFNGLGENTEXTURESPROC gen_textures = NULL;
  PFNGLBINDTEXTUREPROC bind_texture = NULL;
  PFNGLTEXIMAGE2DPROC tex_image_2d = NULL;
  PFNGLGETTEXIMAGEPROC get_tex_image = NULL;
  PFNGLDELETETEXTURESPROC delete_textures = NULL;
  /* Column-major perspective: 20° vertical field of view, near 0.01 m, far 10 m; the plane at 0.12 m
   * spans about 0.66 mm per pixel, so d'Eon's skin spreads the dot over several pixels. */
  const double n = 0.01, f = 10.0, distance = 0.12, focal = 1.0 / tan(10.0 * 3.14159265358979 / 180.0);
  const double z_ndc = (f + n) / (f - n) - 2.0 * f * n / ((f - n) * distance);
  const float projection[16] = {(float)focal, 0, 0, 0, 0, (float)focal, 0, 0, 0, 0, (float)((f + n) / (n - f)), -1,
                                0, 0, (float)(2.0 * f * n / (n - f)), 0};
  unsigned textures[2];
  double before = 0.0, after = 0.0;
  char err[256];
  int i, ok;

  for (i = 0; i < 2 && h == NULL; ++i) {
    sss_headless_desc desc = {SSS_HEADLESS_EGL_SURFACELESS, 3, 3, 1, 0};
    desc.backend = backends[i];
    if (sss_headless_create(&desc, &h, err, sizeof err) != 0) fprintf(stderr, "%s\n", err);
  }
  if (h == NULL) return 1;
  load(h, "glGenTextures", &gen_textures, sizeof gen_textures);
  load(h, "glBindTexture", &bind_texture, sizeof bind_texture);
  load(h, "glTexImage2D", &tex_image_2d, sizeof tex_image_2d);
  load(h, "glGetTexImage", &get_tex_image, sizeof get_tex_image);
  load(h, "glDeleteTextures", &delete_textures, sizeof delete_textures);
  if (!gen_textures || !bind_texture || !tex_image_2d || !get_tex_image || !delete_textures) return 1;

  for (i = 0; i < W * H; ++i) {
    diffuse[i * 4 + 0] = diffuse[i * 4 + 1] = diffuse[i * 4 + 2] = 0.05f;
    diffuse[i * 4 + 3] = 1.0f;
    depth_stencil[i] = ((unsigned)((z_ndc + 1.0) * 0.5 * 16777215.0) << 8) | 1u;
  }
  diffuse[DOT * 4 + 0] = diffuse[DOT * 4 + 1] = diffuse[DOT * 4 + 2] = 50.0f;
  gen_textures(2, textures);
  bind_texture(GL_TEXTURE_2D, textures[0]);
  tex_image_2d(GL_TEXTURE_2D, 0, GL_RGBA16F, W, H, 0, GL_RGBA, GL_FLOAT, diffuse);
  bind_texture(GL_TEXTURE_2D, textures[1]);
  tex_image_2d(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, W, H, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, depth_stencil);
  bind_texture(GL_TEXTURE_2D, 0);

  sss = CREATE(h);
  if (sss == NULL) {
    fprintf(stderr, "%s: creating: %s\n", EXAMPLE, sss_last_error(NULL));
    return 1;
  }
  ok = FRAME(sss, projection, textures[0], textures[1]);
  if (!ok) fprintf(stderr, "engine_sss_frame: %s\n", sss_last_error(sss));
  DESTROY(sss);

  bind_texture(GL_TEXTURE_2D, textures[0]);
  get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, result);
  bind_texture(GL_TEXTURE_2D, 0);
  delete_textures(2, textures);
  sss_headless_destroy(h);
  for (i = 0; i < W * H; ++i) {
    before += diffuse[i * 4];
    after += result[i * 4];
  }
  printf(EXAMPLE ": dot %.2f -> %.2f, energy %.3f -> %.3f\n", diffuse[DOT * 4], result[DOT * 4], before, after);
  return ok && result[DOT * 4] < 45.0f && fabs(after - before) < 0.01 * before ? 0 : 1;
}
