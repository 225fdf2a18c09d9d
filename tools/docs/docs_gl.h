/*
 * The headless GL the docs' C99 hosts run in (example_main.c, guide_quickstart_main.c): a context
 * (EGL surfaceless, else OSMesa; OpenGL 3.3 core or newer) and the few GL calls a host makes to
 * give the module its textures and read the result back.
 */
#ifndef SSS_DOCS_GL_H
#define SSS_DOCS_GL_H

#include <GL/glcorearb.h>

#include <sss_headless.h>

typedef struct docs_gl {
  sss_headless *headless; /* its loader is sss_headless_get_proc_address, with this as `user` */
  PFNGLGENTEXTURESPROC gen_textures;
  PFNGLBINDTEXTUREPROC bind_texture;
  PFNGLTEXIMAGE2DPROC tex_image_2d;
  PFNGLGETTEXIMAGEPROC get_tex_image;
  PFNGLDELETETEXTURESPROC delete_textures;
} docs_gl;

/* Creates the context, current on this thread, and loads the calls above: 0 on success, else -1
 * (the reason on stderr). */
int docs_gl_open(docs_gl *gl);
/* A 2D texture of one level holding `pixels` (format and type as glTexImage2D's). */
GLuint docs_gl_texture(const docs_gl *gl, GLenum internal_format, int width, int height, GLenum format, GLenum type,
                       const void *pixels);
/* The texture's RGBA as floats into `rgba` (width x height x 4). */
void docs_gl_read_rgba(const docs_gl *gl, GLuint texture, float *rgba);
/* Deletes the context (and with it its textures). */
void docs_gl_close(docs_gl *gl);

#endif /* SSS_DOCS_GL_H */
