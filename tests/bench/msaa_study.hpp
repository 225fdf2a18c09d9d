// The MSAA study (issue 7): the sphere and depth-step scenes rendered with 4 samples per pixel
// (an ordered 2x2 grid: the scene made at twice the size), filtered by the library's MSAA path with
// each depth resolve, scored at the silhouettes against a 4x supersampled exact reference (the
// exact 2D filter at twice the size, box-downsampled), with a count of fringe pixels, a zoomed
// picture of an edge, and the cost of the resolve as a share of the total.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "method.hpp"
#include "options.hpp"
#include "timing.hpp"

namespace sss_bench {

struct MsaaRow {
  std::string scene;
  int width = 0, height = 0;  // the filtered (multisampled) size; the reference is made at 2x
  std::string variant;        // "average", "sample-0", "min", "max" (MSAA path), "single-sample"
  int silhouette_pixels = 0;  // pixels whose samples differ in coverage, and their neighbours
  double silhouette_relative_rmse = 0.0, silhouette_max_abs = 0.0;
  int fringe_pixels = 0;      // silhouette pixels with an error above fringe_threshold
  double fringe_threshold = 0.0;
  double interior_relative_rmse = 0.0;  // vs the single-sample result, pixels whose samples agree
  double time_ms = 0.0;                 // the whole sss_apply_frame (output texture)
  double resolve_share = 0.0;           // (MSAA path - single-sample path) / MSAA path, average row only
  double write_back_ms = 0.0;           // the whole frame written back in place, average row only
  std::string picture;                  // zoomed edge PNG (file name in the out folder), average row only ("-" in CSV)
};

std::vector<MsaaRow> run_msaa_study(const Options& options, const GlLoader& loader, Clock clock);
void write_msaa_csv(const std::string& path, const std::vector<MsaaRow>& rows);
// The Markdown section for the results document; `picture_prefix` leads the PNG names in links
// (the out folder relative to the document).
void write_msaa_section(std::ostream& out, const std::vector<MsaaRow>& rows, const std::string& picture_prefix);

}  // namespace sss_bench
