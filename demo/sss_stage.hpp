// Pass 3: the library. Creates the sss context, sets the settings and the camera, and blurs the
// lighting pass's diffuse texture in place.
#pragma once

#include "options.hpp"

#include <sss/sss.h>

#include <glm/mat4x4.hpp>

#include <cstdint>

namespace demo {

struct SssStage {
  sss_context *context = nullptr;
  sss_settings settings{};  // as the library holds them after sss_set_settings
  bool use_stencil = true;
};

// sss_create with the headless loader, then the settings from the options.
bool create_sss_stage(SssStage *stage, void *headless, const Options &options);

// sss_set_camera + sss_apply (with the stencil on the depth-stencil texture when enabled).
bool apply_sss(const SssStage &stage, const glm::mat4 &projection, std::uint32_t diffuse,
               std::uint32_t depth_stencil);

// A second, timing-only run: sss_apply_frame from `source` into `scratch` (leaves `source` as it is).
bool apply_sss_into(const SssStage &stage, std::uint32_t source, std::uint32_t depth_stencil,
                    std::uint32_t scratch);

void destroy_sss_stage(SssStage *stage);

}  // namespace demo
