// The benchmark's results: one row per (scene, resolution, method configuration), written as CSV,
// JSON, a Markdown table and Pareto plots (error against time, one curve per method) through
// gnuplot when it is installed.
#pragma once

#include <array>
#include <limits>
#include <string>
#include <vector>

namespace sss_bench {

struct RunInfo {
  std::string renderer, version, backend, clock, date, mode, command_line, reference;
  int warmup = 0, repetitions = 0;
  // The GL state save and restore per sss_apply_frame call (state_cost.hpp); 0: not measured.
  double state_with_restore_us = 0.0, state_without_restore_us = 0.0;
  int state_calls = 0, state_batches = 0;
  // No hitch, no stall (hitch_cost.hpp): the first frame after a settings change with and without
  // sss_prepare, and GL queries per steady described frame; hitch_repeats 0: not measured.
  int hitch_width = 0, hitch_height = 0, hitch_repeats = 0;
  double first_frame_unprepared_ms = 0.0, first_frame_prepared_ms = 0.0, prepare_ms = 0.0, steady_frame_ms = 0.0;
  double steady_queries_restore = 0.0, steady_queries_no_restore = 0.0;
  std::string hitch_change;
  // The GPU spin before each timed frame (gpu_busy.hpp), as calibrated; 0: none.
  double gpu_preload_ms = 0.0;
  // The profile's reach (regions.hpp: profile_reach_mm), which the regions are measured with.
  double reach_mm = 0.0;
};

// metrics.hpp's miss over one region of regions.hpp: pooled and per channel (R, G, B), NaN where
// the region holds no pixel.
struct RegionScore {
  double miss = std::numeric_limits<double>::quiet_NaN();
  std::array<double, 3> miss_channel{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN(),
                                     std::numeric_limits<double>::quiet_NaN()};
  std::array<double, 3> share_channel{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN(),
                                      std::numeric_limits<double>::quiet_NaN()};  // Miss::share
  int pixels = 0;
};

struct ResultRow {
  std::string scene;
  int width = 0, height = 0;
  // Millimetres per pixel: the footprint sweep's (its planes face the camera), or the median over
  // the translucent pixels of their footprint on a plane facing the camera at their depth; 0 when
  // nothing is translucent.
  double footprint_mm = 0.0;
  bool sweep = false;  // one of the footprint sweep's plane-* scenes
  std::string method;
  int taps = 0;
  bool follow_surface = false;
  int passes = 0;
  double time_ms = 0.0, time_min_ms = 0.0, time_max_ms = 0.0;
  int samples = 0;
  double time_ratio_to_copy = 0.0;  // time_ms / the two-pass copy's median, timed right before it
  std::string path_ran;             // how the library ran the last frame (Method::path_ran), for the document only
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
  // miss in each region of regions.hpp (interior, silhouette, border), and relative RMSE over the
  // interior alone (relative_rmse above is over every translucent pixel).
  std::array<RegionScore, 3> region;
  double relative_rmse_interior = std::numeric_limits<double>::quiet_NaN();
  // The head scenes (head-close, -mid, -far, -grazing): the interior miss once more, against the
  // energy-conserving reference, the exact one divided per channel and receiver by the mass the
  // same convolution gives a uniform irradiance of 1 (reference.hpp: make_mass_reference), which
  // takes out the light the faceted surface loses and no normalised filter can. NaN elsewhere.
  RegionScore interior_conserving;
  const RegionScore& interior() const { return region[0]; }
};

constexpr int kHaloBand = 4;

// The CSV header, in column order (the output test checks these).
const std::vector<std::string>& csv_columns();

void write_csv(const std::string& path, const std::vector<ResultRow>& rows);
void write_json(const std::string& path, const RunInfo& info, const std::vector<ResultRow>& rows);
void write_markdown_table(const std::string& path, const RunInfo& info, const std::vector<ResultRow>& rows);
// One PNG per (scene, resolution) with translucent pixels, outside the footprint sweep: relative
// RMSE and interior miss against time, a curve per method (and per follow-surface setting), drawn
// by gnuplot. Returns the PNG files; `*drawn` says
// whether gnuplot drew them (when it is missing, their .dat and .gp files are left for a later
// `gnuplot FILE.gp` run from the same working folder).
std::vector<std::string> write_pareto_plots(const std::string& directory, const std::vector<ResultRow>& rows,
                                            bool* drawn = nullptr);

// The footprint sweep: interior miss against millimetres per pixel, one curve per method
// configuration, one PNG per sweep scene and one of their median ("footprint-SCENE.png").
std::vector<std::string> write_footprint_plots(const std::string& directory, const std::vector<ResultRow>& rows);
// Per footprint band (sweep_summary.hpp): median interior miss against median time (× copy), a
// curve per method with a point per tap count ("pareto-band-NAME.png").
std::vector<std::string> write_band_pareto_plots(const std::string& directory, const std::vector<ResultRow>& rows);

std::string method_label(const ResultRow& row);  // "separable 17 taps, follow-surface"
// A miss value for a table: "0.123", "–" for NaN (nothing measured), "∞" for infinity.
std::string miss_text(double miss);
// The rows' results for the regression guard (miss.csv): the key columns and every miss value.
void write_miss_csv(const std::string& path, const std::vector<ResultRow>& rows);

}  // namespace sss_bench
