// Text that goes with the pictures: pass-time summaries, the settings, the PNG metadata and the
// README.txt written beside the headless images.
#pragma once

#include "png_output.hpp"
#include "renderer.hpp"
#include "scene.hpp"
#include "sss_stage.hpp"

#include <sss/sss_tools.h>

#include <string>
#include <vector>

namespace demo {

// Per-pass medians over frames.
PassTimes median_times(const std::vector<PassTimes> &frames);

// "shadow 12.3  lighting 4.5  sss 6.7  count 1.2  composite 0.8  total 25.5 ms"
std::string format_times(const PassTimes &t);

// The library's settings as held after sss_set_settings, with the controls' scale and the scene's
// world units per millimetre (what the demo sets them to).
std::string format_settings(const sss_settings &s, const SssControls &controls, float world_units_per_mm);

// The scene's profiles and objects as the profile view colours them, and whether the byte carries
// object IDs: "profiles (one pass pair): 0 skin (pink), 1 marble (blue) ...; objects: 1 head, 2 bust ...".
std::string profile_legend(const DemoScene &scene, const SssControls &controls);

// tEXt chunks for an image of the scene: Title, Software, Description, Copyright (the scene's
// attribution, when it has one), Source (the GL renderer).
PngText image_text(const DemoScene &scene, const std::string &title, const std::string &description,
                   const std::string &renderer);

}  // namespace demo
