// The POV-Ray reference tables of tests/data/patterns (made by make_references.sh): CSV
// files whose first column may name a case and whose other columns are numbers.
#pragma once

#include <catch2/catch.hpp>

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>
#include "../support/paths.h"

namespace lucent::test {

struct ReferenceRow {
  std::string name;            // the case, empty for a table without one
  std::vector<double> values;  // the other columns
};

inline std::string referencePath(const std::string& file) {
  return std::string(lucentSourceDir()) + "/tests/data/patterns/" + file;
}

// Reads `file`; with `named`, the first column is the case name.
inline std::vector<ReferenceRow> readReference(const std::string& file, bool named) {
  std::ifstream in(referencePath(file));
  REQUIRE(in.good());
  std::vector<ReferenceRow> rows;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::stringstream fields(line);
    std::string field;
    ReferenceRow row;
    bool first = true;
    while (std::getline(fields, field, ',')) {
      if (first && named) row.name = field;
      else row.values.push_back(std::stod(field));
      first = false;
    }
    rows.push_back(row);
  }
  REQUIRE(!rows.empty());
  return rows;
}

// The rows of a named table grouped by case, in file order.
inline std::map<std::string, std::vector<ReferenceRow>> referenceCases(const std::string& file) {
  std::map<std::string, std::vector<ReferenceRow>> cases;
  for (ReferenceRow& r : readReference(file, true)) cases[r.name].push_back(std::move(r));
  return cases;
}

// The CSVs give points as integers k with the point at k/4096 (exact).
inline double fromGrid(double k) { return k / 4096.0; }

}  // namespace lucent::test
