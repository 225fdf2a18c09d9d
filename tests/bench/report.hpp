// The results document (docs/benchmarks.md): how it was measured, how errors are measured and the
// footprint sweep (accuracy_report.hpp), the head close-up table the issue asks for, the comparison with the paper's Table 2 and Figure 5, Pareto plots, heat maps,
// the reference's own check, and every row.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "metrics.hpp"
#include "reference.hpp"
#include "results.hpp"

namespace sss_bench {

// Pictures (tone-mapped result and error heat map) are written for a few scenes at the run's
// smallest size, and for the configurations the document shows.
bool is_pictured_scene(const std::string& scene, int width, const std::vector<std::pair<int, int>>& sizes);
bool is_pictured_method(const ResultRow& row);
// "head-close-160x90-separable-17-follow": the file stem of a row's pictures.
std::string picture_stem(const ResultRow& row);

void write_results_document(const std::string& path, const std::string& out_dir, const RunInfo& info,
                            const std::vector<ResultRow>& rows, const std::vector<ReferenceCheck>& checks,
                            const std::vector<std::string>& plots, const std::vector<std::string>& footprint_plots,
                            const std::vector<std::string>& band_plots);

}  // namespace sss_bench
