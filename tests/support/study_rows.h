// The rows of a study CSV for tests: the header checked against the still study's, each data line split into fields.
#pragma once
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "study/records/csv.h"

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

}  // namespace aliaslab::testing
