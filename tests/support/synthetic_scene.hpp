// Deterministic synthetic inputs for the filter: colour (alpha = strength), view distance, the
// matching hardware depth for a projection, and a stencil mask.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "math/projection.hpp"

namespace sss_test {

struct SyntheticScene {
  int width = 0, height = 0;
  std::vector<float> color;         // RGBA, row 0 at the bottom
  std::vector<float> distance;      // view distance (-z_view) per pixel
  std::vector<float> window_depth;  // hardware depth in [0, 1] (GL's default depth convention)
  std::vector<uint8_t> stencil;     // 1 where translucent
  sss::math::Matrix4 projection{};
};

sss::math::Matrix4 perspective_matrix(float fovy_degrees, float aspect, float near_plane, float far_plane);
sss::math::Matrix4 orthographic_matrix(float half_width, float half_height, float near_plane, float far_plane);

// A tilted plane with a nearer box over one quadrant (a depth step) and a spherical bump; colour is
// smooth gradients plus seeded noise; alpha is 1 on most pixels, 0.5 in a band and 0 in a corner;
// the stencil excludes the right quarter.
SyntheticScene make_relief_scene(int width, int height, unsigned seed, const sss::math::Matrix4& projection);

// A plane filling the frame, its normal turned `turn_degrees` away from the view about the axis in
// the screen plane at `axis_degrees` from screen x, through the point `distance` metres in front of
// the camera at the image centre; seen through `projection` (orthographic or perspective). Its
// light, in surface millimetres about that point: a shadow edge along the turn's axis (1.0 on one
// side, 0.05 on the other, so the light changes along the turned, foreshortened direction) times a
// per-pixel albedo in [0.4, 1) from `seed`. Alpha 1 everywhere; every pixel translucent. Scene units
// are metres (a millimetre is 0.001). The exact distance of each pixel's ray, in double, goes to
// `distance_f64` when given (an exact reference needs depth without float rounding).
SyntheticScene make_turned_plane_scene(int width, int height, double turn_degrees, double axis_degrees,
                                       double distance, const sss::math::Matrix4& projection, unsigned seed,
                                       std::vector<double>* distance_f64 = nullptr);

// Uniform colour and alpha on a plane facing the camera at `distance`.
SyntheticScene make_flat_scene(int width, int height, std::array<float, 4> rgba, float distance,
                               const sss::math::Matrix4& projection);

// Fills window_depth from distance for scene.projection.
void compute_window_depth(SyntheticScene* scene);

}  // namespace sss_test

namespace sss_test {

// Scenes for the MSAA path: a scene made at twice the size is the 4-sample version of the one at
// the normal size (sample i of pixel (x, y) is texel (2x + i % 2, 2y + i / 2), an ordered 2x2 grid).
// The single-sample equivalent of such a scene: colour and alpha box-averaged, view distance
// averaged (the paper's resolve), hardware depth recomputed from it, stencil of sample 0.
SyntheticScene downsample_2x2(const SyntheticScene& fine);
// Every pixel repeated into a 2x2 block: a multisampled scene whose samples all equal the pixel.
SyntheticScene upsample_2x2(const SyntheticScene& coarse);

}  // namespace sss_test
