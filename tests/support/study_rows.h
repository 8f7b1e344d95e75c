// The rows of a study CSV for tests: the header checked against the still study's, each data line split into fields;
// and a study run as shards, whose CSVs a test then merges.
#pragma once
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "study/config.h"
#include "study/records/csv.h"
#include "study/sweep/sweep.h"

namespace aliaslab::testing {

inline std::vector<std::vector<std::string>> readStudyRows(const std::string& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, csvHeader()) << csv;
  std::vector<std::vector<std::string>> rows;
  while (std::getline(in, line))
    if (!line.empty()) rows.push_back(splitCsvLine(line));
  return rows;
}

/// Runs `c` as shards 0..count-1 of `count`, one after the other; returns their CSV paths in shard order.
inline std::vector<std::string> runShards(StudyConfig c, int count) {
  std::vector<std::string> shards;
  for (int i = 0; i < count; ++i) {
    c.shardIndex = i, c.shardCount = count;
    runSweep(c);
    shards.push_back(csvPath(c));
  }
  return shards;
}

}  // namespace aliaslab::testing
