// sss_bench_texturing (texturing_bench.cpp, texturing_head.cpp, texturing_report.cpp): what the
// planes' rows, the head's rows and the report share.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "gpu_scene.hpp"
#include "metrics.hpp"
#include "sss/sss.h"

namespace sss_bench::texturing {

struct Options {
  std::string backend = "egl";
  std::vector<double> footprints = {0.05, 0.1, 0.2, 0.5, 1.0};  // mm per pixel where the plane faces the camera
  // The planes' turns (degrees, about screen x: the light and the albedo foreshortened along y).
  std::vector<double> turns = {0.0, 60.0, 75.0};
  std::pair<int, int> head_size = {960, 540};  // the head close-up's frame; 0x0: no head rows
  std::string out = "bench-out/texturing", doc = "docs/benchmarks/texturing.md";
  std::string command_line;
};

struct MethodChoice {
  std::string name;    // "separable" (the default), "sum-of-gaussians" or a control's (below)
  bool sum_of_gaussians = false;
  int taps = 17;       // sss_settings.taps
  float jitter = 0.0f; // sss_settings.jitter
};
// The default and the sum of Gaussians (rank 6), at 17 taps: the methods, on every scene.
std::vector<MethodChoice> method_choices();
// The sum of Gaussians' controls, on the planes only, which say whether its misses over the bound
// at 17 taps come from its taps (how sparsely they sample a pixel-scale albedo) rather than from
// the texturing modes: at 33 taps ("sum-of-gaussians-33"), and at 17 with the outer half of its
// taps jittered per pixel ("sum-of-gaussians-jitter-0.5": the settings' remedy for undersampling,
// which trades the taps' coherent error for noise).
std::vector<MethodChoice> sum_of_gaussians_controls();
inline constexpr const char* kDenserControl = "sum-of-gaussians-33";
inline constexpr const char* kJitteredControl = "sum-of-gaussians-jitter-0.5";

inline constexpr unsigned kModes[3] = {SSS_TEXTURING_PRE_SCATTER, SSS_TEXTURING_POST_SCATTER,
                                       SSS_TEXTURING_PRE_AND_POST_SCATTER};
const char* mode_name(unsigned mode);

struct Row {
  std::string scene;          // "plane" or "head-close"
  double footprint_mm = 0.0;  // the plane's facing footprint; the head's median over its interior
  double turn_deg = 0.0;      // the plane's turn (0 for the head)
  std::string light, albedo, method, mode;
  Miss miss;                  // against the mode's own answer
  double untextured = 0.0;    // the same method's pooled miss on the light alone (pre-scatter)
  double detail = 0.0;        // the output's power above 1 cycle/mm over the input's (NaN: none to measure)
  double detail_exact = 0.0;  // the mode's exact answer's
  double needed = 0.0;        // ‖input − answer‖ / ‖answer‖ on the interior: the change the mode asks for
};

// The library on `colour` (RGBA, uploaded as RGBA16F) with `albedo` (RGBA16F) in `mode` on the
// fragment path with the default settings, into an RGBA32F output, read back. Throws
// std::runtime_error with the library's message when it refuses the frame.
std::vector<float> run_library(sss_context* ctx, const GpuScene& gpu, const MethodChoice& m, unsigned mode,
                               const std::vector<float>& colour, const std::vector<float>& albedo);

// The head close-up (Scene::albedo, its scan's albedo map) at o.head_size, each method in each mode
// against that mode's answer over the visible surface (reference.hpp), on the interior apart from
// silhouettes and depth edges, beside the untextured miss; appends its rows.
void run_head(sss_context* ctx, const Options& o, double reach_mm, std::vector<Row>* rows);

// Every row as CSV (texturing_report.cpp).
void write_csv(const std::string& path, const std::vector<Row>& rows);
// The Markdown document at o.doc: how the rows were made (the renderer, the command line), the
// issue's bounds per plane frame and what the run measured where one is not met, then every row.
void write_document(const Options& o, const std::string& renderer, const std::vector<Row>& rows);

}  // namespace sss_bench::texturing
