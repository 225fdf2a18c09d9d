#include "options.hpp"

#include "kernel_family.hpp"

#include <sss/sss_tools.h>
#include <sss_headless.h>

#include <getopt.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <algorithm>
#include <string>

namespace demo {

namespace {

// "svd:3" -> SSS_KERNEL_SVD, rank 3.
bool parse_kernel(const char *text, Options *o) {
  const std::string arg = text;
  const std::size_t colon = arg.find(':');
  const std::string name = arg.substr(0, colon);
  int rank = 1;
  if (colon != std::string::npos) {
    char *end = nullptr;
    const long v = std::strtol(arg.c_str() + colon + 1, &end, 10);
    if (end == arg.c_str() + colon + 1 || *end != '\0' || v < 1 || v > SSS_KERNEL_MAX_TERMS) return false;
    rank = static_cast<int>(v);
  }
  for (int f = 0; f < SSS_KERNEL_FAMILY_COUNT; ++f) {
    if (name == kernel_family_info(f)->option) {
      o->kernel_family = f;
      o->kernel_rank = rank;
      return true;
    }
  }
  return false;
}

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
  if (w < 64 || h < 64 || w > 8192 || h > 8192) return false;
  *width = w;
  *height = h;
  return true;
}

// "all", or debug view names separated by commas (debug_view_name).
bool parse_debug_views(const char *text, std::vector<int> *out) {
  out->clear();
  const std::string list = text;
  if (list == "all") {
    for (int v = 1; v <= static_cast<int>(SSS_DEBUG_VIEW_LAST); ++v) out->push_back(v);
    return true;
  }
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t end = std::min(list.find(',', start), list.size());
    const std::string name = list.substr(start, end - start);
    int found = 0;
    for (int v = 1; v <= static_cast<int>(SSS_DEBUG_VIEW_LAST); ++v) {
      if (name == debug_view_name(v)) found = v;
    }
    if (found == 0) return false;
    out->push_back(found);
    start = end + 1;
  }
  return !out->empty();
}

bool parse_view(const char *text, ViewMode *out) {
  for (ViewMode m : {ViewMode::kFinal, ViewMode::kSplit, ViewMode::kHeatMap, ViewMode::kTouched, ViewMode::kProfiles}) {
    if (std::strcmp(text, view_mode_name(m)) == 0) {
      *out = m;
      return true;
    }
  }
  return false;
}

bool fail(const char *what, const char *got) {
  std::fprintf(stderr, "sss_demo: %s, got '%s'\n", what, got);
  return false;
}

}  // namespace

void print_usage(const char *program) {
  std::printf(
      "Usage: %s [options] [MODEL.gltf|MODEL.glb]\n"
      "Screen-space separable subsurface scattering (Jimenez et al. 2012) on the Lee Perry-Smith head\n"
      "scan (or MODEL): a window with a control panel, or --headless PNGs for each camera preset.\n\n"
      "  --headless          no window: render through EGL/OSMesa and write, for each preset,\n"
      "                      PRESET-{before,after,split,heatmap,touched,zoom}.png and README.txt into --out\n"
      "                      (and close-zoom-texturing.png: the close-up's zoom in each texturing mode)\n"
      "  --backend NAME      headless context: osmesa | egl | egl-device (default egl; falls back to osmesa)\n"
      "  --scene NAME        head (default) | sphere (a lit sphere and a box's hard shadow) | mixed (the head,\n"
      "                      a marble bust and a wax candle: three profiles in one pass pair) | hand (a hand\n"
      "                      in front of the cheek: the bleeding test scene)\n"
      "  --no-object-ids     the profile byte without object IDs (light crosses between objects of one profile)\n"
      "  --hand-colour R,G,B the hand's linear base colour, each in [0, 1] (--scene hand)\n"
      "  --dump              headless: also PRESET-{before,after}.pfm (linear diffuse, float) and PRESET-ids.pgm\n"
      "                      (the profile/object byte) for the tests\n"
      "  --size WxH          window / image size (default 1280x720)\n"
      "  --out DIR           folder for PNGs and screenshots (default ./demo-out)\n"
      "  --preset NAME       close | mid | far | all (headless default: all; window: the first view)\n"
      "  --no-sss            start with the library off (S toggles it in the window)\n"
      "  --taps N            the most SSS taps per pass, odd, 3..65 (default: the library's, 17); each pixel\n"
      "                      reads as many as its footprint needs\n"
      "  --scale F           multiply every scattering distance, [0, 1000] (default 1: the physical size; the\n"
      "                      scenes are in metres); --width-scale F, the old name, is still accepted\n"
      "  --no-follow-surface turn the follow-surface depth test off\n"
      "  --no-stencil        mask by the diffuse alpha alone instead of the stencil\n"
      "  --shading NAME      screen (the library's filter, default) | preintegrated (LUTs in the lighting\n"
      "                      pass, no SSS pass) | auto (pre-integrated when a mm of skin is < 0.5 pixel)\n"
      "  --cross-bilateral   Mikkelsen's cross-bilateral mode instead of the separable kernel\n"
      "  --kernel NAME[:N]   the separable mode's kernel family: separable (eq. 1, default), sum-of-gaussians:N,\n"
      "                      svd:N (N terms, 1..6, two passes each), preintegrated[:N] (N - 1 terms of the\n"
      "                      residual's SVD beside the marginal), guided, artist\n"
      "  --material NAME     the profile of those families: skin (default), apple, chicken1, chicken2, cream,\n"
      "                      ketchup, marble, potato, skimmilk, skin1, skin2, wholemilk\n"
      "  --jitter F          share of the taps jittered per pixel, [0, 1] (the supplementary uses 0.33)\n"
      "  --moving-noise      give each frame its number as sss_frame.noise_index: the jitter's pattern moves\n"
      "                      every frame, as a host with TAA would have it (without: one pattern)\n"
      "  --region            tell the library the head's projected bounds (work only there)\n"
      "  --path NAME         how the separable passes run: auto (whichever is fastest here; the library's\n"
      "                      default) | fragment (culled to translucent pixels) | masked (since 0.4 the\n"
      "                      same draws as fragment) | compute (OpenGL 4.3+ dispatches, shared-memory tiles)\n"
      "                      | half (half size where the kernel spans 8+ pixels, full size elsewhere: faster\n"
      "                      close-ups, a different image within the benchmark's margin)\n"
      "  --translucency[=F]  light through thin parts (ears, nostrils), translucency F in [0, 1] (default 0.95)\n"
      "  --back-light        put the second light behind the head (for the translucency)\n"
      "  --thickness NAME    where the translucency's thickness comes from: shadow (the light's shadow map,\n"
      "                      default) | baked (each translucent material's baked thickness) | both (the larger)\n"
      "  --baked-thickness MM  the baked thickness of translucent materials, (0, 100] mm (default 2)\n"
      "  --msaa N            0 (default) or 4: light into 4x multisampled targets, hand them to the library\n"
      "  --texturing MODE    where the albedo goes (sss_settings.texturing): pre (blurred with the light),\n"
      "                      post (the light alone blurred, the albedo's detail kept sharp; the default: the\n"
      "                      head scan's albedo already holds the scattering) or pre-and-post (sqrt(albedo)\n"
      "                      each side); the lighting pass's albedo target goes with the frame (with --msaa\n"
      "                      its multisampled one: each sample divided by its own albedo)\n"
      "  --exposure F        linear exposure before tone mapping (default 1)\n"
      "  --heat-scale F      linear error at the top of the heat map's colour ramp (default 0.05)\n"
      "  --heat-factor N     the heat map's exact reference runs at 1/N of each side (default 4)\n"
      "  --repeat N          headless: timed frames per preset, median reported (default 5)\n"
      "  --view NAME         window: final | split | heatmap | touched | profiles (default final)\n"
      "  --debug-view LIST   the library's debug views (sss_frame.debug_view), comma-separated or all: mask,\n"
      "                      depth, footprint, taps, profile, tiles; headless: PRESET-view-NAME.png each;\n"
      "                      window: the first is shown (the panel switches them). Single-sample, separable\n"
      "                      mode only; the tiles view drops the stencil (the masked path culls by alpha)\n"
      "  --frames N          window: close after N frames (for tests)\n"
      "  --screenshot-frame K  window: save a screenshot at frame K, as F12 does (for tests)\n"
      "  --help              this text\n\n"
      "Window keys: S toggles SSS, F12 saves a screenshot into --out, 1/2/3 the presets, V the next view,\n"
      "Esc quits; left drag orbits, right drag pans, the wheel zooms.\n",
      program);
}

ParseResult parse_options(int argc, char **argv, Options *o) {
  enum {
    kHeadless = 1, kBackend, kScene, kSize, kOut, kPreset, kNoSss, kTaps, kScale, kWidthScale, kNoFollow, kNoStencil, kAdaptive, kRegion, kPath,
    kThickness, kBakedThickness,
    kExposure, kHeatScale, kHeatFactor, kRepeat, kView, kFrames, kScreenshotFrame, kMsaa, kHelp, kCrossBilateral,
    kTranslucency, kBackLight, kShading, kKernel, kMaterial, kJitter, kMovingNoise, kNoObjectIds, kDump, kHandColourOption,
    kDebugViewOption, kTexturing
  };
  static const struct option long_options[] = {
      {"headless", no_argument, nullptr, kHeadless},
      {"backend", required_argument, nullptr, kBackend},
      {"scene", required_argument, nullptr, kScene},
      {"size", required_argument, nullptr, kSize},
      {"out", required_argument, nullptr, kOut},
      {"preset", required_argument, nullptr, kPreset},
      {"no-sss", no_argument, nullptr, kNoSss},
      {"taps", required_argument, nullptr, kTaps},
      {"scale", required_argument, nullptr, kScale},
      {"width-scale", required_argument, nullptr, kWidthScale},  // the old name of --scale
      {"no-follow-surface", no_argument, nullptr, kNoFollow},
      {"adaptive-taps", no_argument, nullptr, kAdaptive},
      {"region", no_argument, nullptr, kRegion},
      {"path", required_argument, nullptr, kPath},
      {"no-stencil", no_argument, nullptr, kNoStencil},
      {"msaa", required_argument, nullptr, kMsaa},
      {"exposure", required_argument, nullptr, kExposure},
      {"heat-scale", required_argument, nullptr, kHeatScale},
      {"heat-factor", required_argument, nullptr, kHeatFactor},
      {"repeat", required_argument, nullptr, kRepeat},
      {"view", required_argument, nullptr, kView},
      {"debug-view", required_argument, nullptr, kDebugViewOption},
      {"frames", required_argument, nullptr, kFrames},
      {"screenshot-frame", required_argument, nullptr, kScreenshotFrame},
      {"shading", required_argument, nullptr, kShading},
      {"kernel", required_argument, nullptr, kKernel},
      {"material", required_argument, nullptr, kMaterial},
      {"jitter", required_argument, nullptr, kJitter},
      {"help", no_argument, nullptr, kHelp},
      {"cross-bilateral", no_argument, nullptr, kCrossBilateral},
      {"translucency", optional_argument, nullptr, kTranslucency},
      {"thickness", required_argument, nullptr, kThickness},
      {"baked-thickness", required_argument, nullptr, kBakedThickness},
      {"back-light", no_argument, nullptr, kBackLight},
      {"no-object-ids", no_argument, nullptr, kNoObjectIds},
      {"moving-noise", no_argument, nullptr, kMovingNoise},
      {"dump", no_argument, nullptr, kDump},
      {"hand-colour", required_argument, nullptr, kHandColourOption},
      {"texturing", required_argument, nullptr, kTexturing},
      {nullptr, 0, nullptr, 0}};

  opterr = 1;
  for (;;) {
    const int c = getopt_long(argc, argv, "", long_options, nullptr);
    if (c == -1) break;
    bool ok = true;
    switch (c) {
      case kHeadless: o->headless = true; break;
      case kBackend: {
        sss_headless_backend backend = SSS_HEADLESS_OSMESA;
        ok = sss_headless_backend_from_name(optarg, &backend) == 0 ||
             fail("--backend wants osmesa, egl or egl-device", optarg);
        o->backend = optarg;
        break;
      }
      case kScene:
        o->scene = optarg;
        ok = o->scene == "head" || o->scene == "sphere" || o->scene == "mixed" || o->scene == "hand" ||
             fail("--scene wants head, sphere, mixed or hand", optarg);
        break;
      case kSize:
        ok = parse_size(optarg, &o->width, &o->height) || fail("--size wants WxH with sides in [64, 8192]", optarg);
        break;
      case kOut: o->out_dir = optarg; break;
      case kPreset: {
        Preset p = Preset::kClose;
        if (std::strcmp(optarg, "all") == 0) {
          o->presets = {Preset::kClose, Preset::kMid, Preset::kFar};
        } else if (preset_from_name(optarg, &p)) {
          o->presets = {p};
        } else {
          ok = fail("--preset wants close, mid, far or all", optarg);
        }
        break;
      }
      case kNoSss: o->sss = false; break;
      case kTaps:
        ok = (parse_int(optarg, &o->taps) && o->taps >= 3 && o->taps <= 65 && o->taps % 2 == 1) ||
             fail("--taps wants an odd number in [3, 65]", optarg);
        break;
      case kScale:
      case kWidthScale:
        ok = (parse_float(optarg, &o->scale) && o->scale >= 0.0f && o->scale <= 1000.0f) ||
             fail(c == kScale ? "--scale wants a number in [0, 1000]" : "--width-scale wants a number in [0, 1000]",
                  optarg);
        break;
      case kNoFollow: o->follow_surface = false; break;
      case kAdaptive:  // the old switch: what it turned on is how every kernel without jitter runs now
        std::fprintf(stderr, "sss_demo: note: --adaptive-taps is ignored: taps always follow each pixel's "
                             "footprint now\n");
        break;
      case kRegion: o->region = true; break;
      case kNoStencil: o->use_stencil = false; break;
      case kShading: {
        const std::string v = optarg;
        o->shading = v == "screen" ? 0 : v == "preintegrated" ? 1 : v == "auto" ? 2 : -1;
        ok = o->shading >= 0 || fail("--shading wants screen, preintegrated or auto", optarg);
        break;
      }
      case kMsaa:
        ok = (parse_int(optarg, &o->msaa) && (o->msaa == 0 || o->msaa == 4)) || fail("--msaa wants 0 or 4", optarg);
        break;
      case kExposure:
        ok = (parse_float(optarg, &o->exposure) && o->exposure > 0.0f && o->exposure <= 1000.0f) ||
             fail("--exposure wants a number in (0, 1000]", optarg);
        break;
      case kHeatScale:
        ok = (parse_float(optarg, &o->heat_scale) && o->heat_scale > 0.0f && o->heat_scale <= 1000.0f) ||
             fail("--heat-scale wants a number in (0, 1000]", optarg);
        break;
      case kHeatFactor:
        ok = (parse_int(optarg, &o->heat_factor) && o->heat_factor >= 1 && o->heat_factor <= 64) ||
             fail("--heat-factor wants an integer in [1, 64]", optarg);
        break;
      case kRepeat:
        ok = (parse_int(optarg, &o->repeat) && o->repeat >= 1 && o->repeat <= 1000) ||
             fail("--repeat wants an integer in [1, 1000]", optarg);
        break;
      case kView:
        ok = parse_view(optarg, &o->view) || fail("--view wants final, split, heatmap, touched or profiles", optarg);
        break;
      case kDebugViewOption:
        ok = parse_debug_views(optarg, &o->debug_views) ||
             fail("--debug-view wants all, or mask, depth, footprint, taps, profile, tiles separated by commas", optarg);
        break;
      case kFrames:
        ok = (parse_int(optarg, &o->frames) && o->frames >= 0) || fail("--frames wants a count >= 0", optarg);
        break;
      case kScreenshotFrame:
        ok = (parse_int(optarg, &o->screenshot_frame) && o->screenshot_frame >= 0) ||
             fail("--screenshot-frame wants a frame number >= 0", optarg);
        break;
      case kHelp: return ParseResult::kHelp;
      case kCrossBilateral: o->cross_bilateral = true; break;
      case kKernel: ok = parse_kernel(optarg, o) || fail("--kernel wants separable, sum-of-gaussians[:N], svd[:N], "
                                                        "preintegrated[:N], guided or artist (N in 1..6)", optarg);
        break;
      case kMaterial: {
        o->material = -1;
        for (int m = SSS_PROFILE_SKIN_DEON; m <= SSS_PROFILE_WHOLEMILK; ++m) {
          if (std::strcmp(optarg, sss_profile_name(m)) == 0) o->material = m;
        }
        ok = o->material >= 0 || fail("--material wants skin, apple, chicken1, chicken2, cream, ketchup, marble, "
                                      "potato, skimmilk, skin1, skin2 or wholemilk", optarg);
        break;
      }
      case kPath: {
        const std::string v = optarg;
        if (v == "fragment") {
          o->path = SSS_PATH_FRAGMENT;
        } else if (v == "compute") {
          o->path = SSS_PATH_COMPUTE;
        } else if (v == "auto") {
          o->path = SSS_PATH_AUTO;
        } else if (v == "masked") {
          o->path = SSS_PATH_FRAGMENT_MASKED;
        } else if (v == "half") {
          o->path = SSS_PATH_HALF_RESOLUTION;
        } else {
          ok = fail("--path wants fragment, masked, compute, half or auto", optarg);
        }
        break;
      }
      case kJitter: {
        char *end = nullptr;
        const float v = std::strtof(optarg, &end);
        ok = (end != optarg && *end == '\0' && v >= 0.0f && v <= 1.0f) || fail("--jitter wants a number in [0, 1]", optarg);
        if (ok) o->jitter = v;
        break;
      }
      case kThickness: {
        const std::string v = optarg;
        o->thickness_source = v == "shadow" ? 0 : v == "baked" ? 1 : v == "both" ? 2 : -1;
        ok = o->thickness_source >= 0 || fail("--thickness wants shadow, baked or both", optarg);
        break;
      }
      case kBakedThickness:
        ok = (parse_float(optarg, &o->baked_thickness_mm) && o->baked_thickness_mm > 0.0f &&
              o->baked_thickness_mm <= 100.0f) ||
             fail("--baked-thickness wants millimetres in (0, 100]", optarg);
        break;
      case kTexturing:
        o->texturing = -1;
        for (int t = SSS_TEXTURING_PRE_SCATTER; t <= SSS_TEXTURING_PRE_AND_POST_SCATTER; ++t) {
          if (std::strcmp(optarg, texturing_name(t)) == 0) o->texturing = t;
        }
        ok = o->texturing >= 0 || fail("--texturing wants pre, post or pre-and-post", optarg);
        break;
      case kBackLight: o->back_light = true; break;
      case kNoObjectIds: o->object_ids = false; break;
      case kMovingNoise: o->moving_noise = true; break;
      case kDump: o->dump = true; break;
      case kHandColourOption: {
        char tail = '\0';
        ok = (std::sscanf(optarg, "%f,%f,%f%c", &o->hand_colour[0], &o->hand_colour[1], &o->hand_colour[2], &tail) == 3 &&
              std::all_of(o->hand_colour, o->hand_colour + 3, [](float v) { return v >= 0.0f && v <= 1.0f; })) ||
             fail("--hand-colour wants R,G,B in [0, 1]", optarg);
        break;
      }
      case kTranslucency: {
        o->translucency = true;
        if (optarg != nullptr) {
          char *end = nullptr;
          const float v = std::strtof(optarg, &end);
          if (end == optarg || *end != '\0' || !(v >= 0.0f && v <= 1.0f)) {
            std::fprintf(stderr, "sss_demo: --translucency takes a number in [0, 1]: %s\n", optarg);
            return ParseResult::kError;
          }
          o->translucency_amount = v;
        }
        break;
      }
      default: return ParseResult::kError;  // getopt_long already printed what was wrong
    }
    if (!ok) return ParseResult::kError;
  }
  if (optind < argc) o->gltf_path = argv[optind++];
  if (optind < argc) {
    std::fprintf(stderr, "sss_demo: unexpected argument '%s' (one model at most)\n", argv[optind]);
    return ParseResult::kError;
  }
  return ParseResult::kRun;
}

}  // namespace demo
