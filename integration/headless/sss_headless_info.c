/*
 * sss_headless_info: creates a headless GL context with each requested backend and prints
 * GL_RENDERER and GL_VERSION.
 *
 *   sss_headless_info [options] [osmesa|egl|egl-device|egl-gles ...]
 *
 *   (no backend)     osmesa, egl and egl-device
 *   --gl M.m         requested OpenGL version (default 4.5; OpenGL ES 3.0 for egl-gles)
 *   --compat         compatibility profile (default: core)
 *   --debug          request a debug context
 *   --repeat N       create/destroy every requested backend N times, interleaved (default 1)
 *
 * Exit status: 0 when every requested backend produced a context, 1 when at least one failed,
 * 2 on a usage error.
 */
#include "sss_headless.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void usage(FILE *f) {
  fprintf(f,
          "usage: sss_headless_info [--gl M.m] [--compat] [--debug] [--repeat N] "
          "[osmesa|egl|egl-device|egl-gles ...]\n"
          "Creates a headless OpenGL context per backend (default: all three) and prints\n"
          "GL_RENDERER and GL_VERSION. Exit status 1 if a requested backend failed.\n");
}

int main(int argc, char **argv) {
  sss_headless_backend backends[16];
  int num_backends = 0;
  sss_headless_desc desc;
  int repeat = 1;
  int failed = 0;
  int version_given = 0;
  int i, r;

  memset(&desc, 0, sizeof desc);
  desc.major = 4;
  desc.minor = 5;
  desc.core_profile = 1;

  for (i = 1; i < argc; ++i) {
    const char *a = argv[i];
    if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
      usage(stdout);
      return 0;
    } else if (strcmp(a, "--gl") == 0 && i + 1 < argc) {
      version_given = 1;
      if (sscanf(argv[++i], "%d.%d", &desc.major, &desc.minor) != 2) {
        fprintf(stderr, "sss_headless_info: bad --gl value '%s' (expected e.g. 4.5)\n", argv[i]);
        return 2;
      }
    } else if (strcmp(a, "--compat") == 0) {
      desc.core_profile = 0;
    } else if (strcmp(a, "--debug") == 0) {
      desc.debug = 1;
    } else if (strcmp(a, "--repeat") == 0 && i + 1 < argc) {
      repeat = atoi(argv[++i]);
      if (repeat < 1) {
        fprintf(stderr, "sss_headless_info: bad --repeat value '%s'\n", argv[i]);
        return 2;
      }
    } else {
      sss_headless_backend b;
      if (sss_headless_backend_from_name(a, &b) != 0) {
        fprintf(stderr, "sss_headless_info: unknown argument '%s'\n", a);
        usage(stderr);
        return 2;
      }
      if (num_backends == (int)(sizeof backends / sizeof backends[0])) {
        fprintf(stderr, "sss_headless_info: too many backends\n");
        return 2;
      }
      backends[num_backends++] = b;
    }
  }
  if (num_backends == 0) {
    backends[num_backends++] = SSS_HEADLESS_OSMESA;
    backends[num_backends++] = SSS_HEADLESS_EGL_SURFACELESS;
    backends[num_backends++] = SSS_HEADLESS_EGL_DEVICE;
  }

  for (r = 0; r < repeat; ++r) {
    for (i = 0; i < num_backends; ++i) {
      sss_headless *h = NULL;
      char err[512];
      const char *name = sss_headless_backend_name(backends[i]);
      sss_headless_desc d = desc;
      d.backend = backends[i];
      if (sss_headless_backend_is_gles(d.backend) && !version_given) {
        d.major = 3;
        d.minor = 0;
      }
      if (sss_headless_create(&d, &h, err, sizeof err) != 0) {
        fprintf(stderr, "%s: FAILED (OpenGL %s%d.%d %s): %s\n", name,
                sss_headless_backend_is_gles(d.backend) ? "ES " : "", d.major, d.minor,
                d.core_profile ? "core" : "compat", err);
        failed = 1;
        continue;
      }
      if (r == 0) {
        const char *renderer = sss_headless_renderer(h);
        const char *version = sss_headless_version(h);
        printf("backend:     %s\n", name);
        printf("GL_RENDERER: %s\n", renderer ? renderer : "(glGetString failed)");
        printf("GL_VERSION:  %s\n", version ? version : "(glGetString failed)");
        if (!renderer || !version) failed = 1;
      }
      sss_headless_destroy(h);
    }
  }
  if (repeat > 1)
    printf("%d create/destroy cycles per backend: %s\n", repeat, failed ? "FAILED" : "ok");
  return failed ? 1 : 0;
}
