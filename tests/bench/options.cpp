#include "options.hpp"

#include <getopt.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace sss_bench {

namespace {

const char* const kUsage = R"(sss_bench: run time against error for the separable filter and its baselines.

  --quick               small images, few repetitions: the CI mode (default)
  --full                the full sweep: 1280x720 and 1920x1080, taps 5..65, more repetitions
  --size WxH[:a,b]      a resolution, optionally with its own scenes (repeatable; replaces the
                        mode's list)
  --scenes a,b,...      scenes (default: all canonical scenes)
  --taps n,n,...        separable tap counts (odd, 3..65)
  --gaussian-taps n,... taps per pass of the sum of Gaussians
  --cbf-taps n,...      taps per pass of the cross-bilateral mode (odd, 3..65; default 13)
  --family-taps n,...   taps per pass of each kernel family run by the library (sum of Gaussians,
                        SVD, pre-integrated, guided, artist, jittered eq. 1), at sizes up to 640x360;
                        empty ("") skips them (quick: 9; full: 9,17,33)
  --follow on|off|both  follow-surface settings to run (default both)
  --no-exact            do not time the exact 2D filter as a method (it stays the reference)
  --warmup N            untimed frames before timing (default: mode's)
  --reps N              timed frames; medians are reported (default: mode's)
  --cpu-reference-pixels N  images up to N pixels use the CPU exact reference, larger ones the GL
                        exact filter checked against the CPU at sample pixels
  --reference-stride S  the GL exact reference computes a 1-in-S² grid of receivers and errors are
                        measured there (default: height / 180, so about 180 rows of receivers)
  --backend NAME        osmesa, egl or egl-device (default egl)
  --out DIR             output folder (default bench-out)
  --doc FILE            also write the results document (Markdown) there
  --no-heat-maps        skip the error heat-map PNGs (and the MSAA edge pictures)
  --msaa WxH            size of the MSAA study (sphere and depth-step at 4 samples; the reference
                        is made at 2W x 2H); default: mode's
  --no-msaa             skip the MSAA study
  --footprints f,f,...  the footprint sweep's millimetres per pixel (default: 7 log-spaced values
                        from 0.05 to 2); "" skips the sweep
  --sweep-scenes a,b,.. the sweep's scenes (default: every plane-* scene)
  --sweep-taps n,n,...  eq. (1) tap counts on the sweep (quick: 5,9,17,33; full: --taps)
  --methods k,k,...     only these methods (their kinds: separable, separable-profiles, ...; a partial run for
                        a few rows: the footprint sweep is skipped when none of them runs on it)
  --sweep-reps N        timed frames of each sweep row (quick: 1; full: --reps)
  --sweep-interior N    pixels of the sweep frames' interior side, at least (default 64; and at
                        least 8 mm, so that the 6 mm disk is inside it)
  --gpu-preload-ms MS   on a GPU (timer queries), keep it busy this long before each timed frame so
                        the frame's commands are queued when it starts (gpu_busy.hpp; default 2,
                        0: time from an idle GPU, CPU issue gaps included)
  --help
)";

[[noreturn]] void usage_error(const std::string& message) {
  std::fprintf(stderr, "sss_bench: %s\n\n%s", message.c_str(), kUsage);
  std::exit(2);
}

std::vector<int> parse_ints(const std::string& text, const char* what) {
  std::vector<int> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    char* end = nullptr;
    const long v = std::strtol(item.c_str(), &end, 10);
    if (end == item.c_str() || *end != '\0' || v <= 0 || v > 1000000) usage_error(std::string("bad ") + what + ": " + item);
    values.push_back(static_cast<int>(v));
  }
  if (values.empty()) usage_error(std::string("empty ") + what);
  return values;
}

std::vector<std::string> split_names(const std::string& text) {
  std::vector<std::string> names;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    if (!item.empty()) names.push_back(item);
  }
  return names;
}

std::vector<double> parse_footprints(const std::string& text) {
  std::vector<double> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (end == item.c_str() || *end != '\0' || !(v >= 0.005 && v <= 50.0)) usage_error("bad footprint (mm per pixel, 0.005..50): " + item);
    values.push_back(v);
  }
  return values;
}

std::pair<int, int> parse_size(const std::string& text) {
  int w = 0, h = 0;
  char x = 0;
  std::stringstream stream(text.substr(0, text.find(':')));
  if (!(stream >> w >> x >> h) || (x != 'x' && x != 'X') || w <= 0 || h <= 0 || w > 8192 || h > 8192) {
    usage_error("bad size: " + text);
  }
  return {w, h};
}

void apply_mode_defaults(Options* o) {
  if (o->mode == "quick") {
    o->sizes = {{160, 90}};
    o->size_scenes = {{}};
    o->separable_taps = {5, 9, 17, 33, 65};
    o->gaussian_taps = {17};
    o->cbf_taps = {13};
    o->family_taps = {9};
    o->warmup = 1;
    o->repetitions = 3;
    // The sweep's many frames are there for their errors; in CI one timed frame each is enough, and
    // 65 taps on its largest frames (484x484) would cost more than the rest of the sweep.
    o->sweep_repetitions = 1;
    o->sweep_taps = {5, 9, 17, 33};
    // Odd sizes put the canonical scenes' straight edges inside pixels (even ones land them on
    // pixel borders, where every sample agrees); 130x98 for the reference stays on the CPU.
    o->msaa_size = {65, 49};
  } else {
    // Every scene at 640×360; at 1080p the head scenes the paper's comparisons need (and the empty
    // frame): the exact reference of a full-frame plane at 1080p takes too long on a CPU rasteriser.
    o->sizes = {{640, 360}, {1920, 1080}};
    o->size_scenes = {{}, {"head-close", "head-mid", "head-far", "empty"}};
    o->separable_taps = {5, 9, 11, 17, 25, 33, 65};
    o->gaussian_taps = {17, 65};  // 65: the accuracy ceiling of the tables (every pixel a tap further out)
    o->cbf_taps = {13, 25};
    o->family_taps = {9, 17, 33};
    o->warmup = 3;
    o->repetitions = 15;
    o->msaa_size = {163, 93};  // odd, and the depth step's edges fall inside pixels there
  }
}

}  // namespace

Options parse_options(int argc, char** argv) {
  Options o;
  o.footprints = default_sweep_footprints();
  for (int i = 0; i < argc; ++i) o.command_line += (i ? " " : "") + std::string(argv[i]);
  // The mode first, so explicit flags override its defaults wherever they stand.
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--full") o.mode = "full";
  }
  apply_mode_defaults(&o);
  bool sizes_given = false;
  static const option long_options[] = {
      {"quick", no_argument, nullptr, 'q'},       {"full", no_argument, nullptr, 'F'},
      {"size", required_argument, nullptr, 's'},  {"scenes", required_argument, nullptr, 'S'},
      {"taps", required_argument, nullptr, 't'},  {"gaussian-taps", required_argument, nullptr, 'g'},
      {"cbf-taps", required_argument, nullptr, 'C'}, {"family-taps", required_argument, nullptr, 'T'},
      {"follow", required_argument, nullptr, 'f'}, {"no-exact", no_argument, nullptr, 'E'},
      {"warmup", required_argument, nullptr, 'w'}, {"reps", required_argument, nullptr, 'r'},
      {"cpu-reference-pixels", required_argument, nullptr, 'c'},
      {"reference-stride", required_argument, nullptr, 'R'},
      {"backend", required_argument, nullptr, 'b'}, {"out", required_argument, nullptr, 'o'},
      {"doc", required_argument, nullptr, 'd'},   {"no-heat-maps", no_argument, nullptr, 'H'},
      {"msaa", required_argument, nullptr, 'M'},  {"no-msaa", no_argument, nullptr, 'N'},
      {"gpu-preload-ms", required_argument, nullptr, 'P'},
      {"footprints", required_argument, nullptr, 'p'},  {"sweep-scenes", required_argument, nullptr, 'W'},
      {"sweep-interior", required_argument, nullptr, 'I'},  {"sweep-reps", required_argument, nullptr, 'X'},
      {"sweep-taps", required_argument, nullptr, 'Y'},  {"methods", required_argument, nullptr, 'm'},
      {"help", no_argument, nullptr, 'h'},        {nullptr, 0, nullptr, 0}};
  int c = 0;
  while ((c = getopt_long(argc, argv, "", long_options, nullptr)) != -1) {
    const std::string arg = optarg != nullptr ? optarg : "";
    switch (c) {
      case 'q': case 'F': break;
      case 's':
        if (!sizes_given) o.sizes.clear(), o.size_scenes.clear();
        sizes_given = true;
        o.sizes.push_back(parse_size(arg));
        o.size_scenes.push_back(arg.find(':') == std::string::npos ? std::vector<std::string>{}
                                                                    : split_names(arg.substr(arg.find(':') + 1)));
        break;
      case 'S': o.scenes = split_names(arg); break;
      case 't':
        o.separable_taps = parse_ints(arg, "tap count");
        for (int t : o.separable_taps) {
          if (t < 3 || t > 65 || t % 2 == 0) usage_error("separable taps must be odd in [3, 65]: " + std::to_string(t));
        }
        break;
      case 'g': o.gaussian_taps = parse_ints(arg, "gaussian tap count"); break;
      case 'C':
        o.cbf_taps = parse_ints(arg, "cross-bilateral tap count");
        for (int t : o.cbf_taps) {
          if (t < 3 || t > 65 || t % 2 == 0) usage_error("cross-bilateral taps must be odd in [3, 65]: " + std::to_string(t));
        }
        break;
      case 'T':
        o.family_taps = arg.empty() ? std::vector<int>{} : parse_ints(arg, "family tap count");
        for (int t : o.family_taps) {
          if (t < 3 || t > 65 || t % 2 == 0) usage_error("family taps must be odd in [3, 65]: " + std::to_string(t));
        }
        break;
      case 'f':
        if (arg == "on") o.follow_surface = {true};
        else if (arg == "off") o.follow_surface = {false};
        else if (arg == "both") o.follow_surface = {true, false};
        else usage_error("--follow takes on, off or both");
        break;
      case 'E': o.exact_method = false; break;
      case 'w': {
        char* end = nullptr;
        const long v = std::strtol(arg.c_str(), &end, 10);
        if (end == arg.c_str() || *end != '\0' || v < 0 || v > 1000) usage_error("bad warm-up count: " + arg);
        o.warmup = static_cast<int>(v);
        break;
      }
      case 'r': o.repetitions = parse_ints(arg, "repetition count")[0]; break;
      case 'c': o.cpu_reference_max_pixels = parse_ints(arg, "pixel count")[0]; break;
      case 'R': o.reference_stride = parse_ints(arg, "reference stride")[0]; break;
      case 'b': o.backend = arg; break;
      case 'o': o.out = arg; break;
      case 'd': o.doc = arg; break;
      case 'H': o.heat_maps = false; break;
      case 'M': o.msaa = true, o.msaa_size = parse_size(arg); break;
      case 'N': o.msaa = false; break;
      case 'P': {
        char* end = nullptr;
        o.gpu_preload_ms = std::strtod(arg.c_str(), &end);
        if (end == arg.c_str() || *end != '\0' || !(o.gpu_preload_ms >= 0.0 && o.gpu_preload_ms <= 100.0)) {
          usage_error("bad --gpu-preload-ms: " + arg);
        }
        break;
      }
      case 'p': o.footprints = arg.empty() ? std::vector<double>{} : parse_footprints(arg); break;
      case 'W': o.sweep_scenes = split_names(arg); break;
      case 'I':
        o.sweep_interior_px = parse_ints(arg, "sweep interior")[0];
        if (o.sweep_interior_px < 8 || o.sweep_interior_px > 4096) usage_error("--sweep-interior must be in [8, 4096]");
        break;
      case 'Y': o.sweep_taps = parse_ints(arg, "sweep tap count"); break;
      case 'm': o.methods = split_names(arg); break;
      case 'X': o.sweep_repetitions = parse_ints(arg, "sweep repetition count")[0]; break;
      case 'h': std::fputs(kUsage, stdout); std::exit(0);
      default: usage_error("unknown option");
    }
  }
  if (optind < argc) usage_error(std::string("unexpected argument: ") + argv[optind]);
  return o;
}

}  // namespace sss_bench
