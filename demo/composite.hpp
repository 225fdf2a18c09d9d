// Pass 4: what the frame shows, into the targets' RGBA8 output (already sRGB-encoded):
//   kFinal    (diffuse + specular) x exposure, the filmic curve (Narkowicz's ACES fit, the same
//             tone_map as the benchmark's metrics), sRGB encode
//   kSplit    the same, "before" left of the divider and "after" right of it, a white divider
//   kHeatMap  the heat-map texture (heat_map.hpp: already coloured, lower resolution, nearest)
//   kTouched  which pixels the library changed: orange where after != before (bit for bit),
//             blue where the pixel is translucent (alpha > 0) but came out unchanged, the rest
//             the final image in dim grey
//   kProfiles the G-buffer's profile/object byte in flat false colours: a hue per profile, a shade per
//             object of it; not translucent (alpha 0) dark grey
// Where "after" holds one of the library's debug views (CompositeInput::debug_view), the final, split
// and touched views show it in false colours instead (debug_colour in composite.cpp), over a dim grey
// of the unfiltered frame where the view leaves the pixel alone.
#pragma once

#include "frame_targets.hpp"
#include "gl_functions.hpp"

#include <cstdint>
#include <vector>

namespace demo {

enum class ViewMode { kFinal, kSplit, kHeatMap, kTouched, kProfiles };
constexpr int kViewModeCount = 5;

const char *view_mode_name(ViewMode mode);  // "final", "split", "heatmap", "touched", "profiles"
// How the composite colours a debug view (sss_debug_view `view`), in words for captions and the panel.
const char *debug_view_legend(int view);

struct CompositeInput {
  ViewMode mode = ViewMode::kFinal;
  GLuint before = 0;    // the lighting pass's diffuse
  GLuint after = 0;     // the library's output; for kFinal the texture to show (before when SSS is off)
  GLuint specular = 0;
  GLuint heat_map = 0;  // kHeatMap only
  float exposure = 1.0f;
  float split = 0.5f;   // kSplit: divider position, fraction of the width from the left
  int debug_view = 0;   // the sss_debug_view "after" holds (0: the filtered image)
  float view_depth[2] = {0.0f, 1.0f};  // the depth view's range: nearest and farthest view distance
  int taps = 17;        // the taps view's top: sss_settings.taps
};

struct CompositePass {
  GLuint program = 0;
  GLuint vao = 0;  // empty: the full-screen triangle comes from gl_VertexID
};

bool create_composite_pass(CompositePass *pass);
void run_composite_pass(const CompositePass &pass, const FrameTargets &targets, const CompositeInput &input);
void destroy_composite_pass(CompositePass *pass);

// The output's pixels, RGBA8, rows bottom-up as GL stores them.
std::vector<std::uint8_t> read_output(const FrameTargets &targets);

}  // namespace demo
