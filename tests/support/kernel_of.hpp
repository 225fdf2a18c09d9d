// Tests and benchmark: a settings' kernel desc to change in place. sss_settings.kernel is a pointer
// (sss.h); the suites build settings by value and copy them around, so each call gives the
// settings a fresh copy of the desc it points at (the default desc when NULL), kept for the life of
// the process: a copy of the settings made before keeps its own desc.
#pragma once

#include <deque>

#include "sss/sss_tools.h"

namespace sss_test {

inline sss_kernel_desc& kernel_of(sss_settings& s) {
  static std::deque<sss_kernel_desc> kept;  // a deque: earlier elements never move
  sss_kernel_desc d;
  if (s.kernel != nullptr) {
    d = *s.kernel;
  } else {
    sss_default_kernel_desc(&d);
  }
  kept.push_back(d);
  s.kernel = &kept.back();
  return kept.back();
}

}  // namespace sss_test
