// What the runtime library exports for the tools library alone (the version script exports sss_*;
// no public header declares these). In a shared build each library has its own copy of the math
// layer and of the error helpers (errors.cpp); these entry points reach the runtime's state from
// the tools: the fitters registry (fitters.hpp; sss_tools_init) and the thread's last error
// (sss_last_error(NULL)). In a static build there is one copy, and they set the same state.
#pragma once

#include "sss/sss_common.h"

#ifdef __cplusplus
extern "C" {
#endif
/** `fitters`: a `const sss::math::Fitters*` that lives as long as the process (never NULL). */
SSS_API void sss_internal_register_fitters(const void *fitters);
/** The message sss_last_error(NULL) returns on this thread from now on. */
SSS_API void sss_internal_set_thread_error(const char *message);
#ifdef __cplusplus
}
#endif
