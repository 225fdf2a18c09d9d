// The two ways sss_demo runs: headless (PNGs for each preset) and in a GLFW window with the panel.
#pragma once

#include "options.hpp"
#include "scene.hpp"
#include "sss_stage.hpp"

namespace demo {

// The controls the command line asks for (the library's defaults otherwise).
SssControls controls_from_options(const Options &options);

// Both return the process exit status.
int run_headless(const Options &options, const DemoScene &scene);
int run_window(const Options &options, const DemoScene &scene);

}  // namespace demo
