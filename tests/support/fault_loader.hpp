// Fault injection through the loader: the module takes every GL function from the host's
// get_proc_address, so a test can hand it one that wraps a few functions and makes them fail on
// demand. No hook in the library: what the module sees is what a failing driver would show it.
//
//   sss_create_desc desc = ...; desc.get_proc_address = sss_test::fault_get_proc_address;
//   desc.get_proc_address_user = headless;         // the sss_headless the real functions come from
//   sss_test::faults().break_shader_sources = 1;   // the next shader the module compiles fails
//
// The faults are process-wide (the tests are single-threaded) and consumed as they fire;
// reset_faults() clears them and the counters.
#pragma once

#include <string>

namespace sss_test {

struct Faults {
  // glShaderSource: skip this many calls, then replace the source of the next `break_shader_sources`
  // with text that does not compile (the driver's own compile error, with its log).
  int skip_shader_sources = 0;
  int break_shader_sources = 0;
  // glShaderSource: every source holding this text (when not empty) fails too.
  std::string break_sources_with;
  // glTexImage2D of a `huge_target_format` image without data (RGBA16F: the module's intermediate
  // target for every colour but RGBA32F): ask the driver for GL_MAX_TEXTURE_SIZE squared instead, a
  // real GL_OUT_OF_MEMORY on llvmpipe (it refuses images over 1 GiB without allocating). Where the
  // driver takes it, the image is specified again at the size asked for and GL_OUT_OF_MEMORY is
  // injected instead. The first `huge_target_skip` such images are allocated as asked.
  int huge_intermediate_targets = 0;
  unsigned huge_target_format = 0x8D70;  // GL_RGBA32UI
  int huge_target_skip = 0;
  // glRenderbufferStorage: the call goes through, then GL_OUT_OF_MEMORY is injected (the stencil copy).
  int fail_renderbuffer_storage = 0;

  // glGetTexLevelParameteriv(GL_TEXTURE_2D_MULTISAMPLE, 0, GL_TEXTURE_SAMPLES) while this texture is
  // bound there: report `fake_samples` instead of the driver's count. Stands in for a driver that
  // offers several counts (llvmpipe makes every multisample texture with 4), so the module's
  // mismatched-count and unsupported-count checks can be reached.
  unsigned fake_samples_texture = 0;
  int fake_samples = 0;

  // glDrawArrays: let this many through, then raise `draw_error` (a GL error code, e.g.
  // GL_OUT_OF_MEMORY = 0x0505; 0: none) after the next one has drawn: a driver that fails mid-frame.
  int skip_draws = 0;
  unsigned draw_error = 0;

  // What fired, and what the module called.
  int draws = 0;                        // glDrawArrays and glDispatchCompute calls
  int texture_parameter_queries = 0;    // glGetTexParameteriv calls
  // glBindImageTexture calls that bound this texture (when not 0) to an image unit.
  unsigned watched_image_texture = 0;
  int watched_image_bindings = 0;
  int shader_sources_broken = 0;
  std::string last_broken_source;  // the text the last broken source would have had
  int out_of_memory_from_driver = 0;
  int out_of_memory_injected = 0;
};

Faults& faults();
void reset_faults();

// A get_proc_address for sss_create_desc: `user` is the sss_headless* the real functions come from.
void* fault_get_proc_address(const char* name, void* user);

}  // namespace sss_test
