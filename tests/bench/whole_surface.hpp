// The whole-surface reference (issue 49): the scattered light at a point of a mesh as the exact
// convolution over every triangle of the mesh, the surface the camera cannot see included, at 3D
// distance (Jensen and Buhler's point-based convention: M(x) = Σ_s R(|x - s|) E(s) ΔA_s, R a
// diffusion profile normalised over a plane). CPU only, no GL: the light at the samples comes from
// the caller (tests/bench/scenes/head_surface.hpp evaluates the head's with its own shader).
//
// How it integrates. Each profile term but the narrowest `analytic_terms` is summed over its own
// sampling of the surface: every triangle split into n² equal sub-triangles (n = ceil(longest edge
// / spacing)), one sample at each sub-triangle's centroid, weighted by its area, with the spacing
// `spacing_per_sigma` of the term's width, and samples beyond `cutoff_sigmas` widths ignored. The
// narrowest `analytic_terms` terms (skin: the one of variance 0.0064 mm², 0.08 mm wide, a fifth of a
// 960x540 close-up's pixel and two fifths of a 1080p one's) are integrated analytically on the
// assumption that the light is flat within their reach: they add their weight times the receiver's
// own light. Over light with no detail finer than a pixel the error of that is the term's weight
// (red 0.23) times its variance (0.04 pixel² at the 960x540 close-up, 0.17 at 1080p) times half the
// light's Laplacian; sampling it over the whole mesh instead would take seven times the samples of
// the next term (tens of gigabytes).
//
// Until issue 49's second look the two narrowest terms took flat light. The second (0.22 mm) is 0.6
// of a 960x540 close-up's pixel and 1.1 of a 1080p one's, so "flat" charged every filter, which
// rightly spreads such a term over the neighbouring pixels, with an error the reference made: blue's
// miss, whose profile lies almost all in those two terms, came out ten times its needed change and
// more. It is a sampled term now.
//
// What the convention gets wrong: it measures distance through the air, so across a slit or a thin
// part (lips, eyelids, the ear's folds, a few millimetres apart) light passes between surfaces that
// real skin would carry it around; on a flat or gently curved surface it is the diffusion model's
// answer. WholeSurfaceResult::opposite_share says where such surface is within reach.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "math/exact_reference.hpp"
#include "scenes/scene.hpp"  // SurfacePoint

namespace sss_bench {

using Point3 = std::array<double, 3>;

inline Point3 point_sub(const Point3& a, const Point3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline double point_dot(const Point3& a, const Point3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Point3 point_cross(const Point3& a, const Point3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// A triangle mesh: vertex positions (world units) at the start of each vertex's floats.
struct SurfaceMesh {
  const float* vertices = nullptr;
  std::size_t floats_per_vertex = 3;
  const std::uint32_t* indices = nullptr;  // three per triangle
  std::size_t index_count = 0;
  std::size_t triangle_count() const { return index_count / 3; }
  Point3 vertex(std::size_t triangle, int corner) const;
};

Point3 surface_position(const SurfaceMesh& mesh, const SurfacePoint& p);
// The triangle's unit geometric normal (counter-clockwise corners), zero for a degenerate one.
Point3 triangle_normal(const SurfaceMesh& mesh, std::size_t triangle);

// The centroids of each kept triangle's n² sub-triangles and their areas (world units²), n =
// max(1, ceil(longest edge / spacing)). keep: one flag per triangle, or nullptr for every triangle.
struct SurfaceSampling {
  std::vector<SurfacePoint> points;
  std::vector<double> area;
};
SurfaceSampling sample_surface(const SurfaceMesh& mesh, double spacing, const std::vector<std::uint8_t>* keep);

struct WholeSurfaceSettings {
  sss::math::GaussianProfile profile;  // each term 2D-normalised over a plane, variances in mm²
  double world_units_per_mm = 0.001;
  int analytic_terms = 1;              // the narrowest terms, taken as flat light (above)
  double spacing_per_sigma = 0.4;      // sample spacing of a term, in its standard deviations
  double cutoff_sigmas = 4.5;          // a term ignores samples beyond this many deviations
};

// The light a sampling carries: per sample, two estimates of E (RGB, albedo included, as the
// frame's colour holds it) and whether the frame sees the sample.
//   exact: the light evaluated at the sample itself;
//   pixels: for a sample the frame sees, the light the frame's pixels give there (what any filter of
//           the frame is handed: no detail finer than a pixel); else `exact`.
struct SampleLight {
  std::vector<std::array<float, 3>> exact, pixels;
  std::vector<std::uint8_t> visible;
};

// One term's samples (positions, areas, normals, light), bucketed for the sums. Built by the caller
// per term: WholeSurfaceReference::term_spacing says each term's spacing, term_cutoff its reach.
struct TermSamples {
  std::vector<Point3> position;
  std::vector<double> area;
  std::vector<Point3> normal;  // the sample's triangle's
  SampleLight light;
};

// A sampling's positions, areas and normals; its light left for the caller to fill.
TermSamples term_samples(const SurfaceMesh& mesh, const SurfaceSampling& sampling);

// A receiver: a point on the mesh (where a pixel's centre meets it) and the light there (the
// pixel's: what the analytic terms take as flat).
struct Receiver {
  Point3 position{};
  std::array<float, 3> light{};
};

struct WholeSurfaceValue {
  std::array<double, 3> exact{};    // Σ over the whole surface, exact light
  std::array<double, 3> pixels{};   // the same, the frame's light at the visible samples
  // The visible surface alone, its sum scaled to the whole surface's mass per channel: what the
  // visible surface says, the hidden surface's share filled with the visible surface's mean light.
  std::array<double, 3> visible{};
  std::array<double, 3> mass{};     // Σ R ΔA (analytic terms included): 1 on a plane
  std::array<double, 3> visible_mass{};
  // The share of the mass that comes from surface facing away from the receiver's own triangle
  // (normals more than 90 degrees apart): light across a slit or a thin part (above).
  double opposite_share = 0.0;
};

class WholeSurfaceReference {
 public:
  // Throws std::invalid_argument for an empty profile, analytic_terms outside [0, terms] or
  // non-positive spacing, cutoff or scale.
  explicit WholeSurfaceReference(WholeSurfaceSettings settings);

  std::size_t term_count() const { return settings_.profile.size(); }
  bool analytic(std::size_t term) const { return term < static_cast<std::size_t>(settings_.analytic_terms); }
  double term_width(std::size_t term) const;    // its standard deviation, world units
  double term_spacing(std::size_t term) const;  // world units
  double term_cutoff(std::size_t term) const;   // world units

  // Hands over one numerically integrated term's samples (term >= analytic_terms); buckets them.
  // Throws std::invalid_argument for an analytic term or mismatched sizes.
  void set_samples(std::size_t term, TermSamples samples);

  // The value at a receiver; `normal`: its surface's unit normal (for opposite_share). Every
  // numerical term must have its samples. Thread-safe (const).
  WholeSurfaceValue at(const Receiver& receiver, const Point3& normal) const;

 private:
  struct Buckets {
    TermSamples samples;  // sorted by cell
    double cell = 1.0;
    std::vector<std::uint64_t> keys;      // distinct cells, ascending
    std::vector<std::uint32_t> begin;     // samples of keys[k]: [begin[k], begin[k + 1])
    bool ready = false;
  };
  WholeSurfaceSettings settings_;
  std::vector<Buckets> terms_;
};

// The cell key of a point for a grid of `cell`-sized cubes (21 bits per axis, offset so that any
// scene within a few thousand cells of the origin fits).
std::uint64_t cell_key(const Point3& p, double cell);

}  // namespace sss_bench
