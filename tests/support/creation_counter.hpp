// Counting GL object creations through the loader: the module takes every GL function from the
// host's get_proc_address, so a loader that wraps the functions that compile, link, create or
// allocate sees each such call the module makes (no hook in the library). Modelled on
// fault_loader.hpp.
//
//   set_counting_base(sss_headless_get_proc_address);   // where the real functions come from
//   desc.get_proc_address = sss_test::counting_get_proc_address;  // user: the sss_headless
//   reset_creations(); sss_apply_frame(...); creations()  // {"glCompileShader": 2, ...}
//
// Counted: glCreateShader, glCompileShader, glCreateProgram, glLinkProgram, glProgramBinary,
// glGen{Textures,Framebuffers,Renderbuffers,Queries,Samplers,VertexArrays,Buffers},
// glTexImage2D, glTexImage2DMultisample, glTexStorage2D, glTexStorage2DMultisample,
// glRenderbufferStorage, glRenderbufferStorageMultisample, glBufferData. Process-wide, like the
// fault loader (the tests are single-threaded); the module's calls only (the test's own GL calls go
// through host_gl, not this loader).
#pragma once

#include <map>
#include <string>

#include "sss/sss.h"

namespace sss_test {

using CreationCounts = std::map<std::string, int>;

// The loader the counting one forwards to (default sss_headless_get_proc_address).
void set_counting_base(sss_get_proc_address_fn base);
// A get_proc_address for sss_create_desc: `user` goes to the base loader (the sss_headless).
void* counting_get_proc_address(const char* name, void* user);

void reset_creations();
const CreationCounts& creations();     // calls since reset_creations(), by GL function name
int total_creations();
int count_of(const std::string& function);
std::string describe(const CreationCounts& counts);  // "glCompileShader 2, glGenTextures 1" or "none"

}  // namespace sss_test
