/*
 * Runs the guide's quick start (guide_quickstart.c) as a fresh host would: a headless GL context
 * (docs_gl.c), a diffuse target in GL_RGBA16F and a GL_DEPTH24_STENCIL8 depth texture, then the
 * checklist's steps in order: load (1-3), two frames (4-6; the second repeats the first, a steady
 * frame), unload (7). The left half of the image is skin (alpha 1, a plane 12 cm from the camera)
 * with a bright dot; the right half is background (alpha 0, 2 m away).
 * Exit status 0 when every step succeeded, the dot's light spread to its translucent neighbours and
 * every background pixel kept its exact value.
 */
#include <math.h>
#include <stdio.h>

#include <sss/sss.h>

#include "docs_gl.h"
#include "guide_quickstart.h"

enum { W = 64, H = 48, SKIN_END = 32, DOT = (H / 2) * W + SKIN_END / 2 };

static float diffuse[W * H * 4];
static unsigned depth_stencil[W * H];
static float result[W * H * 4];

/* The window depth (GL's default [0, 1] range, 24 bits) of a point `distance` in front of the camera. */
static unsigned depth24(double n, double f, double distance) {
  const double z_ndc = (f + n) / (f - n) - 2.0 * f * n / ((f - n) * distance);
  return (unsigned)((z_ndc + 1.0) * 0.5 * 16777215.0);
}

int main(void) {
  docs_gl gl;
  sss_context *sss;
  /* Column-major perspective: 20 degrees vertical field of view, near 0.01 m, far 10 m; the plane
   * at 0.12 m spans about 0.66 mm per pixel, so d'Eon's skin spreads the dot over several pixels. */
  const double n = 0.01, f = 10.0, focal = 1.0 / tan(10.0 * 3.14159265358979 / 180.0);
  const float projection[16] = {(float)(focal * H / W), 0, 0, 0, 0, (float)focal, 0, 0, 0, 0, (float)((f + n) / (n - f)),
                                -1, 0, 0, (float)(2.0 * f * n / (n - f)), 0};
  GLuint color, depth;
  int x, y, frames = 0, background_changed = 0, ok;

  if (docs_gl_open(&gl) != 0) return 1;
  for (y = 0; y < H; ++y) {
    for (x = 0; x < W; ++x) {
      const int p = y * W + x, skin = x < SKIN_END;
      diffuse[p * 4 + 0] = diffuse[p * 4 + 1] = diffuse[p * 4 + 2] = skin ? 0.05f : 0.25f; /* 0.25: exact in fp16 */
      diffuse[p * 4 + 3] = skin ? 1.0f : 0.0f;
      depth_stencil[p] = depth24(n, f, skin ? 0.12 : 2.0) << 8;
    }
  }
  diffuse[DOT * 4 + 0] = diffuse[DOT * 4 + 1] = diffuse[DOT * 4 + 2] = 50.0f;
  color = docs_gl_texture(&gl, GL_RGBA16F, W, H, GL_RGBA, GL_FLOAT, diffuse);
  depth = docs_gl_texture(&gl, GL_DEPTH24_STENCIL8, W, H, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, depth_stencil);

  sss = quickstart_load(sss_headless_get_proc_address, gl.headless, W, H);
  if (sss != NULL) {
    while (frames < 2 && quickstart_frame(sss, projection, color, depth, W, H)) ++frames;
    quickstart_unload(sss);
  }

  docs_gl_read_rgba(&gl, color, result);
  docs_gl_close(&gl);
  for (y = 0; y < H; ++y) {
    for (x = SKIN_END; x < W; ++x) {
      const float *p = &result[(y * W + x) * 4];
      if (p[0] != 0.25f || p[1] != 0.25f || p[2] != 0.25f || p[3] != 0.0f) ++background_changed;
    }
  }
  printf("guide quick start: %d frames; dot %.2f -> %.2f, its neighbour %.3f -> %.3f; %d background pixels changed\n",
         frames, diffuse[DOT * 4], result[DOT * 4], diffuse[(DOT + 1) * 4], result[(DOT + 1) * 4], background_changed);
  ok = sss != NULL && frames == 2 && result[DOT * 4] < 45.0f && result[(DOT + 1) * 4] > 0.1f && background_changed == 0;
  return ok ? 0 : 1;
}
