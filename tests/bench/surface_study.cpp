// sss_surface_study: the choices behind the passes' walk over the surface (module/src/math/
// pass_surface.hpp), measured. The CPU model of the separable passes (cpu_separable_filter.hpp),
// which the GL passes match (tests/gl/surface_turns_test.cpp), runs each choice against its
// alternatives on the head scan and on curved and turned analytic surfaces, and the tool writes the
// interior miss (metrics.hpp) of each into a Markdown document (docs/benchmarks/surface-study.md):
//
//   - before: the passes of the previous phase, every surface stepped as if it faced the camera and
//     follow-surface on the raw depth difference (CpuWalkChoices::facing);
//   - the passes: the tangent blend and a ramp slack of kFollowSurfaceSlack;
//   - the tangent by the reference's switch, by the smaller depth change alone, or central;
//   - no slack, or twice the slack;
//   - per-tap chords (3D distances) instead of the centre's footprint;
//   - jittered taps (0.33), one frame and the mean of 8 frames whose noise index moves
//     (sss_frame.noise_index: a TAA host's view).
//
// Against two references, both the 2D surface convolution of exact_reference.hpp (d'Eon's skin
// profile, double) on the interior receivers of a stride grid:
//   - raw: the convolution as it is. On a scanned mesh it loses light where the profile's disc
//     crosses a crease of the mesh's depth (a triangle edge, a concavity), which no separable filter
//     reproduces;
//   - conserving: each receiver's value divided by the convolution of 1 at that receiver (its mass,
//     1 on a smooth surface), so the reference keeps the light a real skin keeps.
//
//   sss_surface_study [--backend egl|osmesa] [--scenes s,...] [--size WxH] [--stride N]
//                     [--doc FILE] [--csv FILE] [--check]
//                     [--pictures DIR [--picture-scenes s,...] [--picture-stride N]]
//
// --pictures: for the picture scenes (default head-grazing, the cheek turned about 70 degrees),
// which then run on a grid of --picture-stride (default 2), the input tone-mapped and heat maps of
// each result's distance from the raw reference on that grid (no scattering, before and the passes,
// both kernels, one scale), into DIR, shown in the document.
//
// --check: exit 1 unless the passes beat the previous phase (check() says how much) and no channel of
// their result is worse than doing nothing (miss 1): the tool's ctest.
#include <getopt.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "list_argument.hpp"
#include "host_context.hpp"
#include "math/cpu_separable_filter.hpp"
#include "math/exact_reference.hpp"
#include "math/half_float.hpp"
#include "math/kernel_request.hpp"
#include "math/pass_kernel.hpp"
#include "metrics.hpp"
#include "regions.hpp"
#include "scenes/scenes.hpp"
#include "sss_headless.h"

namespace {

using sss_bench::Miss;
using sss_bench::RgbImage;

struct Options {
  std::string backend = "egl";
  std::vector<std::string> scenes = {"head-close", "head-mid", "head-grazing", "cylinder", "sphere-40mm",
                                     "turned-60"};
  int width = 1920, height = 1080;  // the head scenes' frame; the analytic ones are square, `height` high
  int stride = 6;
  std::string doc = "docs/benchmarks/surface-study.md", csv;
  // --pictures DIR: heat maps of these scenes, which run on a grid of this stride instead.
  std::string pictures;
  std::vector<std::string> picture_scenes = {"head-grazing"};
  int picture_stride = 2;
  bool check = false;
  std::string command_line;
};

// The analytic scenes' footprint (mm per facing pixel): a 1080p close-up of a face.
constexpr double kAnalyticFootprintMm = 0.2;

[[noreturn]] void usage(const char* program, int status) {
  std::fprintf(status == 0 ? stdout : stderr,
               "usage: %s [--backend egl|osmesa] [--scenes s,...] [--size WxH] [--stride N] [--doc FILE] [--csv FILE]"
               " [--pictures DIR [--picture-scenes s,...] [--picture-stride N]] [--check]\n  scenes: head-close, head-mid, head-grazing, cylinder, sphere-40mm, turned-60\n",
               program);
  std::exit(status);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 0; i < argc; ++i) o.command_line += (i ? " " : "") + std::string(argv[i]);
  static const option long_options[] = {
      {"backend", required_argument, nullptr, 'b'}, {"scenes", required_argument, nullptr, 's'},
      {"size", required_argument, nullptr, 'z'},    {"stride", required_argument, nullptr, 't'},
      {"doc", required_argument, nullptr, 'd'},     {"csv", required_argument, nullptr, 'c'},
      {"pictures", required_argument, nullptr, 'p'}, {"picture-scenes", required_argument, nullptr, 'P'},
      {"picture-stride", required_argument, nullptr, 'S'},
      {"check", no_argument, nullptr, 'k'},         {"help", no_argument, nullptr, 'h'},
      {nullptr, 0, nullptr, 0}};
  for (int c; (c = getopt_long(argc, argv, "", long_options, nullptr)) != -1;) {
    const std::string arg = optarg != nullptr ? optarg : "";
    switch (c) {
      case 'b': o.backend = arg; break;
      case 's': o.scenes = sss_bench::split_list(arg, true); break;
      case 'z':
        if (std::sscanf(arg.c_str(), "%dx%d", &o.width, &o.height) != 2) usage(argv[0], 2);
        break;
      case 't': o.stride = std::atoi(arg.c_str()); break;
      case 'd': o.doc = arg; break;
      case 'c': o.csv = arg; break;
      case 'p': o.pictures = arg; break;
      case 'P': o.picture_scenes = sss_bench::split_list(arg, true); break;
      case 'S': o.picture_stride = std::atoi(arg.c_str()); break;
      case 'k': o.check = true; break;
      case 'h': usage(argv[0], 0);
      default: usage(argv[0], 2);
    }
  }
  const bool ok = optind == argc && (o.backend == "egl" || o.backend == "osmesa") && o.stride >= 1 && o.picture_stride >= 1 &&
                  o.width >= 64 && o.height >= 64 && o.width <= 8192 && o.height <= 8192 && !o.scenes.empty();
  if (!ok) usage(argv[0], 2);
  return o;
}

// ---- The choices and the kernels ----

// The jitter the study's jittered variants run with: the supplementary's 0.33.
constexpr float kStudyJitter = 0.33f;

struct Variant {
  std::string name, what;
  sss::math::CpuWalkChoices walk;
  float jitter = 0.0f;  // sss_settings.jitter of the kernel
  int frames = 1;       // the mean of this many frames, noise indices 0 .. frames - 1 (a TAA host's view)
};

std::vector<Variant> variants() {
  using sss::math::TangentRule;
  std::vector<Variant> out;
  Variant before{"before", "every surface stepped as if it faced the camera, raw depth difference (the previous phase)", {}};
  before.walk.facing = true;
  out.push_back(before);
  out.push_back({"passes", "what the passes do: tangent blend, slack 0.25", {}});
  Variant v{"tangent: reference's switch", "central where smooth, else the smaller depth change", {}};
  v.walk.tangent = TangentRule::reference;
  out.push_back(v);
  v = {"tangent: smaller step", "always the side with the smaller depth change", {}};
  v.walk.tangent = TangentRule::smaller_step;
  out.push_back(v);
  v = {"tangent: central", "always the central difference", {}};
  v.walk.tangent = TangentRule::central;
  out.push_back(v);
  v = {"slack 0", "the ramp on the whole off-surface distance", {}};
  v.walk.slack = 0.0f;
  out.push_back(v);
  v = {"slack 0.5", "twice the passes' slack", {}};
  v.walk.slack = 2.0f * sss::math::kFollowSurfaceSlack;
  out.push_back(v);
  v = {"chords", "each tap weighed by the kernel between the midpoints of the taps' 3D distances from the centre, "
                 "instead of the centre's footprint for every tap (the passes keep the latter: cost)", {}};
  v.walk.chords = true;
  out.push_back(v);
  // The jittered taps (the supplementary's share), one frame and the mean of 8 frames with the noise
  // index moving (sss_frame.noise_index): what a host that averages frames sees.
  v = {"jitter 0.33, one frame", "the outer third of the taps jittered per pixel, one frame", {}};
  v.jitter = kStudyJitter;
  out.push_back(v);
  v = {"jitter 0.33, 8 frames", "the same, the mean of 8 frames with noise indices 0-7", {}};
  v.jitter = kStudyJitter;
  v.frames = 8;
  out.push_back(v);
  return out;
}

struct Family {
  std::string name;
  sss::math::FilterSettings settings;
};

// The default kernel and the sum of Gaussians at sss_bench's rank (separable_method.cpp).
std::vector<Family> families() {
  Family sog{"sum of Gaussians", {}};
  sog.settings.kernel.family = sss::math::KernelFamily::sum_of_gaussians;
  sog.settings.kernel.rank = 6;
  return {{"default", {}}, sog};
}

// ---- The scenes and their references ----

sss_bench::Scene build_scene(const std::string& name, const Options& o) {
  if (name == "cylinder") return sss_bench::make_cylinder_scene(kAnalyticFootprintMm, o.height, o.height);
  if (name == "sphere-40mm") return sss_bench::make_footprint_sphere_scene(kAnalyticFootprintMm, o.height, o.height);
  if (name == "turned-60") {
    // 60 degrees about an axis 30 degrees off screen x, under the perspective camera.
    return sss_bench::make_turned_plane_scene(kAnalyticFootprintMm, 60.0, 30.0, false, o.height, o.height);
  }
  return sss_bench::make_scene(name, o.width, o.height);
}

struct Receivers {
  std::vector<std::size_t> pixels;  // the receivers: pixels on the stride grid (below)
  std::vector<uint8_t> interior;    // per receiver: 1 in the interior (regions.hpp), which is scored
  RgbImage input, raw, conserving;  // at those pixels (pixels.size() x 1)
};

// The 2D reference of `irradiance` at the receivers, two threads.
void convolve_at(const sss::math::ExactSurfaceConvolution& exact, int width, const std::vector<std::size_t>& pixels,
                 RgbImage* out) {
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    for (std::size_t i; (i = next++) < pixels.size();) {
      const auto v = exact.at(static_cast<int>(pixels[i] % static_cast<std::size_t>(width)),
                              static_cast<int>(pixels[i] / static_cast<std::size_t>(width)));
      for (int c = 0; c < 3; ++c) out->at(static_cast<int>(i), 0, c) = v[static_cast<std::size_t>(c)];
    }
  };
  std::thread helper(work);
  work();
  helper.join();
}

sss_bench::RegionInput region_input(const sss_bench::Scene& scene) {
  sss_bench::RegionInput in;
  in.width = scene.width;
  in.height = scene.height;
  in.mask = scene.mask.data();
  in.distance = scene.distance.data();
  for (std::size_t i = 0; i < 16; ++i) in.projection[i] = scene.projection[i];
  in.world_units_per_mm = scene.world_units_per_mm;
  in.reach_mm = sss_bench::profile_reach_mm(sss::math::skin_profile_terms());
  return in;
}

// The receivers on the stride grid: the interior's, and with `every_translucent` (pictures) the
// silhouettes' and borders' too, which are shown but not scored.
Receivers make_receivers(const sss_bench::Scene& scene, const std::vector<float>& irradiance, int stride,
                         bool every_translucent) {
  const std::vector<uint8_t> regions = sss_bench::classify_regions(region_input(scene));
  Receivers r;
  for (int y = stride / 2; y < scene.height; y += stride) {
    for (int x = stride / 2; x < scene.width; x += stride) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(scene.width) + static_cast<std::size_t>(x);
      const bool interior = regions[i] == static_cast<uint8_t>(sss_bench::Region::interior);
      if (interior || (every_translucent && scene.mask[i] != 0)) {
        r.pixels.push_back(i);
        r.interior.push_back(interior ? 1 : 0);
      }
    }
  }
  const int n = static_cast<int>(r.pixels.size());
  r.input = RgbImage(n, 1);
  r.raw = RgbImage(n, 1);
  RgbImage mass(n, 1);
  for (int i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) r.input.at(i, 0, c) = irradiance[r.pixels[static_cast<std::size_t>(i)] * 4 + static_cast<std::size_t>(c)];
  }
  sss::math::ExactInput in;
  in.width = scene.width;
  in.height = scene.height;
  in.irradiance = irradiance.data();
  in.distance = scene.distance.data();
  in.mask = scene.mask.data();
  for (std::size_t i = 0; i < 16; ++i) in.projection[i] = scene.projection[i];
  in.world_units_per_mm = scene.world_units_per_mm;
  convolve_at(sss::math::ExactSurfaceConvolution(in, sss::math::skin_profile_terms()), scene.width, r.pixels, &r.raw);
  const std::vector<float> ones(irradiance.size(), 1.0f);
  in.irradiance = ones.data();
  convolve_at(sss::math::ExactSurfaceConvolution(in, sss::math::skin_profile_terms()), scene.width, r.pixels, &mass);
  r.conserving = r.raw;
  for (std::size_t k = 0; k < r.conserving.rgb.size(); ++k) r.conserving.rgb[k] /= mass.rgb[k];
  return r;
}

// ---- The pictures ----

std::string fixed(double v, int digits = 3) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", digits, v);
  return text;
}


struct Picture {
  std::string file, caption;  // file: relative to the pictures' directory
};

struct ScenePictures {
  std::string scene;
  std::vector<Picture> pictures;
};

// The receivers' grid as an image: receiver pixel (x, y) at cell (x / stride, y / stride).
struct Grid {
  int stride = 1, width = 0, height = 0, scene_width = 0;
  std::vector<uint8_t> mask;  // 1 at the receivers' cells

  Grid(const sss_bench::Scene& scene, const Receivers& r, int s)
      : stride(s), width((scene.width + s - 1) / s), height((scene.height + s - 1) / s), scene_width(scene.width),
        mask(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0) {
    for (std::size_t p : r.pixels) mask[cell(p)] = 1;
  }
  std::size_t cell(std::size_t pixel) const {
    const std::size_t w = static_cast<std::size_t>(scene_width), st = static_cast<std::size_t>(stride);
    return (pixel / w / st) * static_cast<std::size_t>(width) + (pixel % w) / st;
  }
  // Values at the receivers (one per receiver, in their order) as a grid image.
  RgbImage place(const Receivers& r, const RgbImage& values) const {
    RgbImage out(width, height);
    for (std::size_t i = 0; i < r.pixels.size(); ++i) {
      for (std::size_t c = 0; c < 3; ++c) out.rgb[cell(r.pixels[i]) * 3 + c] = values.rgb[i * 3 + c];
    }
    return out;
  }
};

// Writes the picture, or throws: a document must not show a picture that is not there.
void write_heat_map(const std::string& dir, const std::string& file, const Grid& grid, const RgbImage& image,
                    const RgbImage& reference, double scale) {
  if (!sss_bench::write_error_heatmap_png(dir + "/" + file, image, reference, grid.mask.data(), scale)) {
    throw std::runtime_error("cannot write " + dir + "/" + file);
  }
}

// The heat maps' top: the 99th percentile, over the scored receivers, of the largest channel of the
// change scattering makes (|input - raw reference|), so that the no-scattering map shows the change
// to make and each result's map the share of it left.
double change_scale(const Receivers& r) {
  std::vector<double> change;
  for (std::size_t i = 0; i < r.pixels.size(); ++i) {
    if (r.interior[i] == 0) continue;
    double e = 0.0;
    for (std::size_t c = 0; c < 3; ++c) e = std::max(e, std::fabs(r.input.rgb[i * 3 + c] - r.raw.rgb[i * 3 + c]));
    change.push_back(e);
  }
  if (change.empty()) return 1.0;
  const auto at = change.begin() + static_cast<std::ptrdiff_t>(change.size() * 99 / 100);
  std::nth_element(change.begin(), at, change.end());
  return *at > 0.0 ? *at : 1.0;
}

// ---- The runs ----

// The row of the conserving reference itself: what a filter that keeps light and is otherwise
// exact would score against the raw reference.
const char* const kConservingFloor = "the conserving reference itself";

struct Row {
  std::string scene, family, variant;
  int receivers = 0;
  double median_footprint_mm = 0.0;
  Miss raw, conserving;
};

// Every family and variant on one scene; with `pictures` the scene's pictures too.
std::vector<Row> study_scene(const sss_bench::Scene& scene, const Options& o, ScenePictures* pictures) {
  const std::size_t n = static_cast<std::size_t>(scene.width) * static_cast<std::size_t>(scene.height);
  // The colour as the passes get it: RGBA16F, alpha the strength.
  std::vector<float> colour(scene.irradiance.size());
  for (std::size_t i = 0; i < colour.size(); ++i) colour[i] = sss::math::round_to_half(scene.irradiance[i]);
  for (std::size_t i = 0; i < n; ++i) colour[i * 4 + 3] = scene.mask[i] != 0 ? 1.0f : 0.0f;
  const Receivers receivers =
      make_receivers(scene, colour, pictures != nullptr ? o.picture_stride : o.stride, pictures != nullptr);
  const int scored = static_cast<int>(std::count(receivers.interior.begin(), receivers.interior.end(), 1));
  const double footprint = sss_bench::median_footprint_mm(region_input(scene));

  std::unique_ptr<Grid> grid;
  RgbImage grid_reference;
  double scale = 1.0;
  if (pictures != nullptr) {
    grid = std::make_unique<Grid>(scene, receivers, o.picture_stride);
    grid_reference = grid->place(receivers, receivers.raw);
    scale = change_scale(receivers);
    pictures->scene = scene.name;
    const std::string input = scene.name + "-input.png";
    if (!sss_bench::write_tonemapped_png(o.pictures + "/" + input, RgbImage::from_rgba(colour.data(), scene.width, scene.height))) {
      throw std::runtime_error("cannot write " + o.pictures + "/" + input);
    }
    pictures->pictures.push_back({input, "the input (tone-mapped)"});
    const std::string none = scene.name + "-no-scattering-error.png";
    write_heat_map(o.pictures, none, *grid, grid->place(receivers, receivers.input), grid_reference, scale);
    pictures->pictures.push_back({none, "no scattering: the change to make"});
  }

  // The floor of any filter that keeps light: the conserving reference scored against the raw one.
  std::vector<Row> rows = {{scene.name, "–", kConservingFloor, scored, footprint, {}, {}}};
  rows.front().raw = sss_bench::miss_share(receivers.conserving, receivers.raw, receivers.input, receivers.interior.data());
  rows.front().conserving = sss_bench::miss_share(receivers.conserving, receivers.conserving, receivers.input,
                                                  receivers.interior.data());
  std::vector<float> out(n * 4);
  for (const Family& family : families()) {
    const sss::math::PassKernel kernel = sss::math::build_pass_kernel(family.settings);
    sss::math::FrameGeometry geometry;
    geometry.texture_width = scene.width;
    geometry.texture_height = scene.height;
    geometry.viewport = {0, 0, scene.width, scene.height};
    sss::math::Matrix4 projection{};
    for (std::size_t i = 0; i < 16; ++i) projection[i] = scene.projection[i];
    const sss::math::PassConstants constants =
        sss::math::compute_pass_constants(family.settings, projection, geometry, kernel.reach_mm);
    sss::math::FilterSettings jittered_settings = family.settings;
    jittered_settings.jitter = kStudyJitter;
    const sss::math::PassKernel jittered = sss::math::build_pass_kernel(jittered_settings);
    for (const Variant& variant : variants()) {
      sss::math::CpuFilterImage image =
          sss::math::cpu_filter_image(scene.width, scene.height, colour.data(), scene.window_depth.data());
      image.output_is_half = true;
      image.walk = variant.walk;
      const sss::math::PassKernel& run = variant.jitter > 0.0f ? jittered : kernel;
      std::vector<double> sum(variant.frames > 1 ? out.size() : 0, 0.0);
      for (int frame = 0; frame < variant.frames; ++frame) {
        image.noise_index = static_cast<std::uint32_t>(frame);
        sss::math::cpu_pass_kernel_filter(run, constants, image, out.data());
        for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += out[i];
      }
      for (std::size_t i = 0; i < sum.size(); ++i) out[i] = static_cast<float>(sum[i] / variant.frames);
      RgbImage result(static_cast<int>(receivers.pixels.size()), 1);
      for (std::size_t i = 0; i < receivers.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) result.at(static_cast<int>(i), 0, c) = out[receivers.pixels[i] * 4 + static_cast<std::size_t>(c)];
      }
      Row row{scene.name, family.name, variant.name, scored, footprint, {}, {}};
      row.raw = sss_bench::miss_share(result, receivers.raw, receivers.input, receivers.interior.data());
      row.conserving = sss_bench::miss_share(result, receivers.conserving, receivers.input, receivers.interior.data());
      rows.push_back(row);
      if (grid != nullptr && (variant.name == "before" || variant.name == "passes")) {
        const std::string file = scene.name + "-" + (family.name == "default" ? "default" : "sum-of-gaussians") + "-" +
                                 variant.name + "-error.png";
        write_heat_map(o.pictures, file, *grid, grid->place(receivers, result), grid_reference, scale);
        pictures->pictures.push_back({file, family.name + ", " + variant.name + ": miss " + fixed(row.raw.pooled)});
      }
    }
  }
  return rows;
}

// ---- The document ----

std::string miss_cell(const Miss& m) {
  return "**" + fixed(m.pooled) + "** (" + fixed(m.channel[0]) + " / " + fixed(m.channel[1]) + " / " +
         fixed(m.channel[2]) + ")";
}

std::string now_utc() {
  const std::time_t t = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", std::gmtime(&t));
  return text;
}

// The pictures of one scene: a table of images two a row, the caption under each.
void write_pictures(std::ofstream& doc, const Options& o, const ScenePictures& p) {
  const std::filesystem::path doc_dir = std::filesystem::path(o.doc).parent_path();
  const std::string dir = std::filesystem::relative(o.pictures, doc_dir.empty() ? "." : doc_dir).generic_string();
  doc << "\n## Pictures: " << p.scene << "\n\n"
      << "Heat maps of each result's largest channel distance from the raw reference on a grid of "
         "receivers (one cell a receiver, every " << o.picture_stride << " pixels; grey: not translucent), "
         "the silhouettes and borders shown too though only the interior is scored, one scale for all: "
         "the top of the ramp is the 99th percentile of the change scattering makes in the interior, so "
         "the no-scattering map is the change to make and each result's map what it leaves undone. "
         "Head scan: "
      << sss_bench::head_attribution() << "\n\n| | |\n|---|---|\n";
  for (std::size_t i = 0; i < p.pictures.size(); i += 2) {
    doc << "|";
    for (std::size_t k = i; k < i + 2; ++k) {
      if (k < p.pictures.size()) doc << " ![" << p.pictures[k].caption << "](" << dir << "/" << p.pictures[k].file << ")<br>" << p.pictures[k].caption;
      doc << " |";
    }
    doc << "\n";
  }
}

void write_document(const Options& o, const std::vector<Row>& rows, const std::vector<ScenePictures>& pictures,
                    double seconds) {
  std::filesystem::path path(o.doc);
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  std::ofstream doc(o.doc);
  doc << "# How the passes walk the surface: the choices, measured\n\n"
      << "Generated by `sss_surface_study` (tests/bench/surface_study.cpp) on " << now_utc() << " in "
      << fixed(seconds, 0) << " s:\n\n    " << o.command_line << "\n\n"
      << "The CPU model of the separable passes (module/src/math/cpu_separable_filter.hpp; the GL passes "
         "match it, tests/gl/surface_turns_test.cpp) with each choice of docs/surface-turns.md against its "
         "alternatives, scored by the interior miss (docs/benchmark.md: the share of the change scattering "
         "makes that a method leaves undone; 0 exact, 1 doing nothing) on the interior receivers of a "
         "stride-" << o.stride << " grid (the pictured scenes' stride " << o.picture_stride
      << "), pooled **in bold**, then red / green / blue. Two references, both "
         "the 2D surface convolution with d'Eon's six Gaussians (module/src/math/exact_reference.hpp):\n\n"
         "- **raw**: the convolution as it is. On the scanned head it loses light wherever the profile's "
         "disc crosses a crease of the mesh's depth (a triangle edge, a concavity under the eye): a "
         "receiver there gets less than the light around it even under uniform light, which no filter "
         "that keeps light reproduces;\n"
         "- **conserving**: each receiver's value divided by the convolution of uniform light at that "
         "receiver (its mass: 1 on a smooth surface), the light a real skin keeps. Each scene's first "
         "row scores the conserving reference itself against the raw one: the floor of any filter that "
         "keeps light, however exact otherwise.\n\n"
         "The head scenes are " << o.width << "x" << o.height << "; the analytic ones "
      << o.height << "x" << o.height << " at " << kAnalyticFootprintMm << " mm per facing pixel: a "
         "cylinder and a sphere of radius 40 mm, and a plane turned 60 degrees about an axis 30 degrees "
         "off screen x (scenes.hpp). The variants:\n\n";
  for (const Variant& v : variants()) doc << "- **" << v.name << "**: " << v.what << "\n";
  doc << "\nHead scan: " << sss_bench::head_attribution() << "\n";
  std::string scene;
  for (const Row& r : rows) {
    if (r.scene != scene) {
      scene = r.scene;
      doc << "\n## " << scene << " (" << r.receivers << " receivers, median footprint " << fixed(r.median_footprint_mm)
          << " mm per pixel)\n\n"
          << "| kernel | variant | miss, raw reference | miss, conserving reference |\n|---|---|---|---|\n";
    }
    doc << "| " << r.family << " | " << r.variant << " | " << miss_cell(r.raw) << " | " << miss_cell(r.conserving)
        << " |\n";
  }
  for (const ScenePictures& p : pictures) write_pictures(doc, o, p);
}

void write_csv(const std::string& path, const std::vector<Row>& rows) {
  std::ofstream csv(path);
  csv << "scene,kernel,variant,receivers,median_footprint_mm,raw_pooled,raw_r,raw_g,raw_b,conserving_pooled,"
         "conserving_r,conserving_g,conserving_b\n";
  for (const Row& r : rows) {
    csv << r.scene << "," << r.family << "," << r.variant << "," << r.receivers << "," << r.median_footprint_mm;
    for (const Miss* m : {&r.raw, &r.conserving}) {
      csv << "," << m->pooled << "," << m->channel[0] << "," << m->channel[1] << "," << m->channel[2];
    }
    csv << "\n";
  }
}

// --check, on every scene: the sum of Gaussians, whose error on a facing plane is its taps' alone,
// misses less than before against both references (the walk is what changed); the default is no
// more than kDefaultSlack worse than before (issue 40's tolerance against the facing plane: its
// rank-limited kernel is fitted on facing planes, and on a sphere at 0.2 mm per pixel the walk's
// anisotropic footprints cost it a little while the turned plane and the head gain); and no
// channel of either is worse than doing nothing.
constexpr double kDefaultSlack = 0.05;

int check(const std::vector<Row>& rows) {
  int failures = 0;
  for (const Row& passes : rows) {
    if (passes.variant != "passes") continue;
    for (const Row& before : rows) {
      if (before.variant != "before" || before.scene != passes.scene || before.family != passes.family) continue;
      const double slack = passes.family == "default" ? kDefaultSlack : 0.0;
      const bool better = passes.raw.pooled < before.raw.pooled + slack &&
                          passes.conserving.pooled < before.conserving.pooled + slack;
      const bool no_worse = passes.raw.worst_channel() < 1.0 && passes.conserving.worst_channel() < 1.0;
      if (!better || !no_worse) {
        std::fprintf(stderr, "sss_surface_study: %s, %s: the passes miss %.3f / %.3f (worst channel %.3f / %.3f), "
                             "before %.3f / %.3f (raw / conserving)\n",
                     passes.scene.c_str(), passes.family.c_str(), passes.raw.pooled, passes.conserving.pooled,
                     passes.raw.worst_channel(), passes.conserving.worst_channel(), before.raw.pooled,
                     before.conserving.pooled);
        ++failures;
      }
    }
  }
  return failures == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  const auto start = std::chrono::steady_clock::now();
  sss_headless* headless = sss_test::open_host_context(
      o.backend == "osmesa" ? SSS_HEADLESS_OSMESA : SSS_HEADLESS_EGL_SURFACELESS, "sss_surface_study");
  if (headless == nullptr) return 1;
  std::vector<Row> rows;
  std::vector<ScenePictures> pictures;
  try {
    if (!o.pictures.empty()) std::filesystem::create_directories(o.pictures);
    for (const std::string& name : o.scenes) {
      const sss_bench::Scene scene = build_scene(name, o);
      const bool pictured = !o.pictures.empty() &&
                            std::find(o.picture_scenes.begin(), o.picture_scenes.end(), name) != o.picture_scenes.end();
      if (pictured) pictures.emplace_back();
      const std::vector<Row> scene_rows = study_scene(scene, o, pictured ? &pictures.back() : nullptr);
      for (const Row& r : scene_rows) {
        std::printf("%-14s %-17s %-28s raw %.3f  conserving %.3f\n", r.scene.c_str(), r.family.c_str(),
                    r.variant.c_str(), r.raw.pooled, r.conserving.pooled);
      }
      std::fflush(stdout);
      rows.insert(rows.end(), scene_rows.begin(), scene_rows.end());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sss_surface_study: %s\n", e.what());
    sss_headless_destroy(headless);
    return 1;
  }
  sss_headless_destroy(headless);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_document(o, rows, pictures, seconds);
  if (!o.csv.empty()) write_csv(o.csv, rows);
  std::printf("sss_surface_study: wrote %s\n", o.doc.c_str());
  return o.check ? check(rows) : 0;
}
