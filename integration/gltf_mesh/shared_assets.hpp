// Where the project's assets are (assets/ in the source tree by default) and what their licences ask
// for. Used by the demo and the benchmark's head scenes.
#pragma once

#include <string>

namespace sss_assets {

// The directory holding lee-perry-smith-head/: the environment variable SSS_ASSET_DIR when set and
// not empty, else the build's default (the CMake cache variable SSS_ASSET_DIR).
std::string asset_dir();

// <asset_dir()>/lee-perry-smith-head/head.glb
std::string head_path();

// The attribution the head scan's licence (CC BY 3.0) asks for; carry it with any image of it
// (text of assets/lee-perry-smith-head/README.md).
const char* head_attribution();

}  // namespace sss_assets
