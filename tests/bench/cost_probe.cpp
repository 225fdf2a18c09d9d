// sss_cost_probe: the work of one in-place frame of the library on a benchmark scene, for counting
// under callgrind. On Mesa's llvmpipe a frame's wall-clock time moves by tens of per cent from run
// to run on a shared machine, while the instructions it executes (the JIT-compiled shaders
// included) are the same each time: scripts/cost-probe.sh runs this under
// `valgrind --tool=callgrind --instr-atstart=no` with the rasteriser in the calling thread
// (LP_NUM_THREADS=0), and only the timed frame is counted (CALLGRIND_START/STOP_INSTRUMENTATION
// around it). Builds against any release of the library with the same bench scenes, so two
// builds compare on the same frame. With --frames N it also times N more frames (wall clock around
// sss_apply_frame + glFinish, the refill before each outside it) and prints their median and
// fastest: two builds' probes run in turn on one machine give the two times of "the same run".
//
//   sss_cost_probe [--backend osmesa|egl] [--scene NAME] [--size WxH] [--taps N]
//                  [--path default|fragment|masked|auto|compute|half|copy] [--frames N] [--profiles N] [--msaa 0|4]
//                  [--texturing pre|post|pre-and-post]
//
// --path copy: not the library but the benchmark's yardstick, its two-pass full-screen copy
// (copy_method.cpp) of the scene into the frame's colour: the `× copy` of the benchmark's times in
// instructions, which repeat where the copy's wall time moves by a fifth from run to run.
//
// --msaa 4: the MSAA path written back in place, as the MSAA study's write-back row: the scene made
// at twice the size, 4 samples per pixel (RGBA16F colour, DEPTH_COMPONENT32F depth, see
// tests/support/multisample_textures.hpp), filtered at the given size; the same frame with --msaa 0
// (the default) is the single-sample path on the scene made at that size.
//
// --profiles N (0.4 on): N per-pixel profiles (sss_set_profiles; the others are eq. (1) looks of
// other strength, falloff and scale) and an R8UI profile texture of index 0 everywhere: the cost of
// the per-pixel selection on the same frame (the scene is one material).
//
// --path default (also without --path) keeps sss_default_settings' path: the frame a host gets;
// half (0.5 on) is SSS_PATH_HALF_RESOLUTION.
// Prints the path that ran and "frame done" (the counts come from callgrind).
#include <valgrind/callgrind.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "gpu_scene.hpp"
#include "method.hpp"
#include "host_gl.hpp"
#include "multisample_textures.hpp"
#include "scenes/scenes.hpp"
#include "sss/sss.h"
#include "sss_headless.h"

using namespace host_gl;

namespace {

struct Options {
  sss_headless_backend backend = SSS_HEADLESS_EGL_SURFACELESS;
  std::string scene = "head-close";
  int width = 1920, height = 1080;
  int taps = 17;
  bool default_path = true;  // sss_default_settings' path; else `path`
  unsigned path = SSS_PATH_FRAGMENT;
  int frames = 0;  // timed frames after the counted one
  int profiles = 0;  // 0: sss_set_settings and no profile texture; else sss_set_profiles with this many
  int msaa = 0;      // 4: the MSAA path (multisampled colour and depth, written back)
  bool copy = false;  // the benchmark's two-pass copy instead of the library
  unsigned texturing = 0;  // 0.6 on: sss_settings.texturing, with an RGBA8 albedo of 2-pixel cells
};

// --path copy: the benchmark's copy, once to build and allocate, then once counted.
int count_copy(const sss_bench::GpuScene& scene, GLuint color) {
  const std::unique_ptr<sss_bench::Method> copy = sss_bench::make_copy_method();
  std::string error;
  for (int frame_index = 0; frame_index < 2; ++frame_index) {
    if (frame_index == 1) CALLGRIND_START_INSTRUMENTATION;
    const bool ok = copy->run(scene, color, &error);
    glFinish();
    if (frame_index == 1) CALLGRIND_STOP_INSTRUMENTATION;
    if (!ok) {
      std::fprintf(stderr, "sss_cost_probe: the copy: %s\n", error.c_str());
      return 1;
    }
  }
  std::printf("%dx%d two-pass copy: frame done\n", scene.width, scene.height);
  return 0;
}

bool parse(int argc, char** argv, Options* o) {
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--backend") {
      o->backend = value == "osmesa" ? SSS_HEADLESS_OSMESA : SSS_HEADLESS_EGL_SURFACELESS;
    } else if (key == "--scene") {
      o->scene = value;
    } else if (key == "--size") {
      if (std::sscanf(value.c_str(), "%dx%d", &o->width, &o->height) != 2) return false;
    } else if (key == "--taps") {
      o->taps = std::atoi(value.c_str());
    } else if (key == "--path") {
      o->default_path = value == "default";
      if (value == "masked") {
        o->path = SSS_PATH_FRAGMENT_MASKED;
      } else if (value == "auto") {
        o->path = SSS_PATH_AUTO;
      } else if (value == "compute") {
        o->path = SSS_PATH_COMPUTE;
      } else if (value == "half") {
        o->path = SSS_PATH_HALF_RESOLUTION;
      } else if (value == "fragment" || value == "default") {
        o->path = SSS_PATH_FRAGMENT;
      } else if (value == "copy") {
        o->copy = true;
      } else {
        return false;
      }
    } else if (key == "--frames") {
      o->frames = std::atoi(value.c_str());
    } else if (key == "--profiles") {
      o->profiles = std::atoi(value.c_str());
    } else if (key == "--texturing") {
      if (value == "pre") {
        o->texturing = 0;
      } else if (value == "post") {
        o->texturing = 1;
      } else if (value == "pre-and-post") {
        o->texturing = 2;
      } else {
        return false;
      }
    } else if (key == "--msaa") {
      o->msaa = std::atoi(value.c_str());
      if (o->msaa != 0 && o->msaa != 4) return false;
    } else {
      return false;
    }
  }
  return (argc % 2) == 1;
}

// The scene's irradiance into the frame's colour texture, texel for texel (sample for sample:
// `target` GL_TEXTURE_2D_MULTISAMPLE).
void refill(GLuint from, GLuint to, int width, int height, GLenum target = GL_TEXTURE_2D) {
  GLuint framebuffers[2] = {0, 0};
  glGenFramebuffers(2, framebuffers);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffers[0]);
  glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, target, from, 0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffers[1]);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, target, to, 0);
  glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(2, framebuffers);
  glFinish();
}

// The library's defaults at the scene's physical scale: releases before 0.2 took the paper's
// `width` (one profile millimetre spans (2/3)·width world units), later ones world units per mm.
void physical_settings(const sss_bench::GpuScene& scene, const Options& o, sss_settings* s) {
  sss_default_settings(s);
#if SSS_VERSION_MAJOR == 0 && SSS_VERSION_MINOR < 2
  s->width = sss_width_for_world_units_per_mm(scene.world_units_per_mm);
#else
  s->world_units_per_mm = scene.world_units_per_mm;
#endif
#if SSS_VERSION_MAJOR == 0 && SSS_VERSION_MINOR < 3
  s->samples = o.taps;  // renamed `taps` in 0.3
#else
  s->taps = o.taps;
#endif
  if (!o.default_path) s->path = o.path;
#if SSS_VERSION_MAJOR > 0 || SSS_VERSION_MINOR >= 6
  s->texturing = o.texturing;
#endif
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (!parse(argc, argv, &o)) {
    std::fprintf(stderr, "usage: sss_cost_probe [--backend osmesa|egl] [--scene NAME] [--size WxH] [--taps N] "
                         "[--path default|fragment|masked|auto|compute|half] [--frames N] [--profiles N] [--msaa 0|4] [--texturing pre|post|pre-and-post]\n");
    return 2;
  }
  sss_headless_desc hd = {};
  hd.backend = o.backend;
  hd.major = 3;
  hd.minor = 3;
  hd.core_profile = 1;
  sss_headless* headless = nullptr;
  char error[512] = "";
  std::string missing;
  if (sss_headless_create(&hd, &headless, error, sizeof error) != 0 ||
      !host_gl::load(sss_headless_get_proc_address, headless, &missing)) {
    std::fprintf(stderr, "sss_cost_probe: no GL context: %s%s\n", error, missing.c_str());
    return 1;
  }
  sss_bench::GpuScene scene = sss_bench::upload_scene(sss_bench::make_scene(o.scene, o.width, o.height));
  GLuint color = 0;
  glGenTextures(1, &color);
  glBindTexture(GL_TEXTURE_2D, color);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, o.width, o.height, 0, GL_RGBA, GL_FLOAT, nullptr);
  glBindTexture(GL_TEXTURE_2D, 0);
  // --msaa: the scene's samples (kept, refilled from) and the frame's multisampled colour and depth.
  GLuint samples = 0, depth = scene.depth;
  GLenum color_target = GL_TEXTURE_2D;
  if (o.msaa != 0) {
    const sss_bench::Scene fine = sss_bench::make_scene(o.scene, 2 * o.width, 2 * o.height);
    samples = sss_test::make_multisample_texture(GL_RGBA16F, o.width, o.height, o.msaa, fine.irradiance);
    glDeleteTextures(1, &color);
    color = sss_test::make_multisample_texture(GL_RGBA16F, o.width, o.height, o.msaa, fine.irradiance);
    depth = sss_test::make_multisample_texture(GL_DEPTH_COMPONENT32F, o.width, o.height, o.msaa, fine.window_depth);
    glDeleteTextures(1, &scene.irradiance);
    scene.irradiance = samples;
    color_target = GL_TEXTURE_2D_MULTISAMPLE;
    if (samples == 0 || color == 0 || depth == 0) {
      std::fprintf(stderr, "sss_cost_probe: the context has no %d-sample textures\n", o.msaa);
      return 1;
    }
  }

  if (o.copy) {
    const int r = count_copy(scene, color);
    glDeleteTextures(1, &color);
    sss_bench::destroy_scene(&scene);
    sss_headless_destroy(headless);
    return r;
  }

  sss_create_desc desc = {};
  desc.struct_size = sizeof desc;
  desc.get_proc_address = sss_headless_get_proc_address;
  desc.get_proc_address_user = headless;
  sss_context* ctx = nullptr;
  sss_settings s;
  physical_settings(scene, o, &s);
  sss_frame frame = {};
  frame.struct_size = sizeof frame;
  frame.color_texture = color;
  frame.depth_texture = depth;
  if (sss_create(&desc, &ctx) != SSS_OK || sss_set_settings(ctx, &s) != SSS_OK ||
      sss_set_camera(ctx, scene.projection.data()) != SSS_OK) {
    std::fprintf(stderr, "sss_cost_probe: %s\n", sss_last_error(ctx));
    return 1;
  }
#if SSS_VERSION_MAJOR > 0 || SSS_VERSION_MINOR >= 4
  std::vector<uint8_t> zeros;
  GLuint ids = 0;
  if (o.profiles > 0) {
    std::vector<sss_settings> looks(static_cast<std::size_t>(o.profiles), s);
    for (std::size_t i = 1; i < looks.size(); ++i) {
      looks[i].scale = 1.0f + 0.5f * static_cast<float>(i);
      for (int c = 0; c < 3; ++c) {
        looks[i].strength[c] = 0.4f + 0.1f * static_cast<float>((static_cast<int>(i) + c) % 5);
        looks[i].falloff[c] = 0.3f + 0.1f * static_cast<float>((static_cast<int>(i) * 2 + c) % 7);
      }
    }
    zeros.assign(static_cast<std::size_t>(o.width) * static_cast<std::size_t>(o.height), 0);
    glGenTextures(1, &ids);
    glBindTexture(GL_TEXTURE_2D, ids);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8UI, o.width, o.height, 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, zeros.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glBindTexture(GL_TEXTURE_2D, 0);
    frame.profile_texture = ids;
    if (sss_set_profiles(ctx, looks.data(), static_cast<uint32_t>(looks.size())) != SSS_OK) {
      std::fprintf(stderr, "sss_cost_probe: %s\n", sss_last_error(ctx));
      return 1;
    }
  }
#else
  if (o.profiles > 0) {
    std::fprintf(stderr, "sss_cost_probe: --profiles needs 0.4 or later\n");
    return 2;
  }
#endif
  GLuint albedo = 0;
  if (o.texturing != 0) {
#if SSS_VERSION_MAJOR > 0 || SSS_VERSION_MINOR >= 6
    // A checker of 2-pixel cells (the cost does not depend on the values; a pore-scale albedo).
    std::vector<uint8_t> cells(static_cast<std::size_t>(o.width) * static_cast<std::size_t>(o.height) * 4);
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const std::size_t pixel = i / 4;
      const bool dark = ((pixel % static_cast<std::size_t>(o.width)) / 2 + (pixel / static_cast<std::size_t>(o.width)) / 2) % 2 == 0;
      cells[i] = static_cast<uint8_t>(dark ? 90 : 200);
    }
    glGenTextures(1, &albedo);
    glBindTexture(GL_TEXTURE_2D, albedo);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, o.width, o.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, cells.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    frame.albedo_texture = albedo;
#else
    std::fprintf(stderr, "sss_cost_probe: --texturing needs 0.6 or later\n");
    return 2;
#endif
  }
  // One frame first: programs built, targets allocated, as in a steady frame.
  for (int frame_index = 0; frame_index < 2; ++frame_index) {
    refill(scene.irradiance, color, o.width, o.height, color_target);
    if (frame_index == 1) CALLGRIND_START_INSTRUMENTATION;
    const sss_result r = sss_apply_frame(ctx, &frame);
    glFinish();
    if (frame_index == 1) CALLGRIND_STOP_INSTRUMENTATION;
    if (r != SSS_OK) {
      std::fprintf(stderr, "sss_cost_probe: %s\n", sss_last_error(ctx));
      return 1;
    }
  }
  std::vector<double> ms;
  for (int i = 0; i < o.frames; ++i) {
    refill(scene.irradiance, color, o.width, o.height, color_target);
    const auto start = std::chrono::steady_clock::now();
    const sss_result r = sss_apply_frame(ctx, &frame);
    glFinish();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    if (r != SSS_OK) return 1;
  }
  sss_stats stats = {};
  stats.struct_size = sizeof stats;
  const unsigned ran = sss_get_stats(ctx, &stats) == SSS_OK ? stats.last_frame_path : 99u;
  std::printf("%s %dx%d, %d taps, path %u asked (%s), %u ran, %d per-pixel profiles, %d samples, texturing %u: "
              "frame done\n",
              o.scene.c_str(), o.width, o.height, o.taps, s.path, o.default_path ? "the default" : "named", ran,
              o.profiles, o.msaa, o.texturing);
  if (!ms.empty()) {
    std::sort(ms.begin(), ms.end());
    std::printf("time of %d frames: median %.2f ms, fastest %.2f ms\n", o.frames, ms[ms.size() / 2], ms.front());
  }
  sss_destroy(ctx);
  glDeleteTextures(1, &color);
  if (albedo != 0) glDeleteTextures(1, &albedo);
  if (depth != scene.depth) glDeleteTextures(1, &depth);
  sss_bench::destroy_scene(&scene);
  sss_headless_destroy(headless);
  return 0;
}
