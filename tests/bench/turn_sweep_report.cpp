// What sss_bench_turns writes (turn_sweep.hpp): results.csv, the plot and the Markdown document,
// all from the rows, so that the document is generated and never typed.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "analytic_scenes.hpp"  // the perspective planes' spread
#include "calibration.hpp"
#include "method.hpp"
#include "turn_sweep.hpp"

namespace sss_bench::turns {

namespace {

std::ofstream open_for_writing(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  return out;
}

std::string format(double v, const char* pattern = "%.3f") {
  if (std::isnan(v)) return "–";
  if (std::isinf(v)) return "∞";
  char text[48];
  std::snprintf(text, sizeof text, pattern, v);
  return text;
}

// A CSV field: empty where there is no value.
std::string csv_number(double v, const char* pattern = "%.6g") { return std::isnan(v) ? "" : format(v, pattern); }

// ---- Selecting and reducing rows ----

// The rows a table cell covers: a scene kind, one turn for the planes (every axis and projection),
// one footprint (NaN: every footprint), one method.
struct Cell {
  std::string scene = "plane";
  double turn_deg = 0.0;
  double footprint_mm = std::numeric_limits<double>::quiet_NaN();
  std::string method;
};

bool in_cell(const Row& r, const Cell& c) {
  return r.scene == c.scene && r.method == c.method && (c.scene != "plane" || r.turn_deg == c.turn_deg) &&
         (std::isnan(c.footprint_mm) || r.footprint_mm == c.footprint_mm);
}

std::vector<const Row*> select(const std::vector<Row>& rows, const std::function<bool(const Row&)>& keep) {
  std::vector<const Row*> out;
  for (const Row& r : rows) {
    if (keep(r)) out.push_back(&r);
  }
  return out;
}

// The largest, or the median, of a value over rows, NaN ones left out (NaN when none is left).
double largest(const std::vector<const Row*>& rows, const std::function<double(const Row&)>& value) {
  double worst = std::numeric_limits<double>::quiet_NaN();
  for (const Row* r : rows) {
    const double v = value(*r);
    if (!std::isnan(v) && (std::isnan(worst) || v > worst)) worst = v;
  }
  return worst;
}

double median(const std::vector<const Row*>& rows) {
  std::vector<double> v;
  for (const Row* r : rows) {
    if (!std::isnan(r->miss.pooled)) v.push_back(r->miss.pooled);
  }
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

double pooled(const Row& r) { return r.miss.pooled; }
double worst_channel(const Row& r) { return r.miss.pixels > 0 ? r.miss.worst_channel() : std::nan(""); }

// The table rows: each turn for the planes, then the curved scenes that ran.
std::vector<Cell> table_lines(const Options& o, const std::vector<Row>& rows) {
  std::vector<Cell> lines;
  const auto ran = [&](const std::string& scene) {
    return std::any_of(rows.begin(), rows.end(), [&](const Row& r) { return r.scene == scene; });
  };
  if (ran("plane")) {
    for (double t : o.turns) lines.push_back({"plane", t, std::nan(""), ""});
  }
  for (const char* scene : {"cylinder", "sphere"}) {
    if (ran(scene)) lines.push_back({scene, 0.0, std::nan(""), ""});
  }
  return lines;
}

std::string line_label(const Cell& c) {
  if (c.scene != "plane") return c.scene == "sphere" ? "sphere, r 40 mm" : "cylinder, r 40 mm";
  return format(c.turn_deg, "%g") + "°";
}

std::vector<std::string> methods_in(const std::vector<Row>& rows) {
  std::vector<std::string> names;
  for (const Row& r : rows) {
    if (std::find(names.begin(), names.end(), r.method) == names.end()) names.push_back(r.method);
  }
  return names;
}

// ---- The document's parts ----

void write_how(std::ostringstream& md, const Options& o, const RunInfo& info) {
  md << "## How it was measured\n\n"
     << "- **Scenes** (`tests/bench/scenes`, generated in code): a translucent plane filling the frame through the "
        "point at the view distance where a facing pixel measures the footprint, its normal turned by the turn angle "
        "about an axis in the screen plane (at the axis angle from screen x). On it, in surface millimetres: a straight "
        "shadow edge along the turn axis (so the light changes along the foreshortened direction, the hard case), lit "
        "1.0 on one side and 0.02 on the other, a per-pixel albedo in [0.25, 1), and a 0.5 mm spot (4.0) on the lit side "
        "2 mm from the edge, anti-aliased from 4x4 rays per pixel. Orthographic: pixels of the footprint's size; "
        "perspective: a narrow camera whose corner rays are "
     << format(detail::kTurnedPlaneSpreadDegrees, "%g")
     << " degrees off its axis, so every pixel sees the plane within that of its turn (the benchmark's 30-degree "
        "camera saw a plane turned 75 degrees past the region rule's silhouette test over so much of the frame that "
        "at 0.1 and 0.2 mm per pixel nothing was left to score), and the depth still changes by a factor of 1.3 "
        "(1.5 about the diagonal) across a 75-degree frame. Turn 0 is run about the first axis only. Also, "
        "perspective only (the 30-degree camera): a cylinder of radius 40 mm (axis in the screen plane, 20 degrees "
        "from vertical; a directional light's terminator along it, and a cast shadow's hard edge across it, a ring "
        "through its nearest point) and the sphere scene at radius 40 mm (a cast shadow's hard edge through its "
        "nearest point, 30 degrees below screen x there), their nearest point at that distance, both with the "
        "planes' per-pixel albedo, so that their interior needs a clear change.\n"
     << "- **Frames**: as the footprint sweep's (`tests/bench/sweep_geometry.hpp`): the interior (at least "
     << kCalibrationInteriorPx << " pixels and 8 mm) and the profile's reach (" << format(info.reach_mm, "%.2f")
     << " mm, at most 1e-3 of a point's light beyond it) on every side; square.\n"
     << "- **Reference**: the exact surface convolution of the irradiance as the GL holds it (RGBA16F) with d'Eon's "
        "six-Gaussian skin profile. On the orthographic planes, the closed form of "
        "`module/src/math/plane_reference.hpp` (`convolve_turned_plane`: each source pixel's footprint a sheared "
        "rectangle, exact at any turn) at every interior pixel; it agreed with the 2D reference "
        "(`exact_reference.hpp`, depth from the plane in double) at "
     << info.spot_checks << " interior receivers to " << format(info.spot_check_worst, "%.2g")
     << " (largest relative difference). Elsewhere the 2D reference on a grid of at most " << o.max_receivers
     << " interior receivers per frame (the planes' depth from the plane in double).\n"
     << "- **Score**: interior `miss` (`tests/bench/metrics.hpp`, regions of `tests/bench/regions.hpp`): 0 exact, 1 "
        "no better than the input, above 1 worse. The interior leaves out the frame border and anything within the "
        "profile's reach of a silhouette, which includes a translucent neighbour more than four pixel widths nearer or "
        "farther (a surface more than 76 degrees from facing the camera).\n"
     << "- **Methods**: the library on GL through `sss_apply_frame`, physical size, plain fragment path: "
        "the default (eq. (1), 17 taps, follow-surface), d'Eon's six Gaussians as 12 passes (sum of Gaussians, 17 "
        "taps), the cross-bilateral mode (13 taps) and every kernel family at 17 taps, as far as `--methods` allowed.\n\n";
}

// Per turn: the default's and the sum of Gaussians' (and the cross-bilateral mode's) median and
// largest interior miss over footprints, axes and projections, and the worst channel of any family.
void write_summary(std::ostringstream& md, const Options& o, const std::vector<Row>& rows) {
  std::vector<std::string> shown;
  for (const char* m : {"separable", "sum-of-gaussians", "cross-bilateral"}) {
    if (std::any_of(rows.begin(), rows.end(), [&](const Row& r) { return r.method == m; })) shown.push_back(m);
  }
  const bool families = std::any_of(rows.begin(), rows.end(), [](const Row& r) { return is_family(r.method); });
  md << "## Summary\n\nInterior `miss` over every footprint, axis and projection of each turn: median and largest.\n\n"
     << "| turn |";
  for (const std::string& m : shown) md << " " << method_label(m) << ": median | max |";
  if (families) md << " worst channel of any kernel family |";
  md << "\n|---|";
  for (std::size_t i = 0; i < shown.size(); ++i) md << "---:|---:|";
  md << (families ? "---|" : "") << "\n";
  for (Cell line : table_lines(o, rows)) {
    md << "| " << line_label(line) << " |";
    for (const std::string& m : shown) {
      line.method = m;
      const auto cell = select(rows, [&](const Row& r) { return in_cell(r, line); });
      md << " " << format(median(cell)) << " | " << format(largest(cell, pooled)) << " |";
    }
    if (families) {
      double worst = std::nan("");
      std::string which;
      for (const std::string& m : methods_in(rows)) {
        if (!is_family(m)) continue;
        line.method = m;
        const double v = largest(select(rows, [&](const Row& r) { return in_cell(r, line); }), worst_channel);
        if (!std::isnan(v) && (std::isnan(worst) || v > worst)) worst = v, which = m;
      }
      md << " " << format(worst) << (which.empty() ? "" : " (`" + which + "`)") << " |";
    }
    md << "\n";
  }
  md << "\n";
}

// One method: per turn (rows) and footprint (columns), the largest interior miss over the axes and
// projections, with the worst channel in brackets; the input's row above for reference.
void write_method_table(std::ostringstream& md, const Options& o, const std::vector<Row>& rows, const std::string& method) {
  const auto any = select(rows, [&](const Row& r) { return r.method == method; });
  md << "### " << method_label(method);
  if (!any.empty() && any.front()->taps > 0) md << " (" << any.front()->passes << " draws a frame)";
  md << "\n\n| turn |";
  for (double f : o.footprints) md << " " << format(f, "%g") << " mm |";
  md << "\n|---|";
  for (std::size_t i = 0; i < o.footprints.size(); ++i) md << "---:|";
  md << "\n| no scattering, any |";
  for (double f : o.footprints) {
    const auto cell = select(rows, [&](const Row& r) { return r.method == "no-scattering" && r.footprint_mm == f; });
    md << " " << format(largest(cell, pooled)) << " (" << format(largest(cell, worst_channel)) << ") |";
  }
  md << "\n";
  for (Cell line : table_lines(o, rows)) {
    line.method = method;
    md << "| " << line_label(line) << " |";
    for (double f : o.footprints) {
      line.footprint_mm = f;
      const auto cell = select(rows, [&](const Row& r) { return in_cell(r, line); });
      md << " " << format(largest(cell, pooled)) << " (" << format(largest(cell, worst_channel)) << ") |";
    }
    md << "\n";
  }
  md << "\n";
}

// A table of one number per frame (from its no-scattering row), per turn and footprint: the smallest
// over the axes and projections.
void write_frame_table(std::ostringstream& md, const Options& o, const std::vector<Row>& rows,
                       const std::function<double(const Row&)>& value, const char* pattern) {
  md << "| turn |";
  for (double f : o.footprints) md << " " << format(f, "%g") << " mm |";
  md << "\n|---|";
  for (std::size_t i = 0; i < o.footprints.size(); ++i) md << "---:|";
  md << "\n";
  for (Cell line : table_lines(o, rows)) {
    line.method = "no-scattering";
    md << "| " << line_label(line) << " |";
    for (double f : o.footprints) {
      line.footprint_mm = f;
      const auto cell = select(rows, [&](const Row& r) { return in_cell(r, line); });
      md << " " << format(-largest(cell, [&](const Row& r) { return -value(r); }), pattern) << " |";
    }
    md << "\n";
  }
  md << "\n";
}

// Where the interior was thin (the program ends where a frame has none), and how much change
// scattering needed there.
void write_scored(std::ostringstream& md, const Options& o, const std::vector<Row>& rows) {
  md << "## What was scored\n\nThe fewest interior pixels scored over the axes and projections (the 2D reference's "
        "grid where it was used; every frame has some, or the run fails):\n\n";
  write_frame_table(md, o, rows, [](const Row& r) { return static_cast<double>(r.miss.pixels); }, "%.0f");
  md << "The change scattering makes there, ‖input − exact‖ / ‖exact‖ over the scored pixels (the smallest over the axes "
        "and projections). Where it nears the half-float step of the library's RGBA16F colour and intermediates (about "
        "5e-4 relative), rounding alone leaves a visible share of it, whatever the method: `miss` says little there.\n\n";
  write_frame_table(md, o, rows, [](const Row& r) { return r.needed; }, "%.2g");
}

std::string relative_to_doc(const std::string& path, const std::string& doc) {
  const std::filesystem::path from = std::filesystem::absolute(doc).parent_path();
  return std::filesystem::absolute(path).lexically_normal().lexically_relative(from.lexically_normal()).generic_string();
}

}  // namespace

std::string method_label(const std::string& method) {
  if (method == "no-scattering") return "no scattering (the input)";
  if (method == "separable") return "the default (eq. (1), 17 taps)";
  if (method == "sum-of-gaussians") return "sum of Gaussians (d'Eon's six, 17 taps)";
  if (method == "cross-bilateral") return "cross-bilateral (13 taps)";
  return "`" + method + "` (17 taps)";
}

bool is_family(const std::string& method) {
  const auto& choices = kernel_family_choices();
  return std::any_of(choices.begin(), choices.end(), [&](const KernelChoice& k) { return k.name == method; });
}

void write_csv(const std::string& path, const std::vector<Row>& rows) {
  std::ofstream out = open_for_writing(path);
  out << "scene,projection,turn_deg,axis_deg,footprint_mm,width,method,taps,passes,miss_interior,miss_r,miss_g,miss_b,"
         "pixels,needed,reference\n";
  for (const Row& r : rows) {
    out << r.scene << ',' << r.projection << ',' << csv_number(r.turn_deg) << ',' << csv_number(r.axis_deg) << ','
        << csv_number(r.footprint_mm) << ',' << r.width << ',' << r.method << ',' << r.taps << ',' << r.passes << ','
        << csv_number(r.miss.pooled) << ',' << csv_number(r.miss.channel[0]) << ',' << csv_number(r.miss.channel[1]) << ','
        << csv_number(r.miss.channel[2]) << ',' << r.miss.pixels << ',' << csv_number(r.needed) << ',' << r.reference
        << "\n";
  }
}

std::string write_plot(const std::string& directory, const Options& o, const std::vector<Row>& rows) {
  const std::string stem = directory + "/turn-sweep";
  std::vector<std::string> titles;
  {
    std::ofstream data = open_for_writing(stem + ".dat");
    for (const char* method : {"separable", "sum-of-gaussians"}) {
      for (double f : o.footprints) {
        if (select(rows, [&](const Row& r) { return r.method == method && r.scene == "plane"; }).empty()) continue;
        data << "# " << method << " at " << f << " mm: turn_deg miss_interior (largest over axes and projections)\n";
        for (double t : o.turns) {
          const Cell cell{"plane", t, f, method};
          data << t << ' ' << format(largest(select(rows, [&](const Row& r) { return in_cell(r, cell); }), pooled), "%.6g")
               << "\n";
        }
        data << "\n\n";
        titles.push_back(std::string(method == std::string("separable") ? "default" : "sum of Gaussians") + ", " +
                         format(f, "%g") + " mm/px");
      }
    }
  }
  if (titles.empty()) return "";
  std::ofstream script = open_for_writing(stem + ".gp");
  script << "set terminal pngcairo size 1000,640 noenhanced\nset output '" << stem << ".png'\n"
         << "set title 'interior miss against the turn (largest over axes and projections)'\n"
         << "set key outside right\nset grid\nset offsets 3, 3, 0, 0\nset xlabel 'turn from facing the camera (degrees)'\n"
         << "set ylabel 'miss (interior)'\nset yrange [0:*]\nplot ";
  for (std::size_t i = 0; i < titles.size(); ++i) {
    const bool sum = titles[i].rfind("sum", 0) == 0;
    script << (i ? ", " : "") << "'" << stem << ".dat' index " << i << " using 1:2 with linespoints lc " << (i % o.footprints.size()) + 1
           << " dashtype " << (sum ? 2 : 1) << " title '" << titles[i] << "'";
  }
  script << "\n";
  script.close();
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) return "";
  // pngcairo where it is built in, else the plain png terminal.
  if (std::system(("gnuplot '" + stem + ".gp' 2>/dev/null").c_str()) == 0) return stem + ".png";
  if (std::system(("sed -i 's/pngcairo/png/' '" + stem + ".gp' && gnuplot '" + stem + ".gp'").c_str()) == 0) {
    return stem + ".png";
  }
  std::fprintf(stderr, "sss_bench_turns: gnuplot could not draw %s.gp\n", stem.c_str());
  return "";
}

void write_document(const Options& o, const RunInfo& info, const std::vector<Row>& rows, const std::string& plot) {
  std::ostringstream md;
  md << "# The turn sweep: accuracy where the surface turns away from the camera\n\n"
     << "Generated by `" << o.command_line << "` (`tests/bench/turn_sweep.cpp`, run by `scripts/run-turn-sweep.sh`) on "
     << info.date << ", renderer `" << info.renderer << "` (" << info.version << "), in " << format(info.seconds, "%.0f")
     << " s. Do not edit by hand: rerun it. Every row: [" << relative_to_doc(o.out + "/results.csv", o.doc) << "]("
     << relative_to_doc(o.out + "/results.csv", o.doc) << ").\n\n";
  write_how(md, o, info);
  write_summary(md, o, rows);
  if (!plot.empty()) md << "![interior miss against the turn](" << relative_to_doc(plot, o.doc) << ")\n\n";
  md << "## Each method\n\nInterior `miss` per turn and footprint: the largest over the axes and projections, the worst "
        "channel of the same frames in brackets.\n\n";
  for (const std::string& m : methods_in(rows)) {
    if (m != "no-scattering") write_method_table(md, o, rows, m);
  }
  write_scored(md, o, rows);
  open_for_writing(o.doc) << md.str();
}

}  // namespace sss_bench::turns
