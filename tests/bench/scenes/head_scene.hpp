// The head scenes: the head scan rendered with GL into float targets and read back.
// Internal to sss_bench_scenes.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

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
  // The soft light of the whole-surface study (issue 49): the key's shadow filtered over 9 shadow-map
  // texels (about 2.6 mm) and the key projected through bars 14 mm apart whose edges ramp over 1.6 mm
  // (four pixels of the 960x540 close-up), so that the light has no edge narrower than two pixels.
  bool soft_light = false;
};

// The camera of each head scene by name (scenes.cpp: "head-close", "head-grazing", "head-mid",
// "head-mixed"; any other name gets the far shot's).
HeadView head_view(const std::string& name);

// The head scenes' lights (world space, towards the light): the key (which throws the shadow map's
// shadow), the fill and the ambient, linear colours.
struct HeadLights {
  Vec3 key_direction, fill_direction;
  float key[3], fill[3], ambient[3];
};
HeadLights head_lights();

// The camera of `view` for a width x height frame: the projection (rounded to float, as the scene
// stores it) and the world-to-view matrix.
void head_camera(const HeadView& view, int width, int height, Mat4* projection, Mat4* view_matrix);

// How the normal map's green channel is read (see head_scene.cpp): +1 as stored, -1 inverted.
extern const float kNormalMapGreenSign;

// Which points of the scan's mesh to light, chosen from the rendered scene (its colour, distance and
// mask read back): the whole-surface reference picks the surface within reach of the frame's
// receivers.
using PointsOfScene = std::function<std::vector<SurfacePoint>(const Scene&)>;

// The head scene of `view`. With `points_of` (not for a pre-integrated view): also the light the
// scene's shader gives at the points it returns (head_asset's triangles), hidden or not, RGB with the
// albedo, into *point_light (one per point): the scene's fragment shader run once per point, in the
// same GL state as the frame, so the head is rendered once.
Scene render_head_scene(const std::string& name, int width, int height, const HeadView& view,
                        const PointsOfScene& points_of = nullptr,
                        std::vector<std::array<float, 3>>* point_light = nullptr);

// head-mixed (mixed_scene.cpp): the head of `view` with a marble bust and a wax candle beside it;
// fills Scene::profile and Scene::profile_materials.
Scene render_mixed_scene(const std::string& name, int width, int height, const HeadView& view);

}  // namespace sss_bench::detail
