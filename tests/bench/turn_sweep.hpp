// sss_bench_turns (turn_sweep.cpp): the turn sweep's options and rows, shared by the program and
// its report (turn_sweep_report.cpp: the CSV, the Markdown document and the plot).
#pragma once

#include <string>
#include <vector>

#include "metrics.hpp"

namespace sss_bench::turns {

struct Options {
  std::string backend = "egl";
  std::vector<double> footprints = {0.1, 0.2, 0.5, 1.0};  // mm per pixel where the surface faces the camera
  std::vector<double> turns = {0.0, 30.0, 45.0, 60.0, 75.0};
  std::vector<double> axes = {0.0, 45.0, 90.0};           // the turn axis, degrees from screen x
  std::vector<std::string> projections = {"orthographic", "perspective"};
  std::vector<std::string> scenes = {"plane", "sphere", "cylinder"};
  std::vector<std::string> methods;  // the method names to run (empty: all); no-scattering always
  int max_receivers = 1024;          // the 2D reference's receivers per frame, at most
  std::string out = "bench-out/turns", doc = "docs/benchmarks/turn-sweep.md";
  std::string command_line;
};

// One method on one frame.
struct Row {
  std::string scene;       // "plane", "sphere", "cylinder"
  std::string projection;  // "orthographic", "perspective"
  double turn_deg = 0.0;   // planes only (NaN for the curved scenes)
  double axis_deg = 0.0;
  double footprint_mm = 0.0;
  int width = 0;           // the frame's side (square frames)
  std::string method;      // "no-scattering", "separable" (the default), "sum-of-gaussians", "cross-bilateral", "kernel-*"
  int taps = 0;
  int passes = 0;          // the library's draws for the frame (sss_stats), 0 for no-scattering
  Miss miss;               // interior, on the reference's receivers
  double needed = 0.0;     // the change scattering makes there: ‖input − exact‖ / ‖exact‖ (the frame's, every row)
  std::string reference;   // "closed form" or "2D exact, stride N"
};

// What the program learnt about itself besides the rows.
struct RunInfo {
  std::string renderer, version, date;
  double seconds = 0.0;
  double reach_mm = 0.0;            // the profile's reach (regions.hpp), which frames and regions use
  int spot_checks = 0;              // closed form against the 2D reference on the orthographic planes
  double spot_check_worst = 0.0;    // the largest relative difference there
};

// The method names of the document's tables, in their order, and a reader's label for each.
std::string method_label(const std::string& method);
bool is_family(const std::string& method);  // one of kernel_family_choices()

// results.csv: one line per row.
void write_csv(const std::string& path, const std::vector<Row>& rows);
// turn-sweep.png (and its .dat and .gp) in `directory` through gnuplot: interior miss against the turn,
// the default and the sum of Gaussians at each footprint. Returns the PNG's path; "" when gnuplot is
// missing or failed (the .dat and .gp stay for a later run).
std::string write_plot(const std::string& directory, const Options& options, const std::vector<Row>& rows);
// The Markdown document (options.doc), generated: how it was measured, the summary, a table per method.
void write_document(const Options& options, const RunInfo& info, const std::vector<Row>& rows, const std::string& plot);

}  // namespace sss_bench::turns
