// What `sss_bench --quick` wrote (ctest runs it first, as a fixture): every file there, the CSV
// with all its columns and no NaN, the JSON with the same rows, a row for every method, and
// errors that make sense (the exact filter agrees with the CPU reference; the separable filter
// beats a do-nothing copy on scenes with light to scatter).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

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
                             "time_ratio_to_copy", "relative_rmse", "max_abs_error", "p99_abs_error", "ssim"}) {
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
    EXPECT_GT(std::stod(row.at("time_ms")), 0.0);
  }
  // copy-compute: the compute yardstick, on every context with compute shaders (llvmpipe: GL 4.5).
  EXPECT_EQ(methods, (std::set<std::string>{"copy-compute", "separable", "separable-no-restore", "cross-bilateral",
                                            "cross-bilateral-no-tilt", "sum-of-gaussians", "exact-2d",
                                            "separable-in-place", "separable-adaptive", "separable-adaptive-region",
                                            "separable-masked", "separable-masked-adaptive-region",
                                            "separable-compute", "separable-compute-adaptive-region",
                                            "separable-auto-adaptive-region", "kernel-separable-jitter-33", "kernel-sum-of-gaussians-6",
                                            "kernel-sum-of-gaussians-2", "kernel-svd-1", "kernel-svd-3",
                                            "kernel-preintegrated", "kernel-guided", "kernel-artist"}));
  EXPECT_EQ(scenes.size(), 13u);
}

TEST(BenchQuickOutput, JsonMatchesCsv) {
  std::ifstream in(kDir + "/results.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_FALSE(j["run"]["renderer"].get<std::string>().empty());
  EXPECT_EQ(j["results"].size(), read_csv(kDir + "/results.csv").rows.size());
}

TEST(BenchQuickOutput, ErrorsMakeSense) {
  const Csv csv = read_csv(kDir + "/results.csv");
  for (const auto& row : csv.rows) {
    if (std::stoi(row.at("translucent_pixels")) == 0) continue;
    const double rmse = std::stod(row.at("relative_rmse"));
    if (row.at("method") == "exact-2d") {
      // The GL exact filter in fp32 against the CPU one in double (quick mode uses the CPU
      // reference): fp32 positions and sums (~6e-8 each) and the erfc fit (1.2e-7 relative) leave
      // a few 1e-7 (measured 2e-7..4e-7); 1e-5 leaves room for other drivers' exp/sqrt.
      EXPECT_LT(rmse, 1e-5) << row.at("scene");
    } else {
      EXPECT_LT(rmse, 0.5) << row.at("scene") << " " << row.at("method") << " " << row.at("taps");
    }
    const double ssim = std::stod(row.at("ssim"));
    EXPECT_GT(ssim, 0.5);
    EXPECT_LE(ssim, 1.0 + 1e-9);
  }
}

}  // namespace

// The kernel families run by the library: a pass pair per term, errors of the same order as the
// eq. (1) kernel's at the same taps on every scene (a wrong weight, term or sum would be far off),
// and on the axis-aligned shadow edge (additively separable light, supplementary Fig. S.3) the
// pre-integrated kernel closer to the exact result than eq. (1). Errors do not depend on timing.
TEST(BenchQuickOutput, KernelFamiliesRunAsPlannedAndScoreSensibly) {
  const Csv csv = read_csv(kDir + "/results.csv");
  const std::map<std::string, int> passes = {
      {"kernel-separable-jitter-33", 2}, {"kernel-sum-of-gaussians-6", 12}, {"kernel-sum-of-gaussians-2", 4},
      {"kernel-svd-1", 2},  {"kernel-svd-3", 6}, {"kernel-preintegrated", 2}, {"kernel-guided", 2},
      {"kernel-artist", 2}};
  std::map<std::string, double> separable;  // scene -> eq. (1) error at the families' tap count
  int families = 0;
  for (const auto& row : csv.rows) {
    if (row.at("method") == "separable" && row.at("taps") == "9" && row.at("follow_surface") == "1") {
      separable[row.at("scene")] = std::stod(row.at("relative_rmse"));
    }
  }
  double preintegrated_edge = -1.0;
  for (const auto& row : csv.rows) {
    const auto it = passes.find(row.at("method"));
    if (it == passes.end() || std::stoi(row.at("translucent_pixels")) == 0) continue;
    ++families;
    EXPECT_EQ(std::stoi(row.at("passes")), it->second) << row.at("method");
    const double rmse = std::stod(row.at("relative_rmse"));
    ASSERT_TRUE(separable.count(row.at("scene"))) << row.at("scene");
    EXPECT_LT(rmse, 2.0 * separable[row.at("scene")] + 0.01) << row.at("scene") << " " << row.at("method");
    if (row.at("scene") == "edge-0" && row.at("method") == "kernel-preintegrated") preintegrated_edge = rmse;
  }
  EXPECT_GE(families, 8 * 10);  // every family on every scene with translucent pixels
  ASSERT_GE(preintegrated_edge, 0.0);
  EXPECT_LT(preintegrated_edge, separable["edge-0"]);
}

// The host's region, padded by the kernel's reach, must not change the result: the adaptive filter
// with and without it scores the same on every scene (bit-identical images give identical metrics).
TEST(BenchQuickOutput, APaddedRegionChangesNothing) {
  const Csv csv = read_csv(kDir + "/results.csv");
  std::map<std::string, std::map<std::string, std::string>> rmse;  // scene -> method -> value as written
  for (const auto& row : csv.rows) {
    if (row.at("taps") != "17" || row.at("follow_surface") != "1") continue;
    rmse[row.at("scene")][row.at("method")] = row.at("relative_rmse");
  }
  int scenes = 0;
  for (const auto& [scene, methods] : rmse) {
    if (methods.count("separable-adaptive-region") == 0) continue;
    ++scenes;
    EXPECT_EQ(methods.at("separable-adaptive-region"), methods.at("separable-adaptive")) << scene;
    // The compute and masked paths give the fragment path's image (within fp16 rounding; the masked
    // one bit for bit): the same score to three significant digits, fixed taps and adaptive with
    // the region alike; so does the automatic choice, whichever path it took.
    const auto close = [&](const char* a, const char* b) {
      const double x = std::stod(methods.at(a)), y = std::stod(methods.at(b));
      EXPECT_LE(std::fabs(x - y), 1e-3 * std::max(x, 1e-3)) << scene << ": " << a << " vs " << b;
    };
    close("separable-compute", "separable-in-place");
    close("separable-masked", "separable-in-place");
    close("separable-masked-adaptive-region", "separable-adaptive-region");
    close("separable-compute-adaptive-region", "separable-adaptive-region");
    close("separable-auto-adaptive-region", "separable-adaptive-region");
  }
  EXPECT_EQ(scenes, 13);
  std::ifstream doc(kDir + "/benchmarks.md");
  const std::string text((std::istreambuf_iterator<char>(doc)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("## Skipping what a frame does not need"), std::string::npos);
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
  // the samples' linear depths beats every other resolve. On the sphere's silhouette against the
  // empty background the resolves differ by a few per cent and none wins everywhere (the measured
  // numbers are in the results document): not asserted.
  for (const char* other : {"sample-0", "min", "max"}) {
    EXPECT_LT(rmse["depth-step/average"], rmse[std::string("depth-step/") + other]) << other;
  }
  std::ifstream doc(kDir + "/benchmarks.md");
  const std::string text((std::istreambuf_iterator<char>(doc)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("## MSAA: depth resolve at silhouettes"), std::string::npos);
}
