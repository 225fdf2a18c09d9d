// Command line of sss_demo (getopt_long).
#pragma once

#include <string>

namespace demo {

struct Options {
  std::string backend = "egl";  // osmesa | egl | egl-device
  int width = 960;
  int height = 540;
  std::string out_dir = "demo-out";
  int samples = 0;              // SSS taps per pass; 0: the library's default
  bool use_stencil = true;
  float width_scale = 1.0f;     // multiplies the physical width
  float exposure = 1.0f;
};

enum class ParseResult { kRun, kHelp, kError };

ParseResult parse_options(int argc, char **argv, Options *options);
void print_usage(const char *program);

}  // namespace demo
