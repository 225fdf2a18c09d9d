// The accuracy regression guard: every miss value the quick benchmark wrote (miss.csv: each scene,
// footprint and method, per region and channel) against the committed baseline
// (tests/bench/miss_baseline.csv, written by scripts/update-miss-baseline.sh from the same run).
//
// A value worse than its baseline by more than the margin fails. The margin is what the numbers
// may move without a change of method: the benchmark is deterministic on one driver (llvmpipe
// gives the same bits on every run), but another driver or CPU rounds its float arithmetic its own
// way (NVIDIA moved the far head shot's relative RMSE at its 4th digit when the taps were still
// filtered bilinearly, with 8-bit weights; they are whole texels now, and half floats are rounded
// in the shaders), which moves a miss by well under 1 %. kAbsoluteMargin + kRelativeMargin · baseline
// leaves room for that and catches any change of a kernel: a tenfold regression, a weight off by
// a few per cent, a narrower or wider kernel (the note of the issue that added this shows one).
// Values better than the baseline by more than the margin pass and are listed, so the baseline can
// be brought down with them.
//
// A channel's own miss (miss_<region>_<c>) is ill conditioned where that channel needs almost no
// change: on the head's mid shot at 160×90 green holds 5.6e-5 of the needed change, and its miss
// there was 2,600 on one CPU and 2,700 on another under the same llvmpipe (a silhouette's green went
// from 1 to 4), with nothing changed but the CPU's float rounding. Such a value is guarded through
// share_<region>_<c> instead (the channel's error over the needed change of all three channels,
// tests/bench/metrics.hpp), which every run compares: a channel is compared by its own miss only
// where it holds at least kConditionedShare of the pooled needed change
// (share / miss, taken from the baseline). A pooled miss above kIllConditionedAbove (the region needs
// so little change that the result's rounding sets the ratio: the tilted-60 plane's silhouettes at
// 469) moves by a few per cent with the rounding alone, so it gets kIllConditionedMargin; a tenfold
// regression still fails.
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
// ‖input − exact‖ of a channel over the pooled one, below which its own miss is not compared (its
// share is): 0.05, so the channel holds under 0.25 % of the needed change's energy.
constexpr double kConditionedShare = 0.05;
constexpr double kIllConditionedAbove = 10.0;
constexpr double kIllConditionedMargin = 0.10;

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
  int compared = 0, better = 0, added = 0, conditioned_out = 0;
  auto column_of = [&](const std::string& name) {
    for (std::size_t i = 0; i < baseline.columns.size(); ++i) {
      if (baseline.columns[i] == name) return static_cast<int>(i);
    }
    return -1;
  };
  // For miss_<region>_<c>: the column of share_<region>_<c>; -1 for any other column.
  std::vector<int> share_column(baseline.columns.size(), -1);
  for (std::size_t i = 0; i < baseline.columns.size(); ++i) {
    const std::string& name = baseline.columns[i];
    if (name.rfind("miss_", 0) == 0 && name.size() > 2 && name[name.size() - 2] == '_') {
      share_column[i] = column_of("share_" + name.substr(5));
      EXPECT_GE(share_column[i], 0) << "no share column for " << name;
    }
  }
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
      if (std::isinf(was)) continue;  // nothing to change there; any result is as good
      if (share_column[i] >= 0 && was > 0.0) {
        const double channel_need = expected[static_cast<std::size_t>(share_column[i])] / was;  // its ‖input − exact‖ / the pooled
        if (!(channel_need >= kConditionedShare)) {
          ++conditioned_out;
          continue;
        }
      }
      ++compared;
      const double margin = kAbsoluteMargin + (was > kIllConditionedAbove ? kIllConditionedMargin : kRelativeMargin) * was;
      EXPECT_LE(now, was + margin) << where << ": " << now << " against the baseline's " << was << " (margin " << margin << ")";
      if (now < was - margin) {
        if (better++ < 20) std::printf("better than the baseline: %s %.4f (was %.4f)\n", where.c_str(), now, was);
      }
    }
  }
  for (const auto& [key, values] : current.rows) {
    if (baseline.rows.count(key) == 0 && added++ < 20) std::printf("not in the baseline (not guarded): %s\n", key.c_str());
  }
  std::printf("%d values compared (%d channel misses left to their share: the channel needs almost no change), %d better "
              "than the baseline by more than the margin, %d rows not in it\n",
              compared, conditioned_out, better, added);
  if (better > 0 || added > 0) {
    std::printf("the baseline can be updated: scripts/update-miss-baseline.sh (then commit tests/bench/miss_baseline.csv)\n");
  }
  EXPECT_GT(compared, 1000);
}

}  // namespace
