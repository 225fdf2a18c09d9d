#include "options.hpp"

#include <sss_headless.h>

#include <getopt.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace demo {

namespace {

bool parse_int(const char *text, int *out) {
  char *end = nullptr;
  errno = 0;
  const long value = std::strtol(text, &end, 10);
  if (errno != 0 || end == text || *end != '\0' || value < -1000000 || value > 1000000) return false;
  *out = static_cast<int>(value);
  return true;
}

bool parse_float(const char *text, float *out) {
  char *end = nullptr;
  errno = 0;
  const float value = std::strtof(text, &end);
  if (errno != 0 || end == text || *end != '\0' || !std::isfinite(value)) return false;
  *out = value;
  return true;
}

bool parse_size(const char *text, int *width, int *height) {
  int w = 0;
  int h = 0;
  char tail = '\0';
  if (std::sscanf(text, "%dx%d%c", &w, &h, &tail) != 2) return false;
  if (w < 16 || h < 16 || w > 8192 || h > 8192) return false;
  *width = w;
  *height = h;
  return true;
}

}  // namespace

void print_usage(const char *program) {
  std::printf(
      "Usage: %s [options]\n"
      "Renders a lit sphere with a hard shadow, applies screen-space separable subsurface scattering\n"
      "and writes before.png, after.png, split.png, split_zoom.png and README.txt.\n\n"
      "  --backend NAME     osmesa | egl | egl-device (default egl; falls back to osmesa if it fails)\n"
      "  --size WxH         image size (default 960x540)\n"
      "  --out DIR          output folder (default ./demo-out)\n"
      "  --samples N        SSS taps per pass, odd, 3..65 (default: the library's, 17)\n"
      "  --no-stencil       mask by the diffuse alpha alone instead of the stencil\n"
      "  --width-scale F    multiply the physical SSS width (default 1; try 4 to exaggerate)\n"
      "  --exposure F       linear exposure before tone mapping (default 1)\n"
      "  --help             this text\n",
      program);
}

ParseResult parse_options(int argc, char **argv, Options *options) {
  enum { kBackend = 1, kSize, kOut, kSamples, kNoStencil, kWidthScale, kExposure, kHelp };
  static const struct option long_options[] = {
      {"backend", required_argument, nullptr, kBackend},
      {"size", required_argument, nullptr, kSize},
      {"out", required_argument, nullptr, kOut},
      {"samples", required_argument, nullptr, kSamples},
      {"no-stencil", no_argument, nullptr, kNoStencil},
      {"width-scale", required_argument, nullptr, kWidthScale},
      {"exposure", required_argument, nullptr, kExposure},
      {"help", no_argument, nullptr, kHelp},
      {nullptr, 0, nullptr, 0}};

  opterr = 1;
  for (;;) {
    const int c = getopt_long(argc, argv, "", long_options, nullptr);
    if (c == -1) break;
    switch (c) {
      case kBackend: {
        sss_headless_backend backend = SSS_HEADLESS_OSMESA;
        if (sss_headless_backend_from_name(optarg, &backend) != 0) {
          std::fprintf(stderr, "sss_demo: --backend wants osmesa, egl or egl-device, got '%s'\n", optarg);
          return ParseResult::kError;
        }
        options->backend = optarg;
        break;
      }
      case kSize:
        if (!parse_size(optarg, &options->width, &options->height)) {
          std::fprintf(stderr, "sss_demo: --size wants WxH with sides in [16, 8192], got '%s'\n", optarg);
          return ParseResult::kError;
        }
        break;
      case kOut:
        options->out_dir = optarg;
        break;
      case kSamples:
        if (!parse_int(optarg, &options->samples) || options->samples < 3 || options->samples > 65 ||
            options->samples % 2 == 0) {
          std::fprintf(stderr, "sss_demo: --samples wants an odd number in [3, 65], got '%s'\n", optarg);
          return ParseResult::kError;
        }
        break;
      case kNoStencil:
        options->use_stencil = false;
        break;
      case kWidthScale:
        if (!parse_float(optarg, &options->width_scale) || options->width_scale < 0.0f ||
            options->width_scale > 1000.0f) {
          std::fprintf(stderr, "sss_demo: --width-scale wants a number in [0, 1000], got '%s'\n", optarg);
          return ParseResult::kError;
        }
        break;
      case kExposure:
        if (!parse_float(optarg, &options->exposure) || options->exposure <= 0.0f || options->exposure > 1000.0f) {
          std::fprintf(stderr, "sss_demo: --exposure wants a number in (0, 1000], got '%s'\n", optarg);
          return ParseResult::kError;
        }
        break;
      case kHelp:
        return ParseResult::kHelp;
      default:  // getopt_long already printed what was wrong
        return ParseResult::kError;
    }
  }
  if (optind < argc) {
    std::fprintf(stderr, "sss_demo: unexpected argument '%s'\n", argv[optind]);
    return ParseResult::kError;
  }
  return ParseResult::kRun;
}

}  // namespace demo
