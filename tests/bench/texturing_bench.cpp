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
// The planes also run the sum of Gaussians' two controls (33 taps; 17 with jitter), which say where
// its misses come from. Post-scatter's output keeps the albedo's detail (its answer has it all: the
// light is smooth at that scale); pre-scatter's blurs it. The head's rows are texturing_head.cpp's.
// Writes results.csv and a Markdown document (--doc; texturing_report.cpp); exits 1 when
// post-scatter under a uniform light keeps the albedo's detail less closely than 2 % of its answer.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
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

std::vector<MethodChoice> method_choices() {
  return {{"separable", false, 17, 0.0f}, {"sum-of-gaussians", true, 17, 0.0f}};
}

std::vector<MethodChoice> sum_of_gaussians_controls() {
  return {{kDenserControl, true, 33, 0.0f}, {kJitteredControl, true, 17, 0.5f}};
}

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
  s.taps = m.taps;
  s.jitter = m.jitter;
  if (m.sum_of_gaussians) {
    sss_test::kernel_of(s).family = SSS_KERNEL_SUM_OF_GAUSSIANS;
    sss_test::kernel_of(s).rank = 6;
    sss_test::kernel_of(s).taps = m.taps;  // a kernel desc carries its own tap count
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
    std::vector<MethodChoice> methods = method_choices();
    for (const MethodChoice& control : sum_of_gaussians_controls()) methods.push_back(control);
    for (const MethodChoice& method : methods) {
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
