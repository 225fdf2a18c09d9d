// What the filter needs from the host's projection matrix: depth linearisation, clip w and the
// screen-space scale. One formula covers perspective (finite or infinite far, off-centre,
// reversed-Z) and orthographic matrices. Math layer: no GL.
#pragma once

#include <array>
#include <string>

namespace sss::math {

// Column-major 4x4 as GL takes it: element (row r, column c) is m[c * 4 + r].
using Matrix4 = std::array<float, 16>;

enum class ProjectionCheck { ok, invalid, unsupported };

// Checks that depth can be linearised and x/y scales read off. On failure `why` names the element.
ProjectionCheck check_projection(const Matrix4& m, std::string* why);

// View-space distance in front of the camera (-z_view) from NDC z.
// NDC z = (m10·z + m14) / (m11·z + m15)  =>  z = (m14 - zn·m15) / (zn·m11 - m10).
double distance_from_ndc_z(const Matrix4& m, double ndc_z);

// Clip-space w of a point at view distance d: m11·(-d) + m15 (d for perspective, 1 for ortho).
double clip_w_from_distance(const Matrix4& m, double distance);

// The determinant of the depth map (non-zero when depth can be linearised).
double depth_map_determinant(const Matrix4& m);

// How a projection that passes check_projection maps distances to depth (sss_get_projection_info).
struct ProjectionReading {
  bool orthographic = false;  // clip w does not change with the distance (m[11] == 0)
  bool reversed = false;      // NDC z falls as the distance grows (reversed-Z)
  bool infinite_far = false;  // the depth range's far end lies at infinity
  double near_distance = 0.0, far_distance = 0.0;  // view distances at its near and far ends
};
// `zero_to_one`: the depth range is NDC z in [0, 1] (glClipControl's GL_ZERO_TO_ONE), else [-1, 1].
ProjectionReading read_projection(const Matrix4& m, bool zero_to_one);

// The world width one pixel spans on a surface facing the camera at view distance `distance`, along
// `axis` (0: x, 1: y) of a viewport `pixels` wide along it: NDC's 2 units over the projection's scale,
// times clip w.
double world_per_pixel(const Matrix4& m, int axis, int pixels, double distance);

}  // namespace sss::math
