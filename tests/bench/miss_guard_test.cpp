// The accuracy regression guard: every miss value the quick benchmark wrote (miss.csv: each scene,
// footprint and method, per region and channel) against the committed baseline
// (tests/bench/miss_baseline.csv, written by scripts/update-miss-baseline.sh from the same run).
//
// A value worse than its baseline by more than the margin fails. The margin is what the numbers
// may move without a change of method: the benchmark is deterministic on one driver (llvmpipe
// gives the same bits on every run), but another driver filters bilinear taps with 8-bit weights
// (NVIDIA: the far head shot's relative RMSE moved at its 4th digit) and rounds its fp16 targets
// its own way, which moves a miss by well under 1 %. kAbsoluteMargin + kRelativeMargin · baseline
// leaves room for that and catches any change of a kernel: a tenfold regression, a weight off by
// a few per cent, a narrower or wider kernel (the note of the issue that added this shows one).
// Values better than the baseline by more than the margin pass and are listed, so the baseline can
// be brought down with them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

constexpr double kAbsoluteMargin = 0.01;
constexpr double kRelativeMargin = 0.02;

struct Table {
  std::vector<std::string> columns;              // after the key columns
  std::map<std::string, std::vector<double>> rows;  // key -> values
};

constexpr int kKeyColumns = 6;  // scene, width, height, method, taps, follow_surface

Table read_table(const std::string& path) {
  Table t;
  std::ifstream in(path);
  std::string line;
  if (!std::getline(in, line)) return t;
  std::vector<std::string> header;
  {
    std::stringstream s(line);
    std::string field;
    while (std::getline(s, field, ',')) header.push_back(field);
  }
  t.columns.assign(header.begin() + kKeyColumns, header.end());
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::string field, key;
    std::vector<double> values;
    int column = 0;
    while (std::getline(s, field, ',')) {
      if (column++ < kKeyColumns) {
        key += (key.empty() ? "" : ",") + field;
      } else {
        values.push_back(std::strtod(field.c_str(), nullptr));  // "nan", "inf" parse as such
      }
    }
    t.rows[key] = values;
  }
  return t;
}

TEST(MissBaseline, NoValueIsWorseThanTheCommittedBaseline) {
  const Table baseline = read_table(SSS_MISS_BASELINE);
  const Table current = read_table(std::string(SSS_BENCH_QUICK_DIR) + "/miss.csv");
  ASSERT_FALSE(baseline.rows.empty()) << "no baseline at " << SSS_MISS_BASELINE;
  ASSERT_FALSE(current.rows.empty()) << "the quick benchmark wrote no miss.csv";
  ASSERT_EQ(baseline.columns, current.columns);
  int compared = 0, better = 0, added = 0;
  for (const auto& [key, expected] : baseline.rows) {
    const auto it = current.rows.find(key);
    if (it == current.rows.end()) {
      ADD_FAILURE() << "row missing from this run: " << key;
      continue;
    }
    ASSERT_EQ(it->second.size(), expected.size()) << key;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      const double was = expected[i], now = it->second[i];
      const std::string where = key + " " + baseline.columns[i];
      if (std::isnan(was) || std::isnan(now)) {
        // A region with no pixel: the scene's geometry, which a filter cannot change.
        EXPECT_EQ(std::isnan(was), std::isnan(now)) << where << ": " << was << " -> " << now;
        continue;
      }
      ++compared;
      if (std::isinf(was)) continue;  // nothing to change there; any result is as good
      const double margin = kAbsoluteMargin + kRelativeMargin * was;
      EXPECT_LE(now, was + margin) << where << ": " << now << " against the baseline's " << was << " (margin " << margin << ")";
      if (now < was - margin) {
        if (better++ < 20) std::printf("better than the baseline: %s %.4f (was %.4f)\n", where.c_str(), now, was);
      }
    }
  }
  for (const auto& [key, values] : current.rows) {
    if (baseline.rows.count(key) == 0 && added++ < 20) std::printf("not in the baseline (not guarded): %s\n", key.c_str());
  }
  std::printf("%d values compared, %d better than the baseline by more than the margin, %d rows not in it\n", compared,
              better, added);
  if (better > 0 || added > 0) {
    std::printf("the baseline can be updated: scripts/update-miss-baseline.sh (then commit tests/bench/miss_baseline.csv)\n");
  }
  EXPECT_GT(compared, 1000);
}

}  // namespace
