// sss_bench_texturing's head rows (texturing_bench.hpp: run_head): the head close-up with its scan's
// albedo map, each method in each texturing mode against that mode's own answer
// A_post ⊙ (R ∗ (colour / A_post)), R over the visible surface rebuilt from depth (reference.hpp).
//
// The miss is scored on the interior apart from silhouettes and depth edges (regions.hpp), on the GL
// reference's grid, as the benchmark scores the head. The detail kept needs every pixel of the answer,
// which the grid does not hold: it is measured on a square patch of interior skin (the one nearest the
// frame's centre, wholly interior) where the CPU reference fills every pixel.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "calibration.hpp"
#include "math/cpu_texturing.hpp"
#include "math/half_float.hpp"
#include "reference.hpp"
#include "regions.hpp"
#include "scenes/scenes.hpp"
#include "texturing_bench.hpp"
#include "texturing_detail.hpp"

namespace sss_bench::texturing {
namespace {

// The detail patch's side in pixels for a frame `height` high: an eighth of it (67 at 540), within
// 16-96, so that a small frame still finds wholly interior skin and a large one pays a few seconds of CPU.
int patch_side(int height) { return std::clamp(height / 8, 16, 96); }
constexpr double kDetailBoxMm = 1.0;   // texturing_detail.hpp's high-pass box: about 1 cycle per mm

// The lowest-left corner of a `side` square whose pixels are all in `interior`, the one whose
// centre is nearest the frame's; throws when there is none.
std::pair<int, int> interior_patch(const std::vector<uint8_t>& interior, int width, int height, int side) {
  // Summed-area table of the interior: a square is wholly interior when its sum is its area.
  std::vector<long> sum(static_cast<std::size_t>(width + 1) * static_cast<std::size_t>(height + 1), 0);
  const auto at = [&](int x, int y) -> long& { return sum[static_cast<std::size_t>(y) * (width + 1) + x]; };
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      at(x + 1, y + 1) = interior[static_cast<std::size_t>(y) * width + x] + at(x, y + 1) + at(x + 1, y) - at(x, y);
    }
  }
  long best = std::numeric_limits<long>::max();
  std::pair<int, int> corner{-1, -1};
  for (int y = 0; y + side <= height; ++y) {
    for (int x = 0; x + side <= width; ++x) {
      const long inside = at(x + side, y + side) - at(x, y + side) - at(x + side, y) + at(x, y);
      if (inside != static_cast<long>(side) * side) continue;
      const long dx = 2L * x + side - width, dy = 2L * y + side - height;
      if (dx * dx + dy * dy < best) best = dx * dx + dy * dy, corner = {x, y};
    }
  }
  if (corner.first < 0) throw std::runtime_error("the head close-up has no wholly interior patch of this size");
  return corner;
}

// `colour` over `post` (the light a mode's passes see), as a scene the references take.
Scene with_irradiance(const Scene& scene, const std::vector<float>& irradiance) {
  Scene s = scene;
  s.irradiance = irradiance;
  return s;
}

struct ModeAnswer {
  RgbImage grid;   // A_post ⊙ R ∗ (colour / A_post) on the reference's grid (the input elsewhere)
  RgbImage patch;  // the same at every pixel of the patch
};

}  // namespace

void run_head(sss_context* ctx, const Options& o, double reach_mm, std::vector<Row>* rows) {
  const int w = o.head_size.first, h = o.head_size.second;
  const Scene scene = make_scene("head-close", w, h);
  if (scene.albedo.empty()) throw std::runtime_error("head-close rendered no albedo (Scene::albedo)");
  GpuScene gpu = upload_scene(scene);
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  const std::vector<uint8_t> interior =
      region_mask(classify_regions_with_depth_edges(region_input_of(scene, reach_mm)), Region::interior);
  const int stride = std::max(1, (h + 90) / 180);  // the benchmark's grid for this height
  std::vector<uint8_t> scored(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    scored[i] = interior[i] != 0 && on_grid(static_cast<int>(i % w), static_cast<int>(i / w), stride) ? 1 : 0;
  }
  const int side = patch_side(h);
  const auto [px, py] = interior_patch(interior, w, h, side);
  // The high-pass's pixels: the patch less a box's reach on each side, so every box stays inside it.
  std::vector<float> mm_per_pixel(n);
  std::vector<double> interior_footprints;
  for (std::size_t i = 0; i < n; ++i) {
    mm_per_pixel[i] = static_cast<float>(2.0 * scene.distance[i] / (scene.projection[5] * static_cast<double>(h)) / scene.world_units_per_mm);
    if (interior[i] != 0) interior_footprints.push_back(mm_per_pixel[i]);
  }
  std::nth_element(interior_footprints.begin(), interior_footprints.begin() + interior_footprints.size() / 2,
                   interior_footprints.end());
  const double median_mm = interior_footprints[interior_footprints.size() / 2];
  const int margin = static_cast<int>(std::lround(0.5 * kDetailBoxMm / median_mm)) + 1;
  std::vector<uint8_t> patch(n, 0), measured(n, 0);
  for (int y = py; y < py + side; ++y) {
    for (int x = px; x < px + side; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      patch[i] = 1;
      measured[i] = x >= px + margin && x < px + side - margin && y >= py + margin && y < py + side - margin;
    }
  }
  const auto detail_of = [&](const RgbImage& image) {
    return box_high_pass_power(image, measured, patch, mm_per_pixel, kDetailBoxMm);
  };

  // What the library is handed: the colour as the GPU holds it, the albedo as an RGBA16F texture holds it.
  const std::vector<float>& colour = gpu.irradiance_half;
  std::vector<float> albedo = scene.albedo;
  for (float& v : albedo) v = sss::math::round_to_half(v);
  const RgbImage input = RgbImage::from_rgba(colour.data(), w, h);
  const double input_detail = detail_of(input);

  // Each mode's answer: the reference of colour / A_post, times A_post.
  const auto answer_of = [&](unsigned mode, std::vector<float>* light_out) {
    const std::vector<float> post = sss::math::albedo_post_plane(albedo.data(), n, {mode});
    const std::vector<float> light = sss::math::colour_over_albedo(colour.data(), post, false);
    const Scene lit = with_irradiance(scene, light);
    GpuScene lit_gpu = upload_scene(lit);
    const Reference grid = make_reference(lit, lit_gpu, 160 * 90, 8, stride);
    const std::vector<float> patch_rgba = make_patch_reference(lit, lit_gpu, px, py, side, side);
    if (light_out != nullptr) *light_out = lit_gpu.irradiance_half;
    destroy_scene(&lit_gpu);
    ModeAnswer a{RgbImage::from_rgba(grid.rgba.data(), w, h), RgbImage::from_rgba(patch_rgba.data(), w, h)};
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t c = 0; c < 3; ++c) {
        if (scored[i] != 0) a.grid.rgb[i * 3 + c] *= post[i * 3 + c];
        if (patch[i] != 0) a.patch.rgb[i * 3 + c] *= post[i * 3 + c];
      }
    }
    std::printf("head-close %dx%d, %s: reference %s (grid %d) and CPU patch %dx%d at (%d, %d)\n", w, h, mode_name(mode),
                grid.source.c_str(), stride, side, side, px, py);
    std::fflush(stdout);
    return a;
  };
  // The light alone (post-scatter's E = colour / A): its own answer is post-scatter's before the multiply.
  std::vector<float> light;
  ModeAnswer answers[3];
  for (int m = 0; m < 3; ++m) answers[m] = answer_of(kModes[m], kModes[m] == SSS_TEXTURING_POST_SCATTER ? &light : nullptr);
  const RgbImage light_input = RgbImage::from_rgba(light.data(), w, h);
  RgbImage light_answer = answers[1].grid;
  {
    const std::vector<float> post = sss::math::albedo_post_plane(albedo.data(), n, {SSS_TEXTURING_POST_SCATTER});
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t c = 0; c < 3; ++c) {
        if (scored[i] != 0) light_answer.rgb[i * 3 + c] /= post[i * 3 + c];
      }
    }
  }
  const std::vector<float> ones(colour.size(), 1.0f);
  for (const MethodChoice& method : method_choices()) {
    const RgbImage untextured_out =
        RgbImage::from_rgba(run_library(ctx, gpu, method, SSS_TEXTURING_PRE_SCATTER, light, ones).data(), w, h);
    const double untextured = miss_share(untextured_out, light_answer, light_input, scored.data()).pooled;
    for (int m = 0; m < 3; ++m) {
      const RgbImage out = RgbImage::from_rgba(run_library(ctx, gpu, method, kModes[m], colour, albedo).data(), w, h);
      Row r;
      r.scene = "head-close";
      r.footprint_mm = median_mm;
      r.light = "key, fill, ambient";
      r.albedo = "scan's albedo map";
      r.method = method.name;
      r.mode = mode_name(kModes[m]);
      r.miss = miss_share(out, answers[m].grid, input, scored.data());
      r.untextured = untextured;
      r.needed = relative_rmse(input, answers[m].grid, scored.data());
      r.detail = detail_of(out) / input_detail;
      r.detail_exact = detail_of(answers[m].patch) / input_detail;
      rows->push_back(r);
      std::printf("head-close %dx%d, %s, %s: miss %.3f (untextured %.3f), detail kept %.3f (exact %.3f)\n", w, h,
                  r.method.c_str(), r.mode.c_str(), r.miss.pooled, untextured, r.detail, r.detail_exact);
      std::fflush(stdout);
    }
  }
  destroy_scene(&gpu);
}

}  // namespace sss_bench::texturing
