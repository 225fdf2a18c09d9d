// What sss_whole_surface (whole_surface_study.cpp) writes: its rows as a Markdown document with
// the heat maps, and as CSV.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "metrics.hpp"
#include "regions.hpp"

namespace sss_bench {

// The regions a row is scored on, in the tables' order (whole_surface_study.cpp says what each is).
constexpr std::size_t kRegionSlots = 5;
constexpr Region kWholeSurfaceRegions[kRegionSlots] = {Region::interior, Region::silhouette, Region::depth_edge,
                                                       Region::thin, Region::border};
constexpr const char* kWholeSurfaceRegionNames[kRegionSlots] = {"interior", "silhouette", "depth edge", "thin",
                                                                "border"};

struct WholeSurfaceRow {
  std::string shot, method;
  // Against the pixel-consistent answer, the exact-light one, and the pixel-consistent one divided by
  // its mass per channel (energy-conserving: what a normalised filter can reach on a faceted mesh).
  std::array<Miss, kRegionSlots> pixels, exact, conserving;
  std::array<int, kRegionSlots> receivers{};
};

struct WholeSurfacePicture {
  std::string file, caption;  // file: relative to the pictures' folder
};

struct WholeSurfaceShot {
  std::string shot;
  std::size_t receivers = 0, samples = 0, visible_samples = 0;
  double render_seconds = 0, reference_seconds = 0;
  std::vector<WholeSurfacePicture> pictures;
};

struct WholeSurfaceDocument {
  std::string path, pictures, command_line, renderer;
  int width = 0, height = 0, stride = 1;
  int analytic_terms = 1;  // WholeSurfaceSettings: how many of the narrowest terms the tangent plane gives
  double seconds = 0;
  std::string checks;  // --check's findings, Markdown lines; empty without --check
};

void write_whole_surface_document(const WholeSurfaceDocument& doc, const std::vector<WholeSurfaceRow>& rows,
                                  const std::vector<WholeSurfaceShot>& shots);
void write_whole_surface_csv(const std::string& path, const std::vector<WholeSurfaceRow>& rows);

// Letters and digits of `s`, every other run of characters one '-': a file name.
std::string file_slug(const std::string& s);

}  // namespace sss_bench
