/*
 * sss_headless: a GL context without a window, for tests, the benchmark and the demo's headless
 * mode. Backends are loaded at run time (dlopen), so a program links none of libOSMesa/libEGL and
 * runs wherever at least one of them is installed.
 *
 *   OSMesa           Mesa's off-screen library (libOSMesa.so.8), core profile 3.3..4.5.
 *   EGL surfaceless  EGL_MESA_platform_surfaceless: no display, no device; Mesa picks llvmpipe
 *                    (or a GPU through its render node).
 *   EGL device       EGL_EXT_platform_device: enumerates devices, prefers a hardware one (an NVIDIA
 *                    card on a headless server), falls back to the software device.
 *   EGL GLES         EGL surfaceless with EGL_OPENGL_ES_API: an OpenGL ES context of version
 *                    desc->major.minor (3.0 for the module's ES path; core_profile is ignored).
 *                    Mesa gives the highest ES version compatible with the request (3.2 on
 *                    llvmpipe for 3.0), as it does for desktop GL.
 *
 * Rendering goes to framebuffer objects; the context has no usable default framebuffer.
 *
 * Notes:
 *  - Mesa returns the highest version compatible with the request (asking for 3.3 core gives
 *    "4.5 (Core Profile)" on llvmpipe).
 *  - desc->debug is honoured by the EGL backends (GL_CONTEXT_FLAG_DEBUG_BIT); OSMesa has no
 *    debug-context attribute and ignores it.
 *  - Several contexts, of any backends, may exist at once in one process; make_current switches
 *    between them (also between OSMesa and EGL). libOSMesa/libEGL stay loaded and EGL displays
 *    stay initialized until the process exits, so repeated creates are cheap.
 *  - Under LeakSanitizer, libOSMesa itself leaks ~160 bytes per context (Mesa 22.3); see
 *    tests/lsan.supp.
 */
#ifndef SSS_HEADLESS_H
#define SSS_HEADLESS_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum sss_headless_backend {
  SSS_HEADLESS_OSMESA = 0,
  SSS_HEADLESS_EGL_SURFACELESS = 1,
  SSS_HEADLESS_EGL_DEVICE = 2,
  SSS_HEADLESS_EGL_GLES = 3
} sss_headless_backend;

typedef struct sss_headless_desc {
  sss_headless_backend backend;
  int major, minor;     /* requested GL version, e.g. 4, 5 (>= 3.2 for core); the ES version for EGL GLES */
  int core_profile;     /* 1: core profile, 0: compatibility */
  int debug;            /* 1: request a debug context */
} sss_headless_desc;

typedef struct sss_headless sss_headless;

/* Creates the context and makes it current on the calling thread. Returns 0 on success; on failure
 * returns -1, sets *out to NULL and writes a reason into err (when err_size > 0). */
int sss_headless_create(const sss_headless_desc *desc, sss_headless **out, char *err, size_t err_size);

/* Makes the context current / releases it on the calling thread. 0 on success. */
int sss_headless_make_current(sss_headless *h);
int sss_headless_release_current(sss_headless *h);

/* GL function loader with the signature sss_create_desc.get_proc_address expects: user is the
 * sss_headless pointer. */
/* 1 when the backend gives OpenGL ES contexts (SSS_HEADLESS_EGL_GLES), else 0. */
int sss_headless_backend_is_gles(sss_headless_backend b);
void *sss_headless_get_proc_address(const char *name, void *user);

/* Destroys the context (releasing it first if current). NULL is a no-op. */
void sss_headless_destroy(sss_headless *h);

/* "osmesa", "egl" (surfaceless), "egl-device", "egl-gles" (surfaceless, OpenGL ES). */
const char *sss_headless_backend_name(sss_headless_backend b);
/* Parses the names above; 0 on success, -1 for an unknown name. */
int sss_headless_backend_from_name(const char *name, sss_headless_backend *out);

/* GL_RENDERER and GL_VERSION of the current context (static strings owned by the GL). */
const char *sss_headless_renderer(sss_headless *h);
const char *sss_headless_version(sss_headless *h);

#ifdef __cplusplus
}
#endif

#endif /* SSS_HEADLESS_H */
