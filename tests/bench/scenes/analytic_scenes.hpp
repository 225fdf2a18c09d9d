// The scenes computed on the CPU (no GL): dot, edges, sphere, depth step, empty, the footprint
// sweep's planes and the turn sweep's scenes.
// Internal to sss_bench_scenes.
#pragma once

#include <string>

#include "scene.hpp"

namespace sss_bench::detail {

Scene make_dot_scene(int width, int height);
Scene make_edge_scene(const std::string& name, double degrees_from_vertical, int width, int height);
Scene make_sphere_scene(int width, int height);
// The sphere with its Lambert term replaced by eq. (1.1) at the sphere's curvature (per channel).
Scene make_preintegrated_sphere_scene(int width, int height);
// The sphere scene scaled to `radius` metres (camera distance scaled alike): "sphere-20mm",
// "sphere-10mm"; preintegrated: shaded with the diffuse LUT's function at curvature 1/radius.
Scene make_small_sphere_scene(const std::string& name, double radius, int width, int height, bool preintegrated);
Scene make_depth_step_scene(int width, int height);
// The edge-0 plane turned by `degrees` about the view's vertical axis (0: facing the camera), its
// shadow edge still through the image centre: what the footprint's per-axis cosine correction buys.
// Pixels whose ray misses the plane (it turns away at 80°) are a non-translucent backdrop.
Scene make_tilted_plane_scene(const std::string& name, double degrees, int width, int height);
Scene make_empty_scene(int width, int height);
// The footprint sweep's planes (scenes.hpp: footprint_scene_names), facing the camera at the
// distance where a pixel measures footprint_mm.
Scene make_footprint_plane_scene(const std::string& name, double footprint_mm, int width, int height);

// The turn sweep (scenes.hpp: make_turned_plane_scene, make_cylinder_scene, make_footprint_sphere_scene).
Scene make_turned_plane_scene(double footprint_mm, double turn_degrees, double axis_degrees, bool orthographic,
                              int width, int height, PlaneGeometry* plane);
Scene make_cylinder_scene(double footprint_mm, int width, int height);
Scene make_footprint_sphere_scene(double footprint_mm, int width, int height);

// The cameras, shared with the tests and the report (metres, vertical field of view 30 degrees).
constexpr double kFovyDegrees = 30.0;
constexpr double kPlaneDistance = 0.25;         // dot and edges: the plane's view distance
constexpr double kDotRadius = 0.0005;           // 0.5 mm
constexpr double kDark = 0.02, kLit = 1.0;      // dot and edges
constexpr double kSphereDistance = 0.5;         // the sphere's centre
constexpr double kSphereRadius = 0.08;
constexpr double kSphereBackdropDistance = 0.8;
constexpr double kStepNearDistance = 0.3;       // depth step: the square
constexpr double kStepHalfSize = 0.04;
constexpr double kStepFarDistance = 0.6;        // depth step: the background, 0.3 m behind
constexpr double kEmptyDistance = 1.0;
constexpr double kSpotRadiusMm = 0.5;    // plane-spot: a small bright spot (the dot's)
constexpr double kDiskRadiusMm = 3.0;    // plane-disk
constexpr double kAlbedoLow = 0.25;      // plane-albedo: per-pixel albedo in [0.25, 1)
// The turn sweep: the turned plane's spot (on the lit side, its centre this far from the edge) and
// its light; the cylinder's and the sphere's radius.
constexpr double kTurnedSpotOffsetMm = 2.0;
constexpr double kTurnedSpotLight = 4.0;
constexpr double kTurnSweepRadius = 0.04;  // 40 mm
// The turned planes' perspective camera: its corner rays this far off the view axis, so that every
// pixel sees the plane within this many degrees of its turn and every frame of the turn sweep keeps
// an interior (analytic_scenes.cpp: turned_plane_fovy_degrees: 4.24 degrees of vertical field of view on a square frame).
constexpr double kTurnedPlaneSpreadDegrees = 3.0;

}  // namespace sss_bench::detail
