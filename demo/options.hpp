// Command line of sss_demo (getopt_long).
#pragma once

#include "camera.hpp"
#include "sss_stage.hpp"
#include "composite.hpp"
#include "scene.hpp"

#include <string>
#include <vector>

namespace demo {

struct Options {
  bool headless = false;
  std::string backend = "egl";   // headless: osmesa | egl | egl-device
  std::string scene = "head";    // head | sphere | mixed | hand
  std::string gltf_path;         // a glTF file instead of the built-in scene
  int width = 1280;
  int height = 720;
  std::string out_dir = "demo-out";
  std::vector<Preset> presets = {Preset::kClose, Preset::kMid, Preset::kFar};  // window: the first one

  bool sss = true;
  int taps = 0;                  // SSS taps per pass (--taps); 0: the library's default
  bool use_stencil = true;
  int msaa = 0;                  // 0, or 4: render into 4x multisampled targets and hand those to the library
  bool follow_surface = true;
  bool cross_bilateral = false;  // SSS_MODE_CROSS_BILATERAL
  int kernel_family = 0;         // sss_kernel_family (SSS_KERNEL_SEPARABLE: eq. (1))
  int kernel_rank = 1;           // sum of Gaussians / SVD: terms
  int material = 0;              // sss_material the kernel's profile comes from (SSS_PROFILE_SKIN_DEON)
  float jitter = 0.0f;           // sss_settings.jitter
  bool moving_noise = false;     // sss_frame.noise_index = the frame's number (the jitter moves each frame)
  unsigned path = 2;             // sss_settings.path: SSS_PATH_AUTO (the library's default), _FRAGMENT, _COMPUTE, _FRAGMENT_MASKED, _HALF_RESOLUTION
  bool region = false;           // SSS_FRAME_REGION from the head's projected bounds
  bool translucency = false;     // transmittance through thin parts
  float translucency_amount = 0.95f;
  int thickness_source = 0;      // TransmittanceInputs::thickness_source: 0 shadow maps, 1 baked, 2 both (the larger)
  float baked_thickness_mm = 2.0f;  // the translucent materials' baked thickness (--baked-thickness), mm
  bool back_light = false;       // the second light moves behind the head (ears glow with --translucency)
  bool object_ids = true;        // the profile byte carries object IDs (--no-object-ids: the profile alone)
  float hand_colour[3] = {kHandColour[0], kHandColour[1], kHandColour[2]};  // --scene hand
  bool dump = false;             // headless: linear before/after (PFM) and the profile byte (PGM) per preset
  float scale = 1.0f;            // sss_settings.scale: multiplies the scattering distances (1 = physical size)
  int shading = 0;               // SssControls::shading: 0 screen-space, 1 pre-integrated, 2 automatic
  float exposure = 1.0f;
  int texturing = kDefaultTexturing;  // --texturing: an sss_texturing (sss_stage.hpp says why the default)

  float heat_scale = 0.05f;      // linear error at the top of the heat map's ramp
  int heat_factor = 4;           // the heat map's frame is 1/heat_factor of each side
  int repeat = 5;                // headless: timed frames per preset (median reported)

  ViewMode view = ViewMode::kFinal;  // window: the first view
  // --debug-view: sss_debug_view values; headless: a PRESET-view-NAME.png each; window: the first is shown.
  std::vector<int> debug_views;
  int frames = 0;                // window: close after this many frames (0: when the user closes it)
  int screenshot_frame = -1;     // window: save a screenshot at this frame, as F12 does
};

enum class ParseResult { kRun, kHelp, kError };

ParseResult parse_options(int argc, char **argv, Options *options);
void print_usage(const char *program);

}  // namespace demo
