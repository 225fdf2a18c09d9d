// The light a rendered frame's pixels give at a point of the surface they show: the whole-surface
// reference's pixel-consistent light (whole_surface_frame.hpp, issue 49), what any filter of the
// frame is handed there. CPU only, no GL.
#pragma once

#include <array>
#include <cstddef>

#include "scenes/scene.hpp"
#include "scenes/scene_math.hpp"
#include "whole_surface.hpp"  // Point3

namespace sss_bench {

// The light at a world point the frame sees, from its pixels: Catmull-Rom between the pixel centres
// round its projection where all sixteen pixels are translucent and at its depth (within twice the
// visibility tolerance below: the outer ones lie up to two pixels off), else bilinear over those of
// the four nearest that are, else its nearest pixel's. Why Catmull-Rom: a profile term's integral
// over bilinear light is its integral over the pixels blurred by the tent between them, which widens
// every term by a sixth of a pixel² (half again the 0.22 mm term's own width² at the 960x540
// close-up, a seventh of the 0.43 mm term's), while Catmull-Rom reproduces quadratics: each term
// keeps its own width, as over light with no detail finer than a pixel.
//
// Visible: the point's nearest pixel is translucent and the point no further behind that pixel's
// depth than a quarter millimetre plus one pixel's depth change on each axis (the point sits up to
// half a pixel from the pixel's centre along each); `light` is meaningful only then.
struct PixelLight {
  bool visible = false;
  std::array<float, 3> light{};
};
PixelLight light_from_pixels(const Scene& scene, const detail::Mat4& view_matrix, const Point3& world);

// The index of pixel (x, y) in a scene's per-pixel arrays (row 0 at the bottom).
inline std::size_t pixel_index(const Scene& s, int x, int y) {
  return static_cast<std::size_t>(y) * static_cast<std::size_t>(s.width) + static_cast<std::size_t>(x);
}

}  // namespace sss_bench
