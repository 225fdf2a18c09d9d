// The benchmark's results: one row per (scene, resolution, method configuration), written as CSV,
// JSON, a Markdown table and Pareto plots (error against time, one curve per method) through
// gnuplot when it is installed.
#pragma once

#include <string>
#include <vector>

namespace sss_bench {

struct RunInfo {
  std::string renderer, version, backend, clock, date, mode, command_line, reference;
  int warmup = 0, repetitions = 0;
  // The GL state save and restore per sss_apply_frame call (state_cost.hpp); 0: not measured.
  double state_with_restore_us = 0.0, state_without_restore_us = 0.0;
  int state_calls = 0, state_batches = 0;
  // The GPU spin before each timed frame (gpu_busy.hpp), as calibrated; 0: none.
  double gpu_preload_ms = 0.0;
};

struct ResultRow {
  std::string scene;
  int width = 0, height = 0;
  std::string method;
  int taps = 0;
  bool follow_surface = false;
  int passes = 0;
  double time_ms = 0.0, time_min_ms = 0.0, time_max_ms = 0.0;
  int samples = 0;
  double time_ratio_to_copy = 0.0;  // time_ms / the two-pass copy's median, same scene and size
  double relative_rmse = 0.0, max_abs_error = 0.0, p99_abs_error = 0.0, ssim = 1.0;
  int translucent_pixels = 0;
  int reference_stride = 1;         // errors over every pixel (1) or a 1-in-stride² grid of them
  bool time_extrapolated = false;   // exact-2d: timed on `band_rows` full-resolution rows, scaled by pixel count
  int band_rows = 0;
  // Light leaked across silhouettes: over the translucent pixels within kHaloBand pixels of a
  // non-translucent one, Σ max(0, result − max(reference, input)) / Σ reference (RGB summed): light
  // above both the exact result and the pixel's own input. The exact reference loses light past a
  // silhouette (its kernel is cut by the edge) where a normalised filter keeps the input, so
  // `result − reference` alone would count that as a halo. 0: none, or no such pixels.
  double halo_energy = 0.0;
};

constexpr int kHaloBand = 4;

// The CSV header, in column order (the output test checks these).
const std::vector<std::string>& csv_columns();

void write_csv(const std::string& path, const std::vector<ResultRow>& rows);
void write_json(const std::string& path, const RunInfo& info, const std::vector<ResultRow>& rows);
void write_markdown_table(const std::string& path, const RunInfo& info, const std::vector<ResultRow>& rows);
// One PNG per (scene, resolution) with translucent pixels: relative RMSE against time, a curve per
// method (and per follow-surface setting), drawn by gnuplot. Returns the PNG files; `*drawn` says
// whether gnuplot drew them (when it is missing, their .dat and .gp files are left for a later
// `gnuplot FILE.gp` run from the same working folder).
std::vector<std::string> write_pareto_plots(const std::string& directory, const std::vector<ResultRow>& rows,
                                            bool* drawn = nullptr);

std::string method_label(const ResultRow& row);  // "separable 17 taps, follow-surface"

}  // namespace sss_bench
