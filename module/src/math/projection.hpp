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

}  // namespace sss::math
