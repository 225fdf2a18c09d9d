#include "shared_assets.hpp"

#include <cstdlib>

#ifndef SSS_ASSET_DIR
#error "SSS_ASSET_DIR must be defined by the build (CMake cache variable SSS_ASSET_DIR)"
#endif

namespace sss_assets {

std::string asset_dir() {
  const char* env = std::getenv("SSS_ASSET_DIR");
  if (env != nullptr && env[0] != '\0') return env;
  return SSS_ASSET_DIR;
}

std::string head_path() { return asset_dir() + "/lee-perry-smith-head/head.glb"; }

const char* head_attribution() {
  return "\"Infinite, 3D Head Scan\" by Lee Perry-Smith is licensed under a Creative Commons "
         "Attribution 3.0 Unported License. Based on a work at www.triplegangers.com. Permissions "
         "beyond the scope of this license may be available at http://www.ir-ltd.net/";
}

}  // namespace sss_assets
