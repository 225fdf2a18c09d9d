// The results document's accuracy sections (issue "Error that means something"): what `miss` and
// the regions are, the footprint sweep (per footprint and per band, with its plots), and a table
// for every scene at every size and footprint with the no-scattering row first.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "results.hpp"

namespace sss_bench {

// "How errors are measured": miss, the regions, the reach, the frame edge, the references.
void write_error_definitions(std::ostream& out, const RunInfo& info);

// The footprint sweep: median interior miss per footprint, worst channel per footprint, the best
// method per band with the Pareto front marked, and the plots (linked relative to doc_path).
void write_footprint_sweep(std::ostream& out, const std::vector<ResultRow>& rows,
                           const std::vector<std::string>& footprint_plots, const std::vector<std::string>& band_plots,
                           const std::string& doc_path);

// One table per scene, size and footprint: the no-scattering row, then every method, with miss per
// region, interior miss per channel and relative RMSE (in collapsed blocks).
void write_scene_tables(std::ostream& out, const std::vector<ResultRow>& rows);

// The table header and one row in the layout every error table of the document shares; the
// head close-up's adds the interior miss against the energy-conserving reference
// (ResultRow::interior_conserving) after the interior's channels.
extern const char* const kErrorTableHeader;
extern const char* const kConservingErrorTableHeader;
void write_error_row(std::ostream& out, const ResultRow& r, bool conserving = false);

}  // namespace sss_bench
