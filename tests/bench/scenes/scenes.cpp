#include "scenes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analytic_scenes.hpp"
#include "head_scene.hpp"

namespace sss_bench {

// The head cameras (see head_scene.hpp): vertical field of view 30 degrees; yawed 20 degrees
// towards the subject's left cheek (+X, the side the nose shadow falls on), 5 degrees above.
// close: frame height 0.21 m at the target (the face, chin to crown, fills most of it);
// mid:   frame height 1.08 m = 3 x the scan's 0.36 m;  far: 3.6 m = 10 x 0.36 m.
// grazing: the close-up's distance, the camera yawed 40 degrees the other way (towards the
// subject's right, a three-quarter view), the frame centred on the left cheek, which then faces
// about 70 degrees away: at 320x180 the cheek's visible pixels (x 0.02 to 0.07 m, y 0 to 0.06 m, z
// above 0.03 m on the scan, where all four neighbours are skin) turn a median 67.5 degrees from the
// view direction, 74 % of them 60 to 80 (each pixel's normal from its neighbours' depths by central
// differences; 216 pixels, part of them in the nose's shadow). Yawed further, less of the cheek is in
// view (45 degrees: 108 pixels, median 72.5), less far, it faces the camera more (30: median 60).
// Most of such a cheek lies within the profile's reach of the nose's and the face's silhouettes,
// and the region rule calls a surface more than about 76 degrees turned a silhouette
// (regions.hpp), so the frame's interior pixels turn less: a median of 37.6 degrees (a quarter
// beyond 49, 6 % at 60 to 80) at 320x180, against 37.5 for the close-up.
// The backdrop is 0.5 m behind the target along the view axis.
detail::HeadView detail::head_view(const std::string& name) {
  detail::HeadView v;
  v.fovy_degrees = detail::kFovyDegrees;
  v.yaw_degrees = 20;
  v.pitch_degrees = 5;
  const double tan_half = 0.2679491924311227;  // tan(15 degrees)
  double frame_height = 0;
  if (name == "head-close") {
    v.target = {0.0, 0.075, 0.08};
    frame_height = 0.21;
    v.near_plane = 0.15;
  } else if (name == "head-grazing") {
    v.target = {0.04, 0.055, 0.07};
    v.yaw_degrees = -40;
    frame_height = 0.21;
    v.near_plane = 0.15;
  } else if (name == "head-mixed") {
    // The head and the objects beside it (x from -0.44 to 0.37 m) across the frame's width.
    v.target = {0.0, -0.01, 0.0};
    frame_height = 0.56;
    v.near_plane = 0.3;
  } else if (name == "head-mid") {
    v.target = {0.0, 0.0, 0.0};
    frame_height = 1.08;
    v.near_plane = 0.5;
  } else {
    v.target = {0.0, 0.0, 0.0};
    frame_height = 3.6;
    v.near_plane = 2.0;
  }
  v.distance = frame_height / (2 * tan_half);
  v.backdrop_distance = v.distance + 0.5;
  v.far_plane = v.backdrop_distance + 1.0;
  return v;
}

std::vector<std::string> canonical_scene_names() {
  return {"dot",        "edge-0",   "edge-30",  "edge-45", "sphere",    "depth-step", "tilted-30", "tilted-60",
          "tilted-80",  "head-close", "head-mid", "head-far", "head-grazing", "head-mixed", "empty"};
}

bool scene_needs_gl(const std::string& name) {
  return name == "head-close" || name == "head-mid" || name == "head-far" || name == "head-grazing" ||
         name == "head-mixed";
}

Scene make_scene(const std::string& name, int width, int height) {
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw std::invalid_argument("make_scene: bad size " + std::to_string(width) + "x" + std::to_string(height));
  if (name == "dot") return detail::make_dot_scene(width, height);
  if (name == "edge-0") return detail::make_edge_scene(name, 0.0, width, height);
  if (name == "edge-30") return detail::make_edge_scene(name, 30.0, width, height);
  if (name == "edge-45") return detail::make_edge_scene(name, 45.0, width, height);
  if (name == "sphere") return detail::make_sphere_scene(width, height);
  if (name == "depth-step") return detail::make_depth_step_scene(width, height);
  if (name == "tilted-30") return detail::make_tilted_plane_scene(name, 30.0, width, height);
  if (name == "tilted-60") return detail::make_tilted_plane_scene(name, 60.0, width, height);
  if (name == "tilted-80") return detail::make_tilted_plane_scene(name, 80.0, width, height);
  if (name == "head-mixed") return detail::render_mixed_scene(name, width, height, detail::head_view(name));
  if (scene_needs_gl(name)) return detail::render_head_scene(name, width, height, detail::head_view(name));
  if (name == "empty") return detail::make_empty_scene(width, height);
  if (name == "sphere-20mm") return detail::make_small_sphere_scene(name, 0.020, width, height, false);
  if (name == "sphere-10mm") return detail::make_small_sphere_scene(name, 0.010, width, height, false);
  throw std::invalid_argument("make_scene: unknown scene '" + name + "'");
}

std::vector<std::string> footprint_scene_names() {
  return {"plane-edge-0", "plane-edge-20", "plane-edge-45", "plane-spot", "plane-disk", "plane-albedo"};
}

Scene make_footprint_scene(const std::string& name, double footprint_mm, int width, int height) {
  const auto names = footprint_scene_names();
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    throw std::invalid_argument("make_footprint_scene: unknown scene '" + name + "'");
  }
  if (!(footprint_mm > 0.0) || !(footprint_mm < 1000.0)) {
    throw std::invalid_argument("make_footprint_scene: footprint_mm must be in (0, 1000), got " + std::to_string(footprint_mm));
  }
  if (width < 1 || height < 1 || width > 16384 || height > 16384) {
    throw std::invalid_argument("make_footprint_scene: bad size " + std::to_string(width) + "x" + std::to_string(height));
  }
  return detail::make_footprint_plane_scene(name, footprint_mm, width, height);
}

namespace {

void check_turn_sweep_arguments(const char* who, double footprint_mm, int width, int height) {
  if (!(footprint_mm > 0.0) || !(footprint_mm < 1000.0)) {
    throw std::invalid_argument(std::string(who) + ": footprint_mm must be in (0, 1000), got " + std::to_string(footprint_mm));
  }
  if (width < 3 || height < 3 || width > 16384 || height > 16384) {
    throw std::invalid_argument(std::string(who) + ": bad size " + std::to_string(width) + "x" + std::to_string(height));
  }
}

}  // namespace

Scene make_turned_plane_scene(double footprint_mm, double turn_degrees, double axis_degrees, bool orthographic,
                              int width, int height, PlaneGeometry* plane) {
  check_turn_sweep_arguments("make_turned_plane_scene", footprint_mm, width, height);
  if (!(turn_degrees >= 0.0 && turn_degrees <= 89.0) || !std::isfinite(axis_degrees)) {
    throw std::invalid_argument("make_turned_plane_scene: the turn must be in [0, 89] degrees and the axis finite, got " +
                                std::to_string(turn_degrees) + " about " + std::to_string(axis_degrees));
  }
  return detail::make_turned_plane_scene(footprint_mm, turn_degrees, axis_degrees, orthographic, width, height, plane);
}

Scene make_cylinder_scene(double footprint_mm, int width, int height) {
  check_turn_sweep_arguments("make_cylinder_scene", footprint_mm, width, height);
  return detail::make_cylinder_scene(footprint_mm, width, height);
}

Scene make_footprint_sphere_scene(double footprint_mm, int width, int height) {
  check_turn_sweep_arguments("make_footprint_sphere_scene", footprint_mm, width, height);
  return detail::make_footprint_sphere_scene(footprint_mm, width, height);
}

Scene make_preintegrated_scene(const std::string& name, int width, int height) {
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw std::invalid_argument("make_preintegrated_scene: bad size " + std::to_string(width) + "x" + std::to_string(height));
  if (name == "sphere") return detail::make_preintegrated_sphere_scene(width, height);
  if (name == "sphere-20mm") return detail::make_small_sphere_scene(name, 0.020, width, height, true);
  if (name == "sphere-10mm") return detail::make_small_sphere_scene(name, 0.010, width, height, true);
  if (scene_needs_gl(name)) {
    detail::HeadView view = detail::head_view(name);
    view.preintegrated = true;
    return detail::render_head_scene(name, width, height, view);
  }
  throw std::invalid_argument("make_preintegrated_scene: no pre-integrated variant of '" + name + "'");
}

}  // namespace sss_bench
