// Counting GL calls through the loader: the module takes every GL function from the host's
// get_proc_address, so a test can hand it one that wraps the functions and counts their calls.
// What it counts is what a threaded driver (Mesa glthread, NVIDIA's threaded optimisation) cares
// about: queries, each a round trip that waits for the driver thread to catch up, and object
// creation, which should happen once and not every frame.
//
//   sss_create_desc desc = ...;
//   desc.get_proc_address = sss_test::counting_loader(sss_headless_get_proc_address);
//   desc.get_proc_address_user = headless;   // passed on to the base loader
//   sss_test::reset_call_counts();
//   sss_apply_frame(ctx, &frame);
//   EXPECT_EQ(sss_test::call_counts().total_queries(), 0) << sss_test::call_counts().describe_queries();
//
// Every function of the module's loader list (module/src/gl/gl_functions.hpp: the X-macro lists,
// so a function added there is counted without touching this file) whose name makes it a query or
// a creation is wrapped; any other name passes through unwrapped. Only the module's calls are
// counted: the test's own GL (host_gl) does not go through this loader. The counts are
// process-wide (the tests are single-threaded).
#pragma once

#include <map>
#include <string>

#include "sss/sss.h"

namespace sss_test {

struct GlCallCounts {
  // Calls by function name ("glGetIntegerv"): only names that were called at least once.
  std::map<std::string, long> queries;    // glGet*, glIs*, glCheckFramebufferStatus
  std::map<std::string, long> creations;  // glGen*, glCreate*, glCompileShader, glLinkProgram,
                                          // glTexImage*, glTexStorage*, glRenderbufferStorage*
  long total_queries() const;
  long total_creations() const;
  // "glGetIntegerv 12, glIsEnabled 3" (or "none"), names in alphabetical order.
  std::string describe_queries() const;
  std::string describe_creations() const;
};

// The calls counted since the last reset_call_counts().
GlCallCounts call_counts();
void reset_call_counts();

// Whether a GL function name ("glGetError") counts as a query, or as a creation.
bool is_query_function(const std::string& name);
bool is_creation_function(const std::string& name);

// Returns a get_proc_address for sss_create_desc that takes the real functions from `base`
// (called with the same `user`) and counts the calls. One base per process at a time: the last
// call sets it (the tests are single-threaded).
sss_get_proc_address_fn counting_loader(sss_get_proc_address_fn base);

}  // namespace sss_test
