// sss_bench_texturing: the texturing modes (sss.h sss_texturing, issue 48) on planes with an albedo at
// pore scale, facing the camera and turned away from it, and on the head close-up with its scan's
// albedo map, run through the library on GL and scored against each mode's exact answer.
//
// Each plane frame is the turn sweep's orthographic plane (its light: a soft-edged pattern) at one
// footprint and turn, its colour the light E times an albedo A that varies at pore scale on the
// surface (in surface millimetres, so a turned plane's cells are foreshortened as its light is):
// a checker of 0.5 mm cells, or value noise of 0.2 mm cells. A mode with A_pre · A_post = A
// (pre-scatter A_pre = A; post-scatter A_post = A; pre- and post-scatter √A each) has the exact answer
//   A_post ⊙ (R ∗ (colour / A_post))
// with R d'Eon's six-Gaussian skin profile convolved on the plane in closed form
// (plane_reference.hpp: exact for light constant over each pixel, which the colour is), A_post floored
// as the library floors it (sss.h). The rows:
//   - miss: each method in each mode against that mode's own answer, on the interior (regions.hpp),
//     beside the same method on the same light without the albedo ("untextured": pre-scatter on E);
//   - detail kept: the output's power above 1 cycle per surface millimetre over the input's, beside
//     the exact answer's (texturing_detail.hpp: the plane's spectrum; the head's 1 mm high-pass).
// Post-scatter's output keeps the albedo's detail (its answer has it all: the light is smooth at that
// scale); pre-scatter's blurs it. The head's rows are texturing_head.cpp's. Writes results.csv and a
// Markdown document (--doc); exits 1 when post-scatter under a uniform light keeps the albedo's detail
// less closely than 2 % of its answer.
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
#include "texturing_bench.hpp"
#include "texturing_detail.hpp"

namespace sss_bench::texturing {

using namespace host_gl;

namespace {

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
    } else if (key == "--turns") {
      o.turns.clear();
      for (const std::string& item : split_list(value, true)) o.turns.push_back(std::atof(item.c_str()));
    } else if (key == "--head-size") {
      if (std::sscanf(value.c_str(), "%dx%d", &o.head_size.first, &o.head_size.second) != 2 || o.head_size.first < 0 ||
          o.head_size.second < 0) {
        std::fprintf(stderr, "sss_bench_texturing: --head-size %s: expected WxH (0x0: no head rows)\n", value.c_str());
        std::exit(2);
      }
    } else if (key == "--out") {
      o.out = value;
    } else if (key == "--doc") {
      o.doc = value;
    } else {
      std::fprintf(stderr, "usage: sss_bench_texturing [--backend egl|osmesa] [--footprints a,b,...] [--turns a,b,...] "
                           "[--head-size WxH] [--out DIR] [--doc FILE.md]\n");
      std::exit(2);
    }
  }
  return o;
}

// The albedos (RGBA, alpha 1), at pixel (x, y) of a plane whose pixels map to it by `fp`: skin-like base colours
// modulated at pore scale, the cells laid out in surface millimetres (texturing_detail.hpp's map
// u = a·x + c·y, v = b·y of the pixel's centre).
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

std::vector<float> make_albedo(Albedo kind, int width, int height, const sss::math::TurnedPlaneFootprint& fp) {
  const double base[3] = {0.75, 0.5, 0.4};
  std::vector<float> a(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 1.0f);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double mx = fp.a_mm * (x + 0.5) + fp.c_mm * (y + 0.5), my = fp.b_mm * (y + 0.5);
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

// The detail measures' cut-off: the "above 1 cycle per mm".
constexpr double kDetailCutoffPerMm = 1.0;

}  // namespace

std::vector<MethodChoice> method_choices() { return {{"separable", false}, {"sum-of-gaussians", true}}; }

const char* mode_name(unsigned mode) {
  return mode == SSS_TEXTURING_PRE_SCATTER ? "pre-scatter"
                                           : (mode == SSS_TEXTURING_POST_SCATTER ? "post-scatter" : "pre- and post-scatter");
}

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

namespace {

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
  sss::math::convolve_turned_plane(in, sss::math::skin_profile_terms(),
                                   bounding_box(interior, scene.width, scene.height), answer.rgb.data());
  for (std::size_t i = 0; i < n; ++i) {
    if (interior[i] == 0) continue;
    for (std::size_t c = 0; c < 3; ++c) answer.rgb[i * 3 + c] *= post[i * 3 + c];
  }
  return answer;
}

// One plane frame: the scene, what the GPU holds of it, its interior and its footprint.
struct PlaneFrame {
  Scene scene;
  GpuScene gpu;
  std::vector<uint8_t> interior;
  PixelRegion interior_box;
  sss::math::TurnedPlaneFootprint fp;
  double footprint_mm = 0.0, turn_deg = 0.0;
};

// One light over both albedos: each method in each mode, and on the light alone.
void run_light(sss_context* ctx, const PlaneFrame& f, const char* light_name, const std::vector<float>& light,
               std::vector<Row>* rows) {
  const int side = f.scene.width;
  const std::vector<uint8_t>& interior = f.interior;
  const std::vector<float> ones(light.size(), 1.0f);
  const RgbImage light_input = RgbImage::from_rgba(light.data(), side, side);
  const RgbImage light_answer = exact_answer(f.scene, light, ones, SSS_TEXTURING_PRE_SCATTER, interior, f.fp);
  // Where the pixels hold no frequency above the cut-off (the facing 1 mm/px plane), or the input
  // none (a uniform light over cells the pixels do not resolve), there is no detail to keep.
  const bool resolved = resolves_above(f.interior_box, f.fp, kDetailCutoffPerMm);
  const auto detail_of = [&](const RgbImage& image) { return power_above(image, f.interior_box, f.fp, kDetailCutoffPerMm); };
  for (const Albedo kind : {Albedo::checker, Albedo::noise}) {
    const std::vector<float> albedo = make_albedo(kind, side, side, f.fp);
    std::vector<float> colour = light;
    for (std::size_t i = 0; i < colour.size(); ++i) {
      if (i % 4 != 3) colour[i] = sss::math::round_to_half(light[i] * albedo[i]);
    }
    const RgbImage input = RgbImage::from_rgba(colour.data(), side, side);
    const double input_detail = resolved ? detail_of(input) : 0.0;
    for (const MethodChoice& method : method_choices()) {
      const RgbImage untextured_out =
          RgbImage::from_rgba(run_library(ctx, f.gpu, method, SSS_TEXTURING_PRE_SCATTER, light, ones).data(), side, side);
      const double untextured = miss_share(untextured_out, light_answer, light_input, interior.data()).pooled;
      for (const unsigned mode : kModes) {
        const RgbImage answer = exact_answer(f.scene, colour, albedo, mode, interior, f.fp);
        const RgbImage out = RgbImage::from_rgba(run_library(ctx, f.gpu, method, mode, colour, albedo).data(), side, side);
        Row r;
        r.scene = "plane";
        r.footprint_mm = f.footprint_mm;
        r.turn_deg = f.turn_deg;
        r.light = light_name;
        r.albedo = albedo_name(kind);
        r.method = method.name;
        r.mode = mode_name(mode);
        r.miss = miss_share(out, answer, input, interior.data());
        r.untextured = untextured;
        r.needed = relative_rmse(input, answer, interior.data());
        const double nan = std::numeric_limits<double>::quiet_NaN();
        r.detail = input_detail > 0.0 ? detail_of(out) / input_detail : nan;
        r.detail_exact = input_detail > 0.0 ? detail_of(answer) / input_detail : nan;
        rows->push_back(r);
        std::printf("%.3f mm/px, turned %g, %s light, %s, %s, %s: miss %.3f (untextured %.3f), detail kept %.3f "
                    "(exact %.3f)\n",
                    f.footprint_mm, f.turn_deg, light_name, r.albedo.c_str(), r.method.c_str(), r.mode.c_str(),
                    r.miss.pooled, untextured, r.detail, r.detail_exact);
        std::fflush(stdout);
      }
    }
  }
}

// The plane at `footprint_mm` (where it would face the camera) turned by `turn_deg` about screen x.
void run_plane(sss_context* ctx, double footprint_mm, double turn_deg, double reach_mm, std::vector<Row>* rows) {
  const int side = sweep_frame_side(footprint_mm, kCalibrationInteriorPx, reach_mm);
  PlaneGeometry plane;
  PlaneFrame f;
  f.footprint_mm = footprint_mm;
  f.turn_deg = turn_deg;
  f.scene = make_turned_plane_scene(footprint_mm, turn_deg, 0.0, true, side, side, &plane);
  f.gpu = upload_scene(f.scene);
  f.interior = region_mask(classify_regions(region_input_of(f.scene, reach_mm)), Region::interior);
  f.interior_box = bounding_box(f.interior, side, side);
  sss::math::Matrix4 m{};
  std::copy(f.scene.projection.begin(), f.scene.projection.end(), m.begin());
  f.fp = sss::math::turned_plane_footprint(m, side, side, {plane.point[0], plane.point[1], plane.point[2]},
                                           {plane.normal[0], plane.normal[1], plane.normal[2]},
                                           f.scene.world_units_per_mm, side / 2, side / 2);
  // The plane's own soft-edged light, and a uniform light, under which the exact post-scatter answer
  // is the input itself: the share of the albedo's detail a mode keeps, the light's own detail apart.
  for (const bool uniform : {false, true}) {
    std::vector<float> light = f.gpu.irradiance_half;
    if (uniform) {
      for (std::size_t i = 0; i < light.size(); ++i) light[i] = i % 4 == 3 ? light[i] : (i % 4 == 0 ? 0.8f : 0.5f);
    }
    run_light(ctx, f, uniform ? "uniform" : "soft edges", light, rows);
  }
  destroy_scene(&f.gpu);
}

void write_csv(const std::string& path, const std::vector<Row>& rows) {
  std::ofstream f(path);
  f << "scene,footprint_mm,turn_deg,light,albedo,method,mode,miss,miss_r,miss_g,miss_b,untextured_miss,needed,"
       "detail_kept,detail_exact\n";
  for (const Row& r : rows) {
    f << r.scene << ',' << r.footprint_mm << ',' << r.turn_deg << ',' << r.light << ',' << r.albedo << ',' << r.method
      << ',' << r.mode << ',' << r.miss.pooled << ',' << r.miss.channel[0] << ',' << r.miss.channel[1] << ','
      << r.miss.channel[2] << ',' << r.untextured << ',' << r.needed << ',' << r.detail << ',' << r.detail_exact << '\n';
  }
}

// A miss is a share of the needed change: where a mode needs none (uniform light, post-scatter: the
// answer is the input), it has no meaning, and the tables say so.
bool needs_change(const Row& r) { return r.needed >= 1e-3; }
bool has_untextured(const Row& r) { return r.light != "uniform" && needs_change(r); }

std::string number(double v, const char* otherwise) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", v);
  return std::isfinite(v) ? std::string(text) : std::string(otherwise);
}

// The bounds per frame (scene, footprint, turn): the default's worst textured miss over its
// untextured one per mode, the sum of Gaussians' worst textured miss, and post-scatter's detail kept
// under the uniform light over the exact answer's, worst over the albedos.
void write_bounds(std::ofstream& d, const std::vector<Row>& rows) {
  d << "## The issue's bounds\n\n"
       "Per plane frame, the worst over both lights and both albedos: the "
       "default's textured miss minus its untextured miss in each mode (bound: 0.02), the sum of Gaussians' "
       "largest textured miss in any mode (bound: 0.05), and post-scatter's detail kept over the exact answer's "
       "under the uniform light (bound: within 2 % of 1; the run fails otherwise). A cell is — where nothing "
       "was measurable (no change needed, or no detail above 1 cycle/mm).\n\n"
       "| mm/px | turn | default pre | default post | default pre and post | sum of Gaussians | post detail / exact |\n"
       "|---:|---:|---:|---:|---:|---:|---:|\n";
  std::vector<const Row*> firsts;
  for (const Row& r : rows) {
    if (r.scene != "plane") continue;  // the bounds are the planes' (the head's rows have a table of their own)
    bool seen = false;
    for (const Row* f : firsts) seen = seen || (f->scene == r.scene && f->footprint_mm == r.footprint_mm && f->turn_deg == r.turn_deg);
    if (!seen) firsts.push_back(&r);
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto worst = [](double current, double v) { return std::isfinite(current) ? std::max(current, v) : v; };
  char line[400];
  for (const Row* f : firsts) {
    double gap[3] = {nan, nan, nan}, sum_of_gaussians = nan, detail = nan;
    for (const Row& r : rows) {
      if (r.scene != f->scene || r.footprint_mm != f->footprint_mm || r.turn_deg != f->turn_deg) continue;
      for (int m = 0; m < 3; ++m) {
        if (r.method == "separable" && r.mode == mode_name(kModes[m]) && has_untextured(r)) {
          gap[m] = worst(gap[m], r.miss.pooled - r.untextured);
        }
      }
      if (r.method == "sum-of-gaussians" && needs_change(r)) sum_of_gaussians = worst(sum_of_gaussians, r.miss.pooled);
      if (r.light == "uniform" && r.mode == mode_name(SSS_TEXTURING_POST_SCATTER) && std::isfinite(r.detail_exact)) {
        const double off = r.detail / r.detail_exact;
        if (!std::isfinite(detail) || std::fabs(off - 1.0) > std::fabs(detail - 1.0)) detail = off;
      }
    }
    std::snprintf(line, sizeof line, "| %.3f | %g | %s | %s | %s | %s | %s |\n", f->footprint_mm,
                  f->turn_deg, number(gap[0], "—").c_str(), number(gap[1], "—").c_str(), number(gap[2], "—").c_str(),
                  number(sum_of_gaussians, "—").c_str(), number(detail, "—").c_str());
    d << line;
  }
  d << "\n";
}

void write_rows(std::ofstream& d, const std::vector<Row>& rows, bool head) {
  d << "| " << (head ? "median mm/px" : "mm/px") << " | turn | light | albedo | method | mode | miss | untextured | "
    << "miss − untextured | detail kept | exact | kept / exact |\n"
    << "|---:|---:|---|---|---|---|---:|---:|---:|---:|---:|---:|\n";
  char line[400];
  for (const Row& r : rows) {
    if ((r.scene != "plane") != head) continue;
    const auto miss_text = [&](double miss) { return needs_change(r) ? number(miss, "—") : std::string("— (none needed)"); };
    std::snprintf(line, sizeof line, "| %.3f | %g | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", r.footprint_mm,
                  r.turn_deg, r.light.c_str(), r.albedo.c_str(), r.method.c_str(), r.mode.c_str(),
                  miss_text(r.miss.pooled).c_str(), has_untextured(r) ? number(r.untextured, "—").c_str() : "—",
                  has_untextured(r) ? number(r.miss.pooled - r.untextured, "—").c_str() : "—",
                  number(r.detail, "— (no detail)").c_str(), number(r.detail_exact, "— (no detail)").c_str(),
                  number(r.detail / r.detail_exact, "— (no detail)").c_str());
    d << line;
  }
  d << "\n";
}

void write_document(const Options& o, const std::string& renderer, const std::vector<Row>& rows) {
  std::filesystem::create_directories(std::filesystem::path(o.doc).parent_path().empty()
                                          ? std::filesystem::path(".")
                                          : std::filesystem::path(o.doc).parent_path());
  std::ofstream d(o.doc);
  const std::time_t t = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&t));
  d << "# Texturing modes on textured planes and on the head\n\n"
    << "Generated by `sss_bench_texturing` (tests/bench/texturing_bench.cpp, texturing_head.cpp; "
       "`scripts/run-texturing-bench.sh`) on "
    << renderer << ", " << date << ": `" << o.command_line << "`.\n\n"
    << "**Planes**: the turn sweep's orthographic plane, facing the camera or turned about screen x (17 taps, the "
       "library's default settings on the fragment path; mm/px is the footprint where it faces the camera, so a "
       "plane turned 60° measures twice that along y), its colour the light times an albedo at pore scale laid "
       "out on the surface (a checker of 0.5 mm cells, or value noise of 0.2 mm cells, on skin-like base "
       "colours). Each mode is scored against its own exact answer A_post ⊙ (R ∗ (colour / A_post)), R d'Eon's "
       "skin convolved on the plane in closed form: **miss** (the interior's share of the needed change left "
       "undone: 0 exact, 1 no better than the input), beside the same method on the light alone (**untextured**, "
       "pre-scatter: the mode's own accuracy apart from the albedo). **Detail kept**: the image's power above 1 "
       "cycle per surface millimetre (its spectrum over the interior, Hann-windowed: "
       "tests/bench/texturing_detail.hpp) in the output over the input's, beside the exact answer's "
       "(post-scatter's answer keeps nearly all of it; pre-scatter's blurs it).\n\n"
    << "Under the **uniform** light the detail is the albedo's alone, and post-scatter's exact answer is the "
       "input (kept / exact = 1 is the whole albedo kept); under the **soft edges** (the plane's own light, with "
       "its own per-pixel albedo) the light adds detail of its own that every mode blurs. At 1 mm per pixel "
       "facing the camera the pixels hold no frequency above 1 cycle per mm: no detail to measure.\n\n"
    << "**Head**: the close-up with its scan's albedo map, lit as the benchmark lights it; each mode against A_post ⊙ (R ∗ "
       "(colour / A_post)) over the visible surface rebuilt from depth (the benchmark's reference, "
       "tests/bench/reference.hpp), on the interior apart from silhouettes and depth edges. A curved surface has "
       "no one spectrum: its detail kept is the power of each pixel minus its mean over a box 1 mm wide at the "
       "pixel's footprint (its view distance; the slope is not counted), which passes about what lies above 1 "
       "cycle per mm. A scanned albedo already holds the skin's own scattering, so post-scatter's answer is the "
       "right one for it; the other modes' rows say how far each is from its own answer. Head scan: \"Infinite, 3D "
       "Head Scan\" by Lee Perry-Smith is licensed under a Creative Commons Attribution 3.0 Unported License. Based "
       "on a work at www.triplegangers.com. Permissions beyond the scope of this license may be available at "
       "http://www.ir-ltd.net/\n\n";
  write_bounds(d, rows);
  d << "## Planes\n\n";
  write_rows(d, rows, false);
  if (std::any_of(rows.begin(), rows.end(), [](const Row& r) { return r.scene != "plane"; })) {
    d << "## Head\n\n";
    write_rows(d, rows, true);
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
    for (const double turn : o.turns) {
      for (const double footprint : o.footprints) run_plane(ctx, footprint, turn, reach_mm, &rows);
    }
    if (o.head_size.first > 0 && o.head_size.second > 0) run_head(ctx, o, reach_mm, &rows);
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
