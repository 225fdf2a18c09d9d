// The visible surface reconstructed from a depth image: the view-space position of a pixel and the
// patch of surface it covers (its footprint). The exact reference (exact_reference.hpp) integrates
// the diffusion profile over these footprints; a GL port must use exactly these formulas.
// Math layer: no GL.
//
// Conventions
// -----------
// - m is the host's column-major projection (element (row r, column c) is m[c*4 + r]), with
//   m[1] = m[3] = m[4] = m[7] = 0 (what check_projection() accepts): perspective (also off-centre
//   and infinite) or orthographic.
// - The image is W x H pixels, row 0 at the bottom (GL order). Pixel (x, y) has its centre at the
//   window position (x + 0.5, y + 0.5), i.e. at NDC
//       x_ndc = 2 (x + 0.5) / W - 1,   y_ndc = 2 (y + 0.5) / H - 1.
// - The depth of a pixel is its view distance d = -Z_view (> 0 in front of the camera).
//
// Position (view space, world units)
// ----------------------------------
//   Z = -d,  w = m[11] Z + m[15]          (w = d for perspective, 1 for orthographic)
//   X = (x_ndc w - m[8] Z - m[12]) / m[0]
//   Y = (y_ndc w - m[9] Z - m[13]) / m[5]
// (the inverse of clip = m · (X, Y, Z, 1) for the x and y rows at the given Z).
//
// Footprint
// ---------
// A pixel is "usable" when it is inside the image, translucent (mask non-zero, or no mask) and its
// distance is finite with w > 0. For the x axis (y is the same with the down/up neighbours, m[5]
// and H in place of m[0] and W), with P(x, y) the positions above and d the distances:
//
//   s_x = |2 w / (m[0] W)|    the width of the pixel on a plane facing the camera at distance d
//
//   FootprintRule::central_where_smooth (the default):
//     if both the left and the right neighbours are usable and |d_right - 2 d + d_left| <= s_x
//       tx = (P(x+1, y) - P(x-1, y)) / 2                              (central difference)
//     otherwise as one_sided below.
//   FootprintRule::one_sided:
//     among the usable left/right neighbours take the one with the smaller |d_neighbour - d|
//     (the right one on a tie):
//       right: tx = P(x+1, y) - P(x, y)         left: tx = P(x, y) - P(x-1, y)
//     if neither is usable, the footprint of a plane facing the camera at distance d:
//       tx = (2 w / (m[0] W), 0, 0)             (ty = (0, 2 w / (m[5] H), 0))
//
// The smoothness test |d_right - 2 d + d_left| <= s_x says that the surface's slope (depth change
// per lateral pixel width) differs by at most 1 between the two sides of the pixel (a turn of up to
// 45 degrees where the surface faces the camera, less where it is oblique): a sampled smooth
// surface passes, a depth step does not. It has no scale: it holds for any unit and distance. With central differences the
// footprints of neighbouring pixels overlap or leave gaps of third order in the pixel size, so the
// covered area is off by a relative O(α²), α the angle a pixel subtends; one-sided differences
// leave second-order overlaps, O(α · tan(tilt)). On a plane tilted 50 degrees, α = 5e-4 rad (0.25
// mm pixels at 0.5 m): 4.8e-7 against 7.1e-4 (exact_reference_test.cpp measures both). Both rules
// read the same four neighbour depths.
//
// The footprint is then modelled as a rectangle in the plane spanned by tx and ty, centred at P:
//   A  = |tx x ty|                                (its area: that of the parallelogram tx, ty)
//   t1 = tx / |tx|
//   t2 = (ty - (ty . t1) t1) / |ty - (ty . t1) t1|
//   a  = |tx|  (side along t1),   b = A / a  (side along t2)
// When A = 0 (degenerate: tx parallel to ty, or zero) the pixel covers no area: b = 0, t2 = 0.
// Equal-sized parallelograms of a lattice are tiled exactly by these rectangles (a brick pattern),
// so the model is exact on planes under orthographic projection.
#pragma once

#include <cmath>
#include <cstdint>

#include "projection.hpp"

namespace sss::math {

struct Vec3 {
  double x = 0.0, y = 0.0, z = 0.0;
};

inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(const Vec3& a) { return std::sqrt(dot(a, a)); }

// View-space position (world units) of the point at window position (wx, wy) (pixel (x, y)'s
// centre is (x + 0.5, y + 0.5)) and view distance `distance`: the formulas above.
Vec3 view_position(const Matrix4& m, int width, int height, double wx, double wy, double distance);

// The same at the centre of pixel (x, y).
Vec3 pixel_position(const Matrix4& m, int width, int height, int x, int y, double distance);

// A depth image with its mask and camera. Exactly one of distance / distance_f64 is set (double
// distances let analytic scenes avoid the float rounding of depth; see exact_reference_test.cpp).
struct SurfaceImage {
  int width = 0, height = 0;
  const float* distance = nullptr;      // view distance per pixel, row 0 at the bottom
  const double* distance_f64 = nullptr;  // alternative to `distance`
  const uint8_t* mask = nullptr;        // non-zero: translucent; nullptr: every pixel translucent
  Matrix4 projection{};

  double distance_at(int x, int y) const;
  // Inside the image, translucent, finite distance and w > 0 (see "usable" above).
  bool usable(int x, int y) const;
};

enum class FootprintRule { central_where_smooth, one_sided };

// How one tangent was obtained.
enum class TangentSource { central, forward, backward, facing_plane };

struct PixelFootprint {
  Vec3 position;           // P, world units
  Vec3 tx, ty;             // tangents (world units per pixel)
  TangentSource x_source = TangentSource::facing_plane, y_source = TangentSource::facing_plane;
  double area = 0.0;       // |tx x ty|, world units²
  Vec3 t1, t2;             // orthonormal axes of the rectangle (t2 = 0 when area = 0)
  double a = 0.0, b = 0.0;  // side lengths along t1 and t2, world units
};

// The footprint of pixel (x, y), which must be usable (not checked beyond an assertion-free
// fallback: a non-usable pixel gets the facing-plane footprint at its distance).
PixelFootprint pixel_footprint(const SurfaceImage& image, int x, int y,
                               FootprintRule rule = FootprintRule::central_where_smooth);

// The rectangle of a footprint from its two tangents (t1, t2, a, b and area of the result).
void set_footprint_rectangle(const Vec3& tx, const Vec3& ty, PixelFootprint* footprint);

}  // namespace sss::math
