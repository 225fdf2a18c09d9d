// What `sss_bench --quick` wrote (ctest runs it first, as a fixture): every file there, the CSV
// with all its columns and no NaN but where a region is empty, the JSON with the same rows, a row
// for every method, the footprint sweep whole, and the invariants of the error measures (the input
// misses all of the needed change, the exact filter none of it). How accurate each method is, is
// guarded value by value against a committed baseline (miss_guard_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "math/half_resolution.hpp"

namespace {

const std::string kDir = SSS_BENCH_QUICK_DIR;

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, ',')) fields.push_back(field);
  return fields;
}

struct Csv {
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
};

// The scenes scored against the energy-conserving reference too (bench_main.cpp).
bool has_conserving_score(const std::string& scene) {
  return scene == "head-close" || scene == "head-mid" || scene == "head-far" || scene == "head-grazing";
}

Csv read_csv(const std::string& path) {
  Csv csv;
  std::ifstream in(path);
  std::string line;
  if (!std::getline(in, line)) return csv;
  csv.header = split(line);
  while (std::getline(in, line)) {
    const auto fields = split(line);
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < fields.size() && i < csv.header.size(); ++i) row[csv.header[i]] = fields[i];
    EXPECT_EQ(fields.size(), csv.header.size()) << line;
    csv.rows.push_back(row);
  }
  return csv;
}

TEST(BenchQuickOutput, FilesExist) {
  for (const char* name : {"results.csv", "results.json", "results.md", "benchmarks.md"}) {
    EXPECT_TRUE(std::filesystem::exists(kDir + "/" + name)) << name;
  }
}

TEST(BenchQuickOutput, CsvHasEveryColumnAndNoNaN) {
  const Csv csv = read_csv(kDir + "/results.csv");
  for (const char* column : {"halo_energy", "scene", "width", "height", "method", "taps", "follow_surface", "passes", "time_ms",
                             "time_ratio_to_copy", "relative_rmse", "max_abs_error", "p99_abs_error", "ssim",
                             "footprint_mm", "sweep", "relative_rmse_interior", "pixels_interior", "miss_interior",
                             "miss_interior_r", "miss_interior_g", "miss_interior_b", "pixels_silhouette",
                             "miss_silhouette", "miss_silhouette_r", "miss_silhouette_g", "miss_silhouette_b",
                             "pixels_border", "miss_border", "miss_border_r", "miss_border_g", "miss_border_b",
                             "miss_interior_conserving", "miss_interior_conserving_r", "miss_interior_conserving_g",
                             "miss_interior_conserving_b"}) {
    EXPECT_NE(std::find(csv.header.begin(), csv.header.end(), column), csv.header.end()) << column;
  }
  ASSERT_FALSE(csv.rows.empty());
  std::set<std::string> methods, scenes;
  for (const auto& row : csv.rows) {
    methods.insert(row.at("method"));
    scenes.insert(row.at("scene"));
    for (const char* numeric : {"time_ms", "time_ratio_to_copy", "relative_rmse", "max_abs_error", "p99_abs_error", "ssim",
                                "halo_energy"}) {
      const double v = std::stod(row.at(numeric));
      EXPECT_TRUE(std::isfinite(v)) << numeric << " in " << row.at("scene") << " " << row.at("method");
    }
    // A miss is NaN exactly where its region holds no pixel (a plane has no silhouette, the empty
    // frame nothing at all).
    for (const char* region : {"interior", "silhouette", "border"}) {
      const bool empty = std::stoi(row.at(std::string("pixels_") + region)) == 0;
      for (const char* suffix : {"", "_r", "_g", "_b"}) {
        const double v = std::stod(row.at(std::string("miss_") + region + suffix));
        EXPECT_EQ(std::isnan(v), empty) << region << suffix << " in " << row.at("scene") << " " << row.at("method");
      }
    }
    // The conserving reference's score: the head scenes' interior, and NaN everywhere else.
    const bool conserving = has_conserving_score(row.at("scene")) && std::stoi(row.at("pixels_interior")) > 0;
    for (const char* suffix : {"", "_r", "_g", "_b"}) {
      const double v = std::stod(row.at(std::string("miss_interior_conserving") + suffix));
      EXPECT_EQ(std::isnan(v), !conserving) << "conserving" << suffix << " in " << row.at("scene") << " " << row.at("method");
    }
    if (row.at("method") != "no-scattering") {
      EXPECT_GT(std::stod(row.at("time_ms")), 0.0);
    }
  }
  // copy-compute: the compute yardstick, on every context with compute shaders (llvmpipe: GL 4.5).
  EXPECT_EQ(methods, (std::set<std::string>{"copy-compute", "separable", "separable-no-restore", "cross-bilateral",
                                            "cross-bilateral-no-tilt", "sum-of-gaussians", "exact-2d",
                                            "separable-in-place", "separable-region",
                                            "separable-one-profile", "separable-profiles",
                                            "separable-masked", "separable-masked-region", "separable-half",
                                            "separable-compute", "separable-compute-region",
                                            "separable-auto-region", "separable-in-place-post-scatter",
                                            "separable-in-place-pre-and-post-scatter",
                                            "separable-auto-region-post-scatter", "kernel-separable-jitter-33",
                                            "kernel-sum-of-gaussians-2", "kernel-svd-1", "kernel-svd-2", "kernel-svd-3",
                                            "kernel-preintegrated", "kernel-preintegrated-2", "kernel-guided",
                                            "kernel-artist", "no-scattering"}));
  EXPECT_EQ(scenes.size(), 15u + 6u);  // the canonical scenes and the footprint sweep's planes
}

TEST(BenchQuickOutput, JsonMatchesCsv) {
  std::ifstream in(kDir + "/results.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_FALSE(j["run"]["renderer"].get<std::string>().empty());
  EXPECT_EQ(j["results"].size(), read_csv(kDir + "/results.csv").rows.size());
}

// The invariants of the error measures, row by row. Every value itself is guarded against the
// committed baseline (miss_guard_test.cpp); these hold whatever the methods do.
TEST(BenchQuickOutput, ErrorsMakeSense) {
  const Csv csv = read_csv(kDir + "/results.csv");
  int inputs = 0, exact = 0;
  std::set<std::string> nothing_to_change;  // scene/width/column where the input is the reference
  for (const auto& row : csv.rows) {
    if (std::stoi(row.at("translucent_pixels")) == 0) continue;
    const double rmse = std::stod(row.at("relative_rmse"));
    const double ssim = std::stod(row.at("ssim"));
    EXPECT_LE(ssim, 1.0 + 1e-9);
    if (row.at("method") == "no-scattering") {
      // The input misses all of the needed change, in every region and channel that has pixels:
      // exactly 1, or 0 where there is nothing to change (the input already is the reference to
      // float precision: the interior of the far head at 160x90, 40 mm per pixel, where the light
      // stays inside its pixels; the green and blue of the depth step's uniform square). Then every
      // method scores 0 (left it alone) or infinity (changed it), nothing in between.
      ++inputs;
      for (const char* region : {"interior", "silhouette", "border"}) {
        if (std::stoi(row.at(std::string("pixels_") + region)) == 0) continue;
        for (const char* suffix : {"", "_r", "_g", "_b"}) {
          const std::string column = std::string("miss_") + region + suffix;
          const double miss = std::stod(row.at(column));
          EXPECT_TRUE(miss == 1.0 || miss == 0.0) << row.at("scene") << " " << row.at("width") << " " << column << ": " << miss;
          if (miss == 0.0) nothing_to_change.insert(row.at("scene") + "/" + row.at("width") + "/" + column);
        }
      }
    }
    if (row.at("method") == "exact-2d") {
      // The GL exact filter in fp32 against the CPU one in double (quick mode uses the CPU
      // reference): fp32 positions and sums (~6e-8 each) and the erfc fit (1.2e-7 relative) leave
      // a few 1e-7 (measured 2e-7..4e-7); 1e-5 leaves room for other drivers' exp/sqrt. As a miss
      // that is the same error over the needed change, which is small where little light moves:
      // measured 1.5e-5 to 1.8e-5 on the shadow edges and the head close-up, 1.4e-3 on the plane
      // turned 80 degrees and 9.5e-3 on the depth step's uniform square (its interior only loses what crosses its far edge); 0.03
      // keeps the same threefold room.
      ++exact;
      EXPECT_LT(rmse, 1e-5) << row.at("scene");
      EXPECT_LT(std::stod(row.at("miss_interior")), 0.03) << row.at("scene");
    }
  }
  EXPECT_EQ(inputs, 14 + 6 * 7);  // every scene with translucent pixels, every sweep plane at every footprint
  EXPECT_EQ(exact, 13);           // the same but head-mixed (one profile: no exact filter for several)
  // The interior of every sweep plane has something to change at every footprint.
  for (const std::string& key : nothing_to_change) EXPECT_EQ(key.rfind("plane-", 0), std::string::npos) << key;
  for (const auto& row : csv.rows) {
    for (const char* region : {"interior", "silhouette", "border"}) {
      for (const char* suffix : {"", "_r", "_g", "_b"}) {
        const std::string column = std::string("miss_") + region + suffix;
        if (nothing_to_change.count(row.at("scene") + "/" + row.at("width") + "/" + column) == 0) continue;
        const double miss = std::stod(row.at(column));
        EXPECT_TRUE(miss == 0.0 || std::isinf(miss)) << row.at("scene") << " " << row.at("method") << " " << column;
      }
    }
  }
}

// The footprint sweep: every plane at the seven default footprints (0.05 to 2 mm per pixel, log
// spaced), framed so that the interior is there and the border is the reach wide; no silhouettes
// on a plane that fills the frame.
TEST(BenchQuickOutput, FootprintSweepIsWhole) {
  const Csv csv = read_csv(kDir + "/results.csv");
  std::map<std::string, std::set<double>> footprints;
  for (const auto& row : csv.rows) {
    if (row.at("sweep") != "1") continue;
    const double f = std::stod(row.at("footprint_mm"));
    footprints[row.at("scene")].insert(f);
    EXPECT_EQ(row.at("pixels_silhouette"), "0") << row.at("scene");
    EXPECT_GE(std::stoi(row.at("pixels_interior")), 60 * 60) << row.at("scene") << " " << f;
    EXPECT_GT(std::stoi(row.at("pixels_border")), 0);
  }
  ASSERT_EQ(footprints.size(), 6u);
  // Every method of the sweep on every plane at every footprint, the kernel families included
  // (they are limited to 640x360 elsewhere; the finest sweep frames are larger).
  std::map<std::string, int> instances;  // method/taps -> scene x footprint count
  for (const auto& row : csv.rows) {
    if (row.at("sweep") == "1") ++instances[row.at("method") + "/" + row.at("taps")];
  }
  EXPECT_GE(instances.size(), 1u + 4u + 1u + 1u + 8u);  // input, 5/9/17/33 taps, sum of Gaussians, cbf, families
  for (const auto& [method, n] : instances) EXPECT_EQ(n, 6 * 7) << method;
  for (const auto& [scene, values] : footprints) {
    ASSERT_EQ(values.size(), 7u) << scene;
    EXPECT_NEAR(*values.begin(), 0.05, 1e-9) << scene;
    EXPECT_NEAR(*values.rbegin(), 2.0, 1e-9) << scene;
    double previous = 0.0;
    for (double f : values) {
      if (previous > 0.0) {
        EXPECT_NEAR(f / previous, std::pow(40.0, 1.0 / 6.0), 1e-4) << scene;
      }
      previous = f;
    }
  }
  std::ifstream doc(kDir + "/benchmarks.md");
  const std::string text((std::istreambuf_iterator<char>(doc)), std::istreambuf_iterator<char>());
  for (const char* section : {"## How errors are measured", "## Accuracy across pixel footprints", "**fine**",
                              "**coarse**", "## Every scene, size and footprint"}) {
    EXPECT_NE(text.find(section), std::string::npos) << section;
  }
  // The plots' scripts, and where gnuplot is installed (the test dependencies bring it) the PNGs.
  const bool gnuplot = std::system("command -v gnuplot >/dev/null 2>&1") == 0;
  for (const char* plot : {"footprint-median", "footprint-plane-disk", "pareto-band-fine", "pareto-band-medium",
                           "pareto-band-coarse", "pareto-head-close-160x90"}) {
    EXPECT_TRUE(std::filesystem::exists(kDir + "/" + plot + ".gp")) << plot;
    if (gnuplot) {
      EXPECT_TRUE(std::filesystem::exists(kDir + "/" + plot + ".png")) << plot;
      if (std::filesystem::exists(kDir + "/" + plot + ".png")) {
        EXPECT_GT(std::filesystem::file_size(kDir + "/" + plot + ".png"), 10000u) << plot;
      }
    }
  }
}

}  // namespace

// The kernel families run by the library: the inputs draw, a pass pair per term and the copy of the
// culled pixels into the output (the library's draws), errors of the same order as the
// eq. (1) kernel's at the same taps on every scene (a wrong weight, term or sum would be far off),
// and on the axis-aligned shadow edge (additively separable light, supplementary Fig. S.3) the
// pre-integrated kernel closer to the exact result than eq. (1). Errors do not depend on timing.
TEST(BenchQuickOutput, KernelFamiliesRunAsPlannedAndScoreSensibly) {
  const Csv csv = read_csv(kDir + "/results.csv");
  const std::map<std::string, int> passes = {
      {"kernel-separable-jitter-33", 4}, {"sum-of-gaussians", 14}, {"kernel-sum-of-gaussians-2", 6},
      {"kernel-svd-1", 4},  {"kernel-svd-2", 6}, {"kernel-svd-3", 8}, {"kernel-preintegrated", 4},
      {"kernel-preintegrated-2", 6}, {"kernel-guided", 4}, {"kernel-artist", 4}};
  std::map<std::string, double> separable;  // scene -> eq. (1) error at the families' tap count
  int families = 0;
  for (const auto& row : csv.rows) {
    if (row.at("sweep") == "1") continue;  // one row per scene name: the canonical scenes' only
    if (row.at("method") == "separable" && row.at("taps") == "9" && row.at("follow_surface") == "1") {
      separable[row.at("scene")] = std::stod(row.at("relative_rmse"));
    }
  }
  double preintegrated_edge = -1.0;
  for (const auto& row : csv.rows) {
    const auto it = passes.find(row.at("method"));
    if (it == passes.end() || std::stoi(row.at("translucent_pixels")) == 0 || row.at("sweep") == "1") continue;
    ++families;
    EXPECT_EQ(std::stoi(row.at("passes")), it->second) << row.at("method");
    const double rmse = std::stod(row.at("relative_rmse"));
    ASSERT_TRUE(separable.count(row.at("scene"))) << row.at("scene");
    EXPECT_LT(rmse, 2.0 * separable[row.at("scene")] + 0.01) << row.at("scene") << " " << row.at("method");
    if (row.at("scene") == "edge-0" && row.at("method") == "kernel-preintegrated") preintegrated_edge = rmse;
  }
  EXPECT_GE(families, 9 * 10);  // every family (and the six-term baseline) on every scene with translucent pixels
  ASSERT_GE(preintegrated_edge, 0.0);
  EXPECT_LT(preintegrated_edge, separable["edge-0"]);
}

// The host's region, padded by the kernel's reach, must not change the result: the filter with and
// without it scores the same on every scene (bit-identical images give identical metrics).
TEST(BenchQuickOutput, APaddedRegionChangesNothing) {
  const Csv csv = read_csv(kDir + "/results.csv");
  std::map<std::string, std::map<std::string, std::string>> rmse;  // scene -> method -> value as written
  for (const auto& row : csv.rows) {
    if (row.at("taps") != "17" || row.at("follow_surface") != "1" || row.at("sweep") == "1") continue;
    rmse[row.at("scene")][row.at("method")] = row.at("relative_rmse");
  }
  int scenes = 0;
  for (const auto& [scene, methods] : rmse) {
    if (methods.count("separable-region") == 0) continue;
    ++scenes;
    EXPECT_EQ(methods.at("separable-region"), methods.at("separable-in-place")) << scene;
    // The compute and masked paths give the fragment path's image (within fp16 rounding; the masked
    // one bit for bit): the same score to three significant digits, with and without the region;
    // so does the automatic choice, whichever path it took.
    const auto close = [&](const char* a, const char* b) {
      const double x = std::stod(methods.at(a)), y = std::stod(methods.at(b));
      EXPECT_LE(std::fabs(x - y), 1e-3 * std::max(x, 1e-3)) << scene << ": " << a << " vs " << b;
    };
    close("separable-compute", "separable-in-place");
    close("separable-masked", "separable-in-place");
    close("separable-masked-region", "separable-region");
    close("separable-compute-region", "separable-region");
    close("separable-auto-region", "separable-region");
    // A texturing mode over a constant albedo of 0.5: post-scatter divides and multiplies exactly, so
    // it gives pre-scatter's image. Pre- and post-scatter divides by √0.5, and the quotient is rounded
    // to half (the inputs draw) and so is the product: each value moves by at most a half step of
    // 2^-11 relative, and so can the relative RMSE.
    close("separable-in-place-post-scatter", "separable-in-place");
    close("separable-auto-region-post-scatter", "separable-region");
    const double both = std::stod(methods.at("separable-in-place-pre-and-post-scatter"));
    EXPECT_LE(std::fabs(both - std::stod(methods.at("separable-in-place"))), std::ldexp(1.0, -11)) << scene;
  }
  // The half-resolution path keeps its interior miss within the stated margin of the full-size
  // passes' on every canonical scene (issue 24: what lets the automatic path pick it).
  std::map<std::string, std::map<std::string, double>> miss;  // scene -> method -> interior miss
  for (const auto& row : csv.rows) {
    if (row.at("taps") != "17" || row.at("follow_surface") != "1" || row.at("sweep") == "1") continue;
    miss[row.at("scene")][row.at("method")] = std::stod(row.at("miss_interior"));
  }
  for (const auto& [scene, methods] : miss) {
    if (methods.count("separable-half") == 0 || std::isnan(methods.at("separable-half"))) continue;
    EXPECT_LE(methods.at("separable-half"), methods.at("separable-in-place") + sss::math::kHalfResolutionMissMargin) << scene;
  }
  EXPECT_EQ(scenes, 15);
  std::ifstream doc(kDir + "/benchmarks.md");
  const std::string text((std::istreambuf_iterator<char>(doc)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("## Skipping what a frame does not need"), std::string::npos);
}

// Per-pixel profiles (issue 23): on a scene of one material (every pixel profile 0 of one object)
// the selection costs no accuracy, the same score as one profile; on head-mixed (skin, marble and
// wax) they come nearer the per-material reference than skin everywhere does.
TEST(BenchQuickOutput, PerPixelProfilesCostNoAccuracyAndHelpTheMixedScene) {
  const Csv csv = read_csv(kDir + "/results.csv");
  std::map<std::string, std::map<std::string, double>> rmse, miss;  // scene -> method -> value
  for (const auto& row : csv.rows) {
    if (row.at("sweep") == "1") continue;
    rmse[row.at("scene")][row.at("method")] = std::stod(row.at("relative_rmse"));
    miss[row.at("scene")][row.at("method")] = std::stod(row.at("miss_interior"));
  }
  int scenes = 0;
  for (const auto& [scene, methods] : rmse) {
    if (scene == "head-mixed" || methods.count("separable-profiles") == 0) continue;
    ++scenes;
    const double one = methods.at("separable-one-profile"), many = methods.at("separable-profiles");
    EXPECT_LE(std::fabs(one - many), 1e-3 * std::max(one, 1e-3)) << scene;
  }
  EXPECT_EQ(scenes, 14);
  ASSERT_TRUE(miss.count("head-mixed"));
  const auto& mixed = miss.at("head-mixed");
  EXPECT_LT(mixed.at("separable-profiles"), mixed.at("separable-one-profile") - 0.05);
  std::ifstream doc(kDir + "/benchmarks.md");
  const std::string text((std::istreambuf_iterator<char>(doc)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("## Several materials in one pass pair"), std::string::npos);
}

// The head scenes' second score, against the exact result over the mass a uniform irradiance gets
// back (the faceted mesh loses light there that no normalised filter can): the input misses all of
// the needed change against it too (or none, where nothing changes), the GL exact filter (the
// reference's light loss itself) a visible part of it, and at the close-up and the grazing shot,
// whose interiors have edges and folds to lose light at, the library's filters (normalised) come
// nearer to it than to the exact result. The mass map of the close-up and the grazing shot's
// pictures are there.
TEST(BenchQuickOutput, HeadScenesScoreAgainstTheConservingReference) {
  const Csv csv = read_csv(kDir + "/results.csv");
  std::map<std::string, std::map<std::string, std::pair<double, double>>> miss;  // scene -> method -> (exact, conserving)
  for (const auto& row : csv.rows) {
    if (!has_conserving_score(row.at("scene"))) continue;
    const std::string method = row.at("method") + "/" + row.at("taps") + "/" + row.at("follow_surface");
    miss[row.at("scene")][method] = {std::stod(row.at("miss_interior")), std::stod(row.at("miss_interior_conserving"))};
    if (row.at("method") == "no-scattering") {
      for (const char* suffix : {"", "_r", "_g", "_b"}) {
        const double v = std::stod(row.at(std::string("miss_interior_conserving") + suffix));
        EXPECT_TRUE(v == 1.0 || v == 0.0) << row.at("scene") << suffix << ": " << v;
      }
    }
  }
  ASSERT_EQ(miss.size(), 4u);
  for (const char* scene : {"head-close", "head-grazing"}) {
    const auto& m = miss.at(scene);
    EXPECT_GT(m.at("exact-2d/0/0").second, 0.05) << scene;
    for (const char* method : {"separable/17/1", "sum-of-gaussians/17/1"}) {
      EXPECT_LT(m.at(method).second, m.at(method).first) << scene << " " << method;
    }
  }
  for (const char* picture : {"head-close-160x90-mass.png", "head-grazing-160x90-input.png",
                              "head-grazing-160x90-reference.png", "head-grazing-160x90-separable-17-follow-error.png"}) {
    EXPECT_TRUE(std::filesystem::exists(kDir + "/" + picture)) << picture;
  }
  std::ifstream doc(kDir + "/benchmarks.md");
  const std::string text((std::istreambuf_iterator<char>(doc)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("miss interior, conserving reference"), std::string::npos);
  EXPECT_NE(text.find("head-close-160x90-mass.png"), std::string::npos);
}

// The depth step: the background is bright and behind; the cross-bilateral mode must leak less light
// across the silhouette than the separable filter without a depth test, and no more than with it.
TEST(BenchQuickOutput, CrossBilateralLeaksLeastAtTheDepthStep) {
  const Csv csv = read_csv(kDir + "/results.csv");
  double follow = -1.0, none = -1.0, cbf = -1.0;
  for (const auto& row : csv.rows) {
    if (row.at("scene") != "depth-step") continue;
    const double halo = std::stod(row.at("halo_energy"));
    if (row.at("method") == "separable" && row.at("taps") == "17") (row.at("follow_surface") == "1" ? follow : none) = halo;
    if (row.at("method") == "cross-bilateral") cbf = halo;
  }
  ASSERT_GE(follow, 0.0);
  ASSERT_GE(none, 0.0);
  ASSERT_GE(cbf, 0.0);
  EXPECT_LT(cbf, none);
  EXPECT_LE(cbf, follow + 1e-6);
}

// The MSAA study: every scene x depth resolve, finite numbers, silhouettes found, the pictures,
// and the properties that hold whatever the timing: multisampling beats the aliased single-sample
// filter at the silhouettes (error and fringe pixels), and on the depth step averaged depth beats
// sample 0, min and max.
TEST(BenchQuickOutput, MsaaStudy) {
  const Csv csv = read_csv(kDir + "/msaa.csv");
  ASSERT_EQ(csv.rows.size(), 10u);  // sphere, depth-step x {average, sample-0, min, max, single-sample}
  std::map<std::string, double> rmse;
  std::map<std::string, int> fringe;
  for (const auto& row : csv.rows) {
    for (const auto& [key, value] : row) EXPECT_EQ(value.find("nan"), std::string::npos) << key;
    EXPECT_GT(std::stoi(row.at("silhouette_pixels")), 0) << row.at("scene");
    rmse[row.at("scene") + "/" + row.at("variant")] = std::stod(row.at("silhouette_relative_rmse"));
    fringe[row.at("scene") + "/" + row.at("variant")] = std::stoi(row.at("fringe_pixels"));
    if (row.at("variant") == "average") {
      EXPECT_TRUE(std::filesystem::exists(kDir + "/" + row.at("picture"))) << row.at("picture");
      const double share = std::stod(row.at("resolve_share"));
      EXPECT_GE(share, 0.0);
      EXPECT_LE(share, 1.0);
    }
  }
  for (const char* scene : {"sphere", "depth-step"}) {
    const std::string s(scene);
    EXPECT_LT(rmse[s + "/average"], rmse[s + "/single-sample"]) << scene;
    EXPECT_LT(fringe[s + "/average"], fringe[s + "/single-sample"]) << scene;
  }
  // Where translucent surfaces at two depths share pixels (the depth step), the paper's average of
  // the samples' linear depths is no worse than any other resolve and better than the first
  // sample's (with whole-pixel taps the farthest sample's ties it: either depth puts the far side
  // past the follow-surface reach). On the sphere's silhouette against the empty background the
  // resolves differ by a few per cent and none wins everywhere (the measured numbers are in the
  // results document): not asserted.
  for (const char* other : {"sample-0", "min", "max"}) {
    EXPECT_LE(rmse["depth-step/average"], rmse[std::string("depth-step/") + other]) << other;
  }
  EXPECT_LT(rmse["depth-step/average"], rmse["depth-step/sample-0"]);
  std::ifstream doc(kDir + "/benchmarks.md");
  const std::string text((std::istreambuf_iterator<char>(doc)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("## MSAA: depth resolve at silhouettes"), std::string::npos);
}
