/*
 * sss_headless: a GL context without a window (see sss_headless.h).
 *
 * Implementation notes
 * --------------------
 * - libOSMesa and libEGL are opened with dlopen(RTLD_LOCAL) the first time a backend is used and
 *   stay open for the life of the process (never dlclose'd): the drivers register atexit handlers
 *   and thread-local state that must not outlive their code. Each library is loaded at most once
 *   (pthread_once); a failed load is remembered and reported again by later creates.
 * - On Mesa, libOSMesa and libEGL_mesa share libglapi.so.0, i.e. one per-thread "current GL
 *   context" slot, but each carries its own copy of the Mesa core. Letting one library act on a
 *   context that the other made current (flush it, release it, destroy a context while it is
 *   current) breaks that context: e.g. OSMesaDestroyContext while an EGL context is current
 *   leaves the EGL context unusable (its framebuffer objects read as incomplete, Mesa 22.3).
 *   The helper therefore tracks, per thread, the sss_headless it made
 *   current and releases it before a context of the other family (OSMesa vs EGL) is created, made
 *   current or destroyed; destroying restores the previously current context afterwards.
 * - EGL displays are initialized once and never terminated by the helper (Mesa finalizes them at
 *   exit). eglTerminate is not reference counted by EGL, so terminating would break other live
 *   contexts on the same display; on Mesa it also unloads the driver (swrast_dri.so + libLLVM),
 *   which makes every later create reload it and leaks LLVM's per-load allocations. Keeping the
 *   display makes repeated creates cheap.
 * - OSMesa has no debug-context attribute; desc->debug is ignored there (Mesa still implements
 *   KHR_debug in every context: glEnable(GL_DEBUG_OUTPUT) works).
 */
#if !defined(_POSIX_C_SOURCE) || _POSIX_C_SOURCE < 200809L
#undef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif

#include "sss_headless.h"

#include <dlfcn.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Headers for types and constants only: no prototype is used, nothing is linked. */
#include <GL/osmesa.h>
#define EGL_EGL_PROTOTYPES 0
#ifndef EGL_NO_X11
#define EGL_NO_X11 /* native types as void *: no X11 headers needed */
#endif
#include <EGL/egl.h>
#include <EGL/eglext.h>

#if defined(__STDC_VERSION__) && __STDC_VERSION__ >= 201112L && !defined(__STDC_NO_THREADS__)
#define SSS_THREAD_LOCAL _Thread_local
#else
#define SSS_THREAD_LOCAL __thread
#endif

#if defined(__GNUC__)
#define SSS_PRINTF(fmt, args) __attribute__((format(printf, fmt, args)))
#else
#define SSS_PRINTF(fmt, args)
#endif

/* ---------------------------------------------------------------------------------------------- */
/* Small helpers                                                                                  */

typedef void (*sss_fn)(void);

/* POSIX guarantees that function and object pointers convert; ISO C does not, so copy bytes. */
typedef char sss_fn_ptr_size_check[(sizeof(sss_fn) == sizeof(void *)) ? 1 : -1];

static void *fn_to_ptr(sss_fn f) {
  void *p;
  memcpy(&p, &f, sizeof p);
  return p;
}

/* Looks up sym in handle and stores it into the function pointer at dst (NULL when missing). */
static void load_sym(void *handle, const char *sym, void *dst) {
  void *p = dlsym(handle, sym);
  memcpy(dst, &p, sizeof p);
}

static void set_err(char *err, size_t err_size, const char *fmt, ...) SSS_PRINTF(3, 4);
static void set_err(char *err, size_t err_size, const char *fmt, ...) {
  va_list ap;
  if (!err || err_size == 0) return;
  va_start(ap, fmt);
  vsnprintf(err, err_size, fmt, ap);
  va_end(ap);
}

/* Whole-word search in a space separated extension list. */
static int has_ext(const char *list, const char *name) {
  size_t n = strlen(name);
  const char *p = list;
  if (!list || n == 0) return 0;
  while ((p = strstr(p, name)) != NULL) {
    int starts = (p == list) || (p[-1] == ' ');
    int ends = (p[n] == '\0') || (p[n] == ' ');
    if (starts && ends) return 1;
    p += n;
  }
  return 0;
}

/* ---------------------------------------------------------------------------------------------- */
/* OSMesa loader                                                                                  */

typedef OSMesaContext (*pfn_osmesa_create_attribs)(const int *attribs, OSMesaContext share);
typedef GLboolean (*pfn_osmesa_make_current)(OSMesaContext ctx, void *buffer, GLenum type,
                                             GLsizei width, GLsizei height);
typedef void (*pfn_osmesa_destroy)(OSMesaContext ctx);
typedef sss_fn (*pfn_osmesa_get_proc)(const char *name);

static struct {
  pthread_once_t once;
  void *lib;
  const char *lib_name;
  char error[512];
  pfn_osmesa_create_attribs create_attribs;
  pfn_osmesa_make_current make_current;
  pfn_osmesa_destroy destroy;
  pfn_osmesa_get_proc get_proc;
} g_osmesa = {PTHREAD_ONCE_INIT, NULL, NULL, {0}, NULL, NULL, NULL, NULL};

static void osmesa_load_once(void) {
  static const char *const names[] = {"libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so"};
  size_t i;
  void *lib = NULL;
  for (i = 0; i < sizeof names / sizeof names[0]; ++i) {
    lib = dlopen(names[i], RTLD_NOW | RTLD_LOCAL);
    if (lib) {
      g_osmesa.lib_name = names[i];
      break;
    }
    if (i == 0) {
      const char *e = dlerror();
      snprintf(g_osmesa.error, sizeof g_osmesa.error,
               "OSMesa: dlopen(libOSMesa.so.8 / .so.6 / .so) failed: %s", e ? e : "unknown error");
    }
  }
  if (!lib) return;
  load_sym(lib, "OSMesaCreateContextAttribs", &g_osmesa.create_attribs);
  load_sym(lib, "OSMesaMakeCurrent", &g_osmesa.make_current);
  load_sym(lib, "OSMesaDestroyContext", &g_osmesa.destroy);
  load_sym(lib, "OSMesaGetProcAddress", &g_osmesa.get_proc);
  if (!g_osmesa.create_attribs || !g_osmesa.make_current || !g_osmesa.destroy ||
      !g_osmesa.get_proc) {
    snprintf(g_osmesa.error, sizeof g_osmesa.error,
             "OSMesa: %s lacks OSMesaCreateContextAttribs/OSMesaMakeCurrent/"
             "OSMesaDestroyContext/OSMesaGetProcAddress (Mesa >= 12 needed)",
             g_osmesa.lib_name);
    return; /* keep the handle open anyway: never dlclose */
  }
  g_osmesa.error[0] = '\0';
  g_osmesa.lib = lib;
}

static int osmesa_load(char *err, size_t err_size) {
  pthread_once(&g_osmesa.once, osmesa_load_once);
  if (!g_osmesa.lib) {
    set_err(err, err_size, "%s", g_osmesa.error);
    return -1;
  }
  return 0;
}

/* ---------------------------------------------------------------------------------------------- */
/* EGL loader                                                                                     */

typedef EGLDisplay (*pfn_egl_get_platform_display)(EGLenum platform, void *native,
                                                   const EGLAttrib *attribs);

static struct {
  pthread_once_t once;
  void *lib;
  char error[512];
  PFNEGLGETERRORPROC GetError;
  PFNEGLGETPROCADDRESSPROC GetProcAddress;
  PFNEGLQUERYSTRINGPROC QueryString;
  PFNEGLINITIALIZEPROC Initialize;
  PFNEGLBINDAPIPROC BindAPI;
  PFNEGLCHOOSECONFIGPROC ChooseConfig;
  PFNEGLCREATECONTEXTPROC CreateContext;
  PFNEGLDESTROYCONTEXTPROC DestroyContext;
  PFNEGLMAKECURRENTPROC MakeCurrent;
  PFNEGLGETCURRENTCONTEXTPROC GetCurrentContext;
  /* Optional (EGL 1.5 core / extensions); NULL when not available. */
  pfn_egl_get_platform_display GetPlatformDisplay;
  PFNEGLGETPLATFORMDISPLAYEXTPROC GetPlatformDisplayEXT;
  PFNEGLQUERYDEVICESEXTPROC QueryDevicesEXT;
  PFNEGLQUERYDEVICESTRINGEXTPROC QueryDeviceStringEXT;
  const char *client_exts; /* "" when EGL_EXT_client_extensions is missing */
} g_egl;

static pthread_once_t g_egl_once = PTHREAD_ONCE_INIT;

static void egl_load_once(void) {
  void *lib = dlopen("libEGL.so.1", RTLD_NOW | RTLD_LOCAL);
  if (!lib) {
    const char *e = dlerror();
    snprintf(g_egl.error, sizeof g_egl.error, "EGL: dlopen(libEGL.so.1) failed: %s",
             e ? e : "unknown error");
    return;
  }
  load_sym(lib, "eglGetError", &g_egl.GetError);
  load_sym(lib, "eglGetProcAddress", &g_egl.GetProcAddress);
  load_sym(lib, "eglQueryString", &g_egl.QueryString);
  load_sym(lib, "eglInitialize", &g_egl.Initialize);
  load_sym(lib, "eglBindAPI", &g_egl.BindAPI);
  load_sym(lib, "eglChooseConfig", &g_egl.ChooseConfig);
  load_sym(lib, "eglCreateContext", &g_egl.CreateContext);
  load_sym(lib, "eglDestroyContext", &g_egl.DestroyContext);
  load_sym(lib, "eglMakeCurrent", &g_egl.MakeCurrent);
  load_sym(lib, "eglGetCurrentContext", &g_egl.GetCurrentContext);
  load_sym(lib, "eglGetPlatformDisplay", &g_egl.GetPlatformDisplay);
  if (!g_egl.GetError || !g_egl.GetProcAddress || !g_egl.QueryString || !g_egl.Initialize ||
      !g_egl.BindAPI || !g_egl.ChooseConfig || !g_egl.CreateContext ||
      !g_egl.DestroyContext || !g_egl.MakeCurrent || !g_egl.GetCurrentContext) {
    snprintf(g_egl.error, sizeof g_egl.error,
             "EGL: libEGL.so.1 lacks a core EGL 1.4 entry point (dlsym failed)");
    return;
  }
  {
    sss_fn f;
    f = g_egl.GetProcAddress("eglGetPlatformDisplayEXT");
    memcpy(&g_egl.GetPlatformDisplayEXT, &f, sizeof f);
    f = g_egl.GetProcAddress("eglQueryDevicesEXT");
    memcpy(&g_egl.QueryDevicesEXT, &f, sizeof f);
    f = g_egl.GetProcAddress("eglQueryDeviceStringEXT");
    memcpy(&g_egl.QueryDeviceStringEXT, &f, sizeof f);
  }
  g_egl.client_exts = g_egl.QueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!g_egl.client_exts) {
    (void)g_egl.GetError(); /* EGL_BAD_DISPLAY: no client extensions; clear it */
    g_egl.client_exts = "";
  }
  g_egl.lib = lib;
}

static int egl_load(char *err, size_t err_size) {
  pthread_once(&g_egl_once, egl_load_once);
  if (!g_egl.lib) {
    set_err(err, err_size, "%s", g_egl.error);
    return -1;
  }
  return 0;
}

static const char *egl_error_name(EGLint e) {
  switch (e) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
    case EGL_BAD_DEVICE_EXT: return "EGL_BAD_DEVICE_EXT";
    default: return "unknown EGL error";
  }
}

/* Writes "<what> failed (EGL error 0x3001 EGL_NOT_INITIALIZED)" into err. */
static void set_egl_err(char *err, size_t err_size, const char *what) {
  EGLint e = g_egl.GetError();
  set_err(err, err_size, "EGL: %s failed (EGL error 0x%04X %s)", what, (unsigned)e,
          egl_error_name(e));
}

/* ---------------------------------------------------------------------------------------------- */
/* The context object                                                                             */

struct sss_headless {
  sss_headless_backend backend;
  /* OSMesa */
  OSMesaContext osmesa_ctx;
  unsigned char *osmesa_buffer;
  /* EGL */
  EGLDisplay egl_dpy;
  EGLContext egl_ctx;
  EGLenum egl_api; /* EGL_OPENGL_API or EGL_OPENGL_ES_API */
};

enum { OSMESA_BUFFER_SIZE = 16 };

/* The context this helper made current on this thread (NULL: none). */
static SSS_THREAD_LOCAL sss_headless *t_current = NULL;

static int is_egl(const sss_headless *h) { return h->backend != SSS_HEADLESS_OSMESA; }

/* 0 OSMesa, 1 EGL with desktop GL, 2 EGL with OpenGL ES. EGL keeps one current context per client
 * API, but Mesa's dispatch is one per thread: contexts of different families are never current
 * together. */
static int family(const sss_headless *h) {
  if (!is_egl(h)) return 0;
  return h->egl_api == EGL_OPENGL_ES_API ? 2 : 1;
}

/* The raw make-current / release of one backend, without cross-family bookkeeping. */
static int raw_make_current(sss_headless *h) {
  if (!is_egl(h)) {
    if (!g_osmesa.make_current(h->osmesa_ctx, h->osmesa_buffer, GL_UNSIGNED_BYTE,
                               OSMESA_BUFFER_SIZE, OSMESA_BUFFER_SIZE))
      return -1;
  } else {
    /* eglGetCurrentContext and friends answer for the thread's bound API. */
    if (!g_egl.BindAPI(h->egl_api)) return -1;
    if (!g_egl.MakeCurrent(h->egl_dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, h->egl_ctx)) return -1;
  }
  t_current = h;
  return 0;
}

static int raw_release(sss_headless *h) {
  int rc = 0;
  if (!is_egl(h)) {
    /* Only release what this thread made current: OSMesaMakeCurrent(NULL) releases whatever GL
     * context is current in the shared libglapi, which may belong to another library. */
    if (t_current == h && !g_osmesa.make_current(NULL, NULL, 0, 0, 0)) rc = -1;
  } else if (g_egl.BindAPI(h->egl_api) && g_egl.GetCurrentContext() == h->egl_ctx) {
    if (!g_egl.MakeCurrent(h->egl_dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT)) rc = -1;
  }
  if (t_current == h) t_current = NULL;
  return rc;
}

/* Releases this thread's current context if it belongs to the other family than h; returns it
 * (so that it can be made current again), or NULL. */
static sss_headless *release_other_family(const sss_headless *h) {
  sss_headless *cur = t_current;
  if (cur && cur != h && family(cur) != family(h)) {
    (void)raw_release(cur);
    return cur;
  }
  return NULL;
}

/* ---------------------------------------------------------------------------------------------- */
/* OSMesa backend                                                                                 */

static int create_osmesa(const sss_headless_desc *desc, sss_headless *h, char *err,
                         size_t err_size) {
  int attribs[16];
  int n = 0;
  if (osmesa_load(err, err_size) != 0) return -1;
  attribs[n++] = OSMESA_FORMAT;
  attribs[n++] = OSMESA_RGBA;
  attribs[n++] = OSMESA_DEPTH_BITS;
  attribs[n++] = 24;
  attribs[n++] = OSMESA_STENCIL_BITS;
  attribs[n++] = 8;
  attribs[n++] = OSMESA_ACCUM_BITS;
  attribs[n++] = 0;
  attribs[n++] = OSMESA_PROFILE;
  attribs[n++] = desc->core_profile ? OSMESA_CORE_PROFILE : OSMESA_COMPAT_PROFILE;
  attribs[n++] = OSMESA_CONTEXT_MAJOR_VERSION;
  attribs[n++] = desc->major;
  attribs[n++] = OSMESA_CONTEXT_MINOR_VERSION;
  attribs[n++] = desc->minor;
  attribs[n++] = 0;

  h->osmesa_buffer = (unsigned char *)calloc(OSMESA_BUFFER_SIZE * OSMESA_BUFFER_SIZE, 4);
  if (!h->osmesa_buffer) {
    set_err(err, err_size, "OSMesa: out of memory");
    return -1;
  }
  h->osmesa_ctx = g_osmesa.create_attribs(attribs, NULL);
  if (!h->osmesa_ctx) {
    set_err(err, err_size,
            "OSMesa: OSMesaCreateContextAttribs failed for OpenGL %d.%d %s profile (%s; version "
            "or profile not supported?)",
            desc->major, desc->minor, desc->core_profile ? "core" : "compatibility",
            g_osmesa.lib_name);
    return -1;
  }
  if (raw_make_current(h) != 0) {
    set_err(err, err_size, "OSMesa: OSMesaMakeCurrent failed (%dx%d RGBA8 buffer)",
            OSMESA_BUFFER_SIZE, OSMESA_BUFFER_SIZE);
    return -1;
  }
  return 0;
}

/* ---------------------------------------------------------------------------------------------- */
/* EGL backends                                                                                   */

static EGLDisplay egl_platform_display(EGLenum platform, void *native, char *err,
                                       size_t err_size) {
  EGLDisplay dpy = EGL_NO_DISPLAY;
  const char *what;
  if (g_egl.GetPlatformDisplayEXT && has_ext(g_egl.client_exts, "EGL_EXT_platform_base")) {
    what = "eglGetPlatformDisplayEXT";
    dpy = g_egl.GetPlatformDisplayEXT(platform, native, NULL);
  } else if (g_egl.GetPlatformDisplay) {
    what = "eglGetPlatformDisplay";
    dpy = g_egl.GetPlatformDisplay(platform, native, NULL);
  } else {
    set_err(err, err_size,
            "EGL: neither eglGetPlatformDisplayEXT (EGL_EXT_platform_base) nor "
            "eglGetPlatformDisplay (EGL 1.5) is available");
    return EGL_NO_DISPLAY;
  }
  if (dpy == EGL_NO_DISPLAY) {
    char what_buf[96];
    snprintf(what_buf, sizeof what_buf, "%s(0x%04X)", what, (unsigned)platform);
    set_egl_err(err, err_size, what_buf);
  }
  return dpy;
}

/* Initializes dpy, creates the context and makes it current. On failure everything acquired here
 * is released again. */
/* One eglCreateContext of OpenGL (ES) major.minor with the desc's profile and debug flag. */
static EGLContext egl_context_of_version(const sss_headless_desc *desc, const sss_headless *h,
                                         EGLDisplay dpy, EGLConfig config, int egl15, int major,
                                         int minor) {
  EGLint attribs[16];
  int n = 0;
  attribs[n++] = EGL_CONTEXT_MAJOR_VERSION;
  attribs[n++] = major;
  attribs[n++] = EGL_CONTEXT_MINOR_VERSION;
  attribs[n++] = minor;
  if (h->egl_api == EGL_OPENGL_API && (major > 3 || (major == 3 && minor >= 2))) {
    attribs[n++] = EGL_CONTEXT_OPENGL_PROFILE_MASK;
    attribs[n++] = desc->core_profile ? EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT
                                      : EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT;
  }
  if (desc->debug) {
    if (egl15) {
      attribs[n++] = EGL_CONTEXT_OPENGL_DEBUG;
      attribs[n++] = EGL_TRUE;
    } else {
      attribs[n++] = EGL_CONTEXT_FLAGS_KHR;
      attribs[n++] = EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR;
    }
  }
  attribs[n++] = EGL_NONE;
  return g_egl.CreateContext(dpy, config, EGL_NO_CONTEXT, attribs);
}

static int egl_create_on_display(const sss_headless_desc *desc, EGLDisplay dpy, sss_headless *h,
                                 const char *display_label, char *err, size_t err_size) {
  EGLint major = 0, minor = 0;
  const char *exts;
  EGLConfig config = EGL_NO_CONFIG_KHR;
  int egl15, create_ctx_khr;
  char what[128];

  /* On an initialized display eglInitialize is a cheap no-op that returns the version again. */
  if (!g_egl.Initialize(dpy, &major, &minor)) {
    set_egl_err(err, err_size, "eglInitialize");
    return -1;
  }
  exts = g_egl.QueryString(dpy, EGL_EXTENSIONS);
  if (!exts) exts = "";
  egl15 = major > 1 || (major == 1 && minor >= 5);
  create_ctx_khr = has_ext(exts, "EGL_KHR_create_context");
  if (!egl15 && !create_ctx_khr) {
    set_err(err, err_size,
            "EGL: %s: EGL %d.%d without EGL_KHR_create_context cannot create an OpenGL %d.%d "
            "context",
            display_label, (int)major, (int)minor, desc->major, desc->minor);
    return -1;
  }
  if (!g_egl.BindAPI(h->egl_api)) {
    set_egl_err(err, err_size, h->egl_api == EGL_OPENGL_ES_API ? "eglBindAPI(EGL_OPENGL_ES_API)"
                                                                : "eglBindAPI(EGL_OPENGL_API)");
    return -1;
  }

  if (!has_ext(exts, "EGL_KHR_no_config_context") &&
      !has_ext(exts, "EGL_MESA_configless_context")) {
    const EGLint cfg_attribs[] = {EGL_RENDERABLE_TYPE,
                                  h->egl_api == EGL_OPENGL_ES_API ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_BIT,
                                  EGL_SURFACE_TYPE, 0, EGL_NONE};
    EGLint num = 0;
    if (!g_egl.ChooseConfig(dpy, cfg_attribs, &config, 1, &num)) {
      set_egl_err(err, err_size, "eglChooseConfig");
      return -1;
    }
    if (num < 1) {
      set_err(err, err_size, "EGL: %s: eglChooseConfig found no config with EGL_OPENGL_BIT",
              display_label);
      return -1;
    }
  }

  /* A desktop core profile gets the newest version at or above the request: Mesa does that by
   * itself, NVIDIA's driver gives exactly what is asked (3.3 for 3.3, and with it no compute
   * shaders), so the same request means the same features on both. A newer version refused is
   * not the caller's error: its EGL error is dropped and the request itself comes last. */
  if (h->egl_api == EGL_OPENGL_API && desc->core_profile) {
    static const int newer[][2] = {{4, 6}, {4, 5}, {4, 4}, {4, 3}, {4, 2}, {4, 1}, {4, 0}, {3, 3}};
    size_t v;
    for (v = 0; v < sizeof newer / sizeof newer[0] && h->egl_ctx == EGL_NO_CONTEXT; ++v) {
      if (newer[v][0] < desc->major || (newer[v][0] == desc->major && newer[v][1] <= desc->minor)) continue;
      h->egl_ctx = egl_context_of_version(desc, h, dpy, config, egl15, newer[v][0], newer[v][1]);
      if (h->egl_ctx == EGL_NO_CONTEXT) (void)g_egl.GetError();
    }
  }
  if (h->egl_ctx == EGL_NO_CONTEXT) {
    h->egl_ctx = egl_context_of_version(desc, h, dpy, config, egl15, desc->major, desc->minor);
  }
  if (h->egl_ctx == EGL_NO_CONTEXT) {
    snprintf(what, sizeof what, "%s: eglCreateContext(OpenGL %s%d.%d %s%s)", display_label,
             h->egl_api == EGL_OPENGL_ES_API ? "ES " : "", desc->major, desc->minor,
             h->egl_api == EGL_OPENGL_ES_API ? "" : desc->core_profile ? "core" : "compatibility",
             desc->debug ? " debug" : "");
    set_egl_err(err, err_size, what);
    return -1;
  }
  h->egl_dpy = dpy;
  if (raw_make_current(h) != 0) {
    snprintf(what, sizeof what, "%s: eglMakeCurrent(EGL_NO_SURFACE)%s", display_label,
             has_ext(exts, "EGL_KHR_surfaceless_context") ? ""
                                                          : " [no EGL_KHR_surfaceless_context]");
    set_egl_err(err, err_size, what);
    g_egl.DestroyContext(dpy, h->egl_ctx);
    h->egl_ctx = EGL_NO_CONTEXT;
    h->egl_dpy = EGL_NO_DISPLAY;
    return -1;
  }
  return 0;
}

static int create_egl_surfaceless(const sss_headless_desc *desc, sss_headless *h, char *err,
                                  size_t err_size) {
  EGLDisplay dpy;
  if (egl_load(err, err_size) != 0) return -1;
  if (!has_ext(g_egl.client_exts, "EGL_MESA_platform_surfaceless")) {
    set_err(err, err_size,
            "EGL: client extension EGL_MESA_platform_surfaceless is not supported (is Mesa's "
            "libEGL_mesa installed?)");
    return -1;
  }
  dpy = egl_platform_display(EGL_PLATFORM_SURFACELESS_MESA, NULL, err, err_size);
  if (dpy == EGL_NO_DISPLAY) return -1;
  return egl_create_on_display(desc, dpy, h, "surfaceless display", err, err_size);
}

static int create_egl_device(const sss_headless_desc *desc, sss_headless *h, char *err,
                             size_t err_size) {
  EGLint count = 0, i, pass;
  EGLDeviceEXT *devices;
  int tried = 0, rc = -1;
  char first_err[512];

  if (egl_load(err, err_size) != 0) return -1;
  if (!g_egl.QueryDevicesEXT || !g_egl.QueryDeviceStringEXT ||
      !(has_ext(g_egl.client_exts, "EGL_EXT_device_enumeration") ||
        has_ext(g_egl.client_exts, "EGL_EXT_device_base")) ||
      !has_ext(g_egl.client_exts, "EGL_EXT_platform_device")) {
    set_err(err, err_size,
            "EGL: client extensions EGL_EXT_device_enumeration/EGL_EXT_device_query and "
            "EGL_EXT_platform_device are not all supported");
    return -1;
  }
  if (!g_egl.QueryDevicesEXT(0, NULL, &count)) {
    set_egl_err(err, err_size, "eglQueryDevicesEXT");
    return -1;
  }
  if (count <= 0) {
    set_err(err, err_size, "EGL: eglQueryDevicesEXT reports no devices");
    return -1;
  }
  devices = (EGLDeviceEXT *)calloc((size_t)count, sizeof *devices);
  if (!devices) {
    set_err(err, err_size, "EGL: out of memory");
    return -1;
  }
  if (!g_egl.QueryDevicesEXT(count, devices, &count)) {
    set_egl_err(err, err_size, "eglQueryDevicesEXT");
    free(devices);
    return -1;
  }

  /* Pass 0: hardware devices (those not listing EGL_MESA_device_software), in enumeration
   * order; pass 1: software devices. The first device that yields a context wins. */
  first_err[0] = '\0';
  for (pass = 0; pass < 2 && rc != 0; ++pass) {
    for (i = 0; i < count && rc != 0; ++i) {
      const char *dev_exts = g_egl.QueryDeviceStringEXT(devices[i], EGL_EXTENSIONS);
      int software = has_ext(dev_exts, "EGL_MESA_device_software");
      EGLDisplay dpy;
      char label[64];
      char *e = tried == 0 ? first_err : NULL;
      size_t e_size = tried == 0 ? sizeof first_err : 0;
      if (!dev_exts) (void)g_egl.GetError();
      if (software != pass) continue;
      ++tried;
      snprintf(label, sizeof label, "device %d (%s)", (int)i, software ? "software" : "hardware");
      dpy = egl_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], e, e_size);
      if (dpy == EGL_NO_DISPLAY) continue;
      rc = egl_create_on_display(desc, dpy, h, label, e, e_size);
    }
  }
  free(devices);
  if (rc != 0) {
    if (tried > 1)
      set_err(err, err_size, "%s (first of %d devices tried, all failed)", first_err, tried);
    else
      set_err(err, err_size, "%s", first_err);
  }
  return rc;
}

/* ---------------------------------------------------------------------------------------------- */
/* Public API                                                                                     */

int sss_headless_create(const sss_headless_desc *desc, sss_headless **out, char *err,
                        size_t err_size) {
  sss_headless *h, *prev;
  int rc;
  if (err && err_size > 0) err[0] = '\0';
  if (out) *out = NULL;
  if (!desc || !out) {
    set_err(err, err_size, "sss_headless_create: desc and out must not be NULL");
    return -1;
  }
  if (desc->backend != SSS_HEADLESS_OSMESA && desc->backend != SSS_HEADLESS_EGL_SURFACELESS &&
      desc->backend != SSS_HEADLESS_EGL_DEVICE && desc->backend != SSS_HEADLESS_EGL_GLES) {
    set_err(err, err_size, "sss_headless_create: unknown backend %d", (int)desc->backend);
    return -1;
  }
  if (desc->major < 1 || desc->minor < 0 ||
      (desc->backend != SSS_HEADLESS_EGL_GLES && desc->core_profile &&
       (desc->major < 3 || (desc->major == 3 && desc->minor < 2)))) {
    set_err(err, err_size,
            "sss_headless_create: invalid GL version %d.%d for a %s profile (core needs >= 3.2)",
            desc->major, desc->minor, desc->core_profile ? "core" : "compatibility");
    return -1;
  }
  h = (sss_headless *)calloc(1, sizeof *h);
  if (!h) {
    set_err(err, err_size, "sss_headless_create: out of memory");
    return -1;
  }
  h->backend = desc->backend;
  h->egl_dpy = EGL_NO_DISPLAY;
  h->egl_ctx = EGL_NO_CONTEXT;
  h->egl_api = desc->backend == SSS_HEADLESS_EGL_GLES ? EGL_OPENGL_ES_API : EGL_OPENGL_API;

  /* The new context becomes current: release one of the other family first (see the notes);
   * it is made current again if the create fails. */
  prev = release_other_family(h);

  switch (desc->backend) {
    case SSS_HEADLESS_OSMESA: rc = create_osmesa(desc, h, err, err_size); break;
    case SSS_HEADLESS_EGL_SURFACELESS:
    case SSS_HEADLESS_EGL_GLES: rc = create_egl_surfaceless(desc, h, err, err_size); break;
    default: rc = create_egl_device(desc, h, err, err_size); break;
  }
  if (rc != 0) {
    if (h->osmesa_ctx) g_osmesa.destroy(h->osmesa_ctx);
    free(h->osmesa_buffer);
    free(h);
    if (prev) (void)raw_make_current(prev);
    return -1;
  }
  *out = h;
  return 0;
}

int sss_headless_make_current(sss_headless *h) {
  if (!h) return -1;
  (void)release_other_family(h);
  return raw_make_current(h);
}

int sss_headless_release_current(sss_headless *h) {
  if (!h) return -1;
  return raw_release(h);
}

void *sss_headless_get_proc_address(const char *name, void *user) {
  const sss_headless *h = (const sss_headless *)user;
  if (!h || !name) return NULL;
  if (!is_egl(h)) return fn_to_ptr(g_osmesa.get_proc(name));
  return fn_to_ptr(g_egl.GetProcAddress(name));
}

void sss_headless_destroy(sss_headless *h) {
  sss_headless *restore = NULL;
  if (!h) return;
  if (t_current != h) restore = release_other_family(h);
  (void)raw_release(h);
  if (!is_egl(h)) {
    g_osmesa.destroy(h->osmesa_ctx);
    free(h->osmesa_buffer);
  } else {
    g_egl.DestroyContext(h->egl_dpy, h->egl_ctx);
  }
  free(h);
  if (restore) (void)raw_make_current(restore);
}

const char *sss_headless_backend_name(sss_headless_backend b) {
  switch (b) {
    case SSS_HEADLESS_OSMESA: return "osmesa";
    case SSS_HEADLESS_EGL_SURFACELESS: return "egl";
    case SSS_HEADLESS_EGL_DEVICE: return "egl-device";
    case SSS_HEADLESS_EGL_GLES: return "egl-gles";
  }
  return "unknown";
}

int sss_headless_backend_from_name(const char *name, sss_headless_backend *out) {
  sss_headless_backend b;
  if (!name || !out) return -1;
  if (strcmp(name, "osmesa") == 0)
    b = SSS_HEADLESS_OSMESA;
  else if (strcmp(name, "egl") == 0)
    b = SSS_HEADLESS_EGL_SURFACELESS;
  else if (strcmp(name, "egl-device") == 0)
    b = SSS_HEADLESS_EGL_DEVICE;
  else if (strcmp(name, "egl-gles") == 0)
    b = SSS_HEADLESS_EGL_GLES;
  else
    return -1;
  *out = b;
  return 0;
}

typedef const GLubyte *(*pfn_gl_get_string)(GLenum name);

static const char *get_string(sss_headless *h, GLenum name) {
  pfn_gl_get_string get;
  void *p = sss_headless_get_proc_address("glGetString", h);
  if (!p) return NULL;
  memcpy(&get, &p, sizeof p);
  return (const char *)get(name);
}

int sss_headless_backend_is_gles(sss_headless_backend b) { return b == SSS_HEADLESS_EGL_GLES; }

const char *sss_headless_renderer(sss_headless *h) { return get_string(h, GL_RENDERER); }

const char *sss_headless_version(sss_headless *h) { return get_string(h, GL_VERSION); }
