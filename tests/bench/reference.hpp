// The reference image every method is scored against: the exact 2D surface convolution
// (module/src/math/exact_reference.hpp) of the scene's irradiance as the GPU holds it.
#pragma once

#include <string>
#include <vector>

#include "gpu_scene.hpp"
#include "scenes/scene.hpp"

namespace sss_bench {

// How well the GL exact filter agreed with the CPU one where it stood in for it.
struct ReferenceCheck {
  std::string scene;
  int width = 0, height = 0;
  int checked = 0;                       // receivers compared
  double max_relative_difference = 0.0;  // max over receivers and channels of |gl - cpu| / max(cpu, 1e-3)
};

struct Reference {
  std::vector<float> rgba;  // RGBA, alpha = the input's
  std::string source;       // "CPU exact (double)" or "GL exact (fp32)"
  int stride = 1;           // > 1: only pixels on the stride grid hold the reference (GL only)
  double gl_time_ms = 0.0;  // the GL exact filter's frame time when it made the reference
  ReferenceCheck check;
};

// CPU for images of at most `max_cpu_pixels` pixels; otherwise the GL exact filter on the
// receivers of a `stride` grid, compared with the CPU at `spot_checks` of those receivers. A scene of
// several materials (Scene::profile): the CPU at every pixel, each profile/object pair's pixels
// convolved with its own profile over its own pixels (skin: d'Eon's six Gaussians; a measured
// material: the library's Gaussian fit of its dipole, normalised), so no light crosses between them.
Reference make_reference(const Scene& scene, const GpuScene& gpu, long max_cpu_pixels, int spot_checks, int stride);

// The footprint sweep's planes (scene.footprint_mm > 0): the separable exact reference
// (math/plane_reference.hpp) in double, every pixel, with the footprint the 2D reference would
// derive from the scene's projection and depth.
Reference make_plane_reference(const Scene& scene, const GpuScene& gpu);

// The CPU exact reference (double, d'Eon's skin; a scene of one material) at every pixel of the
// rectangle x, y, width, height: RGBA like Reference::rgba, the input outside the rectangle. For
// measures that need every pixel of a patch where the GL reference holds a grid (the texturing
// bench's detail on the head).
std::vector<float> make_patch_reference(const Scene& scene, const GpuScene& gpu, int x, int y, int width, int height);

// The pixels where a reference holds values: the scene's mask, on the stride grid.
bool on_grid(int x, int y, int stride);

// The mass of the surface at each receiver: make_reference's result (the same method, receivers
// and mask, no spot checks) for a uniform irradiance of 1 in R, G and B on the scene's translucent
// pixels. 1 on a plane; on a faceted mesh (the head) a few per cent less along the triangles' edges
// and in concavities, where the surface rebuilt from depth holds less area within the profile's
// reach than a plane would: light the exact reference loses and no normalised filter can.
// Throws std::invalid_argument for a scene of several materials (its reference is per material).
Reference make_mass_reference(const Scene& scene, long max_cpu_pixels, int stride);

// The energy-conserving reference: `reference` divided by `mass` per channel at every translucent
// pixel (the receivers where both hold values), the input elsewhere; RGBA like Reference::rgba.
std::vector<float> divide_by_mass(const Reference& reference, const Reference& mass, const Scene& scene);

}  // namespace sss_bench
