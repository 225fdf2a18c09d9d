// sss_bench_turns: the turn sweep. How accurate the library's filter is where the surface turns away
// from the camera: planes turned 0-75 degrees about three screen axes under an orthographic and a
// perspective camera, a cylinder and a sphere, at footprints from a close-up to a crowd, each method
// run through the library on GL and scored by its interior miss (metrics.hpp, regions.hpp) against
// the exact surface convolution with d'Eon's skin profile.
//
// References: on an orthographic plane the closed form of plane_reference.hpp (convolve_turned_plane:
// every interior receiver, exact at any turn); elsewhere the 2D reference of exact_reference.hpp on
// the interior receivers of a stride grid (at most --max-receivers; x % s == s / 2, as sss_bench's
// GL reference grid), with the planes' depth taken from the plane itself (double). Frames as the
// footprint sweep's (sweep_geometry.hpp: the interior and the profile's reach on every side).
// Sanity checks that end the run with status 1: every frame has interior receivers to score (the
// perspective planes' narrow camera is there for that: analytic_scenes.cpp), every method runs on
// every frame, the input misses exactly 1 wherever something is scored, and on every orthographic
// plane the closed form agrees with the 2D reference at a few interior receivers to 1e-6.
//
//   sss_bench_turns [--backend egl|osmesa] [--footprints f,...] [--turns t,...] [--axes a,...]
//                   [--projections orthographic,perspective] [--scenes plane,sphere,cylinder]
//                   [--methods m,...] [--max-receivers N] [--out DIR] [--doc FILE]
#include <getopt.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "list_argument.hpp"
#include "calibration.hpp"
#include "gpu_scene.hpp"
#include "host_context.hpp"
#include "host_gl.hpp"
#include "math/exact_reference.hpp"
#include "math/plane_reference.hpp"
#include "method.hpp"
#include "metrics.hpp"
#include "reference.hpp"
#include "regions.hpp"
#include "scenes/scenes.hpp"
#include "sss_headless.h"
#include "sweep_geometry.hpp"
#include "turn_sweep.hpp"

using namespace host_gl;

namespace sss_bench::turns {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

[[noreturn]] void usage(const char* program, int code) {
  std::printf("usage: %s [--backend egl|osmesa] [--footprints f,...] [--turns t,...] [--axes a,...]\n"
              "       [--projections orthographic,perspective] [--scenes plane,sphere,cylinder] [--methods m,...]\n"
              "       [--max-receivers N] [--out DIR] [--doc FILE]\n"
              "methods: separable (the default), sum-of-gaussians, cross-bilateral, families (every kernel family)\n"
              "or one family by name (kernel-svd-1, ...); no-scattering is always scored\n",
              program);
  std::exit(code);
}

std::vector<double> numbers(const std::string& text, const char* program) {
  std::vector<double> out;
  for (const std::string& s : sss_bench::split_list(text)) {
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || *end != '\0' || !std::isfinite(v)) usage(program, 2);
    out.push_back(v);
  }
  return out;
}

// Every list must be non-empty and hold known values.
void check_options(const Options& o, const char* program) {
  const auto known = [](const std::vector<std::string>& values, const std::vector<std::string>& allowed) {
    return !values.empty() && std::all_of(values.begin(), values.end(), [&](const std::string& v) {
      return std::find(allowed.begin(), allowed.end(), v) != allowed.end();
    });
  };
  const bool ok = (o.backend == "egl" || o.backend == "osmesa") && !o.footprints.empty() && !o.turns.empty() &&
                  !o.axes.empty() &&
                  std::all_of(o.footprints.begin(), o.footprints.end(), [](double f) { return f > 0.0 && f < 100.0; }) &&
                  std::all_of(o.turns.begin(), o.turns.end(), [](double t) { return t >= 0.0 && t <= 89.0; }) &&
                  known(o.projections, {"orthographic", "perspective"}) && known(o.scenes, {"plane", "sphere", "cylinder"});
  if (!ok) usage(program, 2);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 0; i < argc; ++i) o.command_line += (i ? " " : "") + std::string(argv[i]);
  static const option long_options[] = {
      {"backend", required_argument, nullptr, 'b'},     {"footprints", required_argument, nullptr, 'f'},
      {"turns", required_argument, nullptr, 't'},       {"axes", required_argument, nullptr, 'a'},
      {"projections", required_argument, nullptr, 'p'}, {"scenes", required_argument, nullptr, 's'},
      {"methods", required_argument, nullptr, 'm'},     {"max-receivers", required_argument, nullptr, 'r'},
      {"out", required_argument, nullptr, 'o'},         {"doc", required_argument, nullptr, 'd'},
      {"help", no_argument, nullptr, 'h'},              {nullptr, 0, nullptr, 0}};
  for (int c; (c = getopt_long(argc, argv, "", long_options, nullptr)) != -1;) {
    const std::string v = optarg != nullptr ? optarg : "";
    switch (c) {
      case 'b': o.backend = v; break;
      case 'f': o.footprints = numbers(v, argv[0]); break;
      case 't': o.turns = numbers(v, argv[0]); break;
      case 'a': o.axes = numbers(v, argv[0]); break;
      case 'p': o.projections = sss_bench::split_list(v); break;
      case 's': o.scenes = sss_bench::split_list(v); break;
      case 'm': o.methods = sss_bench::split_list(v); break;
      case 'r': o.max_receivers = std::max(16, std::atoi(v.c_str())); break;
      case 'o': o.out = v; break;
      case 'd': o.doc = v; break;
      case 'h': usage(argv[0], 0);
      default: usage(argv[0], 2);
    }
  }
  if (optind != argc) usage(argv[0], 2);
  check_options(o, argv[0]);
  return o;
}

// ---- What runs: the frames and the methods ----

struct Job {
  std::string scene, projection;
  double turn_deg = 0.0, axis_deg = 0.0, footprint_mm = 0.0;
};

// Per footprint: the planes (turn 0 once, about the first axis: it has no axis), then the curved
// scenes (perspective only: an orthographic sphere is not what a host renders).
std::vector<Job> make_jobs(const Options& o) {
  const double nan = std::nan("");
  std::vector<Job> jobs;
  for (double f : o.footprints) {
    for (const std::string& scene : o.scenes) {
      if (scene != "plane") {
        jobs.push_back({scene, "perspective", nan, nan, f});
        continue;
      }
      for (const std::string& projection : o.projections) {
        for (double turn : o.turns) {
          for (double axis : o.axes) {
            jobs.push_back({scene, projection, turn, turn == 0.0 ? o.axes.front() : axis, f});
            if (turn == 0.0) break;
          }
        }
      }
    }
  }
  return jobs;
}

struct NamedMethod {
  std::string name;
  int taps = 0;
  std::unique_ptr<Method> method;  // one context each for the whole sweep: built once
};

bool wanted(const Options& o, const std::string& name) {
  if (o.methods.empty()) return true;
  const auto has = [&](const std::string& n) { return std::find(o.methods.begin(), o.methods.end(), n) != o.methods.end(); };
  return has(name) || (is_family(name) && has("families"));
}

std::vector<NamedMethod> make_methods(const GlLoader& loader, const Options& o) {
  constexpr int kTaps = 17, kCrossBilateralTaps = 13;
  std::vector<NamedMethod> methods;
  if (wanted(o, "separable")) methods.push_back({"separable", kTaps, make_separable_method(loader, kTaps, true)});
  const KernelChoice& sum = sum_of_gaussians_baseline();
  if (wanted(o, sum.name)) methods.push_back({sum.name, kTaps, make_kernel_family_method(loader, sum, kTaps)});
  if (wanted(o, "cross-bilateral")) {
    methods.push_back({"cross-bilateral", kCrossBilateralTaps, make_cross_bilateral_method(loader, kCrossBilateralTaps)});
  }
  for (const KernelChoice& k : kernel_family_choices()) {
    if (wanted(o, k.name)) methods.push_back({k.name, kTaps, make_kernel_family_method(loader, k, kTaps)});
  }
  for (const std::string& name : o.methods) {
    const bool known = name == "families" || name == "no-scattering" ||
                       std::any_of(methods.begin(), methods.end(), [&](const NamedMethod& m) { return m.name == name; });
    if (!known) throw std::invalid_argument("unknown method '" + name + "' (--help lists them)");
  }
  return methods;
}

// ---- The frame and its reference ----

struct Frame {
  Scene scene;
  PlaneGeometry plane;
  bool is_plane = false;
};

Frame build_frame(const Job& job, int side) {
  Frame f;
  if (job.scene == "plane") {
    f.is_plane = true;
    f.scene = make_turned_plane_scene(job.footprint_mm, job.turn_deg, job.axis_deg, job.projection == "orthographic",
                                      side, side, &f.plane);
  } else if (job.scene == "sphere") {
    f.scene = make_footprint_sphere_scene(job.footprint_mm, side, side);
  } else {
    f.scene = make_cylinder_scene(job.footprint_mm, side, side);
  }
  return f;
}

sss::math::Vec3 vec3(const std::array<double, 3>& v) { return {v[0], v[1], v[2]}; }

// The plane's view distance at every translucent pixel's centre in double (the scene's are floats);
// the others keep the scene's.
std::vector<double> plane_distances(const Frame& f) {
  const Scene& s = f.scene;
  sss::math::Matrix4 m{};
  std::copy(s.projection.begin(), s.projection.end(), m.begin());
  const sss::math::Vec3 point = vec3(f.plane.point), normal = vec3(f.plane.normal);
  std::vector<double> d(s.distance.begin(), s.distance.end());
  for (int y = 0; y < s.height; ++y) {
    for (int x = 0; x < s.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(s.width) + static_cast<std::size_t>(x);
      if (s.mask[i] == 0) continue;
      const sss::math::Vec3 origin = sss::math::pixel_position(m, s.width, s.height, x, y, 0.0);
      const sss::math::Vec3 direction = sss::math::pixel_position(m, s.width, s.height, x, y, 1.0) - origin;
      d[i] = sss::math::dot(normal, point - origin) / sss::math::dot(normal, direction);
    }
  }
  return d;
}

struct Reference {
  RgbImage image;                // the input, with the exact result on the scored pixels
  std::vector<uint8_t> scored;   // the interior pixels that hold it
  std::string kind;
  double seconds = 0.0;
};

sss::math::ExactInput exact_input(const Frame& f, const GpuScene& gpu, const std::vector<double>* distances) {
  sss::math::ExactInput in;
  in.width = f.scene.width;
  in.height = f.scene.height;
  in.irradiance = gpu.irradiance_half.data();
  if (distances != nullptr) in.distance_f64 = distances->data();
  else in.distance = f.scene.distance.data();
  in.mask = f.scene.mask.data();
  in.projection = f.scene.projection;
  in.world_units_per_mm = f.scene.world_units_per_mm;
  return in;
}

// The 2D reference at the chosen pixels (indices), on all cores, into image.
void exact_at(const sss::math::ExactSurfaceConvolution& exact, const std::vector<std::size_t>& pixels, RgbImage* image) {
  std::atomic<std::size_t> next{0};
  const auto work = [&]() {
    for (std::size_t k = next++; k < pixels.size(); k = next++) {
      const std::size_t i = pixels[k];
      const auto w = static_cast<std::size_t>(image->width);
      const std::array<double, 3> v = exact.at(static_cast<int>(i % w), static_cast<int>(i / w));
      for (std::size_t c = 0; c < 3; ++c) image->rgb[i * 3 + c] = v[c];
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < std::max(1u, std::thread::hardware_concurrency()); ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
}

// The interior's bounding rectangle.
sss::math::PixelRegion bounds_of(const std::vector<uint8_t>& mask, int width, int height) {
  int x0 = width, y0 = height, x1 = -1, y1 = -1;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (mask[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)] == 0) continue;
      x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
    }
  }
  if (x1 < 0) return {0, 0, 0, 0};
  return {x0, y0, x1 - x0 + 1, y1 - y0 + 1};
}

sss::math::TurnedPlaneFootprint plane_footprint(const Frame& f) {
  sss::math::Matrix4 m{};
  std::copy(f.scene.projection.begin(), f.scene.projection.end(), m.begin());
  return sss::math::turned_plane_footprint(m, f.scene.width, f.scene.height, vec3(f.plane.point), vec3(f.plane.normal),
                                           f.scene.world_units_per_mm, f.scene.width / 2, f.scene.height / 2);
}

// An orthographic plane: the closed form at every interior receiver.
Reference closed_form_reference(const Frame& f, const GpuScene& gpu, const std::vector<uint8_t>& interior) {
  const Scene& s = f.scene;
  if (std::count(s.mask.begin(), s.mask.end(), uint8_t{0}) != 0) {
    throw std::runtime_error(s.name + ": the closed form needs the plane in every pixel");
  }
  Reference r;
  r.image = RgbImage::from_rgba(gpu.irradiance_half.data(), s.width, s.height);
  r.scored = interior;
  r.kind = "closed form";
  sss::math::TurnedPlaneInput in;
  in.width = s.width;
  in.height = s.height;
  in.irradiance = gpu.irradiance_half.data();
  in.footprint = plane_footprint(f);
  const Clock::time_point start = Clock::now();
  sss::math::convolve_turned_plane(in, sss::math::skin_profile_terms(), bounds_of(interior, s.width, s.height),
                                   r.image.rgb.data());
  r.seconds = seconds_since(start);
  return r;
}

// Anything else: the 2D reference on the interior receivers of a stride grid of at most max_receivers.
Reference grid_reference(const Frame& f, const GpuScene& gpu, const std::vector<uint8_t>& interior, int max_receivers) {
  const Scene& s = f.scene;
  const auto count = static_cast<double>(std::count(interior.begin(), interior.end(), uint8_t{1}));
  const int stride = std::max(1, static_cast<int>(std::ceil(std::sqrt(count / max_receivers))));
  Reference r;
  r.image = RgbImage::from_rgba(gpu.irradiance_half.data(), s.width, s.height);
  r.scored = interior;
  r.kind = "2D exact at stride " + std::to_string(stride);
  std::vector<std::size_t> pixels;
  for (std::size_t i = 0; i < interior.size(); ++i) {
    const int x = static_cast<int>(i % static_cast<std::size_t>(s.width)), y = static_cast<int>(i / static_cast<std::size_t>(s.width));
    if (interior[i] != 0 && on_grid(x, y, stride)) pixels.push_back(i);
    else r.scored[i] = 0;
  }
  const std::vector<double> distances = f.is_plane ? plane_distances(f) : std::vector<double>{};
  const Clock::time_point start = Clock::now();
  const sss::math::ExactSurfaceConvolution exact(exact_input(f, gpu, f.is_plane ? &distances : nullptr),
                                                 sss::math::skin_profile_terms());
  exact_at(exact, pixels, &r.image);
  r.seconds = seconds_since(start);
  return r;
}

// The closed form against the 2D reference (exact depth, its tail cut at 1e-12) at a few interior
// receivers of an orthographic plane: the largest relative difference.
double spot_check(const Frame& f, const GpuScene& gpu, const Reference& closed, int* checked) {
  std::vector<std::size_t> interior;
  for (std::size_t i = 0; i < closed.scored.size(); ++i) {
    if (closed.scored[i] != 0) interior.push_back(i);
  }
  constexpr std::size_t kChecks = 3;
  std::vector<std::size_t> pixels;
  for (std::size_t k = 0; k < std::min(kChecks, interior.size()); ++k) pixels.push_back(interior[(2 * k + 1) * interior.size() / (2 * kChecks)]);
  const std::vector<double> distances = plane_distances(f);
  sss::math::ExactOptions options;
  options.tail_mass = 1e-12;
  const sss::math::ExactSurfaceConvolution exact(exact_input(f, gpu, &distances), sss::math::skin_profile_terms(), options);
  RgbImage brute = closed.image;
  exact_at(exact, pixels, &brute);
  double worst = 0.0;
  for (std::size_t i : pixels) {
    for (std::size_t c = 0; c < 3; ++c) {
      worst = std::max(worst, std::fabs(brute.rgb[i * 3 + c] - closed.image.rgb[i * 3 + c]) / std::fabs(brute.rgb[i * 3 + c]));
    }
  }
  *checked += static_cast<int>(pixels.size());
  return worst;
}

// ---- The run ----

struct Sweep {
  const Options& options;
  std::vector<NamedMethod>& methods;
  RunInfo& info;
  std::vector<Row>& rows;
};

Row row_of(const Job& job, int side, const std::string& method, int taps, int passes, const Miss& miss,
           const std::string& reference, double needed) {
  Row r;
  r.scene = job.scene;
  r.projection = job.projection;
  r.turn_deg = job.turn_deg;
  r.axis_deg = job.axis_deg;
  r.footprint_mm = job.footprint_mm;
  r.width = side;
  r.method = method;
  r.taps = taps;
  r.passes = passes;
  r.miss = miss;
  r.reference = reference;
  r.needed = needed;
  return r;
}

void score_methods(Sweep& sweep, const Job& job, const GpuScene& gpu, const Reference& reference) {
  const int side = gpu.width;
  const RgbImage input = RgbImage::from_rgba(gpu.irradiance_half.data(), side, side);
  const Miss none = miss_share(input, reference.image, input, reference.scored.data());
  // 1 by definition (0 where nothing needed to change): anything else is a fault of the plumbing.
  if (none.pixels > 0 && none.pooled != 0.0 && !(std::fabs(none.pooled - 1.0) < 1e-12)) {
    throw std::runtime_error("the input's miss is " + std::to_string(none.pooled) + ", not 1");
  }
  const double needed = none.pixels > 0 ? relative_rmse(input, reference.image, reference.scored.data()) : std::nan("");
  sweep.rows.push_back(row_of(job, side, "no-scattering", 0, 0, none, reference.kind, needed));
  const GLuint output = make_output_texture(side, side);
  for (NamedMethod& m : sweep.methods) {
    std::string error;
    if (!m.method->run(gpu, output, &error)) {
      glDeleteTextures(1, &output);
      throw std::runtime_error(m.name + ": " + error);
    }
    const RgbImage result = RgbImage::from_rgba(read_texture_rgba(output, side, side).data(), side, side);
    sweep.rows.push_back(row_of(job, side, m.name, m.taps, m.method->passes(),
                                miss_share(result, reference.image, input, reference.scored.data()), reference.kind,
                                needed));
  }
  glDeleteTextures(1, &output);
}

std::string job_label(const Job& job) {
  char text[160];
  if (job.scene == "plane") {
    std::snprintf(text, sizeof text, "plane %s turned %g about %g, %.3g mm/px", job.projection.c_str(), job.turn_deg,
                  job.axis_deg, job.footprint_mm);
  } else {
    std::snprintf(text, sizeof text, "%s, %.3g mm/px", job.scene.c_str(), job.footprint_mm);
  }
  return text;
}

void run_job(Sweep& sweep, const Job& job) {
  const Clock::time_point start = Clock::now();
  const int side = sweep_frame_side(job.footprint_mm, kCalibrationInteriorPx, sweep.info.reach_mm);
  const Frame frame = build_frame(job, side);
  GpuScene gpu = upload_scene(frame.scene);
  const std::vector<uint8_t> interior =
      region_mask(classify_regions(region_input_of(frame.scene, sweep.info.reach_mm)), Region::interior);
  const bool closed = frame.is_plane && job.projection == "orthographic";
  const Reference reference =
      closed ? closed_form_reference(frame, gpu, interior) : grid_reference(frame, gpu, interior, sweep.options.max_receivers);
  if (std::count(reference.scored.begin(), reference.scored.end(), uint8_t{1}) == 0) {
    throw std::runtime_error(job_label(job) + ": no interior receiver to score");
  }
  if (closed) {
    const double difference = spot_check(frame, gpu, reference, &sweep.info.spot_checks);
    sweep.info.spot_check_worst = std::max(sweep.info.spot_check_worst, difference);
    if (!(difference < 1e-6)) throw std::runtime_error("the closed form differs from the 2D reference by " + std::to_string(difference));
  }
  score_methods(sweep, job, gpu, reference);
  destroy_scene(&gpu);
  const Row& first = sweep.rows[sweep.rows.size() - sweep.methods.size()];  // the first method's row
  std::printf("%s: %dx%d, %zu receivers (%s, %.1f s); %s miss %.3f; %.1f s\n", job_label(job).c_str(), side, side,
              first.miss.pixels, reference.kind.c_str(), reference.seconds,
              sweep.methods.empty() ? "no-scattering" : first.method.c_str(), first.miss.pooled, seconds_since(start));
  std::fflush(stdout);
}

std::string now_utc() {
  const std::time_t t = std::time(nullptr);
  char buffer[64];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%d %H:%M UTC", std::gmtime(&t));
  return buffer;
}

std::string gl_string(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s != nullptr ? reinterpret_cast<const char*>(s) : "unknown";
}

// The sweep in an open context; returns the process status.
int run(const Options& options, sss_headless* headless) {
  RunInfo info;
  info.renderer = gl_string(GL_RENDERER);
  info.version = gl_string(GL_VERSION);
  info.date = now_utc();
  info.reach_mm = profile_reach_mm(sss::math::skin_profile_terms());
  std::vector<Row> rows;
  const Clock::time_point start = Clock::now();
  try {
    std::vector<NamedMethod> methods = make_methods(GlLoader{sss_headless_get_proc_address, headless}, options);
    Sweep sweep{options, methods, info, rows};
    for (const Job& job : make_jobs(options)) run_job(sweep, job);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sss_bench_turns: %s\n", e.what());
    return 1;
  }
  info.seconds = seconds_since(start);
  std::filesystem::create_directories(options.out);
  write_csv(options.out + "/results.csv", rows);
  const std::string plot = write_plot(options.out, options, rows);
  write_document(options, info, rows, plot);
  std::printf("%zu rows in %.0f s: %s/results.csv, %s%s%s\n", rows.size(), info.seconds, options.out.c_str(),
              options.doc.c_str(), plot.empty() ? "" : ", ", plot.c_str());
  return 0;
}

}  // namespace

}  // namespace sss_bench::turns

int main(int argc, char** argv) {
  const sss_bench::turns::Options options = sss_bench::turns::parse(argc, argv);
  sss_headless_backend backend;
  if (sss_headless_backend_from_name(options.backend.c_str(), &backend) != 0) {
    std::fprintf(stderr, "sss_bench_turns: unknown backend %s\n", options.backend.c_str());
    return 2;
  }
  sss_headless* headless = sss_test::open_host_context(backend, "sss_bench_turns");
  if (headless == nullptr) return 1;
  const int status = sss_bench::turns::run(options, headless);
  sss_headless_destroy(headless);
  return status;
}
