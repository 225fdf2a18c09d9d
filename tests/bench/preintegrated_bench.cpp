// sss_bench_preintegrated: the pre-integrated skin path (docs/preintegrated.md) in numbers.
//  1. Generation time of 256² LUTs (diffuse, shadow): CPU on 1 thread and on all, GPU
//     (sss_lut_create_texture, glFinish'ed; each run with new inputs so nothing comes from the cache).
//  2. Error against the exact 2D reference (the benchmark's, reference.hpp) on the sphere and head
//     scenes: the unscattered input, the separable filter (17 taps, follow-surface) and
//     pre-integrated shading (make_preintegrated_scene), on the translucent pixels.
// Writes a Markdown report (--doc) and tone-mapped pictures of the pre-integrated heads (--out).
//   sss_bench_preintegrated [--backend egl] [--size 320x180] [--repetitions 5] [--lut-size 256] [--scenes a,b]
//                           [--out DIR] [--doc FILE]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "list_argument.hpp"
#include "gpu_scene.hpp"
#include "host_context.hpp"
#include "host_gl.hpp"
#include "math/preintegrated_lut.hpp"
#include "method.hpp"
#include "metrics.hpp"
#include "reference.hpp"
#include "scenes/scenes.hpp"
#include "sss/sss_lut.h"
#include "sss_headless.h"
#include "timing.hpp"

using namespace host_gl;

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

struct Args {
  std::string backend = "egl", out = ".", doc;
  int width = 320, height = 180, repetitions = 5;
  int lut_size = 256;  // the timed LUTs are lut_size²
  std::vector<std::string> scenes = {"sphere", "sphere-20mm", "sphere-10mm", "head-close", "head-mid", "head-far"};
  std::string command_line;
};

Args parse(int argc, char** argv) {
  Args a;
  for (int i = 0; i < argc; ++i) a.command_line += (i ? " " : "") + std::string(argv[i]);
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    const bool has = i + 1 < argc;
    if (k == "--backend" && has) {
      a.backend = argv[++i];
    } else if (k == "--out" && has) {
      a.out = argv[++i];
    } else if (k == "--doc" && has) {
      a.doc = argv[++i];
    } else if (k == "--lut-size" && has) {
      a.lut_size = std::clamp(std::atoi(argv[++i]), 2, 4096);
    } else if (k == "--repetitions" && has) {
      a.repetitions = std::max(1, std::atoi(argv[++i]));
    } else if (k == "--size" && has) {
      if (std::sscanf(argv[++i], "%dx%d", &a.width, &a.height) != 2 || a.width < 16 || a.height < 16) {
        std::fprintf(stderr, "bad --size\n");
        std::exit(2);
      }
    } else if (k == "--scenes" && has) {
      a.scenes = sss_bench::split_list(argv[++i]);
    } else {
      std::printf("usage: %s [--backend egl|osmesa] [--size WxH] [--repetitions N] [--lut-size N] [--scenes a,b] [--out DIR] [--doc FILE]\n",
                  argv[0]);
      std::exit(k == "--help" ? 0 : 2);
    }
  }
  return a;
}

struct GenerationRow {
  std::string lut, where;
  double median_ms = 0.0;
};

// Within 5% either way counts as a tie (the metrics differ in the third digit between runs).
const char* verdict(double mine, double other) {
  if (mine < 0.95 * other) return "better than";
  if (mine <= 1.05 * other || mine - other < 1e-4) return "as good as";
  return "worse than";
}

struct ErrorRow {
  std::string scene, method;
  sss_bench::ErrorMetrics metrics;
  sss_bench::Miss miss;  // against the input (metrics.hpp): 1 for the input's own row
};

}  // namespace

// The mask without its pixels within kInteriorBand pixels (Chebyshev) of a pixel outside it.
constexpr int kInteriorBand = 6;
static std::vector<uint8_t> interior(const std::vector<uint8_t>& mask, int width, int height) {
  std::vector<uint8_t> out(mask.size(), 0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      bool keep = mask[static_cast<std::size_t>(y) * width + x] != 0;
      for (int dy = -kInteriorBand; dy <= kInteriorBand && keep; ++dy) {
        for (int dx = -kInteriorBand; dx <= kInteriorBand && keep; ++dx) {
          const int sx = x + dx, sy = y + dy;
          keep = sx >= 0 && sy >= 0 && sx < width && sy < height && mask[static_cast<std::size_t>(sy) * width + sx] != 0;
        }
      }
      out[static_cast<std::size_t>(y) * width + x] = keep ? 1 : 0;
    }
  }
  return out;
}

int main(int argc, char** argv) {
  const Args args = parse(argc, argv);
  sss_headless_backend backend;
  if (sss_headless_backend_from_name(args.backend.c_str(), &backend) != 0) {
    std::fprintf(stderr, "unknown backend %s\n", args.backend.c_str());
    return 2;
  }
  sss_headless* headless = sss_test::open_host_context(backend, "sss_bench_preintegrated");
  if (headless == nullptr) return 1;
  const std::string renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  std::printf("sss_bench_preintegrated: GL_RENDERER %s, %u hardware threads\n", renderer.c_str(), cores);

  // ---- 1. Generation time.
  std::vector<GenerationRow> generation;
  const sss::math::RadialProfile& profile = sss::math::deon_skin_profile();
  const int n = args.lut_size;
  std::vector<float> buffer(4u * static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  sss::math::DiffuseLutDesc diffuse_desc;
  sss::math::ShadowLutDesc shadow_desc;
  diffuse_desc.width = diffuse_desc.height = shadow_desc.width = shadow_desc.height = n;
  for (int lut = 0; lut < 2; ++lut) {
    const std::string name = (lut == 0 ? "diffuse " : "shadow ") + std::to_string(n) + "²" + (lut == 0 ? "" : " (box)");
    for (int threads : {1, static_cast<int>(cores)}) {
      std::vector<double> times;
      for (int r = 0; r < args.repetitions; ++r) {
        const Clock::time_point start = Clock::now();
        if (lut == 0) {
          sss::math::generate_diffuse_lut(profile, diffuse_desc, threads, buffer.data());
        } else {
          sss::math::generate_shadow_lut(profile, shadow_desc, threads, buffer.data());
        }
        times.push_back(ms_since(start));
      }
      generation.push_back({name, "CPU, " + std::to_string(threads) + (threads == 1 ? " thread" : " threads"),
                            sss_bench::median(times)});
    }
    sss_create_desc cd = {};
    cd.struct_size = sizeof cd;
    cd.get_proc_address = sss_headless_get_proc_address;
    cd.get_proc_address_user = headless;
    sss_context* ctx = nullptr;
    if (sss_create(&cd, &ctx) != SSS_OK) {
      std::fprintf(stderr, "sss_create: %s\n", sss_last_error(nullptr));
      return 1;
    }
    for (int format : {SSS_LUT_FORMAT_RGBA16F, SSS_LUT_FORMAT_RGBA8}) {
      std::vector<double> times;
      for (int r = 0; r < args.repetitions; ++r) {
        sss_lut_desc d;
        sss_lut_default_desc(&d);
        d.width = d.height = n;
        d.format = format;
        d.curvature_max += 1e-4f * static_cast<float>(r + 1);  // new inputs: never a cache hit
        d.penumbra_max += 1e-5f * static_cast<float>(r + 1);
        const uint64_t before = sss_lut_generation_count(ctx);
        glFinish();
        const Clock::time_point start = Clock::now();
        uint32_t texture = 0;
        if (sss_lut_create_texture(ctx, lut == 0 ? SSS_LUT_DIFFUSE : SSS_LUT_SHADOW, &d, &texture) != SSS_OK) {
          std::fprintf(stderr, "sss_lut_create_texture: %s\n", sss_last_error(ctx));
          return 1;
        }
        glFinish();
        times.push_back(ms_since(start));
        if (sss_lut_generation_count(ctx) != before + 1) {
          std::fprintf(stderr, "a timed GPU generation came from the cache\n");
          return 1;
        }
      }
      generation.push_back({name, std::string("GPU (") + renderer + "), " +
                                      (format == SSS_LUT_FORMAT_RGBA16F ? "RGBA16F" : "RGBA8") + ", shader compile included",
                            sss_bench::median(times)});
    }
    sss_destroy(ctx);
  }
  for (const auto& g : generation) std::printf("  %-18s %-60s %10.2f ms\n", g.lut.c_str(), g.where.c_str(), g.median_ms);

  // ---- 2. Error against the exact reference.
  std::filesystem::create_directories(args.out);
  std::vector<ErrorRow> errors;
  sss_bench::GlLoader loader{sss_headless_get_proc_address, headless};
  for (const std::string& name : args.scenes) {
    const sss_bench::Scene scene = sss_bench::make_scene(name, args.width, args.height);
    const sss_bench::Scene pre = sss_bench::make_preintegrated_scene(name, args.width, args.height);
    sss_bench::GpuScene gpu = sss_bench::upload_scene(scene);
    const Clock::time_point start = Clock::now();
    // CPU double reference for every pixel at these sizes (stride 1).
    const sss_bench::Reference reference =
        sss_bench::make_reference(scene, gpu, static_cast<long>(args.width) * args.height, 0, 1);
    std::printf("  %s: reference (%s) in %.1f s\n", name.c_str(), reference.source.c_str(), ms_since(start) / 1000.0);
    const sss_bench::RgbImage ref = sss_bench::RgbImage::from_rgba(reference.rgba.data(), scene.width, scene.height);
    const sss_bench::RgbImage input =
        sss_bench::RgbImage::from_rgba(gpu.irradiance_half.data(), scene.width, scene.height);
    const sss_bench::RgbImage preintegrated = sss_bench::RgbImage::from_rgba(pre.irradiance.data(), pre.width, pre.height);
    auto separable = sss_bench::make_separable_method(loader, 17, true);
    const GLuint output = sss_bench::make_output_texture(scene.width, scene.height);
    std::string message;
    if (!separable->run(gpu, output, &message)) {
      std::fprintf(stderr, "separable: %s\n", message.c_str());
      return 1;
    }
    const std::vector<float> separable_rgba = sss_bench::read_texture_rgba(output, scene.width, scene.height);
    glDeleteTextures(1, &output);
    separable.reset();
    const sss_bench::RgbImage filtered = sss_bench::RgbImage::from_rgba(separable_rgba.data(), scene.width, scene.height);
    // Pixels translucent in both renders (the pre-integrated head shades the same triangles).
    std::vector<uint8_t> mask(scene.mask.size());
    for (std::size_t i = 0; i < mask.size(); ++i) mask[i] = scene.mask[i] && pre.mask[i];
    const auto row = [&](const std::string& scene_name, const char* method, const sss_bench::RgbImage& image,
                         const std::vector<uint8_t>& selected) {
      errors.push_back({scene_name, method, sss_bench::compare_images(image, ref, selected.data()),
                        sss_bench::miss_share(image, ref, input, selected.data())});
    };
    row(name, "input (no scattering)", input, mask);
    row(name, "separable 17 taps, follow-surface", filtered, mask);
    row(name, "pre-integrated (LUTs)", preintegrated, mask);
    if (name.rfind("sphere", 0) == 0) {
      // The spheres again away from their silhouette (no background pixel within kInteriorBand):
      // there every method shares the error of the grazing surface, and the terminator, where
      // pre-integration acts, is what remains.
      const std::vector<uint8_t> inner = interior(mask, scene.width, scene.height);
      const std::string scene_name = name + " (interior)";
      row(scene_name, "input (no scattering)", input, inner);
      row(scene_name, "separable 17 taps, follow-surface", filtered, inner);
      row(scene_name, "pre-integrated (LUTs)", preintegrated, inner);
    }
    const std::string base = args.out + "/preintegrated-" + name + "-" + std::to_string(args.width) + "x" +
                             std::to_string(args.height);
    sss_bench::write_tonemapped_png(base + ".png", preintegrated);
    sss_bench::write_error_heatmap_png(base + "-error.png", preintegrated, ref, mask.data(), 0.1);
    sss_bench::destroy_scene(&gpu);
  }
  for (const auto& e : errors) {
    std::printf("  %-11s %-36s miss %.3f (worst channel %.3f)  rel RMSE %.4f  p99 %.4f  max %.4f  SSIM %.4f\n",
                e.scene.c_str(), e.method.c_str(), e.miss.pooled, e.miss.worst_channel(), e.metrics.relative_rmse,
                e.metrics.p99_abs, e.metrics.max_abs, e.metrics.ssim);
  }

  if (!args.doc.empty()) {
    std::ofstream md(args.doc);
    md << "# Pre-integrated skin shading: generation time and error\n\n"
       << "Written by `" << args.command_line << "` (tests/bench/preintegrated_bench.cpp); GL_RENDERER "
       << renderer << ", " << cores << " hardware threads; medians of " << args.repetitions << " runs.\n\n"
       << "## LUT generation\n\n| LUT | where | median ms |\n|---|---|---:|\n";
    char line[256];
    for (const auto& g : generation) {
      std::snprintf(line, sizeof line, "| %s | %s | %.2f |\n", g.lut.c_str(), g.where.c_str(), g.median_ms);
      md << line;
    }
    md << "\nThe GPU rows include compiling the generator shader (it is built for each generation and "
          "deleted after) and the driver's own work; a cached LUT costs nothing.\n\n"
       << "## Error against the exact 2D reference\n\nAt " << args.width << "x" << args.height
       << ", on the pixels that are skin in both renders; the reference is the exact surface convolution of the "
          "scene's Lambert irradiance (reference.hpp, CPU double). Pre-integrated shading replaces the Lambert "
          "terms (curvature from derivatives, per-channel normals between the normal map and its profile-blurred "
          "copy, a 9x9 box PCF on the key's shadow read through the shadow LUT); it never blurs the albedo or the normal map, which the reference "
          "does. *miss* is the share of the needed change (the input's distance from the reference) a method leaves "
          "undone, pooled over R, G and B (0 exact, 1 as wrong as no scattering, above 1 worse; tests/bench/metrics.hpp), "
          "with its worst channel.\n\n| scene | method | miss | worst channel | relative RMSE | p99 abs | max abs | SSIM |\n"
          "|---|---|---:|---:|---:|---:|---:|---:|\n";
    for (const auto& e : errors) {
      std::snprintf(line, sizeof line, "| %s | %s | %.3f | %.3f | %.4f | %.4f | %.4f | %.4f |\n", e.scene.c_str(),
                    e.method.c_str(), e.miss.pooled, e.miss.worst_channel(), e.metrics.relative_rmse, e.metrics.p99_abs,
                    e.metrics.max_abs, e.metrics.ssim);
      md << line;
    }
    // Where it wins and loses, from the rows above (relative RMSE).
    md << "\n### Where it wins and where it loses (relative RMSE, from the table)\n\n";
    for (std::size_t i = 0; i + 2 < errors.size(); i += 3) {
      const double in = errors[i].metrics.relative_rmse, sep = errors[i + 1].metrics.relative_rmse,
                   pre = errors[i + 2].metrics.relative_rmse;
      std::snprintf(line, sizeof line, "- %s: pre-integrated %.4f against %.4f for the separable filter and %.4f "
                    "unscattered: %s the filter, %s doing nothing.\n", errors[i].scene.c_str(), pre, sep, in,
                    verdict(pre, sep), verdict(pre, in));
      md << line;
    }
    md << "\nWhat decides it: pre-integration is exact only for a smooth sphere lit from one direction. The spheres "
          "(80, 20 and 10 mm, each framed alike) show it: over their interiors (no background within "
       << kInteriorBand << " pixels; at the silhouette every method shares the error of the grazing surface) it "
          "lands where the separable filter does, and both move away from the unscattered image as the sphere "
          "shrinks and the terminator's scattering widens, at no pass at all. It never scatters "
          "light across albedo detail, normal-map creases finer than the blurred map, or shadow edges sharper than "
          "the PCF penumbra it reinterprets; at the close-up those are what the reference blurs. Where skin is far "
          "(head-mid, head-far) the reference is nearly the unscattered image: the filter's kernel spans about a "
          "pixel, and the pre-integrated frame differs by its shading model (the wider PCF shadow and curvature from "
          "derivatives at silhouettes), not by missing scattering. Its win is cost: no pass at all (the LUT fetches "
          "are part of the lighting pass), which is why the demo switches to it automatically at a distance.\n";
    md << "\nPictures: `preintegrated-<scene>-<size>.png` (tone-mapped) and `-error.png` (|error| heat map, "
          "full scale 0.1) next to this file. The head scan: " << sss_bench::head_attribution() << "\n";
  }
  sss_headless_destroy(headless);
  return 0;
}
