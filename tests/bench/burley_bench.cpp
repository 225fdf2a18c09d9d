// sss_bench_burley: Burley's normalized diffusion on the footprint sweep (issue 23): the interior
// `miss` of the kernel families the runtime builds from a Burley profile (sss_settings.kernel with
// profile SSS_PROFILE_BURLEY, through sss_apply_frame, follow-surface on), against the exact plane
// reference for radial profiles (module/src/math/radial_plane_reference.hpp: every source pixel's
// exact cell integral, the 1/r centre included), on the sweep's planes at its footprints.
//
// Frames as sss_bench sizes them (sweep_geometry.hpp) with the Burley profile's own reach (the
// radius beyond which at most 1e-3 of a point's light lands, regions.hpp's definition) and the
// interior region it defines. The reference sums every source of the frame for each receiver, so it
// is computed on a grid of at most --max-receivers interior pixels (stride s: x % s == s / 2, as
// sss_bench's GL reference grid), and the miss is taken there.
//
//   sss_bench_burley [--backend egl] [--footprints f,f,...] [--scenes a,b] [--taps N]
//                    [--max-receivers N] [--doc FILE]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "list_argument.hpp"
#include "gpu_scene.hpp"
#include "host_context.hpp"
#include "host_gl.hpp"
#include "math/burley_profile.hpp"
#include "math/radial_plane_reference.hpp"
#include "method.hpp"
#include "metrics.hpp"
#include "reference.hpp"
#include "regions.hpp"
#include "calibration.hpp"
#include "scenes/scenes.hpp"
#include "sss/sss_tools.h"
#include "sss_headless.h"
#include "sweep_geometry.hpp"
#include "timing.hpp"

using namespace host_gl;

namespace {

using Clock = std::chrono::steady_clock;

struct Args {
  std::string backend = "egl", doc;
  std::vector<double> footprints = sss_bench::default_sweep_footprints();
  std::vector<std::string> scenes = sss_bench::footprint_scene_names();
  int taps = 17;
  int max_receivers = 1024;
  std::string command_line;
};

[[noreturn]] void usage(const char* program, int code) {
  std::printf("usage: %s [--backend egl|osmesa] [--footprints f,f,...] [--scenes a,b] [--taps N] "
              "[--max-receivers N] [--doc FILE]\n", program);
  std::exit(code);
}

Args parse(int argc, char** argv) {
  Args a;
  for (int i = 0; i < argc; ++i) a.command_line += (i ? " " : "") + std::string(argv[i]);
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    if (i + 1 >= argc) usage(argv[0], k == "--help" ? 0 : 2);
    const std::string v = argv[++i];
    if (k == "--backend") {
      a.backend = v;
    } else if (k == "--doc") {
      a.doc = v;
    } else if (k == "--scenes") {
      a.scenes = sss_bench::split_list(v);
    } else if (k == "--footprints") {
      a.footprints.clear();
      for (const std::string& f : sss_bench::split_list(v)) a.footprints.push_back(std::atof(f.c_str()));
    } else if (k == "--taps") {
      a.taps = std::atoi(v.c_str());
    } else if (k == "--max-receivers") {
      a.max_receivers = std::max(16, std::atoi(v.c_str()));
    } else {
      usage(argv[0], 2);
    }
  }
  for (double f : a.footprints) {
    if (!(f > 0.0)) usage(argv[0], 2);
  }
  return a;
}

// A profile the sweep runs: its API desc and the math profile of the same (float) parameters.
struct BurleyCase {
  std::string name;  // "marble"
  sss_profile_desc desc{};
  sss::math::BurleyParameters parameters;
};

BurleyCase burley_case(int32_t material) {
  BurleyCase c;
  c.name = sss_profile_name(material);
  if (sss_profile_burley_from_measured(material, &c.desc) != SSS_OK) throw std::runtime_error(sss_last_error(nullptr));
  for (std::size_t k = 0; k < 3; ++k) {
    c.parameters.albedo[k] = c.desc.burley_albedo[k];
    c.parameters.dmfp_mm[k] = c.desc.burley_dmfp_mm[k];
  }
  return c;
}

struct Row {
  std::string profile, method, scene;
  double footprint_mm = 0.0;
  sss_bench::Miss miss;
  int stride = 1;
  int passes = 0;  // full-screen passes per frame (2 × the plan's terms)
};

// The kernel families a host would pick for a Burley profile: the per-pixel profiles' rank 1
// pre-integrated kernel and the multi-term ones.
std::vector<sss_bench::KernelChoice> families(const sss_profile_desc* profile) {
  return {{"kernel-preintegrated", SSS_KERNEL_PREINTEGRATED, 1, 0.0f, profile},
          {"kernel-preintegrated-2", SSS_KERNEL_PREINTEGRATED, 2, 0.0f, profile},
          {"kernel-svd-3", SSS_KERNEL_SVD, 3, 0.0f, profile},
          {"kernel-sum-of-gaussians-4", SSS_KERNEL_SUM_OF_GAUSSIANS, 4, 0.0f, profile}};
}

// One sweep frame: the reference on the interior grid, then every family scored there.
struct Family {
  std::string name;
  std::unique_ptr<sss_bench::Method> method;  // one context each for the whole sweep: built once
};

void run_frame(const BurleyCase& b, const sss::math::RadialPixelKernel& kernel, double reach_mm,
               const std::string& scene_name, double footprint, const Args& args, std::vector<Family>& methods,
               std::vector<Row>* rows) {
  const int side = sss_bench::sweep_frame_side(footprint, sss_bench::kCalibrationInteriorPx, reach_mm);
  const sss_bench::Scene scene = sss_bench::make_footprint_scene(scene_name, footprint, side, side);
  sss_bench::GpuScene gpu = sss_bench::upload_scene(scene);
  std::vector<uint8_t> interior = sss_bench::region_mask(
      sss_bench::classify_regions(sss_bench::region_input_of(scene, reach_mm)), sss_bench::Region::interior);
  const auto count = static_cast<double>(std::count(interior.begin(), interior.end(), uint8_t{1}));
  const int stride = std::max(1, static_cast<int>(std::ceil(std::sqrt(count / args.max_receivers))));
  int x0 = side, y0 = side, x1 = -1, y1 = -1;
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      uint8_t& m = interior[static_cast<std::size_t>(y * side + x)];
      if (m == 0) continue;
      if (!sss_bench::on_grid(x, y, stride)) {
        m = 0;
        continue;
      }
      x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
    }
  }
  sss::math::PlaneInput plane;
  plane.width = plane.height = side;
  plane.irradiance = gpu.irradiance_half.data();
  plane.pixel_x_mm = sss::math::plane_pixel_mm_x(scene.projection, side, scene.distance[0], scene.world_units_per_mm);
  plane.pixel_y_mm = sss::math::plane_pixel_mm_y(scene.projection, side, scene.distance[0], scene.world_units_per_mm);
  const sss_bench::RgbImage input = sss_bench::RgbImage::from_rgba(gpu.irradiance_half.data(), side, side);
  std::vector<double> exact = input.rgb;  // the grid's pixels are overwritten
  const Clock::time_point start = Clock::now();
  sss::math::convolve_plane_radial(plane, kernel, {x0, y0, x1 - x0 + 1, y1 - y0 + 1}, exact.data(), 0, stride);
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  // The kernels redistribute irradiance (each channel sums to 1; the diffuse albedo is the host's),
  // so they are scored against R/A, the profile normalised per channel, as sss_bench's skin is.
  for (std::size_t i = 0; i < interior.size(); ++i) {
    if (interior[i] == 0) continue;
    for (std::size_t c = 0; c < 3; ++c) exact[i * 3 + c] /= b.parameters.albedo[c];
  }
  const sss_bench::RgbImage reference = sss_bench::RgbImage::from_rgb(exact.data(), side, side);
  Row none{b.name, "no-scattering", scene_name, footprint, sss_bench::miss_share(input, reference, input, interior.data()),
           stride};
  rows->push_back(none);
  const GLuint output = sss_bench::make_output_texture(side, side);
  for (Family& k : methods) {
    std::string error;
    if (!k.method->run(gpu, output, &error)) throw std::runtime_error(k.name + " on " + scene_name + ": " + error);
    const sss_bench::RgbImage result =
        sss_bench::RgbImage::from_rgba(sss_bench::read_texture_rgba(output, side, side).data(), side, side);
    rows->push_back({b.name, k.name, scene_name, footprint, sss_bench::miss_share(result, reference, input, interior.data()),
                     stride, k.method->passes()});
  }
  std::printf("burley-%s %s %.4g mm/px: %dx%d, %zu receivers (stride %d), their sums %.1f s; miss %s %.3f\n",
              b.name.c_str(), scene_name.c_str(), footprint, side, side, rows->back().miss.pixels, stride, seconds,
              rows->back().method.c_str(), rows->back().miss.pooled);
  std::fflush(stdout);
  glDeleteTextures(1, &output);
  sss_bench::destroy_scene(&gpu);
}

double median_of(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

std::string fmt(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3f", v);
  return b;
}

std::string footprint_label(double f) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", f);  // as docs/benchmarks.md labels the sweep
  return b;
}

// The median interior miss of one method over the scenes at one footprint.
double median_miss(const std::vector<Row>& rows, const std::string& profile, const std::string& method, double f) {
  std::vector<double> v;
  for (const Row& r : rows) {
    if (r.profile == profile && r.method == method && r.footprint_mm == f) v.push_back(r.miss.pooled);
  }
  return median_of(v);
}

// One sentence: the rank-1 kernel's range over the footprints and the best family at each.
void write_headline(std::ostringstream& md, const std::vector<Row>& rows, const BurleyCase& b, const Args& args) {
  double lo = 1e30, hi = 0.0;
  for (double f : args.footprints) {
    const double m = median_miss(rows, b.name, "kernel-preintegrated", f);
    lo = std::min(lo, m), hi = std::max(hi, m);
  }
  md << "**Headline.** `kernel-preintegrated` (one pass pair) leaves " << fmt(lo) << " to " << fmt(hi)
     << " of the needed change undone on the interior (median over the scenes, per footprint); the most accurate "
        "family per footprint:";
  for (double f : args.footprints) {
    std::string best;
    double best_miss = 1e30;
    for (const sss_bench::KernelChoice& k : families(nullptr)) {
      const double m = median_miss(rows, b.name, k.name, f);
      if (m < best_miss) best_miss = m, best = k.name;
    }
    md << (f == args.footprints.front() ? " " : ", ") << footprint_label(f) << " mm `" << best << "` (" << fmt(best_miss)
       << ")";
  }
  md << ".\n\n";
}

// Per profile: the median interior miss over the scenes and the worst channel, per footprint.
void write_tables(std::ostringstream& md, const std::vector<Row>& rows, const BurleyCase& b, const Args& args) {
  std::vector<std::string> methods;
  std::vector<int> passes;
  for (const Row& r : rows) {
    if (r.profile == b.name && std::find(methods.begin(), methods.end(), r.method) == methods.end()) {
      methods.push_back(r.method);
      passes.push_back(r.passes);
    }
  }
  for (int table = 0; table < 2; ++table) {
    md << (table == 0 ? "**Median interior miss over the scenes**" : "**Worst channel** over the scenes")
       << ", Burley " << b.name << ", per footprint (mm per pixel):\n\n| method |";
    for (double f : args.footprints) md << " " << footprint_label(f) << " |";
    md << "\n|---|";
    for (std::size_t i = 0; i < args.footprints.size(); ++i) md << "---:|";
    md << "\n";
    for (std::size_t i = 0; i < methods.size(); ++i) {
      const std::string& m = methods[i];
      md << "| " << m
         << (m == "no-scattering" ? "" : " " + std::to_string(args.taps) + " taps, " + std::to_string(passes[i]) + " passes")
         << " |";
      for (double f : args.footprints) {
        double worst = 0.0;
        for (const Row& r : rows) {
          if (r.profile == b.name && r.method == m && r.footprint_mm == f) worst = std::max(worst, r.miss.worst_channel());
        }
        md << " " << fmt(table == 0 ? median_miss(rows, b.name, m, f) : worst) << " |";
      }
      md << "\n";
    }
    md << "\n";
  }
}

std::string now_utc() {
  const std::time_t t = std::time(nullptr);
  char buffer[64];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%d %H:%M UTC", std::gmtime(&t));
  return buffer;
}

void write_doc(const Args& args, const std::vector<BurleyCase>& cases, const std::vector<double>& reaches,
               const std::vector<Row>& rows, const std::string& renderer) {
  std::ostringstream md;
  md << "# Burley's normalized diffusion on the footprint sweep\n\n"
     << "Generated by `" << args.command_line << "` (tests/bench/burley_bench.cpp, run by `scripts/run-benchmark.sh`) on "
     << now_utc() << ", renderer `" << renderer << "`. Do not edit by hand: rerun it.\n\n"
     << "The kernel families the runtime builds from a Burley profile (`SSS_PROFILE_BURLEY`; the parameters: "
        "[../burley.md](../burley.md)), each through `sss_apply_frame` with `sss_settings.kernel` at "
     << args.taps << " taps per pass, follow-surface on, at the profile's physical size, on the footprint sweep's planes ("
     << args.scenes.size() << " scenes: ";
  for (std::size_t i = 0; i < args.scenes.size(); ++i) md << (i ? ", " : "") << "`" << args.scenes[i] << "`";
  md << "). Reference: the exact plane convolution with the Burley profile itself, normalised per channel (R/A: the "
        "kernels redistribute irradiance and leave the albedo to the host, as for every profile) "
        "(module/src/math/radial_plane_reference.hpp: each source pixel's cell integral in closed form around the 1/r "
        "centre, every source pixel of the frame), computed on a grid of at most "
     << args.max_receivers << " interior receivers per frame. `miss` as in [../benchmarks.md](../benchmarks.md): "
        "0 is exact, 1 no better than doing nothing. Frames are the interior plus the profile's reach on every side; "
        "the reach (at most 1e-3 of a point's light beyond it, widest channel): ";
  for (std::size_t i = 0; i < cases.size(); ++i) md << (i ? ", " : "") << cases[i].name << " " << fmt(reaches[i]) << " mm";
  md << ". `kernel-preintegrated` (rank 1, one pass pair) is the kernel per-pixel profiles take.\n\n";
  for (const BurleyCase& b : cases) {
    md << "## Burley " << b.name << " (A " << fmt(b.desc.burley_albedo[0]) << " " << fmt(b.desc.burley_albedo[1]) << " "
       << fmt(b.desc.burley_albedo[2]) << ", ℓ_d " << fmt(b.desc.burley_dmfp_mm[0]) << " " << fmt(b.desc.burley_dmfp_mm[1])
       << " " << fmt(b.desc.burley_dmfp_mm[2]) << " mm)\n\n";
    write_headline(md, rows, b, args);
    write_tables(md, rows, b, args);
  }
  std::filesystem::create_directories(std::filesystem::path(args.doc).parent_path());
  std::ofstream(args.doc) << md.str();
}

}  // namespace

int main(int argc, char** argv) {
  const Args args = parse(argc, argv);
  sss_headless_backend backend;
  if (sss_headless_backend_from_name(args.backend.c_str(), &backend) != 0) {
    std::fprintf(stderr, "unknown backend %s\n", args.backend.c_str());
    return 2;
  }
  sss_headless* headless = sss_test::open_host_context(backend, "sss_bench_burley");
  if (headless == nullptr) return 1;
  const std::string renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const sss_bench::GlLoader loader{sss_headless_get_proc_address, headless};
  std::vector<BurleyCase> cases = {burley_case(SSS_PROFILE_MARBLE), burley_case(SSS_PROFILE_SKIN1)};
  std::vector<double> reaches;
  std::vector<Row> rows;
  try {
    for (const BurleyCase& b : cases) {
      const sss::math::BurleyProfile profile(b.parameters);
      reaches.push_back(profile.support_mm(sss_bench::kReachTail));
      std::vector<Family> methods;
      for (const sss_bench::KernelChoice& k : families(&b.desc)) {
        methods.push_back({k.name, sss_bench::make_kernel_family_method(loader, k, args.taps)});
      }
      for (double f : args.footprints) {
        // The sweep's planes share one frame and pixel per footprint (scene.hpp), so the first
        // scene's pixel sides serve them all.
        const int side = sss_bench::sweep_frame_side(f, sss_bench::kCalibrationInteriorPx, reaches.back());
        const sss_bench::Scene first = sss_bench::make_footprint_scene(args.scenes.front(), f, side, side);
        const Clock::time_point start = Clock::now();
        const sss::math::RadialPixelKernel kernel(
            profile, sss::math::plane_pixel_mm_x(first.projection, side, first.distance[0], first.world_units_per_mm),
            sss::math::plane_pixel_mm_y(first.projection, side, first.distance[0], first.world_units_per_mm), side, side);
        std::printf("burley-%s %.4g mm/px: the reference's %dx%d cells in %.1f s\n", b.name.c_str(), f, side, side,
                    std::chrono::duration<double>(Clock::now() - start).count());
        for (const std::string& scene : args.scenes) run_frame(b, kernel, reaches.back(), scene, f, args, methods, &rows);
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sss_bench_burley: %s\n", e.what());
    sss_headless_destroy(headless);
    return 1;
  }
  if (!args.doc.empty()) write_doc(args, cases, reaches, rows, renderer);
  sss_headless_destroy(headless);
  return 0;
}
