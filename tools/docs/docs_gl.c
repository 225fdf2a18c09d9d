/* See docs_gl.h. */
#include "docs_gl.h"

#include <stdio.h>
#include <string.h>

/* A GL entry point into a function pointer (ISO C has no cast from void * to a function pointer). */
static int load(sss_headless *h, const char *name, void *function_pointer, size_t size) {
  void *address = sss_headless_get_proc_address(name, h);
  if (address == NULL || size != sizeof address) return -1;
  memcpy(function_pointer, &address, size);
  return 0;
}

int docs_gl_open(docs_gl *gl) {
  static const sss_headless_backend backends[] = {SSS_HEADLESS_EGL_SURFACELESS, SSS_HEADLESS_OSMESA};
  char err[256];
  int i;
  memset(gl, 0, sizeof *gl);
  for (i = 0; i < 2 && gl->headless == NULL; ++i) {
    sss_headless_desc desc = {SSS_HEADLESS_EGL_SURFACELESS, 3, 3, 1, 0};
    desc.backend = backends[i];
    if (sss_headless_create(&desc, &gl->headless, err, sizeof err) != 0) fprintf(stderr, "%s\n", err);
  }
  if (gl->headless == NULL) return -1;
  if (load(gl->headless, "glGenTextures", &gl->gen_textures, sizeof gl->gen_textures) != 0 ||
      load(gl->headless, "glBindTexture", &gl->bind_texture, sizeof gl->bind_texture) != 0 ||
      load(gl->headless, "glTexImage2D", &gl->tex_image_2d, sizeof gl->tex_image_2d) != 0 ||
      load(gl->headless, "glGetTexImage", &gl->get_tex_image, sizeof gl->get_tex_image) != 0 ||
      load(gl->headless, "glDeleteTextures", &gl->delete_textures, sizeof gl->delete_textures) != 0) {
    fprintf(stderr, "docs_gl: the GL lacks a texture call\n");
    docs_gl_close(gl);
    return -1;
  }
  return 0;
}

GLuint docs_gl_texture(const docs_gl *gl, GLenum internal_format, int width, int height, GLenum format, GLenum type,
                       const void *pixels) {
  GLuint texture = 0;
  gl->gen_textures(1, &texture);
  gl->bind_texture(GL_TEXTURE_2D, texture);
  gl->tex_image_2d(GL_TEXTURE_2D, 0, (GLint)internal_format, width, height, 0, format, type, pixels);
  gl->bind_texture(GL_TEXTURE_2D, 0);
  return texture;
}

void docs_gl_read_rgba(const docs_gl *gl, GLuint texture, float *rgba) {
  gl->bind_texture(GL_TEXTURE_2D, texture);
  gl->get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, rgba);
  gl->bind_texture(GL_TEXTURE_2D, 0);
}

void docs_gl_close(docs_gl *gl) {
  sss_headless_destroy(gl->headless);
  gl->headless = NULL;
}
