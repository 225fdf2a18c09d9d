/*
 * The smallest complete integration of sss, in C99, as docs/integration.md walks through it:
 * a host with its own GL context (here EGL without a window), its own loader, a lit diffuse target
 * in RGBA16F with alpha = SSS strength, a depth-stencil texture, and one call per frame.
 * Built in CI against an installed sss (CMake package and pkg-config). Exit status 0 when the
 * filter spread a bright dot's light and conserved it.
 */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/glcorearb.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <sss/sss.h>

/* The host's GL entry points (an engine already has these from its own loader). */
static PFNGLGENTEXTURESPROC gen_textures;
static PFNGLBINDTEXTUREPROC bind_texture;
static PFNGLTEXIMAGE2DPROC tex_image_2d;
static PFNGLGETTEXIMAGEPROC get_tex_image;
static PFNGLDELETETEXTURESPROC delete_textures;

/* 1. Give sss the host's loader. */
static void *load_gl(const char *name, void *user) {
  (void)user;
  return (void *)eglGetProcAddress(name);
}

static int make_context(void) {
  PFNEGLGETPLATFORMDISPLAYEXTPROC get_display =
      (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
  const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLDisplay display;
  EGLContext context;
  if (get_display == NULL) return 0;
  display = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, NULL, NULL) || !eglBindAPI(EGL_OPENGL_API)) return 0;
  context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, context_attributes);
  return context != EGL_NO_CONTEXT && eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context);
}

int main(void) {
  enum { W = 64, H = 64 };
  static float diffuse[W * H * 4];
  static unsigned depth_stencil[W * H];
  static float result[W * H * 4];
  /* A column-major perspective projection: 45° vertical field of view, near 0.1, far 10. */
  const float f = 2.4142136f, n = 0.1f, far_plane = 10.0f;
  const float projection[16] = {f, 0, 0, 0, 0, f, 0, 0, 0, 0, (far_plane + n) / (n - far_plane), -1,
                                0, 0, 2 * far_plane * n / (n - far_plane), 0};
  sss_create_desc desc;
  sss_settings settings;
  sss_stencil mask;
  sss_context *sss = NULL;
  unsigned textures[2];
  double before = 0.0, after = 0.0;
  int i;

  if (!make_context()) {
    fprintf(stderr, "no EGL surfaceless OpenGL 3.3 context\n");
    return 1;
  }
  gen_textures = (PFNGLGENTEXTURESPROC)load_gl("glGenTextures", NULL);
  bind_texture = (PFNGLBINDTEXTUREPROC)load_gl("glBindTexture", NULL);
  tex_image_2d = (PFNGLTEXIMAGE2DPROC)load_gl("glTexImage2D", NULL);
  get_tex_image = (PFNGLGETTEXIMAGEPROC)load_gl("glGetTexImage", NULL);
  delete_textures = (PFNGLDELETETEXTURESPROC)load_gl("glDeleteTextures", NULL);

  /* 2. What the lighting pass leaves: linear diffuse irradiance (no specular), alpha = strength;
   *    here a dim plane with one bright pixel. Depth 0.9 everywhere, stencil 1 = skin. */
  for (i = 0; i < W * H; ++i) {
    diffuse[i * 4 + 0] = diffuse[i * 4 + 1] = diffuse[i * 4 + 2] = 0.05f;
    diffuse[i * 4 + 3] = 1.0f;
    depth_stencil[i] = ((unsigned)(0.9 * 16777215.0) << 8) | 1u;
  }
  diffuse[(32 * W + 32) * 4 + 0] = diffuse[(32 * W + 32) * 4 + 1] = diffuse[(32 * W + 32) * 4 + 2] = 50.0f;
  gen_textures(2, textures);
  bind_texture(GL_TEXTURE_2D, textures[0]);
  tex_image_2d(GL_TEXTURE_2D, 0, GL_RGBA16F, W, H, 0, GL_RGBA, GL_FLOAT, diffuse);
  bind_texture(GL_TEXTURE_2D, textures[1]);
  tex_image_2d(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, W, H, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, depth_stencil);
  bind_texture(GL_TEXTURE_2D, 0);

  /* 3. Once: create the context and give it the scene's scale: world units per millimetre of
   *    surface. This scene takes a millimetre as 0.004 world units, so a pixel at its depth spans
   *    about 3 mm and the blur shows on 64 pixels; scale stays 1, the physical size. */
  memset(&desc, 0, sizeof desc);
  desc.struct_size = sizeof desc;
  desc.get_proc_address = load_gl;
  if (sss_create(&desc, &sss) != SSS_OK) {
    fprintf(stderr, "sss_create: %s\n", sss_last_error(NULL));
    return 1;
  }
  sss_default_settings(&settings);
  settings.world_units_per_mm = 0.004f;
  if (sss_set_settings(sss, &settings) != SSS_OK) return fprintf(stderr, "%s\n", sss_last_error(sss)), 1;

  /* 4. Every frame, after lighting and before adding specular and tone mapping. */
  mask.depth_stencil_texture = textures[1];
  mask.ref = 1;
  mask.mask = 0xFF;
  if (sss_set_camera(sss, projection) != SSS_OK || sss_apply(sss, textures[0], textures[1], &mask) != SSS_OK) {
    fprintf(stderr, "sss: %s\n", sss_last_error(sss));
    return 1;
  }

  bind_texture(GL_TEXTURE_2D, textures[0]);
  get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, result);
  bind_texture(GL_TEXTURE_2D, 0);
  for (i = 0; i < W * H; ++i) {
    before += diffuse[i * 4];
    after += result[i * 4];
  }
  printf("sss %d.%d.%d: dot %.2f -> %.2f, energy %.3f -> %.3f\n", SSS_VERSION_MAJOR, SSS_VERSION_MINOR,
         SSS_VERSION_PATCH, diffuse[(32 * W + 32) * 4], result[(32 * W + 32) * 4], before, after);
  sss_destroy(sss);
  delete_textures(2, textures);
  /* The dot spread (it lost more than a tenth to its neighbours) and the light was conserved. */
  return result[(32 * W + 32) * 4] < 45.0f && fabs(after - before) < 0.01 * before ? 0 : 1;
}
