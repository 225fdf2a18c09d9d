// sss_bench: run time against error. For every scene × resolution it builds the exact reference
// (the CPU exact 2D convolution for small images; the GL exact filter, spot-checked against the
// CPU, for large ones), then times every method configuration and scores its output against the
// reference. Writes results.csv, results.json, results.md, Pareto plots and heat maps into --out,
// and with --doc the results document.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "calibration.hpp"
#include "gpu_busy.hpp"
#include "gpu_scene.hpp"
#include "host_context.hpp"
#include "host_gl.hpp"
#include "host_gl_util.hpp"
#include "math/exact_reference.hpp"
#include "method.hpp"
#include "metrics.hpp"
#include "msaa_study.hpp"
#include "options.hpp"
#include "reference.hpp"
#include "regions.hpp"
#include "report.hpp"
#include "results.hpp"
#include "scenes/scenes.hpp"
#include "sss/sss_tools.h"
#include "sss_headless.h"
#include "state_cost.hpp"
#include "hitch_cost.hpp"
#include "timing.hpp"

using namespace host_gl;

namespace sss_bench {
namespace {

struct MethodConfig {
  std::string kind;  // "separable", "separable-no-restore", "cross-bilateral", "cross-bilateral-no-tilt",
                     // "sum-of-gaussians", "exact-2d", "kernel-*"
  int taps = 0;
  bool follow_surface = false;
};

std::vector<MethodConfig> method_configs(const Options& o) {
  std::vector<MethodConfig> configs;
  // The second yardstick, where compute shaders run: the two-pass copy as compute dispatches.
  configs.push_back({"copy-compute", 1, false});
  for (bool follow : o.follow_surface) {
    for (int taps : o.separable_taps) configs.push_back({"separable", taps, follow});
    if (follow) {
      for (int taps : o.gaussian_taps) configs.push_back({"sum-of-gaussians", taps, true});
    }
  }
  // What the state save and restore costs: the paper's default kernel once more, with the host
  // managing GL state itself (SSS_CREATE_NO_STATE_RESTORE).
  configs.push_back({"separable-no-restore", SSS_TAPS_MEDIUM, true});
  // Skipping what a frame does not need: the default kernel written back in place (a host's
  // frame), and with the host's region of translucent pixels.
  // The masked fragment path and the compute path (sss_settings.path) the same two ways, and the
  // automatic choice.
  // Several materials in one pass pair: one profile against per-pixel profiles, in the same run.
  configs.push_back({"separable-one-profile", SSS_TAPS_MEDIUM, true});
  configs.push_back({"separable-profiles", SSS_TAPS_MEDIUM, true});
  // The half-resolution path (SSS_PATH_HALF_RESOLUTION) in place, beside the masked one. The
  // texturing modes' divide and multiply (sss_settings.texturing, over a constant albedo), in place
  // on the fragment path and with the fastest path and the region.
  for (const char* kind : {"separable-in-place", "separable-region",
                           "separable-masked", "separable-masked-region", "separable-half", "separable-compute",
                           "separable-compute-region", "separable-auto-region", "separable-in-place-post-scatter",
                           "separable-in-place-pre-and-post-scatter", "separable-auto-region-post-scatter"}) {
    configs.push_back({kind, SSS_TAPS_MEDIUM, true});
  }
  // Mikkelsen's cross-bilateral mode: its own depth handling (range weights, zero weight for
  // non-translucent neighbours), so no follow-surface variants.
  for (int taps : o.cbf_taps) configs.push_back({"cross-bilateral", taps, false});
  // The same without the footprint's cosine correction, at the default tap count only.
  if (!o.cbf_taps.empty()) configs.push_back({"cross-bilateral-no-tilt", o.cbf_taps.front(), false});
  // The kernel families through the library (sss_settings.kernel), follow-surface on.
  for (const KernelChoice& k : kernel_family_choices()) {
    for (int taps : o.family_taps) configs.push_back({k.name, taps, true});
  }
  if (o.exact_method) configs.push_back({"exact-2d", 0, false});
  if (!o.methods.empty()) {
    const auto unwanted = [&o](const MethodConfig& c) {
      return std::find(o.methods.begin(), o.methods.end(), c.kind) == o.methods.end();
    };
    configs.erase(std::remove_if(configs.begin(), configs.end(), unwanted), configs.end());
  }
  return configs;
}

// The footprint sweep measures accuracy on planes facing the camera, where the depth test, the
// paths and the region change nothing but time: there it runs each kernel once (follow-surface on)
// with the sum of Gaussians, the cross-bilateral mode and the kernel families.
bool runs_on_sweep(const MethodConfig& c, const Options& o) {
  if (c.kind == "separable") {
    return c.follow_surface &&
           (o.sweep_taps.empty() || std::find(o.sweep_taps.begin(), o.sweep_taps.end(), c.taps) != o.sweep_taps.end());
  }
  if (c.kind == "sum-of-gaussians") return c.follow_surface;
  return c.kind == "cross-bilateral" || c.kind.rfind("kernel-", 0) == 0;
}


// One scene at one size: a canonical scene, or a footprint sweep plane (footprint_mm > 0).
struct SceneJob {
  std::string name;
  int width = 0, height = 0;
  double footprint_mm = 0.0;
};

// nullptr: the configuration cannot run on this context (copy-compute below GL 4.3).
std::unique_ptr<Method> make_method(const MethodConfig& c, const GlLoader& loader) {
  if (c.kind == "copy-compute") return make_compute_copy_method();
  if (c.kind == "separable") return make_separable_method(loader, c.taps, c.follow_surface);
  if (c.kind == "separable-no-restore") {
    return make_separable_method(loader, c.taps, c.follow_surface, SSS_CREATE_NO_STATE_RESTORE);
  }
  if (c.kind == "separable-in-place") return make_in_place_method(loader, c.taps, false);
  if (c.kind == "separable-one-profile") return make_profiles_method(loader, c.taps, false);
  if (c.kind == "separable-profiles") return make_profiles_method(loader, c.taps, true);
  if (c.kind == "separable-region") return make_in_place_method(loader, c.taps, true);
  if (c.kind == "separable-masked") return make_in_place_method(loader, c.taps, false, SSS_PATH_FRAGMENT_MASKED);
  if (c.kind == "separable-masked-region") return make_in_place_method(loader, c.taps, true, SSS_PATH_FRAGMENT_MASKED);
  if (c.kind == "separable-half") return make_in_place_method(loader, c.taps, false, SSS_PATH_HALF_RESOLUTION);
  if (c.kind == "separable-compute") return make_in_place_method(loader, c.taps, false, SSS_PATH_COMPUTE);
  if (c.kind == "separable-compute-region") return make_in_place_method(loader, c.taps, true, SSS_PATH_COMPUTE);
  if (c.kind == "separable-auto-region") return make_in_place_method(loader, c.taps, true, SSS_PATH_AUTO);
  if (c.kind == "separable-in-place-post-scatter") {
    return make_in_place_method(loader, c.taps, false, SSS_PATH_FRAGMENT, SSS_TEXTURING_POST_SCATTER);
  }
  if (c.kind == "separable-in-place-pre-and-post-scatter") {
    return make_in_place_method(loader, c.taps, false, SSS_PATH_FRAGMENT, SSS_TEXTURING_PRE_AND_POST_SCATTER);
  }
  if (c.kind == "separable-auto-region-post-scatter") {
    return make_in_place_method(loader, c.taps, true, SSS_PATH_AUTO, SSS_TEXTURING_POST_SCATTER);
  }
  // The 12-pass baseline: d'Eon's six Gaussians, each a horizontal and a vertical pass of its own
  // footprint-integrated weights (the library's family, exact on a plane where every pixel gets a tap).
  if (c.kind == "sum-of-gaussians") return make_kernel_family_method(loader, sum_of_gaussians_baseline(), c.taps);
  if (c.kind == "cross-bilateral") return make_cross_bilateral_method(loader, c.taps);
  if (c.kind == "cross-bilateral-no-tilt") return make_cross_bilateral_method(loader, c.taps, false);
  for (const KernelChoice& k : kernel_family_choices()) {
    if (c.kind == k.name) return make_kernel_family_method(loader, k, c.taps);
  }
  return make_exact_method();
}

std::string now_utc() {
  const std::time_t t = std::time(nullptr);
  char buffer[64];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%d %H:%M UTC", std::gmtime(&t));
  return buffer;
}

// Scores results where the reference holds values: every pixel (stride 1), or the 1-in-stride²
// grid of receivers, decimated to a small image so that SSIM's windows see only reference pixels.
// Each translucent pixel is in one region of regions.hpp (classified at full size, then decimated).
class Grid {
 public:
  Grid(int stride, const RgbImage& reference, const RgbImage& input, const std::vector<uint8_t>& mask,
       const std::vector<uint8_t>& regions, int width, int height)
      : stride_(stride), width_(width), height_(height) {
    reference_ = decimate(reference);
    input_ = decimate(input);
    mask_.resize(static_cast<std::size_t>(reference_.width) * reference_.height);
    band_.resize(mask_.size());
    for (auto& m : region_masks_) m.resize(mask_.size());
    for (int y = 0; y < reference_.height; ++y) {
      for (int x = 0; x < reference_.width; ++x) {
        const int fx = x * stride_ + stride_ / 2, fy = y * stride_ + stride_ / 2;
        const std::size_t full = static_cast<std::size_t>(fy) * width_ + static_cast<std::size_t>(fx);
        const std::size_t i = reference_.index(x, y);
        mask_[i] = mask[full];
        band_[i] = mask_[i] != 0 && near_outside(mask, fx, fy);
        for (int r = 0; r < kRegionCount; ++r) region_masks_[static_cast<std::size_t>(r)][i] = regions[full] == r + 1 ? 1 : 0;
      }
    }
  }
  ErrorMetrics compare(const RgbImage& result) const { return compare_images(decimate(result), reference_, mask_.data()); }
  // The miss of `result` in each region, and relative RMSE on the interior, into `row`.
  void score_regions(const RgbImage& result, ResultRow* row) const {
    const RgbImage small = decimate(result);
    for (std::size_t r = 0; r < region_masks_.size(); ++r) row->region[r] = score_of(small, r);
    row->relative_rmse_interior = row->region[0].pixels > 0 ? relative_rmse(small, reference_, region_masks_[0].data())
                                                            : std::numeric_limits<double>::quiet_NaN();
  }
  // The miss of `result` on the interior alone (ResultRow::interior_conserving, on a grid made with
  // the conserving reference).
  RegionScore interior_score(const RgbImage& result) const { return score_of(decimate(result), 0); }
  // results.hpp's halo_energy on the grid's pixels.
  double halo(const RgbImage& result) const {
    const RgbImage small = decimate(result);
    double leaked = 0.0, reference = 0.0;
    for (std::size_t i = 0; i < band_.size(); ++i) {
      if (!band_[i]) continue;
      for (std::size_t c = 0; c < 3; ++c) {
        const double bound = std::max(reference_.rgb[i * 3 + c], input_.rgb[i * 3 + c]);
        leaked += std::max(0.0, small.rgb[i * 3 + c] - bound);
        reference += reference_.rgb[i * 3 + c];
      }
    }
    return reference > 0.0 ? leaked / reference : 0.0;
  }
  std::size_t selected() const { return static_cast<std::size_t>(std::count(mask_.begin(), mask_.end(), 1)); }

 private:
  RegionScore score_of(const RgbImage& small, std::size_t region) const {
    const Miss m = miss_share(small, reference_, input_, region_masks_[region].data());
    RegionScore score;
    score.miss = m.pooled;
    score.miss_channel = m.channel;
    score.share_channel = m.share;
    score.pixels = static_cast<int>(m.pixels);
    return score;
  }
  RgbImage decimate(const RgbImage& full) const {
    if (stride_ == 1) return full;
    RgbImage small((width_ - stride_ / 2 + stride_ - 1) / stride_, (height_ - stride_ / 2 + stride_ - 1) / stride_);
    for (int y = 0; y < small.height; ++y) {
      for (int x = 0; x < small.width; ++x) {
        for (int c = 0; c < 3; ++c) small.at(x, y, c) = full.at(x * stride_ + stride_ / 2, y * stride_ + stride_ / 2, c);
      }
    }
    return small;
  }
  // A non-translucent pixel within kHaloBand pixels (Chebyshev) of (x, y).
  bool near_outside(const std::vector<uint8_t>& mask, int x, int y) const {
    for (int dy = -kHaloBand; dy <= kHaloBand; ++dy) {
      for (int dx = -kHaloBand; dx <= kHaloBand; ++dx) {
        const int sx = x + dx, sy = y + dy;
        if (sx < 0 || sy < 0 || sx >= width_ || sy >= height_) continue;
        if (mask[static_cast<std::size_t>(sy) * width_ + static_cast<std::size_t>(sx)] == 0) return true;
      }
    }
    return false;
  }
  int stride_, width_, height_;
  RgbImage reference_, input_;
  std::vector<uint8_t> mask_;
  std::vector<bool> band_;
  std::array<std::vector<uint8_t>, kRegionCount> region_masks_;
};

// Rows [y0, y1) around the middle translucent row holding about 1/stride² of the translucent pixels.
struct Band {
  int y0 = 0, y1 = 0;
  long inside = 0, total = 0;
};
Band translucent_band(const std::vector<uint8_t>& mask, int width, int height, int stride) {
  std::vector<long> per_row(static_cast<std::size_t>(height), 0);
  Band b;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) per_row[static_cast<std::size_t>(y)] += mask[static_cast<std::size_t>(y) * width + x] != 0;
    b.total += per_row[static_cast<std::size_t>(y)];
  }
  long seen = 0;
  int middle = 0;
  while (middle < height - 1 && seen + per_row[static_cast<std::size_t>(middle)] < b.total / 2) seen += per_row[static_cast<std::size_t>(middle++)];
  const long wanted = std::max(1L, b.total / (static_cast<long>(stride) * stride));
  b.y0 = b.y1 = middle;
  while (b.inside < wanted && (b.y0 > 0 || b.y1 < height)) {
    if (b.y1 < height) b.inside += per_row[static_cast<std::size_t>(b.y1++)];
    if (b.inside < wanted && b.y0 > 0) b.inside += per_row[static_cast<std::size_t>(--b.y0)];
  }
  return b;
}

// The scenes scored a second time against the energy-conserving reference (results.hpp:
// interior_conserving): the head's faceted mesh loses light that no normalised filter can. Not
// head-mixed, whose reference is per material.
bool has_conserving_score(const std::string& scene) {
  return scene == "head-close" || scene == "head-mid" || scene == "head-far" || scene == "head-grazing";
}

// The mass as a picture: the heat maps' ramp of |mass - 1| (the largest channel), 0.05 at its top.
// On a receivers' grid each pixel shows the receiver of its stride block.
void write_mass_map(const std::string& path, const Reference& mass, const Scene& scene) {
  const int w = scene.width, h = scene.height, s = mass.stride;
  RgbImage filled(w, h, 1.0);
  std::vector<uint8_t> shown(scene.mask.size(), 0);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const int rx = std::min(x / s * s + s / 2, w - 1), ry = std::min(y / s * s + s / 2, h - 1);
      const std::size_t i = filled.index(x, y), r = filled.index(rx, ry);
      if (scene.mask[i] == 0 || scene.mask[r] == 0 || !on_grid(rx, ry, s)) continue;
      shown[i] = 1;
      for (int c = 0; c < 3; ++c) filled.at(x, y, c) = mass.rgba[r * 4 + static_cast<std::size_t>(c)];
    }
  }
  write_error_heatmap_png(path, filled, RgbImage(w, h, 1.0), shown.data(), 0.05);
}

// The grid that scores a head scene's rows against reference / mass (the same receivers, regions
// and input as `reference`'s); with mass_map set, the mass's picture there.
std::unique_ptr<Grid> make_conserving_grid(const Scene& scene, const Reference& reference, const RgbImage& input,
                                           const std::vector<uint8_t>& regions, long max_cpu_pixels,
                                           const std::string& mass_map) {
  const auto start = std::chrono::steady_clock::now();
  const Reference mass = make_mass_reference(scene, max_cpu_pixels, reference.stride);
  std::vector<double> interior;  // the least of the three channels' mass at each interior receiver
  for (std::size_t i = 0; i < regions.size(); ++i) {
    const auto w = static_cast<std::size_t>(scene.width);
    if (regions[i] != static_cast<uint8_t>(Region::interior) ||
        !on_grid(static_cast<int>(i % w), static_cast<int>(i / w), mass.stride)) {
      continue;
    }
    interior.push_back(std::min({mass.rgba[i * 4], mass.rgba[i * 4 + 1], mass.rgba[i * 4 + 2]}));
  }
  std::sort(interior.begin(), interior.end());
  if (!interior.empty()) {
    std::printf("  %s: mass of a uniform irradiance at the interior receivers: median %.4f, lowest %.4f (%.1f s)\n",
                scene.name.c_str(), interior[interior.size() / 2], interior.front(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  if (!mass_map.empty()) write_mass_map(mass_map, mass, scene);
  const std::vector<float> conserving = divide_by_mass(reference, mass, scene);
  return std::make_unique<Grid>(reference.stride, RgbImage::from_rgba(conserving.data(), scene.width, scene.height),
                                input, scene.mask, regions, scene.width, scene.height);
}

void set_error_metrics(const ErrorMetrics& e, ResultRow* row) {
  row->relative_rmse = e.relative_rmse;
  row->max_abs_error = e.max_abs;
  row->p99_abs_error = e.p99_abs;
  row->ssim = e.ssim;
}


int count(const std::vector<uint8_t>& mask) {
  return static_cast<int>(std::count_if(mask.begin(), mask.end(), [](uint8_t m) { return m != 0; }));
}

int run(const Options& options) {
  sss_headless_backend backend;
  if (sss_headless_backend_from_name(options.backend.c_str(), &backend) != 0) {
    std::fprintf(stderr, "sss_bench: unknown backend %s\n", options.backend.c_str());
    return 2;
  }
  sss_headless* headless = sss_test::open_host_context(backend, "sss_bench");
  if (headless == nullptr) return 1;
  std::filesystem::create_directories(options.out);
  RunInfo info;
  info.renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  info.version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  info.backend = sss_headless_backend_name(backend);
  const Clock clock = clock_for_renderer(info.renderer);
  info.clock = clock_name(clock);
  info.date = now_utc();
  info.mode = options.mode;
  info.command_line = options.command_line;
  info.warmup = options.warmup;
  info.repetitions = options.repetitions;
  info.reference = "exact 2D surface convolution with the six-Gaussian skin profile (CPU double up to " +
                   std::to_string(options.cpu_reference_max_pixels) + " pixels; GL fp32 above, spot-checked on the CPU)";
  std::printf("sss_bench: %s mode, GL_RENDERER %s, %s, timing: %s\n", options.mode.c_str(), info.renderer.c_str(),
              info.version.c_str(), info.clock.c_str());

  const GlLoader loader{sss_headless_get_proc_address, headless};
  std::unique_ptr<GpuBusy> busy;
  if (clock == Clock::timer_query && options.gpu_preload_ms > 0.0) busy = GpuBusy::create(options.gpu_preload_ms);
  if (busy != nullptr) {
    info.gpu_preload_ms = busy->calibrated_ms();
    set_timer_preamble([&busy] { busy->run(); });
    std::printf("sss_bench: the GPU spins %.3f ms before each timed frame (--gpu-preload-ms)\n", info.gpu_preload_ms);
  }
  {
    const StateCost cost = measure_state_cost(loader);
    info.state_with_restore_us = cost.with_restore_us;
    info.state_without_restore_us = cost.without_restore_us;
    info.state_calls = cost.calls_per_batch;
    info.state_batches = cost.batches;
    std::printf("sss_bench: one sss_apply_frame drawing nothing: %.1f us with the state restore, %.1f us without\n",
                cost.with_restore_us, cost.without_restore_us);
  }
  record_hitch_cost(loader, 320, 180, &info);
  const std::vector<std::string> default_scenes = options.scenes.empty() ? canonical_scene_names() : options.scenes;
  auto scenes_at = [&](std::size_t size_index) {
    const bool own = size_index < options.size_scenes.size() && !options.size_scenes[size_index].empty();
    return own ? options.size_scenes[size_index] : default_scenes;
  };
  // The profile's reach (regions.hpp) sizes the sweep's frames and defines the regions.
  const double reach_mm = profile_reach_mm(sss::math::skin_profile_terms());
  std::vector<SceneJob> jobs;
  for (std::size_t i = 0; i < options.sizes.size(); ++i) {
    for (const std::string& name : scenes_at(i)) jobs.push_back({name, options.sizes[i].first, options.sizes[i].second, 0.0});
  }
  const std::vector<MethodConfig> configs = method_configs(options);
  const auto sweep_count = static_cast<std::size_t>(
      std::count_if(configs.begin(), configs.end(), [&](const MethodConfig& c) { return runs_on_sweep(c, options); }));
  for (const std::string& name : options.sweep_scenes.empty() ? footprint_scene_names() : options.sweep_scenes) {
    if (sweep_count == 0) break;  // --methods left nothing that runs on the sweep
    for (double f : options.footprints) {
      const int side = sweep_frame_side(f, options.sweep_interior_px, reach_mm);
      jobs.push_back({name, side, side, f});
    }
  }
  info.reach_mm = reach_mm;
  std::size_t total = 0;
  for (const SceneJob& job : jobs) total += (job.footprint_mm > 0.0 ? sweep_count : configs.size()) + 1;
  std::size_t done = 0;
  std::vector<ResultRow> rows;
  std::vector<ReferenceCheck> checks;
  auto copy_method = make_copy_method();

  for (const SceneJob& job : jobs) {
    const int width = job.width, height = job.height;
    const std::string& scene_name = job.name;
    const bool sweep = job.footprint_mm > 0.0;
    const Scene scene = sweep ? make_footprint_scene(scene_name, job.footprint_mm, width, height)
                              : make_scene(scene_name, width, height);
    GpuScene gpu = upload_scene(scene);
    const GLuint output = make_output_texture(width, height);
    const std::string tag = scene_name + "-" + std::to_string(width) + "x" + std::to_string(height);

    // The reference, and the yardstick time.
    if (!check_gl(("making " + tag).c_str())) throw std::runtime_error("making " + tag + " left a GL error");
    const int stride = options.reference_stride > 0 ? options.reference_stride : std::max(1, (height + 90) / 180);
    const Reference reference =
        sweep ? make_plane_reference(scene, gpu)
              : make_reference(scene, gpu, options.cpu_reference_max_pixels, options.cpu_spot_checks, stride);
    if (reference.check.checked > 0) checks.push_back(reference.check);
    std::string message;
    // The yardstick: the two-pass copy of this scene, timed here and again before each method.
    const auto time_copy = [&] {
      return time_frames(clock, options.warmup, options.repetitions,
                         [&] { return copy_method->run(gpu, output, &message); });
    };
    const Timing copy = time_copy();
    ++done;
    std::printf("[%zu/%zu] %s%s: reference %s, copy %.3f ms\n", done, total, tag.c_str(),
                sweep ? (" (" + std::to_string(job.footprint_mm).substr(0, 6) + " mm/px)").c_str() : "",
                reference.source.c_str(), copy.median_ms);
    std::fflush(stdout);
    const RgbImage reference_image = RgbImage::from_rgba(reference.rgba.data(), width, height);
    const bool pictured = !sweep && options.heat_maps && is_pictured_scene(scene_name, width, options.sizes);
    if (pictured) {
      write_tonemapped_png(options.out + "/" + tag + "-input.png",
                           RgbImage::from_rgba(gpu.irradiance_half.data(), width, height));
      write_tonemapped_png(options.out + "/" + tag + "-reference.png", reference_image);
    }

    const RegionInput region_input = region_input_of(scene, reach_mm);
    const std::vector<uint8_t> regions = classify_regions(region_input);
    const double footprint_mm = sweep ? job.footprint_mm : median_footprint_mm(region_input);
    const RgbImage input_image = RgbImage::from_rgba(gpu.irradiance_half.data(), width, height);  // as the GL holds it
    const Grid grid(reference.stride, reference_image, input_image, scene.mask, regions, width, height);
    const std::unique_ptr<Grid> conserving =
        has_conserving_score(scene_name)
            ? make_conserving_grid(scene, reference, input_image, regions, options.cpu_reference_max_pixels,
                                   pictured && scene_name == "head-close" ? options.out + "/" + tag + "-mass.png" : "")
            : nullptr;
    // What every row of this scene shares.
    ResultRow scene_row;
    scene_row.scene = scene_name;
    scene_row.width = width;
    scene_row.height = height;
    scene_row.footprint_mm = footprint_mm;
    scene_row.sweep = sweep;
    scene_row.reference_stride = reference.stride;
    scene_row.translucent_pixels = count(scene.mask);
    // Doing nothing: the input itself, the row every other one is read against.
    {
      ResultRow row = scene_row;
      row.method = "no-scattering";
      set_error_metrics(grid.compare(input_image), &row);
      grid.score_regions(input_image, &row);
      if (conserving != nullptr) row.interior_conserving = conserving->interior_score(input_image);
      rows.push_back(row);
    }
    for (const MethodConfig& config : configs) {
      if (sweep && !runs_on_sweep(config, options)) continue;
      // The kernel families are compared at up to 640x360 (their Pareto curves); the 1080p head
      // rows keep the methods of the paper's Table 2. The sweep runs them at every footprint.
      if (!sweep && config.kind.rfind("kernel-", 0) == 0 && static_cast<long>(width) * height > options.family_max_pixels) {
        ++done;
        continue;
      }
      // The exact 2D filter convolves with one profile (skin): no method for a scene of several
      // materials, whose reference is per material.
      if (config.kind == "exact-2d" && !scene.profile.empty()) {
        ++done;
        continue;
      }
      ResultRow row = scene_row;
      std::string path_ran;
      ErrorMetrics e;
      Timing t;
      Timing beside_copy;  // the copy timed right before this method (none for the exact filter)
      const bool exact = config.kind == "exact-2d";
      if (exact && reference.source.rfind("GL", 0) == 0) {
        // The reference was this filter, so its error is zero by definition. Its time: the
        // reference's own frame at stride 1; on a grid, a full-resolution band of rows holding
        // 1/stride² of the translucent pixels, timed and scaled by the pixel count (the grid
        // itself runs less coherently on SIMD hardware and would overstate the cost).
        row.method = "exact-2d";
        row.passes = 2;
        e.pixels = grid.selected();
        grid.score_regions(reference_image, &row);
        if (conserving != nullptr) row.interior_conserving = conserving->interior_score(reference_image);
        if (reference.stride == 1) {
          t.median_ms = t.min_ms = t.max_ms = reference.gl_time_ms;
        } else {
          const Band band = translucent_band(scene.mask, width, height, reference.stride);
          auto method = make_exact_method(1, {band.y0, band.y1});
          t = time_frames(clock, 1, 1, [&] { return method->run(gpu, output, &message); });
          if (t.samples == 0) throw std::runtime_error(tag + " exact-2d band: " + message);
          // Nothing translucent: the band was the whole frame, so the time is measured as it is.
          const double scale = band.total > 0 ? static_cast<double>(band.total) / static_cast<double>(band.inside) : 1.0;
          t.median_ms = t.min_ms = t.max_ms = t.median_ms * scale;
          row.time_extrapolated = band.total > 0;
          row.band_rows = band.y1 - band.y0;
        }
        t.samples = 1;
      } else {
        auto method = make_method(config, loader);
        if (method == nullptr) {
          ++done;
          continue;
        }
        // The copy again, as the scene's above, right before this method's frames, so that
        // its ratio sets two times taken moments apart: llvmpipe's 1080p copy moved between 13 and
        // 26 ms within one run of this machine, and with one copy per scene the last method's ratio
        // used a copy timed minutes before it. (Not interleaved frame by frame: a copy right after a
        // method's frame, even after an untimed copy, took 18.5-19 ms against 16-17 back to back,
        // most likely as the method left the caches, which would flatter every ratio by 15 %.) The
        // exact filter's one frame keeps the scene's copy.
        if (!exact) beside_copy = time_copy();
        // The exact filter is slow on a software rasteriser: one frame (after one that compiles
        // its shaders) is its measurement.
        t = time_frames(
            clock, exact ? 1 : options.warmup,
            exact ? 1 : (sweep && options.sweep_repetitions > 0 ? options.sweep_repetitions : options.repetitions),
            [&] { return method->run(gpu, output, &message); }, [&] { method->before_run(gpu); },
            [&] { method->after_run(gpu, output); });
        if (t.samples == 0) throw std::runtime_error(tag + " " + config.kind + ": " + message);
        if (!check_gl((tag + " " + config.kind).c_str())) throw std::runtime_error(tag + " " + config.kind + " left a GL error");
        row.method = method->name();
        path_ran = method->path_ran();
        row.path_ran = path_ran;
        row.taps = method->taps();
        row.follow_surface = method->follow_surface();
        row.passes = method->passes();
        const RgbImage result = RgbImage::from_rgba(read_texture_rgba(output, width, height).data(), width, height);
        e = grid.compare(result);
        grid.score_regions(result, &row);
        if (conserving != nullptr) row.interior_conserving = conserving->interior_score(result);
        row.halo_energy = grid.halo(result);
        if (pictured && is_pictured_method(row)) {
          const std::string stem = options.out + "/" + picture_stem(row);
          write_tonemapped_png(stem + ".png", result);
          write_error_heatmap_png(stem + "-error.png", result, reference_image, scene.mask.data(),
                                  heat_map_scale(reference_image, scene.mask.data()));
        }
      }
      ++done;
      row.time_ms = t.median_ms;
      row.time_min_ms = t.min_ms;
      row.time_max_ms = t.max_ms;
      row.samples = t.samples;
      const double copy_ms = beside_copy.samples > 0 ? beside_copy.median_ms : copy.median_ms;
      row.time_ratio_to_copy = copy_ms > 0.0 ? t.median_ms / copy_ms : 0.0;
      set_error_metrics(e, &row);
      rows.push_back(row);
      std::printf("[%zu/%zu] %s %s: %.3f ms (%.2f x copy), miss interior %s (no scattering: 1), rel. RMSE %.4g, "
                  "SSIM %.4f%s%s\n",
                  done, total, tag.c_str(), method_label(row).c_str(), row.time_ms, row.time_ratio_to_copy,
                  miss_text(row.interior().miss).c_str(), row.relative_rmse, row.ssim,
                  path_ran.empty() ? "" : ", path ", path_ran.c_str());
      std::fflush(stdout);
    }
    glDeleteTextures(1, &output);
    destroy_scene(&gpu);
  }
  copy_method.reset();
  std::vector<MsaaRow> msaa_rows;
  if (options.msaa) {
    msaa_rows = run_msaa_study(options, loader, clock);
    write_msaa_csv(options.out + "/msaa.csv", msaa_rows);
    std::ofstream md(options.out + "/msaa.md");
    write_msaa_section(md, msaa_rows, "");
  }

  write_csv(options.out + "/results.csv", rows);
  write_miss_csv(options.out + "/miss.csv", rows);
  write_json(options.out + "/results.json", info, rows);
  write_markdown_table(options.out + "/results.md", info, rows);
  bool plots_drawn = false;
  const std::vector<std::string> plots = write_pareto_plots(options.out, rows, &plots_drawn);
  const std::vector<std::string> footprint_plots = write_footprint_plots(options.out, rows);
  const std::vector<std::string> band_plots = write_band_pareto_plots(options.out, rows);
  if (!options.doc.empty()) {
    write_results_document(options.doc, options.out, info, rows, checks, plots, footprint_plots, band_plots);
    std::ofstream doc(options.doc, std::ios::app);
    const std::string prefix = std::filesystem::relative(std::filesystem::absolute(options.out),
                                                         std::filesystem::absolute(options.doc).parent_path())
                                   .generic_string();
    write_msaa_section(doc, msaa_rows, prefix.empty() || prefix == "." ? "" : prefix + "/");
  }
  std::printf("sss_bench: %zu rows, %zu plots in %s%s\n", rows.size(),
              plots.size() + footprint_plots.size() + band_plots.size(), options.out.c_str(),
              plots_drawn ? "" : " (gnuplot not found: their .gp scripts are there to draw them)");
  set_timer_preamble({});
  busy.reset();
  sss_headless_destroy(headless);
  return 0;
}

}  // namespace
}  // namespace sss_bench

int main(int argc, char** argv) {
  try {
    return sss_bench::run(sss_bench::parse_options(argc, argv));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sss_bench: %s\n", e.what());
    return 1;
  }
}
