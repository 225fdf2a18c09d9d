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
// Every scene is in metres (world_units_per_mm = 0.001), deterministic, with finite distances and
// a perspective camera (vertical field of view 30 degrees). The head scenes render with GL: a GL
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
