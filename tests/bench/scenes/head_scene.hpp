// The head scenes: the head scan rendered with GL into float targets and read back.
// Internal to sss_bench_scenes.
#pragma once

#include <string>

#include "scene.hpp"
#include "scene_math.hpp"

namespace sss_bench::detail {

struct HeadView {
  double fovy_degrees = 30;
  Vec3 target;                 // world point at the image centre
  double distance = 1;         // from the camera to target
  double yaw_degrees = 0;      // camera position around +Y, from +Z (the face) towards +X
  double pitch_degrees = 0;    // camera elevation
  double near_plane = 0.1, far_plane = 10;
  double backdrop_distance = 2;  // view distance (-z_view) of the backdrop plane
  // Shade the skin with pre-integrated scattering (docs/preintegrated.md) instead of Lambert: the
  // LUTs of the math layer, integration/preintegrated/sss_preintegrated.glsl, curvature from
  // derivatives, the geometric normal as the blurred one, and a wide box PCF on the key's shadow.
  bool preintegrated = false;
};

// How the normal map's green channel is read (see head_scene.cpp): +1 as stored, -1 inverted.
extern const float kNormalMapGreenSign;

Scene render_head_scene(const std::string& name, int width, int height, const HeadView& view);

}  // namespace sss_bench::detail
