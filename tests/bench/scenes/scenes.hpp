// The canonical scenes of DESIGN.md §6, by name (see scene.hpp for what a Scene holds).
//
//   dot          a translucent plane facing the camera, dark (0.02), with a bright disk (1.0,
//                radius 0.5 mm) at the centre
//   edge-0/30/45 a translucent plane lit 1.0 left of a straight line through the image centre and
//                0.02 right of it (a hard shadow edge); the line at 0, 30, 45 degrees from the
//                vertical, its top leaning right
//   sphere       a translucent sphere (radius 0.08 m) with a hard terminator in front of a grey
//                non-translucent backdrop
//   depth-step   a near translucent square (0.6) over a bright (4.0) non-translucent background
//                0.3 m behind it
//   head-close/mid/far  the Lee Perry-Smith head scan, lit with a shadowing key light, a fill and
//                an ambient term, in front of a dark backdrop (needs GL)
//   head-grazing the same head at the close-up's distance in a three-quarter view from its right,
//                the frame centred on its left cheek, which faces about 70 degrees away (scenes.cpp)
//   head-mixed   the head with a marble bust and a wax candle beside it (the demo's mixed scene):
//                three profiles and three objects in one frame (Scene::profile), the objects ray-cast
//   empty        the backdrop alone (nothing translucent)
//
// The footprint sweep (footprint_scene_names): a translucent plane facing the camera, filling the
// frame, at the distance where one pixel measures a given number of millimetres, so that the same
// light is seen from a 4K close-up (0.05 mm per pixel) to a crowd (2 mm and more):
//   plane-edge-0/20/45  a straight shadow edge (1.0 left, 0.02 right) through the centre, 0, 20 and
//                       45 degrees from the vertical: additively separable light
//   plane-spot          a bright spot of radius 0.5 mm on 0.02: non-separable, narrower than the profile
//   plane-disk          a bright disk of radius 3 mm on 0.02
//   plane-albedo        uniform light times a per-pixel albedo in [0.25, 1): detail at the pixel scale
//
// The turn sweep (sss_bench_turns; frames as the footprint sweep's): how the filter does where the
// surface turns away from the camera, at a given footprint (mm per pixel where the surface faces it):
//   turned-T-about-A-orthographic/-perspective  a translucent plane filling the frame through the
//                point at the view distance where a facing pixel measures the footprint, its normal
//                turned by T degrees about the axis in the screen plane at A degrees from screen x.
//                On it, in surface millimetres about its point at the image centre: a straight
//                shadow edge along the turn axis (the light changes along the foreshortened
//                direction; lit 1.0 on one side, 0.02 on the other), a per-pixel albedo in [0.25, 1)
//                on both sides and a spot of radius 0.5 mm (4.0) on the lit side 2 mm from the edge;
//                edge and spot anti-aliased from 4x4 rays per pixel. Perspective: a narrow camera
//                whose corner rays are 3 degrees off its axis, so every pixel sees the plane within
//                3 degrees of its turn and every frame keeps an interior to score (pixels whose ray
//                meets the plane beyond 4 times the distance, or not at all, are a non-translucent
//                backdrop: past a turn of 83 degrees); orthographic: pixels of the footprint's size.
//   cylinder     a translucent cylinder of radius 40 mm, its axis in a plane facing the camera and
//                tilted 20 degrees from the vertical, its nearest line at that distance, lit by a
//                directional light whose hard terminator runs along it 4 degrees (2.8 mm) from that
//                line, shading across it, before a non-translucent backdrop; a cast shadow's hard
//                edge (a ring round the cylinder through its nearest point, the light's shadow plane
//                normal to the axis) darkens the lit side below it to the ambient term
//   sphere-40mm  the sphere scene (its light and backdrop) at radius 40 mm, its nearest point at
//                that distance; a cast shadow's hard edge through that point (30 degrees below
//                screen x there) darkens the side away from the light to the ambient term
//   The cylinder and the sphere carry the planes' per-pixel albedo in [0.25, 1) (times their
//   colour), and their cast shadow's edge is anti-aliased from 4x4 rays per pixel, so the interior
//   the turn sweep scores needs a clear change at every footprint (their smooth light alone needed
//   about one half-float step on the sphere).
//
// Every scene is in metres (world_units_per_mm = 0.001), deterministic, with finite distances and
// a perspective camera (vertical field of view 30 degrees), except the turned planes (orthographic,
// or the narrow camera above). The head scenes render with GL: a GL
// 3.3 core context must be current and host_gl loaded for it; every GL object they make is deleted
// before make_scene returns and every state they touch is restored. The others need no GL.
#pragma once

#include <string>
#include <vector>

#include "scene.hpp"

namespace sss_bench {

// The canonical scene names, in the order listed above.
std::vector<std::string> canonical_scene_names();

// True for the scenes that need a current GL context (the head scenes).
bool scene_needs_gl(const std::string& name);

// The footprint sweep's scenes, in the order listed above.
std::vector<std::string> footprint_scene_names();

// A footprint sweep scene at footprint_mm (> 0) millimetres per pixel, width x height (>= 1).
// Throws std::invalid_argument for an unknown name or bad arguments.
Scene make_footprint_scene(const std::string& name, double footprint_mm, int width, int height);

// The turn sweep's scenes (above) at footprint_mm (> 0) millimetres per pixel, width x height (>= 3):
// the turned plane (turn_degrees in [0, 89], any axis_degrees), with its plane in `plane` when not
// null (scene.hpp); the cylinder; the sphere of radius 40 mm. Throws std::invalid_argument for bad arguments,
// or a footprint that puts the sphere through the sphere scene's backdrop (0.8 m).
Scene make_turned_plane_scene(double footprint_mm, double turn_degrees, double axis_degrees, bool orthographic,
                              int width, int height, PlaneGeometry* plane = nullptr);
Scene make_cylinder_scene(double footprint_mm, int width, int height);
Scene make_footprint_sphere_scene(double footprint_mm, int width, int height);

// Builds the scene at width x height (both >= 1). Throws std::invalid_argument for an unknown name
// or a bad size, std::runtime_error when the head asset cannot be loaded or GL fails.
Scene make_scene(const std::string& name, int width, int height);

// The same scene shaded with pre-integrated skin scattering instead of Lambert (docs/preintegrated.md):
// translucent pixels already hold the scattered light (compare them with the exact reference of
// make_scene's irradiance). For "sphere" (CPU: eq. 1.1 evaluated at the sphere's curvature) and the
// head scenes (GL, as make_scene); throws std::invalid_argument for the others.
Scene make_preintegrated_scene(const std::string& name, int width, int height);

// The directory holding lee-perry-smith-head/: the environment variable SSS_ASSET_DIR when set and
// not empty, else the build's default (the CMake cache variable SSS_ASSET_DIR).
std::string asset_dir();

// The attribution the head scan's licence (CC BY 3.0) asks for; carry it with any image of it.
const char* head_attribution();

}  // namespace sss_bench
