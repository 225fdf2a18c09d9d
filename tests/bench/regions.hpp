// Where an error is measured (issue "Error that means something"): every translucent pixel is in
// exactly one region, so that the shared floors of the frame border and the silhouettes do not
// hide what a method does on the surface itself.
//
//   border      the pixel's centre is nearer to the frame edge than the profile's reach
//   silhouette  not border; within the reach of a silhouette pixel: a non-translucent pixel, or a
//               translucent one whose 4-neighbour (translucent too) lies more than four pixel
//               widths nearer or farther (the surface turns more than 76 degrees away between the
//               two: a fold or an occlusion, where the screen puts far-apart surface next to each
//               other)
//   interior    every other translucent pixel: the headline
//
// The reach is the profile's (profile_reach_mm: the radius beyond which at most 1e-3 of a point's
// light lands, in every channel), in pixels at the pixel's own depth (its footprint on a plane
// facing the camera there; the smaller of its two sides). Distances are Euclidean between pixel
// centres; the frame edge is half a pixel beyond the outermost centres.
//
// Why these: the exact reference takes the surface to end at the frame edge and at a silhouette
// (light from beyond is missing, light scattered beyond is lost), while a normalised filter keeps
// that light, so both regions carry an error that no screen-space method can remove and that is
// not the method's; beyond the reach, the reference and every filter see the whole neighbourhood.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "math/exact_reference.hpp"

namespace sss_bench {

enum class Region : uint8_t { none = 0, interior = 1, silhouette = 2, border = 3, depth_edge = 4, thin = 5 };
constexpr int kRegionCount = 3;  // interior, silhouette, border: what classify_regions gives

// The tail share that defines the reach above.
constexpr double kReachTail = 1e-3;

// The share of a point's light that lands beyond r (mm) in the profile's widest-reaching channel:
// max over c of Σ_t w_t,c exp(-r² / 2 v_t) (each 2D-normalised term has exp(-r²/2v) of its mass there).
double profile_tail_share(const sss::math::GaussianProfile& profile, double r_mm);

// The smallest radius R (mm) with Σ_t w_t,c exp(-R² / 2 v_t) <= tail for every channel c: the
// share of a point's light that lands beyond R (each 2D-normalised term has exp(-R²/2v) of its mass
// there). Bisection to 1e-9 mm. Throws std::invalid_argument for tail outside (0, 1).
double profile_reach_mm(const sss::math::GaussianProfile& profile, double tail = kReachTail);

struct RegionInput {
  int width = 0, height = 0;
  const uint8_t* mask = nullptr;      // non-zero: translucent
  const float* distance = nullptr;    // view distance per pixel (world units)
  std::array<float, 16> projection{};
  double world_units_per_mm = 0.001;
  double reach_mm = 0.0;
};

// Per pixel, the smaller side (mm) of its footprint on a plane facing the camera at its depth; 0
// for non-translucent pixels.
std::vector<double> pixel_footprints_mm(const RegionInput& input);
// Their median over the translucent pixels (0 when there is none): a scene's footprint in one number.
double median_footprint_mm(const RegionInput& input);

// One Region (as uint8_t) per pixel, row 0 at the bottom. Throws std::invalid_argument on bad input.
std::vector<uint8_t> classify_regions(const RegionInput& input);

// As classify_regions, with the silhouette split where the whole-surface study (issue 49) needs it:
// silhouette (within the reach of a non-translucent pixel: the surface's outline) and depth_edge
// (otherwise within the reach of a depth step between translucent pixels: the nose over the cheek,
// eyelids, lips). Never Region::thin (the study finds thin parts on the mesh).
std::vector<uint8_t> classify_regions_with_depth_edges(const RegionInput& input);

// The selection mask of one region (1 where the pixel is in it), for metrics.hpp's functions.
std::vector<uint8_t> region_mask(const std::vector<uint8_t>& regions, Region r);

}  // namespace sss_bench
