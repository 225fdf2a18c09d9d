// sss_bench_texturing: the texturing modes (sss.h sss_texturing, issue 48) on facing planes with an
// albedo at pore scale, run through the library on GL and scored against each mode's exact answer.
//
// Each frame is the turn sweep's orthographic plane facing the camera (its light: a soft-edged
// pattern) at one footprint, its colour the light E times an albedo A that varies at pore scale:
// a checker of 0.5 mm cells, or value noise of 0.2 mm cells. A mode with A_pre · A_post = A (pre-scatter
// A_pre = A; post-scatter A_post = A; pre- and post-scatter √A each) has the exact answer
//   A_post ⊙ (R ∗ (colour / A_post))
// with R d'Eon's six-Gaussian skin profile convolved on the plane in closed form
// (plane_reference.hpp: exact for light constant over each pixel, which the colour is), A_post floored
// as the library floors it (sss.h). The rows:
//   - miss: each method in each mode against that mode's own answer, on the interior (regions.hpp),
//     beside the same method on the same light without the albedo ("untextured": pre-scatter on E);
//   - detail kept: the power of the output's high frequencies (the image minus its mean over a
//     1 mm box: roughly what lies above 1 cycle per mm) over the input's, beside the exact answer's.
// Post-scatter's output keeps the albedo's detail (its answer has it all: the light is smooth at that
// scale); pre-scatter's blurs it. Writes results.csv and a Markdown document (--doc); exits 1 when
// post-scatter under a uniform light keeps the albedo's detail less closely than 2 % of its answer.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "../support/kernel_of.hpp"
#include "calibration.hpp"
#include "gpu_scene.hpp"
#include "host_context.hpp"
#include "host_gl.hpp"
#include "list_argument.hpp"
#include "math/cpu_texturing.hpp"
#include "math/half_float.hpp"
#include "math/plane_reference.hpp"
#include "metrics.hpp"
#include "regions.hpp"
#include "scenes/scenes.hpp"
#include "sss/sss_tools.h"
#include "sss_headless.h"
#include "sweep_geometry.hpp"

namespace sss_bench::texturing {
namespace {

using namespace host_gl;

struct Options {
  std::string backend = "egl";
  std::vector<double> footprints = {0.05, 0.1, 0.2, 0.5, 1.0};  // mm per pixel
  std::string out = "bench-out/texturing", doc = "docs/benchmarks/texturing.md";
  std::string command_line;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 0; i < argc; ++i) o.command_line += std::string(i > 0 ? " " : "") + argv[i];
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--backend") {
      o.backend = value;
    } else if (key == "--footprints") {
      o.footprints.clear();
      for (const std::string& item : split_list(value, true)) o.footprints.push_back(std::atof(item.c_str()));
    } else if (key == "--out") {
      o.out = value;
    } else if (key == "--doc") {
      o.doc = value;
    } else {
      std::fprintf(stderr, "usage: sss_bench_texturing [--backend egl|osmesa] [--footprints a,b,...] [--out DIR] "
                           "[--doc FILE.md]\n");
      std::exit(2);
    }
  }
  return o;
}

// The albedos (RGBA, alpha 1), at pixel (x, y) of a plane of `footprint` mm per pixel: skin-like
// base colours modulated at pore scale.
enum class Albedo { checker, noise };
const char* albedo_name(Albedo a) { return a == Albedo::checker ? "checker 0.5 mm" : "noise 0.2 mm"; }

// A hash of a cell to [0, 1).
double cell_hash(long long cx, long long cy, int channel) {
  unsigned long long h = static_cast<unsigned long long>(cx) * 0x9E3779B97F4A7C15ull ^
                         static_cast<unsigned long long>(cy) * 0xC2B2AE3D27D4EB4Full ^
                         static_cast<unsigned long long>(channel + 1) * 0x165667B19E3779F9ull;
  h ^= h >> 29;
  h *= 0xBF58476D1CE4E5B9ull;
  h ^= h >> 32;
  return static_cast<double>(h % 1000003ull) / 1000003.0;
}

std::vector<float> make_albedo(Albedo kind, int width, int height, double footprint_mm) {
  const double base[3] = {0.75, 0.5, 0.4};
  std::vector<float> a(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 1.0f);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double mx = (x + 0.5) * footprint_mm, my = (y + 0.5) * footprint_mm;
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
      for (int c = 0; c < 3; ++c) {
        double m = 1.0;
        if (kind == Albedo::checker) {
          const long long cx = static_cast<long long>(std::floor(mx / 0.5)), cy = static_cast<long long>(std::floor(my / 0.5));
          m = ((cx + cy) % 2 == 0) ? 0.6 : 1.2;
        } else {
          const long long cx = static_cast<long long>(std::floor(mx / 0.2)), cy = static_cast<long long>(std::floor(my / 0.2));
          m = 0.6 + 0.6 * cell_hash(cx, cy, c);
        }
        a[i * 4 + static_cast<std::size_t>(c)] = sss::math::round_to_half(static_cast<float>(base[c] * m));
      }
    }
  }
  return a;
}

struct Row {
  double footprint_mm = 0.0;
  std::string light, albedo, method, mode;
  Miss miss;                  // against the mode's own answer
  double untextured = 0.0;    // the same method's pooled miss on the light alone (pre-scatter)
  double detail = 0.0;        // the output's high-frequency power over the input's
  double detail_exact = 0.0;  // the mode's exact answer's
  double needed = 0.0;        // ‖input − answer‖ / ‖answer‖ on the interior: the change the mode asks for
};

// The power of `image`'s high frequencies over the selected pixels: the image minus its mean over a
// box of 1 mm (the box clipped to the image), summed over the channels.
double high_frequency_power(const RgbImage& image, const std::vector<uint8_t>& selected, double footprint_mm) {
  const int r = std::max(1, static_cast<int>(std::lround(0.5 / footprint_mm)));
  double power = 0.0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (selected[image.index(x, y)] == 0) continue;
      for (int c = 0; c < 3; ++c) {
        double sum = 0.0;
        int n = 0;
        for (int dy = -r; dy <= r; ++dy) {
          for (int dx = -r; dx <= r; ++dx) {
            const int sx = x + dx, sy = y + dy;
            if (sx < 0 || sy < 0 || sx >= image.width || sy >= image.height) continue;
            sum += image.at(sx, sy, c);
            ++n;
          }
        }
        const double d = image.at(x, y, c) - sum / n;
        power += d * d;
      }
    }
  }
  return power;
}

struct MethodChoice {
  std::string name;  // "separable" (the default) or "sum-of-gaussians"
  bool sum_of_gaussians = false;
};

// The library on `colour` (RGBA16F) with `albedo` in `mode`, into an RGBA32F output, read back.
std::vector<float> run_library(sss_context* ctx, const GpuScene& gpu, const MethodChoice& m, unsigned mode,
                               const std::vector<float>& colour, const std::vector<float>& albedo) {
  const int w = gpu.width, h = gpu.height;
  sss_settings s;
  sss_default_settings(&s);
  s.world_units_per_mm = gpu.world_units_per_mm;
  s.path = SSS_PATH_FRAGMENT;
  s.texturing = mode;
  if (m.sum_of_gaussians) {
    sss_test::kernel_of(s).family = SSS_KERNEL_SUM_OF_GAUSSIANS;
    sss_test::kernel_of(s).rank = 6;
  }
  GLuint textures[3] = {0, 0, 0};
  glGenTextures(3, textures);
  const auto upload = [&](GLuint t, GLenum format, const float* data) {
    glBindTexture(GL_TEXTURE_2D, t);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, format, w, h, 0, GL_RGBA, GL_FLOAT, data);
  };
  upload(textures[0], GL_RGBA16F, colour.data());
  upload(textures[1], GL_RGBA16F, albedo.data());
  upload(textures[2], GL_RGBA32F, nullptr);
  glBindTexture(GL_TEXTURE_2D, 0);
  sss_frame frame = {};
  frame.struct_size = sizeof frame;
  frame.color_texture = textures[0];
  frame.depth_texture = gpu.depth;
  frame.output_texture = textures[2];
  frame.albedo_texture = mode != SSS_TEXTURING_PRE_SCATTER ? textures[1] : 0u;
  if (sss_set_settings(ctx, &s) != SSS_OK || sss_set_camera(ctx, gpu.projection.data()) != SSS_OK ||
      sss_apply_frame(ctx, &frame) != SSS_OK) {
    throw std::runtime_error(std::string("the library: ") + sss_last_error(ctx));
  }
  std::vector<float> out = read_texture_rgba(textures[2], w, h);
  glDeleteTextures(3, textures);
  return out;
}

// The mode's exact answer: A_post ⊙ (R ∗ (colour / A_post)) on the plane, over the interior.
RgbImage exact_answer(const Scene& scene, const std::vector<float>& colour, const std::vector<float>& albedo,
                      unsigned mode, const std::vector<uint8_t>& interior, const sss::math::TurnedPlaneFootprint& fp) {
  const std::size_t n = static_cast<std::size_t>(scene.width) * static_cast<std::size_t>(scene.height);
  const std::vector<float> post = sss::math::albedo_post_plane(albedo.data(), n, {mode});
  const std::vector<float> light = sss::math::colour_over_albedo(colour.data(), post, false);
  RgbImage answer = RgbImage::from_rgba(colour.data(), scene.width, scene.height);
  sss::math::TurnedPlaneInput in;
  in.width = scene.width;
  in.height = scene.height;
  in.irradiance = light.data();
  in.footprint = fp;
  int x0 = scene.width, y0 = scene.height, x1 = -1, y1 = -1;
  for (int y = 0; y < scene.height; ++y) {
    for (int x = 0; x < scene.width; ++x) {
      if (interior[answer.index(x, y)] == 0) continue;
      x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
    }
  }
  sss::math::convolve_turned_plane(in, sss::math::skin_profile_terms(), {x0, y0, x1 - x0 + 1, y1 - y0 + 1},
                                   answer.rgb.data());
  for (std::size_t i = 0; i < n; ++i) {
    if (interior[i] == 0) continue;
    for (std::size_t c = 0; c < 3; ++c) answer.rgb[i * 3 + c] *= post[i * 3 + c];
  }
  return answer;
}

const char* mode_name(unsigned mode) {
  return mode == SSS_TEXTURING_PRE_SCATTER ? "pre-scatter"
                                           : (mode == SSS_TEXTURING_POST_SCATTER ? "post-scatter" : "pre- and post-scatter");
}

// One light over both albedos: each method in each mode, and on the light alone.
void run_light(sss_context* ctx, const Scene& scene, const GpuScene& gpu, const std::vector<uint8_t>& interior,
               const sss::math::TurnedPlaneFootprint& fp, const std::vector<MethodChoice>& methods,
               double footprint_mm, const char* light_name, const std::vector<float>& light, std::vector<Row>* rows) {
  const int side = scene.width;
  const std::vector<float> ones(light.size(), 1.0f);
  const RgbImage light_input = RgbImage::from_rgba(light.data(), side, side);
  const RgbImage light_answer = exact_answer(scene, light, ones, SSS_TEXTURING_PRE_SCATTER, interior, fp);
  for (const Albedo kind : {Albedo::checker, Albedo::noise}) {
    const std::vector<float> albedo = make_albedo(kind, side, side, footprint_mm);
    std::vector<float> colour = light;
    for (std::size_t i = 0; i < colour.size(); ++i) {
      if (i % 4 != 3) colour[i] = sss::math::round_to_half(light[i] * albedo[i]);
    }
    const RgbImage input = RgbImage::from_rgba(colour.data(), side, side);
    const double input_detail = high_frequency_power(input, interior, footprint_mm);
    for (const MethodChoice& method : methods) {
      const RgbImage untextured_out =
          RgbImage::from_rgba(run_library(ctx, gpu, method, SSS_TEXTURING_PRE_SCATTER, light, ones).data(), side, side);
      const double untextured = miss_share(untextured_out, light_answer, light_input, interior.data()).pooled;
      for (const unsigned mode :
           {SSS_TEXTURING_PRE_SCATTER, SSS_TEXTURING_POST_SCATTER, SSS_TEXTURING_PRE_AND_POST_SCATTER}) {
        const RgbImage answer = exact_answer(scene, colour, albedo, mode, interior, fp);
        const RgbImage out =
            RgbImage::from_rgba(run_library(ctx, gpu, method, mode, colour, albedo).data(), side, side);
        Row r;
        r.footprint_mm = footprint_mm;
        r.light = light_name;
        r.albedo = albedo_name(kind);
        r.method = method.name;
        r.mode = mode_name(mode);
        r.miss = miss_share(out, answer, input, interior.data());
        r.untextured = untextured;
        r.needed = relative_rmse(input, answer, interior.data());
        // No detail in the input (a uniform light over cells the pixels do not resolve): nothing to keep.
        const double nan = std::numeric_limits<double>::quiet_NaN();
        r.detail = input_detail > 0.0 ? high_frequency_power(out, interior, footprint_mm) / input_detail : nan;
        r.detail_exact = input_detail > 0.0 ? high_frequency_power(answer, interior, footprint_mm) / input_detail : nan;
        rows->push_back(r);
        std::printf("%.3f mm/px, %s light, %s, %s, %s: miss %.3f (untextured %.3f), detail kept %.3f (exact %.3f)\n",
                    footprint_mm, light_name, r.albedo.c_str(), r.method.c_str(), r.mode.c_str(), r.miss.pooled, untextured,
                    r.detail, r.detail_exact);
        std::fflush(stdout);
      }
    }
  }
}

void run_footprint(sss_context* ctx, double footprint_mm, double reach_mm, std::vector<Row>* rows) {
  const int side = sweep_frame_side(footprint_mm, kCalibrationInteriorPx, reach_mm);
  PlaneGeometry plane;
  const Scene scene = make_turned_plane_scene(footprint_mm, 0.0, 0.0, true, side, side, &plane);
  GpuScene gpu = upload_scene(scene);
  const std::vector<uint8_t> interior =
      region_mask(classify_regions(region_input_of(scene, reach_mm)), Region::interior);
  sss::math::Matrix4 m{};
  std::copy(scene.projection.begin(), scene.projection.end(), m.begin());
  const sss::math::TurnedPlaneFootprint fp =
      sss::math::turned_plane_footprint(m, side, side, {plane.point[0], plane.point[1], plane.point[2]},
                                        {plane.normal[0], plane.normal[1], plane.normal[2]}, scene.world_units_per_mm,
                                        side / 2, side / 2);
  const std::vector<MethodChoice> methods = {{"separable", false}, {"sum-of-gaussians", true}};
  // The plane's own soft-edged light, and a uniform light, under which the exact post-scatter answer
  // is the input itself: the share of the albedo's detail a mode keeps, the light's own detail apart.
  for (const bool uniform : {false, true}) {
    std::vector<float> light = gpu.irradiance_half;
    if (uniform) {
      for (std::size_t i = 0; i < light.size(); ++i) light[i] = i % 4 == 3 ? light[i] : (i % 4 == 0 ? 0.8f : 0.5f);
    }
    run_light(ctx, scene, gpu, interior, fp, methods, footprint_mm, uniform ? "uniform" : "soft edges", light, rows);
  }
  destroy_scene(&gpu);
}
void write_csv(const std::string& path, const std::vector<Row>& rows) {
  std::ofstream f(path);
  f << "footprint_mm,light,albedo,method,mode,miss,miss_r,miss_g,miss_b,untextured_miss,detail_kept,detail_exact\n";
  for (const Row& r : rows) {
    f << r.footprint_mm << ',' << r.light << ',' << r.albedo << ',' << r.method << ',' << r.mode << ',' << r.miss.pooled << ','
      << r.miss.channel[0] << ',' << r.miss.channel[1] << ',' << r.miss.channel[2] << ',' << r.untextured << ','
      << r.detail << ',' << r.detail_exact << '\n';
  }
}

void write_document(const Options& o, const std::string& renderer, const std::vector<Row>& rows) {
  std::filesystem::create_directories(std::filesystem::path(o.doc).parent_path().empty()
                                          ? std::filesystem::path(".")
                                          : std::filesystem::path(o.doc).parent_path());
  std::ofstream d(o.doc);
  const std::time_t t = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&t));
  d << "# Texturing modes on textured planes\n\n"
    << "Generated by `sss_bench_texturing` (tests/bench/texturing_bench.cpp; `scripts/run-texturing-bench.sh`) on "
    << renderer << ", " << date << ": `" << o.command_line << "`.\n\n"
    << "A plane facing the camera (the turn sweep's orthographic plane, 17 taps, the library's default "
       "settings on the fragment path), its colour the light times an albedo at pore scale (a checker of 0.5 mm "
       "cells, or value noise of 0.2 mm cells, on skin-like base colours). Each mode is scored against its own "
       "exact answer A_post ⊙ (R ∗ (colour / A_post)), R d'Eon's skin convolved on the plane in closed form: "
       "**miss** (the interior's share of the needed change left undone: 0 exact, 1 no better than the input), "
       "beside the same method on the light alone (**untextured**, pre-scatter: the mode's own accuracy apart "
       "from the albedo). **Detail kept**: the power of the image minus its mean over a 1 mm box (roughly what "
       "lies above 1 cycle per mm) in the output over the input's, beside the exact answer's (post-scatter's "
       "answer keeps nearly all of it; pre-scatter's blurs it).\n\n"
    << "Under the **uniform** light the detail is the albedo's alone, and post-scatter's exact answer is the "
       "input (kept / exact = 1 is the whole albedo kept); under the **soft edges** (the plane's own light) the "
       "light's edges add detail of their own that every mode blurs. At 1 mm per pixel the checker's 0.5 mm cells "
       "fall on one colour per pixel (sampled at the pixel's centre): no detail to keep.\n\n"
    << "| mm/px | light | albedo | method | mode | miss | untextured | miss − untextured | detail kept | exact | kept / exact |\n"
    << "|---:|---|---|---|---|---:|---:|---:|---:|---:|---:|\n";
  char line[400];
  // A miss is a share of the needed change: where a mode needs none (uniform light, post-scatter:
  // the answer is the input), it has no meaning, and the table says so.
  const auto miss_text = [](const Row& r, double miss) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", miss);
    return r.needed < 1e-3 ? std::string("— (none needed)") : std::string(text);
  };
  for (const Row& r : rows) {
    const bool light_only = r.light == "uniform";  // the light alone needs no change: no untextured miss
    const auto ratio = [](double v) {
      char text[32];
      std::snprintf(text, sizeof text, "%.3f", v);
      return std::isfinite(v) ? std::string(text) : std::string("— (no detail)");
    };
    std::snprintf(line, sizeof line, "| %.3f | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n",
                  r.footprint_mm, r.light.c_str(), r.albedo.c_str(), r.method.c_str(), r.mode.c_str(),
                  miss_text(r, r.miss.pooled).c_str(), light_only ? "—" : miss_text(r, r.untextured).c_str(),
                  light_only || r.needed < 1e-3 ? "—" : miss_text(r, r.miss.pooled - r.untextured).c_str(),
                  ratio(r.detail).c_str(), ratio(r.detail_exact).c_str(), ratio(r.detail / r.detail_exact).c_str());
    d << line;
  }
}

int run(const Options& o, sss_headless* headless) {
  sss_create_desc desc = {};
  desc.struct_size = sizeof desc;
  desc.get_proc_address = sss_headless_get_proc_address;
  desc.get_proc_address_user = headless;
  sss_context* ctx = nullptr;
  sss_tools_init();  // the sum of Gaussians is a fitted family
  if (sss_create(&desc, &ctx) != SSS_OK) {
    std::fprintf(stderr, "sss_bench_texturing: %s\n", sss_last_error(nullptr));
    return 1;
  }
  std::vector<Row> rows;
  int status = 0;
  try {
    const double reach_mm = profile_reach_mm(sss::math::skin_profile_terms());
    for (const double footprint : o.footprints) run_footprint(ctx, footprint, reach_mm, &rows);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sss_bench_texturing: %s\n", e.what());
    status = 1;
  }
  const GLubyte* renderer = glGetString(GL_RENDERER);
  sss_destroy(ctx);
  if (status != 0) return status;
  // The run's own check (bench.texturing_quick): under uniform light post-scatter's exact answer is
  // the input, and the library's output must keep the albedo's detail to within 2 % of it.
  for (const Row& r : rows) {
    if (r.light != "uniform" || r.mode != mode_name(SSS_TEXTURING_POST_SCATTER)) continue;
    if (!std::isfinite(r.detail_exact)) continue;  // no detail at this footprint (the checker at 1 mm/px)
    if (!(std::fabs(r.detail / r.detail_exact - 1.0) <= 0.02)) {
      std::fprintf(stderr, "sss_bench_texturing: %.3f mm/px, %s, %s: post-scatter kept %.3f of the albedo's detail "
                           "where the exact answer keeps %.3f\n",
                   r.footprint_mm, r.albedo.c_str(), r.method.c_str(), r.detail, r.detail_exact);
      status = 1;
    }
  }
  std::filesystem::create_directories(o.out);
  write_csv(o.out + "/results.csv", rows);
  write_document(o, renderer != nullptr ? reinterpret_cast<const char*>(renderer) : "unknown", rows);
  std::printf("%zu rows: %s/results.csv, %s\n", rows.size(), o.out.c_str(), o.doc.c_str());
  return status;
}

}  // namespace
}  // namespace sss_bench::texturing

int main(int argc, char** argv) {
  const sss_bench::texturing::Options options = sss_bench::texturing::parse(argc, argv);
  sss_headless_backend backend;
  if (sss_headless_backend_from_name(options.backend.c_str(), &backend) != 0) {
    std::fprintf(stderr, "sss_bench_texturing: unknown backend %s\n", options.backend.c_str());
    return 2;
  }
  sss_headless* headless = sss_test::open_host_context(backend, "sss_bench_texturing");
  if (headless == nullptr) return 1;
  const int status = sss_bench::texturing::run(options, headless);
  sss_headless_destroy(headless);
  return status;
}
