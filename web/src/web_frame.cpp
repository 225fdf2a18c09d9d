// sss_web_frame: the web demo's frame rendered natively, on OpenGL ES 3.0 (EGL surfaceless, Mesa
// llvmpipe), with the same code (web_app, web_scene) and the same settings as the page: the
// reference the browser test compares the page's pixels with, and the native time of the frame.
//
//   sss_web_frame [--size WxH] [--out image.ppm] [--off-out image.ppm] [--time N] [--split X]
//
// Prints one JSON object: the renderer, the sss_result of the frame, the median ms of N frames with
// and without the library.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "sss_headless.h"
#include "web_app.hpp"

namespace {

struct Options {
  int width = 640, height = 360, time_frames = 0;
  float split = 0.0f;
  std::string out, off_out;
};

bool parse(int argc, char** argv, Options* o) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--size" && has_value) {
      if (std::sscanf(argv[++i], "%dx%d", &o->width, &o->height) != 2) return false;
    } else if (a == "--out" && has_value) {
      o->out = argv[++i];
    } else if (a == "--off-out" && has_value) {
      o->off_out = argv[++i];
    } else if (a == "--time" && has_value) {
      o->time_frames = std::atoi(argv[++i]);
    } else if (a == "--split" && has_value) {
      o->split = static_cast<float>(std::atof(argv[++i]));
    } else {
      return false;
    }
  }
  return o->width > 0 && o->height > 0;
}

// Binary PPM (P6): the image's RGB (its alpha is always 1), top row first.
bool write_ppm(const std::string& path, const std::vector<uint8_t>& rgba, int width, int height) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) return false;
  std::fprintf(f, "P6\n%d %d\n255\n", width, height);
  std::vector<uint8_t> rgb(static_cast<size_t>(width) * height * 3);
  for (size_t i = 0; i < rgb.size() / 3; ++i) std::memcpy(&rgb[i * 3], &rgba[i * 4], 3);
  const bool ok = std::fwrite(rgb.data(), 1, rgb.size(), f) == rgb.size();
  return std::fclose(f) == 0 && ok;
}

std::string asset_path() {
  const char* env = std::getenv("SSS_ASSET_DIR");
  return std::string(env != nullptr && env[0] != '\0' ? env : SSS_ASSET_DIR) + "/lee-perry-smith-head/head.glb";
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (!parse(argc, argv, &o)) {
    std::fprintf(stderr, "usage: sss_web_frame [--size WxH] [--out image.ppm] [--off-out image.ppm] [--time N] [--split X]\n");
    return 2;
  }
  sss_headless_desc desc = {SSS_HEADLESS_EGL_GLES, 3, 0, 0, 0};
  sss_headless* headless = nullptr;
  char err[256] = {};
  if (sss_headless_create(&desc, &headless, err, sizeof err) != 0) {
    std::fprintf(stderr, "sss_web_frame: no OpenGL ES 3.0 context: %s\n", err);
    return 1;
  }
  int status = 0;
  {
    web::App app;
    if (!app.init(sss_headless_get_proc_address, headless, asset_path(), o.width, o.height)) {
      std::fprintf(stderr, "sss_web_frame: %s\n", app.message().c_str());
      status = 1;
    } else {
      web::Knobs off = app.default_knobs();
      off.enabled = false;
      app.set_knobs(off);
      app.render(o.split);
      const double off_ms = o.time_frames > 0 ? app.time_frames(o.time_frames, o.split) : 0.0;
      if (!o.off_out.empty() && !write_ppm(o.off_out, app.pixels_top_first(), o.width, o.height)) status = 1;
      app.set_knobs(app.default_knobs());
      const sss_result r = app.render(o.split);
      if (!o.out.empty() && !write_ppm(o.out, app.pixels_top_first(), o.width, o.height)) status = 1;
      const double ms = o.time_frames > 0 ? app.time_frames(o.time_frames, o.split) : 0.0;
      std::printf("{\"renderer\": \"%s\", \"result\": \"%s\", \"message\": \"%s\", \"frame_ms\": %.3f, "
                  "\"frame_ms_without_sss\": %.3f, \"frames\": %d}\n",
                  app.renderer().c_str(), sss_result_string(r), app.message().c_str(), ms, off_ms, o.time_frames);
      if (r != SSS_OK) status = 1;
    }
  }
  sss_headless_destroy(headless);
  return status;
}
