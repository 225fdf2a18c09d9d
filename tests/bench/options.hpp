// Command line of sss_bench.
#pragma once

#include "sweep_geometry.hpp"

#include <string>
#include <utility>
#include <vector>

namespace sss_bench {

struct Options {
  std::string mode = "quick";                       // "quick" (CI) or "full"
  std::vector<std::pair<int, int>> sizes;           // resolutions
  std::vector<std::vector<std::string>> size_scenes;  // per size: its scenes (empty: --scenes / all)
  std::vector<std::string> scenes;                  // canonical scene names
  std::vector<int> separable_taps;                  // tap counts of the separable filter
  std::vector<int> gaussian_taps;                   // taps per 1D pass of the sum of Gaussians
  std::vector<int> cbf_taps;                        // taps per pass of the cross-bilateral mode
  std::vector<int> family_taps;                     // taps per pass of each kernel family (kernel_family_choices)
  long family_max_pixels = 640 * 360;               // the families run at sizes up to this many pixels
  std::vector<bool> follow_surface = {true, false};
  bool exact_method = true;                         // time the GL exact 2D filter as a method
  int warmup = 2, repetitions = 5;
  long cpu_reference_max_pixels = 160 * 90;         // above: GL exact reference, spot-checked on the CPU
  int cpu_spot_checks = 24;                         // receivers checked against the CPU when on the GL
  int reference_stride = 0;                         // GL reference receivers on a 1-in-s² grid; 0: auto
  std::string out = "bench-out";
  std::string backend = "egl";
  std::string doc;                                  // also write this results document (Markdown)
  bool heat_maps = true;
  double gpu_preload_ms = 2.0;                      // GpuBusy before each timed frame on a GPU; 0: none
  bool msaa = true;                                 // the MSAA study (msaa_study.hpp)
  std::pair<int, int> msaa_size = {65, 49};         // its filtered size (the reference is made at 2x)
  // The footprint sweep (scenes.hpp: footprint_scene_names): each scene at each footprint, a frame
  // of sweep_interior_px plus the profile's reach on every side. Empty footprints: no sweep.
  std::vector<double> footprints;                   // millimetres per pixel (default: sweep_footprints())
  std::vector<std::string> sweep_scenes;            // empty: every sweep scene
  int sweep_interior_px = 64;
  int sweep_repetitions = 0;                        // timed frames of the sweep's rows; 0: `repetitions`
  std::vector<int> sweep_taps;                      // eq. (1) tap counts on the sweep; empty: separable_taps
  std::vector<std::string> methods;                 // --methods: only these method kinds; empty: all
  std::string command_line;
};


// Parses argv (after the mode's defaults); prints usage and exits on --help or bad input.
Options parse_options(int argc, char** argv);

}  // namespace sss_bench
