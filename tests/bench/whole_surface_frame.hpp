// The whole-surface reference of one rendered head frame (issue 49): the frame, its receivers on
// the mesh, the samples of each profile term with the light the scene's shader gives there and the
// light the frame's pixels give there, and the reference's value at each receiver.
// Needs a current GL context (the head scene and its points pass).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "scenes/head_scene.hpp"
#include "scenes/scene.hpp"
#include "whole_surface.hpp"

namespace sss_bench {

struct WholeSurfaceFrameSettings {
  int width = 960, height = 540;
  int stride = 2;                  // receivers: the translucent pixels of a 1-in-stride² grid
  double spacing_per_sigma = 0.4;  // WholeSurfaceSettings
  int analytic_terms = 1;          // WholeSurfaceSettings
};

struct WholeSurfaceFrame {
  Scene scene;                     // its irradiance rounded to half floats: the RGBA16F colour a filter gets
  detail::Mat4 view_matrix{};      // world to view
  std::vector<std::size_t> pixels;  // the receivers' pixels
  std::vector<Point3> normals;      // each receiver's surface normal (world), from its neighbours' depths
  std::vector<WholeSurfaceValue> values;
  std::size_t samples = 0;          // over every numerical term
  std::size_t visible_samples = 0;
  double render_seconds = 0.0, reference_seconds = 0.0;
};

// Renders `view` (Lambert, its soft_light as set) at the settings' size and computes the reference
// at every receiver: each numerical term sampled only where it can reach a receiver.
WholeSurfaceFrame make_whole_surface_frame(const std::string& name, const detail::HeadView& view,
                                           const WholeSurfaceFrameSettings& settings);

// The world point where pixel i's centre meets the surface (its view distance along its ray).
Point3 pixel_world_point(const Scene& scene, const detail::Mat4& view_matrix, std::size_t pixel);

}  // namespace sss_bench
