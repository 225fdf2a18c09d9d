// sss_soak: many frames through one library instance the way a long-running host drives it, with
// the sizes, settings and contexts changing under it, watching memory and GL objects.
//
//   sss_soak [--backend osmesa|egl] [--frames N] [--max-size S] [--resize-every K]
//            [--recreate-every M] [--seed X] [--json FILE]
//
// Every frame: new random settings (scale, strength, falloff, taps, follow-surface), and an apply
// (in place, into a separate output, through the stencil, or in a sub-viewport, in turn). Every K
// frames: the host's textures are recreated at a random size up to S x S (RGBA16F or RGBA32F
// colour; DEPTH24_STENCIL8, DEPTH_COMPONENT32F or R32F depth) and the camera changes. Every M
// frames: sss_destroy, the GL context destroyed, a new one created, sss_create (as after a device
// loss). Every 50th frame is read back: pixels with finite input must come out finite.
//
// Measured: resident memory (VmRSS) at the end of every context's life, and the GL objects of
// each kind that exist in the context then (glIs* over names 1..4096) and after sss_destroy. Exit
// status 0 when every apply succeeded, every check passed, no context held more objects than the
// module can own (plus the host's three textures), sss_destroy left exactly what there was before
// sss_create, and resident memory grew by at most --rss-slack-kib (default 4096) over the second
// half of the contexts (Mesa and LLVM fill their caches over the first ones, then stop).
#include <GL/glcorearb.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "gl_objects.hpp"
#include "host_context.hpp"
#include "host_gl.hpp"
#include "sss/sss.h"
#include "sss_headless.h"

using namespace host_gl;

namespace {

struct Options {
  sss_headless_backend backend = SSS_HEADLESS_OSMESA;
  long frames = 10000;
  int max_size = 96;
  int resize_every = 5;
  int recreate_every = 500;
  unsigned seed = 20261121;
  long rss_slack_kib = 4096;
  std::string json;
};

long rss_kib() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmRSS:", 0) == 0) return std::strtol(line.c_str() + 6, nullptr, 10);
  }
  return -1;
}

bool parse(int argc, char** argv, Options* o) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](const char* name) -> const char* {
      if (a != name || i + 1 >= argc) return nullptr;
      return argv[++i];
    };
    const char* v = nullptr;
    if ((v = value("--backend"))) {
      if (sss_headless_backend_from_name(v, &o->backend) != 0) return false;
    } else if ((v = value("--frames"))) {
      o->frames = std::strtol(v, nullptr, 10);
    } else if ((v = value("--max-size"))) {
      o->max_size = std::max(1, std::atoi(v));
    } else if ((v = value("--resize-every"))) {
      o->resize_every = std::max(1, std::atoi(v));
    } else if ((v = value("--recreate-every"))) {
      o->recreate_every = std::max(1, std::atoi(v));
    } else if ((v = value("--seed"))) {
      o->seed = static_cast<unsigned>(std::strtoul(v, nullptr, 0));
    } else if ((v = value("--rss-slack-kib"))) {
      o->rss_slack_kib = std::strtol(v, nullptr, 10);
    } else if ((v = value("--json"))) {
      o->json = v;
    } else {
      return false;
    }
  }
  return o->frames > 0;
}

struct HostFrame {
  GLuint color = 0, depth = 0, output = 0;
  int width = 0, height = 0;
  bool stencil = false, linear = false, half = true;
  std::vector<float> input;
};

class Soak {
 public:
  explicit Soak(const Options& o) : o_(o), rng_(o.seed) {}

  int run() {
    if (!open_context()) return 2;
    const auto start = std::chrono::steady_clock::now();
    for (long frame = 0; frame < o_.frames; ++frame) {
      if (frame > 0 && frame % o_.recreate_every == 0) {
        end_context_life();
        if (!open_context()) return 2;
        resize();  // the host's textures went with the context
      } else if (frame % o_.resize_every == 0) {
        resize();
      }
      change_settings();
      apply(frame);
      if (frame == 0) rss_first_frame_ = rss_kib();
    }
    end_context_life();
    close_context();
    seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report();
  }

 private:
  bool open_context() {
    headless_ = sss_test::open_host_context(o_.backend, "sss_soak");
    if (headless_ == nullptr) return false;
    objects_without_module_ = objects();
    sss_create_desc cd = {};
    cd.struct_size = sizeof cd;
    cd.get_proc_address = sss_headless_get_proc_address;
    cd.get_proc_address_user = headless_;
    if (sss_create(&cd, &sss_) != SSS_OK) {
      std::fprintf(stderr, "sss_soak: sss_create: %s\n", sss_last_error(nullptr));
      return false;
    }
    ++contexts_;
    return true;
  }

  sss_test::GlObjectCounts objects() { return sss_test::count_gl_objects(sss_headless_get_proc_address, headless_); }

  // At the end of a context's life: the objects in it (the host's three textures and the
  // module's), which must stay within what the module can own at most, then sss_destroy and what
  // is left (must be what there was before sss_create), then the context goes.
  void end_context_life() {
    glFinish();
    const sss_test::GlObjectCounts live = objects();
    // textures, buffers, framebuffers, renderbuffers, vertex arrays, samplers, programs, shaders:
    // the host's 3 textures; the module's three pass targets (inputs, strength, intermediate; the
    // two term accumulators are for kernels of several terms only: the soak's eq. (1) never makes
    // them); the culling depth-stencil renderbuffer; 4 framebuffers made at create and 2 for the
    // pass targets; the masked path's (the default's choice on a software rasteriser) two tile-mark
    // textures, their 2 framebuffers and 2 programs; the vertex array; 3 samplers (colour, depth,
    // nearest for the integer targets, made at create); the copy program, up to 2 pass-input
    // variants (hardware or linear depth) and up to 36 blur variants (the horizontal pass x 3
    // follow-surface modes, the vertical one x 2 outside modes x 3 follow-surface modes, each for
    // the three preset tap counts and for any other count: 12 x 3 = 36); 2 shaders each, flagged
    // for deletion.
    const std::array<int, 8> most = {3 + 3 + 2, 0, 4 + 2 + 2, 1, 1, 3, 1 + 2 + 2 + 36, 2 * (1 + 2 + 2 + 36)};
    for (std::size_t k = 0; k < most.size(); ++k) {
      if (live.count[k] - objects_without_module_.count[k] > most[k]) {
        fail("GL objects at the end of context " + std::to_string(contexts_) + ": " + live.describe() +
             " (more than the module can own)");
        break;
      }
    }
    context_objects_.push_back(live);
    sss_destroy(sss_);
    sss_ = nullptr;
    release_frame();
    const sss_test::GlObjectCounts after = objects();
    if (after != objects_without_module_) {
      fail("after sss_destroy and the host's deletes: " + after.describe() +
           "; before sss_create: " + objects_without_module_.describe());
    }
    if (glGetError() != GL_NO_ERROR) fail("a GL error was left pending");
    close_context();
    rss_.push_back(rss_kib());
  }

  void close_context() {
    if (headless_ == nullptr) return;
    sss_headless_destroy(headless_);
    headless_ = nullptr;
  }

  void release_frame() {
    const GLuint names[3] = {frame_.color, frame_.depth, frame_.output};
    for (GLuint n : names) {
      if (n != 0) glDeleteTextures(1, &n);
    }
    frame_ = HostFrame{};
  }

  GLuint texture(GLenum internal_format, int w, int h, GLenum format, GLenum type, const void* data) {
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal_format), w, h, 0, format, type, data);
    glBindTexture(GL_TEXTURE_2D, 0);
    return t;
  }

  void resize() {
    release_frame();
    std::uniform_int_distribution<int> size(1, o_.max_size);
    HostFrame& f = frame_;
    f.width = size(rng_);
    f.height = size(rng_);
    const int kind = static_cast<int>(rng_() % 3);
    f.half = rng_() % 2 == 0;
    f.stencil = kind == 0;
    f.linear = kind == 2;
    const std::size_t n = static_cast<std::size_t>(f.width) * f.height;
    std::uniform_real_distribution<float> value(0.0f, 4.0f);
    f.input.resize(n * 4);
    std::vector<float> distance(n);
    std::vector<uint32_t> packed(n);
    const float fov_scale = 1.0f / std::tan(0.5f * (0.2f + 2.5f * static_cast<float>(rng_() % 100) / 100.0f));
    camera_ = {fov_scale, 0, 0, 0, 0, fov_scale, 0, 0, 0, 0, -1.002f, -1.0f, 0, 0, -0.02002f, 0};
    for (std::size_t i = 0; i < n; ++i) {
      for (int c = 0; c < 3; ++c) f.input[i * 4 + c] = value(rng_);
      f.input[i * 4 + 3] = (i % 7 == 0) ? 0.0f : 1.0f;
      distance[i] = 0.5f + 0.1f * static_cast<float>((i * 2654435761u) % 97) / 97.0f;
      const double z = -distance[i];
      const double window = 0.5 * ((camera_[10] * z + camera_[14]) / (camera_[11] * z)) + 0.5;
      packed[i] = (static_cast<uint32_t>(window * 16777215.0) << 8) | (i % 5 == 0 ? 0u : 1u);
    }
    const GLenum color_format = f.half ? GL_RGBA16F : GL_RGBA32F;
    f.color = texture(color_format, f.width, f.height, GL_RGBA, GL_FLOAT, f.input.data());
    if (f.stencil) {
      f.depth = texture(GL_DEPTH24_STENCIL8, f.width, f.height, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, packed.data());
    } else if (f.linear) {
      f.depth = texture(GL_R32F, f.width, f.height, GL_RED, GL_FLOAT, distance.data());
    } else {
      std::vector<float> window(n);
      for (std::size_t i = 0; i < n; ++i) window[i] = static_cast<float>((packed[i] >> 8) / 16777215.0);
      f.depth = texture(GL_DEPTH_COMPONENT32F, f.width, f.height, GL_DEPTH_COMPONENT, GL_FLOAT, window.data());
    }
    f.output = texture(color_format, f.width, f.height, GL_RGBA, GL_FLOAT, nullptr);
    if (sss_set_camera(sss_, camera_.data()) != SSS_OK) fail(std::string("sss_set_camera: ") + sss_last_error(sss_));
  }

  void change_settings() {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    sss_settings s;
    sss_default_settings(&s);
    s.world_units_per_mm = 0.0005f + 0.05f * unit(rng_);
    for (int c = 0; c < 3; ++c) {
      s.strength[c] = unit(rng_);
      s.falloff[c] = unit(rng_);
    }
    s.taps = 3 + 2 * static_cast<int>(rng_() % 32);
    s.flags = rng_() % 4 ? SSS_FOLLOW_SURFACE : 0u;
    if (sss_set_settings(sss_, &s) != SSS_OK) fail(std::string("sss_set_settings: ") + sss_last_error(sss_));
  }

  void apply(long frame) {
    HostFrame& f = frame_;
    sss_frame fr = {};
    fr.struct_size = sizeof fr;
    fr.color_texture = f.color;
    fr.depth_texture = f.depth;
    sss_stencil stencil = {f.depth, 1, 0xFF};
    const int mode = static_cast<int>(frame % 4);
    if (mode == 1) fr.output_texture = f.output;
    if (mode == 2 && f.stencil) fr.stencil = &stencil;
    if (mode == 3) {
      fr.viewport[0] = f.width / 4;
      fr.viewport[1] = f.height / 4;
      fr.viewport[2] = std::max(1, f.width / 2);
      fr.viewport[3] = std::max(1, f.height / 2);
    }
    const sss_result r = sss_apply_frame(sss_, &fr);
    ++applies_;
    if (r != SSS_OK) {
      fail("frame " + std::to_string(frame) + ": " + sss_last_error(sss_));
      return;
    }
    if (frame % 50 != 0) return;
    // Read back and check: finite input, finite output.
    std::vector<float> out(static_cast<std::size_t>(f.width) * f.height * 4);
    glBindTexture(GL_TEXTURE_2D, mode == 1 ? f.output : f.color);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, out.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    ++readbacks_;
    for (float v : out) {
      if (!std::isfinite(v)) {
        fail("frame " + std::to_string(frame) + ": a non-finite output from finite input");
        break;
      }
    }
  }

  void fail(const std::string& what) {
    if (++failures_ <= 10) std::fprintf(stderr, "sss_soak: %s\n", what.c_str());
  }

  int report() {
    // Mesa and LLVM grow their caches over the first contexts (shader variants, JIT code, malloc
    // arenas) and then stop: the growth is judged over the second half of the contexts.
    const long rss_first = rss_.empty() ? -1 : rss_.front();
    const long rss_second = rss_.size() >= 2 ? rss_[1] : rss_first;
    const long rss_middle = rss_.empty() ? -1 : rss_[(rss_.size() - 1) / 2];
    const long rss_end = rss_.empty() ? -1 : rss_.back();
    const long growth = rss_end - rss_middle;
#if defined(__SANITIZE_ADDRESS__)
    // AddressSanitizer keeps freed memory in its quarantine (up to 256 MiB): resident memory says
    // nothing about leaks there (LeakSanitizer checks them at exit instead).
    const bool judge_rss = false;
#else
    const bool judge_rss = true;
#endif
    if (judge_rss && growth > o_.rss_slack_kib) {
      fail("resident memory grew by " + std::to_string(growth) + " KiB over the second half of the contexts");
    }
    int fewest = 1 << 30, most = 0;
    for (const auto& c : context_objects_) {
      fewest = std::min(fewest, c.total());
      most = std::max(most, c.total());
    }
    std::printf(
        "sss_soak: %s, %ld frames (%ld applies, %ld read back), %d contexts, resize every %d, max %dx%d, %.1f s\n",
        sss_headless_backend_name(o_.backend), o_.frames, applies_, readbacks_, contexts_, o_.resize_every, o_.max_size,
        o_.max_size, seconds_);
    std::printf(
        "  resident memory (KiB): after frame 0 %ld; at the end of context 1 %ld, 2 %ld, %zu (middle) %ld, %zu (last) "
        "%ld; growth over the second half %ld%s\n",
        rss_first_frame_, rss_first, rss_second, (rss_.size() + 1) / 2, rss_middle, rss_.size(), rss_end, growth,
        judge_rss ? "" : " (not judged under ASan)");
    std::printf("  resident memory at the end of every context (KiB):");
    for (long r : rss_) std::printf(" %ld", r);
    std::printf("\n  GL objects at the end of each context: %d to %d in all (last: %s)\n", fewest, most,
                context_objects_.empty() ? "-" : context_objects_.back().describe().c_str());
    std::printf("  GL objects after sss_destroy: the host's alone (%s)\n", objects_without_module_.describe().c_str());
    std::printf("  failures: %ld\n", failures_);
    if (!o_.json.empty()) {
      std::FILE* j = std::fopen(o_.json.c_str(), "w");
      if (j != nullptr) {
        std::fprintf(j,
                     "{\"backend\": \"%s\", \"frames\": %ld, \"applies\": %ld, \"readbacks\": %ld, \"contexts\": %d, "
                     "\"resize_every\": %d, \"recreate_every\": %d, \"max_size\": %d, \"seconds\": %.2f, "
                     "\"rss_kib_after_frame_0\": %ld, \"rss_kib_first_context_end\": %ld, "
                     "\"rss_kib_second_context_end\": %ld, \"rss_kib_middle_context_end\": %ld, \"rss_kib_end\": %ld, "
                     "\"rss_growth_second_half_kib\": %ld, \"gl_objects_per_context_min\": %d, "
                     "\"gl_objects_per_context_max\": %d, \"gl_objects_after_destroy\": %d, \"failures\": %ld}\n",
                     sss_headless_backend_name(o_.backend), o_.frames, applies_, readbacks_, contexts_, o_.resize_every,
                     o_.recreate_every, o_.max_size, seconds_, rss_first_frame_, rss_first, rss_second, rss_middle,
                     rss_end, growth, fewest, most, objects_without_module_.total(), failures_);
        std::fclose(j);
      }
    }
    return failures_ == 0 ? 0 : 1;
  }

  Options o_;
  std::mt19937 rng_;
  sss_headless* headless_ = nullptr;
  sss_context* sss_ = nullptr;
  HostFrame frame_;
  std::array<float, 16> camera_{};
  sss_test::GlObjectCounts objects_without_module_;
  std::vector<sss_test::GlObjectCounts> context_objects_;
  std::vector<long> rss_;
  long rss_first_frame_ = -1, applies_ = 0, readbacks_ = 0, failures_ = 0;
  int contexts_ = 0;
  double seconds_ = 0.0;
};

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (!parse(argc, argv, &o)) {
    std::fprintf(stderr,
                 "usage: sss_soak [--backend osmesa|egl] [--frames N] [--max-size S] [--resize-every K]\n"
                 "                [--recreate-every M] [--seed X] [--rss-slack-kib K] [--json FILE]\n");
    return 2;
  }
  return Soak(o).run();
}
