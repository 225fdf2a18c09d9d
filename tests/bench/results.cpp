#include "results.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "sweep_summary.hpp"

namespace sss_bench {

namespace {

std::ofstream open_for_writing(const std::string& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  return out;
}

std::string format(double value, const char* spec = "%.6g") {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, spec, value);
  return buffer;
}

// JSON has no NaN or infinity: null stands for "not measured" (NaN), a string for infinity.
nlohmann::json json_number(double v) {
  if (std::isnan(v)) return nullptr;
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return v;
}

std::string series_name(const ResultRow& r) {
  std::string name = r.method;
  if (r.method == "separable" || r.method == "sum-of-gaussians") name += r.follow_surface ? " (follow-surface)" : " (no follow)";
  if (r.method == "separable-no-restore") name = "separable, host restores state";
  return name;
}

}  // namespace

const std::vector<std::string>& csv_columns() {
  static const std::vector<std::string> columns = {
      "scene", "width", "height", "method", "taps", "follow_surface", "passes", "time_ms", "time_min_ms",
      "time_max_ms", "samples", "time_ratio_to_copy", "relative_rmse", "max_abs_error", "p99_abs_error", "ssim",
      "translucent_pixels", "reference_stride", "time_extrapolated", "halo_energy", "footprint_mm", "sweep",
      "relative_rmse_interior", "pixels_interior", "miss_interior", "miss_interior_r", "miss_interior_g",
      "miss_interior_b", "pixels_silhouette", "miss_silhouette", "miss_silhouette_r", "miss_silhouette_g",
      "miss_silhouette_b", "pixels_border", "miss_border", "miss_border_r", "miss_border_g", "miss_border_b",
      "miss_interior_conserving", "miss_interior_conserving_r", "miss_interior_conserving_g",
      "miss_interior_conserving_b"};
  return columns;
}

namespace {

// The region columns of csv_columns() from "pixels_interior" on, in that order, then the
// conserving reference's.
std::string region_fields(const ResultRow& r) {
  std::string text;
  for (const RegionScore& score : r.region) {
    text += ',' + std::to_string(score.pixels) + ',' + format(score.miss);
    for (double v : score.miss_channel) text += ',' + format(v);
  }
  text += ',' + format(r.interior_conserving.miss);
  for (double v : r.interior_conserving.miss_channel) text += ',' + format(v);
  return text;
}

const char* const kRegionKeys[3] = {"interior", "silhouette", "border"};

}  // namespace

std::string miss_text(double miss) {
  if (std::isnan(miss)) return "–";
  if (std::isinf(miss)) return "∞";
  return format(miss, "%.3f");
}

std::string method_label(const ResultRow& row) {
  if (row.method == "exact-2d") {
    return row.time_extrapolated ? "exact-2d (time scaled from a band of " + std::to_string(row.band_rows) + " rows)"
                                 : "exact-2d";
  }
  if (row.method == "copy" || row.method == "copy-compute" || row.method == "no-scattering") return row.method;
  return row.method + " " + std::to_string(row.taps) + " taps" + (row.follow_surface ? ", follow-surface" : "");
}

void write_csv(const std::string& path, const std::vector<ResultRow>& rows) {
  std::ofstream out = open_for_writing(path);
  const auto& columns = csv_columns();
  for (std::size_t i = 0; i < columns.size(); ++i) out << (i ? "," : "") << columns[i];
  out << "\n";
  for (const ResultRow& r : rows) {
    out << r.scene << ',' << r.width << ',' << r.height << ',' << r.method << ',' << r.taps << ','
        << (r.follow_surface ? 1 : 0) << ',' << r.passes << ',' << format(r.time_ms) << ',' << format(r.time_min_ms)
        << ',' << format(r.time_max_ms) << ',' << r.samples << ',' << format(r.time_ratio_to_copy) << ','
        << format(r.relative_rmse) << ',' << format(r.max_abs_error) << ',' << format(r.p99_abs_error) << ','
        << format(r.ssim) << ',' << r.translucent_pixels << ',' << r.reference_stride << ','
        << (r.time_extrapolated ? 1 : 0) << ',' << format(r.halo_energy) << ',' << format(r.footprint_mm) << ','
        << (r.sweep ? 1 : 0) << ',' << format(r.relative_rmse_interior) << region_fields(r) << "\n";
  }
}

void write_miss_csv(const std::string& path, const std::vector<ResultRow>& rows) {
  std::ofstream out = open_for_writing(path);
  out << "scene,width,height,method,taps,follow_surface";
  for (const char* region : kRegionKeys) {
    out << ",miss_" << region << ",miss_" << region << "_r,miss_" << region << "_g,miss_" << region << "_b";
  }
  for (const char* region : kRegionKeys) {
    out << ",share_" << region << "_r,share_" << region << "_g,share_" << region << "_b";
  }
  out << "\n";
  for (const ResultRow& r : rows) {
    if (r.method == "copy" || r.method == "copy-compute" || r.translucent_pixels == 0) continue;
    out << r.scene << ',' << r.width << ',' << r.height << ',' << r.method << ',' << r.taps << ','
        << (r.follow_surface ? 1 : 0);
    for (const RegionScore& score : r.region) {
      out << ',' << format(score.miss);
      for (double v : score.miss_channel) out << ',' << format(v);
    }
    for (const RegionScore& score : r.region) {
      for (double v : score.share_channel) out << ',' << format(v);
    }
    out << "\n";
  }
}

void write_json(const std::string& path, const RunInfo& info, const std::vector<ResultRow>& rows) {
  nlohmann::json j;
  j["run"] = {{"renderer", info.renderer}, {"version", info.version},   {"backend", info.backend},
              {"clock", info.clock},       {"date", info.date},         {"mode", info.mode},
              {"command_line", info.command_line}, {"reference", info.reference},
              {"warmup", info.warmup},     {"repetitions", info.repetitions}};
  if (info.hitch_repeats > 0) {
    j["run"]["first_frame"] = {{"width", info.hitch_width},
                               {"height", info.hitch_height},
                               {"repeats", info.hitch_repeats},
                               {"change", info.hitch_change},
                               {"unprepared_ms", info.first_frame_unprepared_ms},
                               {"prepare_ms", info.prepare_ms},
                               {"prepared_ms", info.first_frame_prepared_ms},
                               {"steady_ms", info.steady_frame_ms},
                               {"steady_queries_per_frame", info.steady_queries_restore},
                               {"steady_queries_per_frame_no_restore", info.steady_queries_no_restore}};
  }
  j["results"] = nlohmann::json::array();
  for (const ResultRow& r : rows) {
    j["results"].push_back({{"scene", r.scene},
                            {"width", r.width},
                            {"height", r.height},
                            {"method", r.method},
                            {"taps", r.taps},
                            {"follow_surface", r.follow_surface},
                            {"passes", r.passes},
                            {"time_ms", r.time_ms},
                            {"time_min_ms", r.time_min_ms},
                            {"time_max_ms", r.time_max_ms},
                            {"samples", r.samples},
                            {"time_ratio_to_copy", r.time_ratio_to_copy},
                            {"relative_rmse", r.relative_rmse},
                            {"max_abs_error", r.max_abs_error},
                            {"p99_abs_error", r.p99_abs_error},
                            {"ssim", r.ssim},
                            {"halo_energy", r.halo_energy},
                            {"translucent_pixels", r.translucent_pixels},
                            {"reference_stride", r.reference_stride},
                            {"time_extrapolated", r.time_extrapolated},
                            {"footprint_mm", r.footprint_mm},
                            {"sweep", r.sweep},
                            {"relative_rmse_interior", json_number(r.relative_rmse_interior)}});
    for (std::size_t k = 0; k < r.region.size(); ++k) {
      const RegionScore& score = r.region[k];
      j["results"].back()[std::string("region_") + kRegionKeys[k]] = {
          {"pixels", score.pixels},
          {"miss", json_number(score.miss)},
          {"miss_rgb", {json_number(score.miss_channel[0]), json_number(score.miss_channel[1]), json_number(score.miss_channel[2])}}};
    }
    const RegionScore& conserving = r.interior_conserving;
    j["results"].back()["interior_conserving"] = {
        {"miss", json_number(conserving.miss)},
        {"miss_rgb", {json_number(conserving.miss_channel[0]), json_number(conserving.miss_channel[1]),
                      json_number(conserving.miss_channel[2])}}};
  }
  open_for_writing(path) << j.dump(2) << "\n";
}

namespace {
// The first frame after a settings change and the queries of a steady frame (hitch_cost.hpp).
void write_first_frame_table(std::ostream& out, const RunInfo& info) {
  if (info.hitch_repeats == 0) return;
  out << "No hitch, no stall (tests/bench/hitch_cost.cpp): " << info.hitch_width << "×" << info.hitch_height
      << ", in place, a settings change from " << info.hitch_change << "; wall clock with glFinish around each call, "
      << "medians of " << info.hitch_repeats << " fresh contexts.\n\n"
      << "| measure | value |\n|---|---:|\n"
      << "| first frame after the change, no `sss_prepare` | " << format(info.first_frame_unprepared_ms, "%.2f")
      << " ms |\n| `sss_prepare` after the change | " << format(info.prepare_ms, "%.2f")
      << " ms |\n| first frame after the change, prepared | " << format(info.first_frame_prepared_ms, "%.2f")
      << " ms |\n| a steady frame of those settings | " << format(info.steady_frame_ms, "%.2f")
      << " ms |\n| GL queries per steady described frame, state restore | "
      << format(info.steady_queries_restore, "%.1f")
      << " |\n| GL queries per steady described frame, `SSS_CREATE_NO_STATE_RESTORE` | "
      << format(info.steady_queries_no_restore, "%.1f") << " |\n\n";
}
}  // namespace

void write_markdown_table(const std::string& path, const RunInfo& info, const std::vector<ResultRow>& rows) {
  std::ofstream out = open_for_writing(path);
  out << "Renderer: `" << info.renderer << "` (" << info.version << ", " << info.backend << "), timing: " << info.clock
      << ", " << info.warmup << " warm-up + " << info.repetitions << " timed frames, medians; reference: "
      << info.reference << ".\n\n";
  write_first_frame_table(out, info);
  out << "| scene | size | mm/px | method | passes | time ms | × copy | miss interior | R | G | B | miss silhouette | "
         "miss border | rel. RMSE interior | rel. RMSE | max abs | p99 abs | SSIM |\n";
  out << "|---|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const ResultRow& r : rows) {
    out << "| " << r.scene << " | " << r.width << "×" << r.height << " | " << format(r.footprint_mm, "%.3g") << " | "
        << method_label(r) << " | " << r.passes << " | " << format(r.time_ms, "%.3f") << " | "
        << format(r.time_ratio_to_copy, "%.2f") << " | " << miss_text(r.interior().miss) << " | "
        << miss_text(r.interior().miss_channel[0]) << " | " << miss_text(r.interior().miss_channel[1]) << " | "
        << miss_text(r.interior().miss_channel[2]) << " | " << miss_text(r.region[1].miss) << " | "
        << miss_text(r.region[2].miss) << " | " << format(r.relative_rmse_interior, "%.4g") << " | "
        << format(r.relative_rmse, "%.4g") << " | " << format(r.max_abs_error, "%.3g") << " | "
        << format(r.p99_abs_error, "%.3g") << " | " << format(r.ssim, "%.4f") << " |\n";
  }
}

namespace {

bool gnuplot_found() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

// Runs the script (pngcairo, or the plain png terminal where cairo is missing); without gnuplot
// (a lent GPU machine has none) the data and script stay for a later `gnuplot FILE.gp` from the
// folder the benchmark ran in, and the PNG they name is listed all the same.
bool draw(const std::string& script_path, bool have_gnuplot) {
  if (!have_gnuplot) return true;
  if (std::system(("gnuplot '" + script_path + "' 2>/dev/null").c_str()) == 0) return true;
  if (std::system(("sed -i 's/pngcairo/png/' '" + script_path + "' && gnuplot '" + script_path + "'").c_str()) == 0) {
    return true;
  }
  std::fprintf(stderr, "sss_bench: gnuplot could not draw %s\n", script_path.c_str());
  return false;
}

}  // namespace

std::vector<std::string> write_pareto_plots(const std::string& directory, const std::vector<ResultRow>& rows,
                                            bool* drawn) {
  std::vector<std::string> written;
  const bool have_gnuplot = gnuplot_found();
  if (drawn != nullptr) *drawn = have_gnuplot;
  std::map<std::string, std::vector<const ResultRow*>> by_scene;
  for (const ResultRow& r : rows) {
    if (r.sweep || r.method == "copy" || r.method == "copy-compute" || r.method == "no-scattering" ||
        r.translucent_pixels == 0) {
      continue;
    }
    by_scene[r.scene + "-" + std::to_string(r.width) + "x" + std::to_string(r.height)].push_back(&r);
  }
  for (const auto& [key, scene_rows] : by_scene) {
    std::map<std::string, std::vector<const ResultRow*>> series;
    for (const ResultRow* r : scene_rows) series[series_name(*r)].push_back(r);
    const std::string data_path = directory + "/pareto-" + key + ".dat";
    const std::string script_path = directory + "/pareto-" + key + ".gp";
    const std::string png_path = directory + "/pareto-" + key + ".png";
    {
      std::ofstream data = open_for_writing(data_path);
      for (const auto& [name, points] : series) {
        data << "# " << name << ": time_ms relative_rmse miss_interior taps\n";
        for (const ResultRow* p : points) {
          const double miss = p->interior().miss;
          data << format(p->time_ms) << ' ' << format(std::max(p->relative_rmse, 1e-7)) << ' '
               << (std::isfinite(miss) ? format(miss) : std::string("NaN")) << ' ' << p->taps << "\n";
        }
        data << "\n\n";
      }
    }
    // Left: relative RMSE; right: the share of the needed change missed on the interior, with the
    // line where a method is as wrong as doing nothing.
    std::ofstream script = open_for_writing(script_path);
    script << "set terminal pngcairo size 1400,720 noenhanced\nset output '" << png_path << "'\n"
           << "set multiplot layout 1,2 title 'error against time: " << key << "'\n"
           << "set key below\nset grid\nset logscale x\nset xlabel 'time per frame (ms)'\n";
    for (int panel = 0; panel < 2; ++panel) {
      if (panel == 0) {
        script << "set logscale y\nset format y '%.0e'\nset ylabel 'relative RMSE vs exact (all translucent pixels)'\n";
      } else {
        script << "unset logscale y\nset format y '%.2f'\nset yrange [0:*]\n"
               << "set ylabel 'miss = |out - exact| / |input - exact| (interior)'\n";
      }
      script << "plot ";
      int index = 0;
      for (const auto& [name, points] : series) {
        script << (index ? ", " : "") << "'" << data_path << "' index " << index << " using 1:" << (panel == 0 ? 2 : 3)
               << " with linespoints title '" << name << "'";
        if (name.rfind("separable", 0) == 0) {
          script << ", '' index " << index << " using 1:" << (panel == 0 ? 2 : 3) << ":4 with labels offset 0,0.8 notitle";
        }
        ++index;
      }
      if (panel == 1) script << ", 1 with lines dashtype 2 lc rgb 'black' title 'no scattering (miss = 1)'";
      script << "\n";
    }
    script << "unset multiplot\n";
    script.close();
    if (draw(script_path, have_gnuplot)) written.push_back(png_path);
  }
  return written;
}

std::vector<std::string> write_footprint_plots(const std::string& directory, const std::vector<ResultRow>& rows) {
  std::vector<std::string> written;
  const std::vector<SweepSeries> series = sweep_series(rows);
  const std::vector<double> footprints = sweep_footprints(rows);
  if (series.empty() || footprints.empty()) return written;
  const bool have_gnuplot = gnuplot_found();
  std::vector<std::string> panels = sweep_scenes(rows);
  panels.insert(panels.begin(), "median");  // the median over the scenes first
  for (const std::string& panel : panels) {
    const std::string stem = directory + "/footprint-" + panel;
    {
      std::ofstream data = open_for_writing(stem + ".dat");
      for (const SweepSeries& s : series) {
        data << "# " << s.label << ": footprint_mm miss_interior\n";
        for (double f : footprints) {
          double miss = std::numeric_limits<double>::quiet_NaN();
          if (panel == "median") {
            miss = median_miss_at(rows, s, f);
          } else if (const ResultRow* r = sweep_row(rows, s, panel, f)) {
            miss = r->interior().miss;
          }
          data << format(f) << ' ' << (std::isfinite(miss) ? format(miss) : std::string("NaN")) << "\n";
        }
        data << "\n\n";
      }
    }
    std::ofstream script = open_for_writing(stem + ".gp");
    script << "set terminal pngcairo size 1200,900 noenhanced\nset output '" << stem << ".png'\n"
           << "set title 'interior miss against pixel footprint: "
           << (panel == "median" ? std::string("median over the sweep scenes") : panel) << "'\n"
           << "set logscale x\nset xrange [" << format(footprints.front() * 0.8) << ":" << format(footprints.back() * 1.25)
           << "]\nset grid\nset key below maxcols 3\nset xlabel 'millimetres per pixel'\n"
           << "set ylabel 'miss (0 = exact, 1 = as wrong as no scattering)'\nset yrange [0:*]\nplot ";
    int curve = 0;
    for (std::size_t k = 0; k < series.size(); ++k) {
      if (series[k].method == "no-scattering") continue;  // the dashed line at 1
      script << (curve ? ", " : "") << "'" << stem << ".dat' index " << k << " using 1:2 with linespoints lw 1.5 pt "
             << 1 + curve % 13 << " dashtype " << 1 + curve / 8 << " title '" << series[k].label << "'";
      ++curve;
    }
    script << ", 1 with lines dashtype 2 lc rgb 'black' lw 2 title 'no scattering'\n";
    script.close();
    if (draw(stem + ".gp", have_gnuplot)) written.push_back(stem + ".png");
  }
  return written;
}

std::vector<std::string> write_band_pareto_plots(const std::string& directory, const std::vector<ResultRow>& rows) {
  std::vector<std::string> written;
  const std::vector<SweepSeries> series = sweep_series(rows);
  if (series.empty()) return written;
  const bool have_gnuplot = gnuplot_found();
  for (const FootprintBand& band : footprint_bands()) {
    // One curve per (method, follow-surface), a point per tap count.
    std::map<std::string, std::vector<std::pair<const SweepSeries*, BandSummary>>> curves;
    for (const SweepSeries& s : series) {
      if (s.method == "no-scattering") continue;
      const BandSummary b = band_summary(rows, s, band);
      if (b.count == 0) continue;
      ResultRow probe;
      probe.method = s.method;
      probe.follow_surface = s.follow_surface;
      curves[series_name(probe)].push_back({&s, b});
    }
    if (curves.empty()) continue;
    const std::string stem = directory + "/pareto-band-" + band.name;
    {
      std::ofstream data = open_for_writing(stem + ".dat");
      for (const auto& [name, points] : curves) {
        data << "# " << name << ": median_time_ratio median_miss_interior taps\n";
        for (const auto& [s, b] : points) data << format(b.median_time_ratio) << ' ' << format(b.median_miss) << ' ' << s->taps << "\n";
        data << "\n\n";
      }
    }
    std::ofstream script = open_for_writing(stem + ".gp");
    script << "set terminal pngcairo size 1000,720 noenhanced\nset output '" << stem << ".png'\n"
           << "set title 'miss against time, " << band.name << " footprints (" << band.what
           << "): medians over the sweep scenes and footprints'\n"
           << "set logscale x\nset grid\nset key below\nset xlabel 'time per frame (x the two-pass copy)'\n"
           << "set ylabel 'miss (interior)'\nset yrange [0:*]\nplot ";
    int index = 0;
    for (const auto& [name, points] : curves) {
      script << (index ? ", " : "") << "'" << stem << ".dat' index " << index << " using 1:2 with linespoints title '"
             << name << "', '' index " << index << " using 1:2:3 with labels offset 0,0.8 notitle";
      ++index;
    }
    script << ", 1 with lines dashtype 2 lc rgb 'black' title 'no scattering'\n";
    script.close();
    if (draw(stem + ".gp", have_gnuplot)) written.push_back(stem + ".png");
  }
  return written;
}

}  // namespace sss_bench
