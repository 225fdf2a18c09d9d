// --dump: the frame's linear data for the demo's tests, beside the PNGs (which are tone-mapped and
// 8-bit): PRESET-before.pfm and PRESET-after.pfm (the diffuse before and after the library, RGB
// float, Portable Float Map: rows bottom-up, little-endian) and PRESET-ids.pgm (the G-buffer's
// profile/object byte, binary PGM, rows top-down).
#pragma once

#include "frame_targets.hpp"

#include <string>

namespace demo {

// `prefix`: the path up to and including "PRESET-". `sss_ran` false: "after" is the diffuse too.
// Prints the reason and returns false when a file cannot be written.
bool write_frame_dumps(const FrameTargets &targets, bool sss_ran, const std::string &prefix);

}  // namespace demo
