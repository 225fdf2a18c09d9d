// The canonical scenes of DESIGN.md §6: what the filter gets from a host (irradiance, depth, mask,
// camera) for a few situations that stress it, generated deterministically in code.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace sss_bench {

struct Scene {
  std::string name;                 // "dot", "edge-0", "edge-30", "edge-45", "sphere", "depth-step",
                                    // "tilted-30/60/80", "head-close", "head-mid", "head-far",
                                    // "head-grazing", "head-mixed", "empty",
                                    // the footprint sweep's "plane-*", the turn sweep's
                                    // "turned-*", "cylinder", "sphere-40mm"
  int width = 0, height = 0;
  std::vector<float> irradiance;    // RGBA, row 0 at the bottom (GL order); linear diffuse irradiance
                                    // (albedo included); alpha = SSS strength: 1 translucent, 0 not
  std::vector<float> distance;      // linear view distance (-z_view) per pixel, finite everywhere
                                    // (background geometry or a far backdrop, never Inf)
  std::vector<float> window_depth;  // the hardware depth of `distance` for `projection` (GL default
                                    // convention: (z_ndc + 1) / 2), as a DEPTH_COMPONENT32F would hold
  std::vector<uint8_t> mask;        // 1 where translucent (alpha > 0), else 0
  // The albedo `irradiance` was multiplied by, RGBA linear (alpha 1), row 0 at the bottom: the
  // texturing modes' albedo texture (sss_frame.albedo_texture). Only the head scenes that render with
  // Lambert shading fill it (1 on the backdrop); empty for every other scene.
  std::vector<float> albedo;
  std::array<float, 16> projection{};  // column-major GL projection matrix used to make the scene
  float world_units_per_mm = 0.001f;   // scene units are metres
  // The footprint sweep's planes (plane-*): the millimetres one pixel measures on the plane, which
  // faces the camera, so every pixel's footprint is this square; 0 for every other scene.
  double footprint_mm = 0.0;
  // Several materials (head-mixed): per pixel profile | object << 4 as a host's R8UI G-buffer byte
  // holds it (sss_frame.profile_texture), 0 on the background; and the sss_profile of each profile
  // index (the exact reference convolves each profile's pixels with that profile alone). Both empty
  // for every other scene (one material: d'Eon's skin).
  std::vector<uint8_t> profile;
  std::vector<int> profile_materials;
};

// A point on a triangle mesh: triangle t at barycentric (1 - b1 - b2, b1, b2) of its corners (the
// whole-surface reference's samples, tests/bench/whole_surface.hpp).
struct SurfacePoint {
  std::uint32_t triangle = 0;
  float b1 = 0.0f, b2 = 0.0f;
};

// The turn sweep's plane (make_turned_plane_scene): a point on it and its unit normal, view space,
// metres, so that a reference can take its depth and tangents exactly rather than from the floats.
struct PlaneGeometry {
  std::array<double, 3> point{}, normal{};
};

}  // namespace sss_bench
