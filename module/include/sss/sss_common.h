/*
 * sss: what every public header shares (C99): export macro, version, status codes, tap-count limits.
 * Included by sss.h (and through it by sss_tools.h and sss_lut.h); not meant to be included alone.
 */
#ifndef SSS_SSS_COMMON_H
#define SSS_SSS_COMMON_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(_WIN32) && defined(SSS_SHARED)
#  ifdef SSS_BUILDING
#    define SSS_API __declspec(dllexport)
#  else
#    define SSS_API __declspec(dllimport)
#  endif
#elif defined(__GNUC__) && defined(SSS_SHARED)
#  define SSS_API __attribute__((visibility("default")))
#else
#  define SSS_API
#endif

/* The version of the headers. sss_get_version() (sss.h) returns the library's, which a host may
 * compare with SSS_VERSION to catch a header and a library from different releases. */
#define SSS_VERSION_MAJOR 0 /**< incompatible API changes (none before 1.0: see docs/migration.md) */
#define SSS_VERSION_MINOR 6 /**< features; before 1.0 also API changes, each with a migration note */
#define SSS_VERSION_PATCH 0 /**< fixes only */
/** Packs a version as sss_get_version() returns it: major in bits 16-31, minor 8-15, patch 0-7. */
#define SSS_MAKE_VERSION(major, minor, patch) \
  (((uint32_t)(major) << 16) | ((uint32_t)(minor) << 8) | (uint32_t)(patch))
/** This header's version, packed as SSS_MAKE_VERSION does. */
#define SSS_VERSION SSS_MAKE_VERSION(SSS_VERSION_MAJOR, SSS_VERSION_MINOR, SSS_VERSION_PATCH)

/** Status codes. Every failing call also leaves a message naming the bad argument and its value,
 *  readable with sss_last_error(). */
typedef enum sss_result {
  SSS_OK = 0,                     /**< success */
  SSS_ERROR_INVALID_ARGUMENT,     /**< a pointer, number or flag outside its documented range */
  SSS_ERROR_UNSUPPORTED,          /**< valid, but not supported (GL version, projection kind) */
  SSS_ERROR_GL_FUNCTION_MISSING,  /**< get_proc_address gave no pointer for a needed function */
  SSS_ERROR_SHADER_COMPILE,       /**< an embedded shader did not compile or link (the driver's log in
                                       the message) */
  SSS_ERROR_FRAMEBUFFER,          /**< a framebuffer the module built is incomplete */
  SSS_ERROR_INVALID_TEXTURE,      /**< not a texture name, wrong target, format or size */
  SSS_ERROR_OUT_OF_MEMORY,        /**< host or GL allocation failed */
  SSS_ERROR_GL,                   /**< the GL raised an error inside the module's work */
  SSS_ERROR_NO_CONTEXT,           /**< no GL context is current on this thread, or the current one does
                                       not hold the module's objects (the one it was created in was lost
                                       or destroyed) */
  SSS_ERROR_INVALID_OPERATION     /**< call order: a frame without a projection before any
                                       sss_set_camera() */
} sss_result;

/* Taps per pass (sss_settings.taps, sss_kernel_desc.taps): any odd count in [SSS_MIN_TAPS,
 * SSS_MAX_TAPS]. */
#define SSS_TAPS_LOW 11    /**< a preset: cheap, for far shots */
#define SSS_TAPS_MEDIUM 17 /**< a preset: the paper's default, and sss_default_settings()' */
#define SSS_TAPS_HIGH 25   /**< a preset: 4K close-ups */
#define SSS_MIN_TAPS 3     /**< the fewest taps per pass */
#define SSS_MAX_TAPS 65    /**< the most taps per pass */

#ifdef __cplusplus
}
#endif

#endif /* SSS_SSS_COMMON_H */
