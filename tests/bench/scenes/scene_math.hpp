// Small double-precision vector and matrix helpers for the scenes (column-major like GL), and the
// depth conventions of scene.hpp. Internal to sss_bench_scenes.
#pragma once

#include <array>
#include <cmath>

namespace sss_bench::detail {

struct Vec3 {
  double x = 0, y = 0, z = 0;
};

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(Vec3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline double length(Vec3 a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalize(Vec3 a) { return a * (1.0 / length(a)); }

// Column-major 4x4: element (row r, column c) is m[c * 4 + r].
using Mat4 = std::array<double, 16>;

Mat4 identity();
Mat4 multiply(const Mat4& a, const Mat4& b);
// Symmetric perspective, GL clip conventions (z_ndc in [-1, 1]); fovy in radians.
Mat4 perspective(double fovy, double aspect, double near_plane, double far_plane);
Mat4 orthographic(double left, double right, double bottom, double top, double near_plane, double far_plane);
// World to view: the camera at `eye` looks at `target`, `up` roughly up.
Mat4 look_at(Vec3 eye, Vec3 target, Vec3 up);
Vec3 transform_point(const Mat4& m, Vec3 p);  // w = 1, no division

// The float matrix a scene stores and GL gets, and the same values back as doubles, so that the
// CPU scenes are computed with exactly the matrix they report.
std::array<float, 16> to_float(const Mat4& m);
Mat4 to_double(const std::array<float, 16>& m);

// GL default window depth ((z_ndc + 1) / 2) of a point at view distance d (= -z_view) for the
// projection p, rounded to float as a DEPTH_COMPONENT32F holds it.
float window_depth(const Mat4& p, double distance);

// A pinhole camera for the CPU scenes: looks down -z in view space, vertical field of view fovy,
// square pixels.
struct PinholeCamera {
  int width = 0, height = 0;
  Mat4 projection{};  // the float-rounded values (see to_float)
  // The view-space direction through the centre of pixel (column i, row j from the bottom), scaled
  // so that z = -1: a point at view distance d on that ray is direction * d.
  Vec3 ray(int i, int j) const;
  // Pixels per world unit on a plane facing the camera at view distance d.
  double pixels_per_unit(double distance) const;
};
PinholeCamera make_pinhole(int width, int height, double fovy, double near_plane, double far_plane);

}  // namespace sss_bench::detail
