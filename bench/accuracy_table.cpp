// Prints the accuracy table of docs/accuracy.md: every hard case of the suite in
// tests/numeric/ (the same code the tests assert on), measured against its long-double or
// exact reference. Deterministic: every case has its own seed.
//
//   build/bench/accuracy_table                          # the table on stdout
//   build/bench/accuracy_table --update docs/accuracy.md  # replace the table in the file
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <fstream>
#include <sstream>

#include "numeric/accuracy_cases.h"

using namespace lucent::accuracy;

namespace {

const char* kBegin = "<!-- accuracy-table:begin -->";
const char* kEnd = "<!-- accuracy-table:end -->";

// Replaces the text between the markers in `path` with `table`.
bool updateFile(const std::string& path, const std::string& table) {
  std::ifstream in(path);
  if (!in) return false;
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  size_t b = text.find(kBegin), e = text.find(kEnd);
  if (b == std::string::npos || e == std::string::npos || e < b) return false;
  b += std::string(kBegin).size();
  text = text.substr(0, b) + "\n" + table + "\n" + text.substr(e);
  std::ofstream out(path);
  out << text;
  return bool(out);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Lucent's accuracy table: the hard cases against exact or long-double references");
  double effort = 4.0;
  std::string update;
  app.add_option("--effort", effort, "ray counts relative to the tests' (default 4)")
      ->check(CLI::PositiveNumber);
  app.add_option("--update", update,
                 "write the table into this file between the accuracy-table markers");
  CLI11_PARSE(app, argc, argv);

  auto start = std::chrono::steady_clock::now();
  std::vector<CaseResult> results = allCases(effort);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::string table = markdownTable(results);
  fmt::print("{}\n", table);
  long wrong = 0;
  for (const CaseResult& r : results) {
    wrong += r.wrong + r.nonFinite;
    if (!r.firstProblem.empty())
      fmt::print(stderr, "{} / {}: {}\n", r.group, r.name, r.firstProblem);
  }
  fmt::print(stderr, "accuracy_table: {} cases in {:.1f} s, {} wrong or non-finite\n",
             results.size(), seconds, wrong);
  if (!update.empty() && !updateFile(update, table)) {
    fmt::print(stderr, "accuracy_table: cannot update {} (missing file or markers)\n", update);
    return 1;
  }
  return 0;
}
