// The error heat map: the frame's diffuse against the exact reference (DESIGN.md §6, reference 1:
// module/src/math/exact_reference.hpp, the surface convolution with d'Eon's full six-Gaussian skin
// profile at the scene's physical scale, CPU, double precision).
//
// The reference costs about (translucent pixels) x (pixels within the profile's 17.5 mm reach):
// a 1280x720 close-up would take minutes, so the heat map is made from a re-render of the same
// frame (same camera, same settings) at a reduced size (1/4 of each side by default): the
// lighting pass and the library run again into small targets, the reference is computed from that
// small frame's irradiance and depth, and the heat map is shown scaled up (nearest). In the
// window the reference runs on a background thread and is kept while the camera stands still; the
// comparison with the current settings is redone every frame (it is cheap).
//
// Colours: |shown - reference| (max over R, G, B, linear irradiance) / scale through the
// benchmark's error ramp (tests/bench/metrics.hpp, viridis-like: dark violet 0, yellow >= scale);
// pixels that are not translucent show the frame in dim grey.
#pragma once

#include "camera.hpp"
#include "frame_targets.hpp"
#include "image.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace demo {

// One small frame read back from its targets: what the reference needs, plus the library's output.
struct SmallFrame {
  int width = 0;
  int height = 0;
  std::vector<float> before;    // RGBA, row 0 at the bottom: the lighting pass's diffuse
  std::vector<float> after;     // RGBA: the library's output (empty when SSS is off)
  std::vector<float> distance;  // view distance (-z_view) per pixel, world units
  std::vector<uint8_t> mask;    // 1 where translucent (alpha > 0)
  std::vector<uint8_t> ids;     // the G-buffer's profile | object << 4
  // The sss_profile of each profile index (the reference convolves each profile/object byte's pixels
  // with its profile over those pixels only); empty: d'Eon's skin for every pixel, as one surface.
  std::vector<int> materials;
  std::array<float, 16> projection{};
  double world_units_per_mm = 0.001;
  // The texturing mode the library ran (an sss_texturing) and the lighting pass's albedo (RGBA): for a
  // mode other than pre-scatter the reference is A_post * (R * (before / A_post)).
  int texturing = 0;
  std::vector<float> albedo;
};

// A_post of a texturing mode for one albedo channel (the library's rule: 1/256 stands in below 1/256):
// 1 pre-scatter, A post-scatter, sqrt(A) pre-and-post.
double texturing_post_factor(int texturing, double albedo);

// A texture's level 0 read back, rows bottom-up: RGBA floats; the R8UI profile/object bytes.
std::vector<float> read_texture_rgba(GLuint texture, int width, int height);
std::vector<uint8_t> read_texture_r8ui(GLuint texture, int width, int height);

// Reads the small targets back (a current context; `sss_ran`: whether `after` holds the library's
// output; `texturing`: the mode it ran, whose albedo is read back too).
SmallFrame read_small_frame(const FrameTargets &targets, const CameraMatrices &camera, bool sss_ran,
                            double world_units_per_mm, int texturing = 0);

struct Reference {
  int width = 0;
  int height = 0;
  std::vector<double> rgb;  // row 0 at the bottom
  double seconds = 0.0;     // wall-clock time of the computation
  std::size_t translucent_pixels = 0;
  int texturing = 0;        // the frame's texturing mode it is the reference of
};

// The scene's profiles as SmallFrame::materials wants them (profile 0, the controls', as skin);
// empty for a scene of one material and one object.
std::vector<int> reference_materials(const DemoScene &scene);

// The exact reference of the frame's diffuse (no GL; any thread; uses every core), of the frame's
// texturing mode: A_post * (R * (E * A_pre)). With materials:
// per profile/object byte (skin: d'Eon's six Gaussians; a measured material: the library's Gaussian
// fit of its dipole, tests/bench/material_terms.hpp).
Reference compute_reference(const SmallFrame &frame);

struct HeatMap {
  Image image;                    // the small frame's size, rows top-down
  double relative_rmse_before = 0;  // no SSS against the reference (translucent pixels)
  double relative_rmse_after = 0;   // the library against the reference (0 when SSS is off)
  // The share of the needed change the library misses (tests/bench/metrics.hpp: 0 exact, 1 as wrong
  // as no SSS) on the interior of tests/bench/regions.hpp (translucent pixels beyond the profile's
  // reach from a silhouette or the frame edge), pooled and its worst channel; NaN when the interior
  // is empty or SSS is off.
  double miss_interior = 0;
  double miss_interior_worst_channel = 0;
  std::size_t interior_pixels = 0;
  double max_abs_error = 0;         // of what is shown
  double p99_abs_error = 0;
  bool shows_after = false;         // the map is of the library's output (else of "before")
};

// `show_after`: colour the library's output (else the unfiltered diffuse). `scale`: the error at the
// top of the ramp; `exposure`: for the grey background.
HeatMap make_heat_map(const SmallFrame &frame, const Reference &reference, bool show_after, double scale,
                      double exposure);

// The size of the small frame for a full frame of width x height: each side / factor (at least 16).
void small_frame_size(int width, int height, int factor, int *small_width, int *small_height);

}  // namespace demo
