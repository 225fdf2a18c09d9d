#include "msaa_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <ostream>
#include <stdexcept>

#include "gpu_scene.hpp"
#include "host_gl_util.hpp"
#include "metrics.hpp"
#include "multisample_textures.hpp"
#include "reference.hpp"
#include "report.hpp"
#include "scenes/scenes.hpp"
#include "sss/sss.h"

using namespace host_gl;
using sss_test::make_multisample_texture;
using sss_test::texture_samples;

namespace sss_bench {

namespace {

struct Variant {
  const char* name;
  uint32_t mode;
};
constexpr Variant kVariants[] = {{"average", SSS_MSAA_DEPTH_AVERAGE},
                                 {"sample-0", SSS_MSAA_DEPTH_SAMPLE0},
                                 {"min", SSS_MSAA_DEPTH_MIN},
                                 {"max", SSS_MSAA_DEPTH_MAX}};

// Sample i of pixel (x, y) is texel (2x + i % 2, 2y + i / 2) of the fine image.
std::size_t fine_index(const Scene& fine, int x, int y, int i) {
  return static_cast<std::size_t>(2 * y + i / 2) * static_cast<std::size_t>(fine.width) +
         static_cast<std::size_t>(2 * x + i % 2);
}

RgbImage box_downsample(const RgbImage& fine) {
  RgbImage out(fine.width / 2, fine.height / 2);
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        out.at(x, y, c) = 0.25 * (fine.at(2 * x, 2 * y, c) + fine.at(2 * x + 1, 2 * y, c) +
                                  fine.at(2 * x, 2 * y + 1, c) + fine.at(2 * x + 1, 2 * y + 1, c));
      }
    }
  }
  return out;
}

double max_channel_error(const RgbImage& a, const RgbImage& r, int x, int y) {
  double e = 0.0;
  for (int c = 0; c < 3; ++c) e = std::max(e, std::fabs(a.at(x, y, c) - r.at(x, y, c)));
  return e;
}

// A crop of each image around (cx, cy), zoomed by nearest neighbour and laid side by side.
RgbImage zoomed_strip(const std::vector<const RgbImage*>& images, int cx, int cy, int crop, int zoom) {
  const int gap = 2, panel = crop * zoom;
  RgbImage strip(static_cast<int>(images.size()) * (panel + gap) - gap, panel, 0.0);
  for (std::size_t k = 0; k < images.size(); ++k) {
    const RgbImage& im = *images[k];
    const int x0 = std::clamp(cx - crop / 2, 0, std::max(0, im.width - crop));
    const int y0 = std::clamp(cy - crop / 2, 0, std::max(0, im.height - crop));
    for (int y = 0; y < panel; ++y) {
      for (int x = 0; x < panel; ++x) {
        const int sx = std::min(im.width - 1, x0 + x / zoom), sy = std::min(im.height - 1, y0 + y / zoom);
        for (int c = 0; c < 3; ++c) strip.at(static_cast<int>(k) * (panel + gap) + x, y, c) = im.at(sx, sy, c);
      }
    }
  }
  return strip;
}

class Study {
 public:
  Study(const GlLoader& loader) {
    sss_create_desc desc = {};
    desc.struct_size = sizeof desc;
    desc.get_proc_address = loader.get_proc_address;
    desc.get_proc_address_user = loader.user;
    if (sss_create(&desc, &ctx_) != SSS_OK) throw std::runtime_error(sss_last_error(nullptr));
  }
  ~Study() { sss_destroy(ctx_); }
  Study(const Study&) = delete;
  Study& operator=(const Study&) = delete;

  void configure(const Scene& scene, float width_scale) {
    sss_settings s;
    sss_default_settings(&s);
    s.world_units_per_mm = (scene.world_units_per_mm) * width_scale;
    if (sss_set_settings(ctx_, &s) != SSS_OK || sss_set_camera(ctx_, scene.projection.data()) != SSS_OK) {
      throw std::runtime_error(std::string("msaa study: ") + sss_last_error(ctx_));
    }
  }
  bool apply(GLuint color, GLuint depth, GLuint output, uint32_t mode) {
    sss_frame f = {};
    f.struct_size = sizeof f;
    f.color_texture = color;
    f.depth_texture = depth;
    f.output_texture = output;
    f.msaa_depth_resolve = mode;
    if (sss_apply_frame(ctx_, &f) == SSS_OK) return true;
    std::fprintf(stderr, "msaa study: %s\n", sss_last_error(ctx_));
    return false;
  }

 private:
  sss_context* ctx_ = nullptr;
};

}  // namespace

std::vector<MsaaRow> run_msaa_study(const Options& options, const GlLoader& loader, Clock clock) {
  std::vector<MsaaRow> rows;
  const int width = options.msaa_size.first, height = options.msaa_size.second;
  Study study(loader);
  for (const std::string name : {"sphere", "depth-step"}) {
    const Scene fine = make_scene(name, 2 * width, 2 * height);
    const Scene coarse = make_scene(name, width, height);
    GpuScene fine_gpu = upload_scene(fine);
    GpuScene coarse_gpu = upload_scene(coarse);
    // The 4x supersampled exact reference, whole image (stride 1).
    const Reference reference =
        make_reference(fine, fine_gpu, options.cpu_reference_max_pixels, options.cpu_spot_checks, 1);
    const RgbImage ref = box_downsample(RgbImage::from_rgba(reference.rgba.data(), fine.width, fine.height));
    destroy_scene(&fine_gpu);

    const GLuint color = make_multisample_texture(GL_RGBA16F, width, height, 4, fine.irradiance);
    const GLuint depth = make_multisample_texture(GL_DEPTH_COMPONENT32F, width, height, 4, fine.window_depth);
    if (texture_samples(color) != 4) throw std::runtime_error("msaa study: the context has no 4-sample textures");
    const GLuint output = make_output_texture(width, height);

    // Silhouettes: pixels whose samples disagree about translucency, and their 8 neighbours.
    // Interior: pixels whose four samples are all translucent, outside the silhouettes.
    std::vector<uint8_t> mixed(static_cast<std::size_t>(width * height), 0), silhouette(mixed), interior(mixed),
        translucent(mixed);
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        int covered = 0;
        for (int i = 0; i < 4; ++i) covered += fine.mask[fine_index(fine, x, y, i)] != 0;
        mixed[static_cast<std::size_t>(y * width + x)] = covered > 0 && covered < 4;
        translucent[static_cast<std::size_t>(y * width + x)] = covered > 0;
        interior[static_cast<std::size_t>(y * width + x)] = covered == 4;
      }
    }
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        bool near = false;
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx >= 0 && ny >= 0 && nx < width && ny < height && mixed[static_cast<std::size_t>(ny * width + nx)]) near = true;
          }
        }
        silhouette[static_cast<std::size_t>(y * width + x)] = near;
        if (near) interior[static_cast<std::size_t>(y * width + x)] = 0;
      }
    }
    // Fringe threshold: 5 % of the reference's brightest translucent value (half the heat maps'
    // full scale), a step a viewer sees as a light or dark line along the edge.
    const double threshold = 0.5 * heat_map_scale(ref, translucent.data());
    const int silhouette_count = static_cast<int>(std::count(silhouette.begin(), silhouette.end(), 1));

    auto score = [&](const std::string& variant, const RgbImage& result) {
      MsaaRow row;
      row.scene = name;
      row.width = width;
      row.height = height;
      row.variant = variant;
      row.silhouette_pixels = silhouette_count;
      row.silhouette_relative_rmse = relative_rmse(result, ref, silhouette.data());
      row.silhouette_max_abs = max_abs_error(result, ref, silhouette.data());
      row.fringe_threshold = threshold;
      for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
          if (silhouette[static_cast<std::size_t>(y * width + x)] && max_channel_error(result, ref, x, y) > threshold) {
            ++row.fringe_pixels;
          }
        }
      }
      return row;
    };

    // Single-sample: the same scene rendered at pixel centres.
    study.configure(coarse, 1.0f);
    // Every path once before any timing: a software rasteriser compiles code for each new state
    // and shader combination at its first draws, which would land on whichever row runs first.
    for (int i = 0; i < 2; ++i) {
      study.apply(coarse_gpu.irradiance, coarse_gpu.depth, output, 0);
      for (const Variant& v : kVariants) study.apply(color, depth, output, v.mode);
    }
    const Timing single_time = time_frames(clock, options.warmup, options.repetitions,
                                           [&] { return study.apply(coarse_gpu.irradiance, coarse_gpu.depth, output, 0); });
    const RgbImage single = RgbImage::from_rgba(read_texture_rgba(output, width, height).data(), width, height);
    MsaaRow single_row = score("single-sample", single);
    single_row.time_ms = single_time.median_ms;

    std::vector<RgbImage> results;
    for (const Variant& v : kVariants) {
      const Timing t = time_frames(clock, options.warmup, options.repetitions,
                                   [&] { return study.apply(color, depth, output, v.mode); });
      if (t.samples == 0) throw std::runtime_error("msaa study: " + name + " " + v.name + " failed");
      results.push_back(RgbImage::from_rgba(read_texture_rgba(output, width, height).data(), width, height));
      MsaaRow row = score(v.name, results.back());
      row.time_ms = t.median_ms;
      row.interior_relative_rmse = relative_rmse(results.back(), single, interior.data());
      if (v.mode == SSS_MSAA_DEPTH_AVERAGE) {
        row.resolve_share = t.median_ms > 0.0 ? std::max(0.0, (t.median_ms - single_time.median_ms) / t.median_ms) : 0.0;
      }
      rows.push_back(row);
    }
    rows.push_back(single_row);

    // The zoomed edge: around the silhouette pixel where sample-0 depth errs most.
    int best = -1;
    double worst = -1.0;
    for (int i = 0; i < width * height; ++i) {
      if (!silhouette[static_cast<std::size_t>(i)]) continue;
      const double e = max_channel_error(results[1], ref, i % width, i / width);
      if (e > worst) worst = e, best = i;
    }
    if (best >= 0 && options.heat_maps) {
      const std::string file = "msaa-" + name + "-" + std::to_string(width) + "x" + std::to_string(height) + "-edge.png";
      const RgbImage strip = zoomed_strip({&ref, &results[0], &results[1], &results[2], &results[3], &single},
                                          best % width, best / width, 16, 8);
      write_tonemapped_png(options.out + "/" + file, strip);
      // Under it, the error of each panel against the reference (the first panel is 0), on the
      // heat maps' ramp with the fringe threshold at half scale.
      const RgbImage refs = zoomed_strip({&ref, &ref, &ref, &ref, &ref, &ref}, best % width, best / width, 16, 8);
      write_error_heatmap_png(options.out + "/" + file.substr(0, file.size() - 4) + "-error.png", strip, refs,
                              nullptr, 2.0 * threshold);
      for (MsaaRow& r : rows) {
        if (r.scene == name && r.variant == "average") r.picture = file;
      }
    }

    // Writing back into the samples (in place: the image changes each frame, the cost does not).
    const Timing write_back = time_frames(clock, std::max(2, options.warmup), options.repetitions,
                                          [&] { return study.apply(color, depth, 0, SSS_MSAA_DEPTH_AVERAGE); });
    for (MsaaRow& r : rows) {
      if (r.scene == name && r.variant == "average") r.write_back_ms = write_back.median_ms;
    }
    const GLuint textures[3] = {color, depth, output};
    glDeleteTextures(3, textures);
    destroy_scene(&coarse_gpu);
    if (!check_gl(("msaa study " + name).c_str())) throw std::runtime_error("msaa study left a GL error");
    std::printf("msaa study %s %dx%d: done\n", name.c_str(), width, height);
  }
  return rows;
}

void write_msaa_csv(const std::string& path, const std::vector<MsaaRow>& rows) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << "scene,width,height,variant,silhouette_pixels,silhouette_relative_rmse,silhouette_max_abs,fringe_pixels,"
         "fringe_threshold,interior_relative_rmse,time_ms,resolve_share,write_back_ms,picture\n";
  for (const MsaaRow& r : rows) {
    out << r.scene << ',' << r.width << ',' << r.height << ',' << r.variant << ',' << r.silhouette_pixels << ','
        << r.silhouette_relative_rmse << ',' << r.silhouette_max_abs << ',' << r.fringe_pixels << ','
        << r.fringe_threshold << ',' << r.interior_relative_rmse << ',' << r.time_ms << ',' << r.resolve_share << ','
        << r.write_back_ms << ',' << (r.picture.empty() ? "-" : r.picture) << '\n';
  }
}

void write_msaa_section(std::ostream& out, const std::vector<MsaaRow>& rows, const std::string& picture_prefix) {
  if (rows.empty()) return;
  out << "\n## MSAA: depth resolve at silhouettes\n\n"
      << "The sphere and depth-step scenes with 4 samples per pixel (the scene made at twice the size; sample i of "
         "a pixel is texel (2x + i % 2, 2y + i / 2) of it), filtered by the library's MSAA path "
         "(`sss_frame.msaa_depth_resolve`) into a single-sample output, and scored against the exact 2D filter of "
         "the twice-size scene, box-downsampled (a 4x supersampled reference). `single-sample` is the filter on the "
         "scene rendered at pixel centres. Silhouette pixels: those whose samples disagree about translucency, and "
         "their 8 neighbours; a fringe pixel is a silhouette pixel whose error exceeds 5 % of the reference's "
         "brightest translucent value. Interior: relative RMSE against the single-sample result where all four "
         "samples are translucent. Resolve share: (MSAA path - single-sample path) / MSAA path, same size, i.e. "
         "what the resolve and the stencil mark it is followed by add to the two blur passes; write "
         "back: the whole frame filtered in place (`output_texture` = 0: resolve, passes and the write-back into the "
         "translucent samples, one blended draw that reads none of them). Pictures: reference | average | sample 0 | "
         "min | max | single-sample, 16x16 pixels around the edge where sample-0 depth errs most, zoomed 8x, and "
         "under them each one's error against the reference (heat-map ramp, the fringe threshold at mid scale).\n\n"
      << "| scene | size | depth resolve | silhouette px | silhouette rel. RMSE | silhouette max abs | fringe px | "
         "interior rel. RMSE vs single | time ms | resolve share | write-back ms |\n"
      << "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  char line[512];
  for (const MsaaRow& r : rows) {
    std::snprintf(line, sizeof line, "| %s | %dx%d | %s | %d | %.4f | %.4f | %d | %s | %.3f | %s | %s |\n",
                  r.scene.c_str(), r.width, r.height, r.variant.c_str(), r.silhouette_pixels,
                  r.silhouette_relative_rmse, r.silhouette_max_abs, r.fringe_pixels,
                  r.variant == "single-sample" ? "-" : std::to_string(r.interior_relative_rmse).c_str(), r.time_ms,
                  r.variant == "average" ? (std::to_string(static_cast<int>(std::lround(100.0 * r.resolve_share))) + " %").c_str() : "-",
                  r.variant == "average" ? std::to_string(r.write_back_ms).c_str() : "-");
    out << line;
  }
  out << '\n';
  for (const MsaaRow& r : rows) {
    if (r.picture.empty()) continue;
    const std::string stem = picture_prefix + r.picture.substr(0, r.picture.size() - 4);
    out << "**" << r.scene << "**, reference | average | sample 0 | min | max | single-sample:\n\n![" << r.scene
        << " edge, zoomed](" << stem << ".png)\n\n![" << r.scene << " edge error](" << stem << "-error.png)\n\n";
  }
}

}  // namespace sss_bench
