#include "results.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>

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
      "translucent_pixels", "reference_stride", "time_extrapolated", "halo_energy"};
  return columns;
}

std::string method_label(const ResultRow& row) {
  if (row.method == "exact-2d") {
    return row.time_extrapolated ? "exact-2d (time scaled from a band of " + std::to_string(row.band_rows) + " rows)"
                                 : "exact-2d";
  }
  if (row.method == "copy" || row.method == "copy-compute") return row.method;
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
        << (r.time_extrapolated ? 1 : 0) << ',' << format(r.halo_energy) << "\n";
  }
}

void write_json(const std::string& path, const RunInfo& info, const std::vector<ResultRow>& rows) {
  nlohmann::json j;
  j["run"] = {{"renderer", info.renderer}, {"version", info.version},   {"backend", info.backend},
              {"clock", info.clock},       {"date", info.date},         {"mode", info.mode},
              {"command_line", info.command_line}, {"reference", info.reference},
              {"warmup", info.warmup},     {"repetitions", info.repetitions}};
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
                            {"time_extrapolated", r.time_extrapolated}});
  }
  open_for_writing(path) << j.dump(2) << "\n";
}

void write_markdown_table(const std::string& path, const RunInfo& info, const std::vector<ResultRow>& rows) {
  std::ofstream out = open_for_writing(path);
  out << "Renderer: `" << info.renderer << "` (" << info.version << ", " << info.backend << "), timing: " << info.clock
      << ", " << info.warmup << " warm-up + " << info.repetitions << " timed frames, medians; reference: "
      << info.reference << ".\n\n";
  out << "| scene | size | method | passes | time ms | × copy | rel. RMSE | max abs | p99 abs | SSIM |\n";
  out << "|---|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const ResultRow& r : rows) {
    out << "| " << r.scene << " | " << r.width << "×" << r.height << " | " << method_label(r) << " | " << r.passes
        << " | " << format(r.time_ms, "%.3f") << " | " << format(r.time_ratio_to_copy, "%.2f") << " | "
        << format(r.relative_rmse, "%.4g") << " | " << format(r.max_abs_error, "%.3g") << " | "
        << format(r.p99_abs_error, "%.3g") << " | " << format(r.ssim, "%.4f") << " |\n";
  }
}

std::vector<std::string> write_pareto_plots(const std::string& directory, const std::vector<ResultRow>& rows,
                                            bool* drawn) {
  std::vector<std::string> written;
  // Without gnuplot (a lent GPU machine has none) the data and scripts are still written, and the
  // PNGs they name are listed: `gnuplot FILE.gp`, from the folder the benchmark ran in, draws them.
  const bool have_gnuplot = std::system("command -v gnuplot >/dev/null 2>&1") == 0;
  if (drawn != nullptr) *drawn = have_gnuplot;
  std::map<std::string, std::vector<const ResultRow*>> by_scene;
  for (const ResultRow& r : rows) {
    if (r.method == "copy" || r.method == "copy-compute" || r.translucent_pixels == 0) continue;
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
        data << "# " << name << "\n";
        for (const ResultRow* p : points) {
          data << format(p->time_ms) << ' ' << format(std::max(p->relative_rmse, 1e-7)) << ' ' << p->taps << "\n";
        }
        data << "\n\n";
      }
    }
    std::ofstream script = open_for_writing(script_path);
    script << "set terminal pngcairo size 800,640 noenhanced\nset output '" << png_path << "'\n"
           << "set title 'error against time: " << key << "'\n"
           << "set xlabel 'time per frame (ms)'\nset ylabel 'relative RMSE vs exact 2D'\n"
           << "set logscale xy\nset grid\nset format y '%.0e'\nset key below\n"
           << "plot ";
    int index = 0;
    for (const auto& [name, points] : series) {
      script << (index ? ", " : "") << "'" << data_path << "' index " << index
             << " using 1:2 with linespoints title '" << name << "'";
      // Tap counts next to the separable filter's points only (the others would overlap them).
      if (name.rfind("separable", 0) == 0) {
        script << ", '' index " << index << " using 1:2:3 with labels offset 0,0.8 notitle";
      }
      ++index;
    }
    script << "\n";
    script.close();
    if (!have_gnuplot) {
      written.push_back(png_path);
    } else if (std::system(("gnuplot '" + script_path + "' 2>/dev/null").c_str()) == 0) {
      written.push_back(png_path);
    } else if (std::system(("sed -i 's/pngcairo/png/' '" + script_path + "' && gnuplot '" + script_path + "'").c_str()) == 0) {
      written.push_back(png_path);
    }
  }
  return written;
}

}  // namespace sss_bench
