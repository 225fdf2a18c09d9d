// How much of an image's fine detail survives a texturing mode (sss_bench_texturing, issue 48): the
// power an image holds above a frequency measured on the surface, in cycles per surface millimetre.
//
// The measure is spectral: the output's power above 1 cycle per millimetre over the input's,
// beside the exact answer's. On a plane (facing or turned) every pixel maps to the surface by one
// affine map, so that power is read off the image's 2D spectrum. On the head the map changes from
// pixel to pixel and no single spectrum exists: there a high-pass of the same scale stands in (each
// pixel minus its mean over a box one millimetre wide at the pixel's own footprint).
#pragma once

#include <cstdint>
#include <vector>

#include "math/plane_reference.hpp"
#include "metrics.hpp"

namespace sss_bench {

using sss::math::PixelRegion;  // a rectangle of pixels (math/exact_reference.hpp)

// The bounding box of the selected pixels of a width-wide mask (empty box when none is selected).
PixelRegion bounding_box(const std::vector<uint8_t>& selected, int width, int height);

// The surface frequency (cycles per mm) of the pixel frequency (fx, fy) (cycles per pixel) on a plane
// of `footprint`: the pixels map to the surface by u = a·x + c·y, v = b·y, so a wave of pixel
// frequency f has surface frequency J^-T f, J = [[a, c], [0, b]].
double surface_frequency_per_mm(const sss::math::TurnedPlaneFootprint& footprint, double fx, double fy);

// Whether the pixels of `box` hold any frequency above `cutoff_per_mm` on the plane: false when the
// pixels are too coarse for it (at a facing footprint above √2 / (2 · cutoff), 0.71 mm for 1 cycle/mm,
// even the diagonal's Nyquist frequency lies below the cutoff).
bool resolves_above(const PixelRegion& box, const sss::math::TurnedPlaneFootprint& footprint, double cutoff_per_mm);

// The power of `image` above `cutoff_per_mm` on the plane over `box`, summed over R, G and B: each
// channel's mean over the box removed, a Hann window across the box (so the box's borders add no
// frequencies of their own), the 2D discrete Fourier transform (Eigen's FFT along rows, then
// columns), and the squared magnitudes of the frequencies whose surface frequency exceeds the cutoff.
// The same box and window on two images make the ratio of their results a ratio of band powers.
double power_above(const RgbImage& image, const PixelRegion& box, const sss::math::TurnedPlaneFootprint& footprint,
                   double cutoff_per_mm);

// The head's stand-in: Σ over the `selected` pixels and R, G, B of (value − mean over a box of
// `box_mm` surface millimetres at the pixel's footprint `mm_per_pixel[i]`, clipped to the
// `support` pixels)². A box of width w passes little below 1 / w cycles per millimetre.
double box_high_pass_power(const RgbImage& image, const std::vector<uint8_t>& selected,
                           const std::vector<uint8_t>& support, const std::vector<float>& mm_per_pixel, double box_mm);

}  // namespace sss_bench
