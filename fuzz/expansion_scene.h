// The expansion fuzz target's input format: the bytes are a small program that writes a
// scene out of <repeat>, <if>, local <param>, <defs> and <use> with and without parameters
// (fuzz/fuzz_inputs.h parses it). Each byte picks the next element or value from a short
// list, so mutations stay within the scene language and reach the expansion itself: nested
// repeats with small or huge counts, ids written with ${i} (duplicates included), and
// definitions that use each other or themselves.
//
// The counts are bounded so that a valid scene stays small (a few thousand nodes): counts
// near the node limit are written only where the limit refuses them (past it, or two such
// repeats nested), since a scene that legitimately expands to 10^7 nodes takes seconds and
// gigabytes (72 s under the fuzz build's sanitizers for 10^7 empty instances); what is
// refused must be refused quickly.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

namespace lucent::fuzz {

class ExpansionSceneWriter {
 public:
  ExpansionSceneWriter(const uint8_t* data, size_t size) : data_(data), size_(size) {}

  std::string scene() {
    out_ = "<scene version=\"1\">\n<camera position=\"0 1 8\" look-at=\"0 0 0\"/>\n";
    out_ += "<light type=\"point\" position=\"4 6 4\"/>\n";
    for (int n = next() % 3; n > 0; --n) param(0);
    out_ += "<defs>\n";
    for (int d = 0, n = next() % 4; d < n; ++d) definition(d);
    out_ += "</defs>\n";
    double total = 0;
    while (pos_ < size_ && elements_ < kMaxElements && total < kTotalBudget)
      total += element(0, false);
    out_ += "</scene>\n";
    return out_;
  }

 private:
  static constexpr int kMaxDepth = 8;
  static constexpr int kMaxElements = 120;
  // Bounds on what a valid scene can make (nodes, lights, instances), so that it is quick:
  // per repeat, and for the whole scene.
  static constexpr double kRepeatBudget = 1000;
  static constexpr double kTotalBudget = 5000;
  // A count that is refused whatever the body (it is only written twice nested, see element).
  static constexpr const char* kBig = "5000";

  uint8_t next() { return pos_ < size_ ? data_[pos_++] : 0; }
  template <size_t N>
  const char* pick(const char* const (&list)[N]) {
    return list[next() % N];
  }

  void param(int depth) {
    static const char* const names[] = {"r", "n", "i", "k", "s", "pi"};
    static const char* const values[] = {"1",     "0.5",  "${i}", "${r*2}", "$r",
                                         "1 2 3", "${n}", "${k}", "${r",    "3"};
    const std::string name = pick(names);  // one pick a statement: the bytes are read in order
    out_ += indent(depth) + "<param name=\"" + name + "\" value=\"" + pick(values) + "\"/>\n";
  }

  // d0 .. d3, each a node that may use the others (and itself) with or without parameters.
  void definition(int d) {
    static const char* const kinds[] = {"group", "union", "sphere", "group"};
    std::string kind = pick(kinds);
    out_ += "<" + kind + " id=\"d" + std::to_string(d) + "\"";
    if (kind == "sphere") out_ += " radius=\"${r}\"";
    out_ += ">\n";
    if (next() % 2) out_ += "  <param name=\"r\" value=\"" + std::string(pick(kRadii)) + "\"/>\n";
    double weight = 1;
    if (kind != "sphere")
      for (int n = 1 + next() % 3; n > 0 && elements_ < kMaxElements; --n)
        weight += element(1, true);
    out_ += "</" + kind + ">\n";
    defWeights_[d] = weight;
  }

  static constexpr const char* kRadii[] = {"1",  "0.25",   "${r*0.5}", "${r}",
                                           "-1", "${1/0}", "${i+1}",   "${n}"};

  // The largest value a count written as an expression can take: parameters double at most
  // a few times on the way (r = ${r*2} through nested uses), repeat variables are below the
  // counts around them.
  double expressionMax() const {
    double m = 4;
    for (double c : counts_) m = std::max(m, c);
    return 64 * m;
  }

  // Writes one element; returns at most how many nodes, lights and instances it makes (0
  // when the scene is refused for it anyway).
  double element(int depth, bool inDefs) {
    ++elements_;
    static const char* const counts[] = {
        "0",  "1",   "2",   "3",      "${n}", "${i+1}",   "4",  "${k}",
        "-1", "1.5", "abc", "${2*r}", "10",   "10000001", kBig, "99999999999999999999"};
    static const char* const tests[] = {"1",          "0",  "${i % 2}", "${i == 0}",
                                        "${r > 0.5}", "$r", "${j}",     "yes"};
    static const char* const vars[] = {"i", "j", "k", "i", "j", "r", "pi"};
    static const char* const ids[] = {"", "", "a", "a${i}", "b${i}${j}", "d0", "${i}"};
    static const char* const refs[] = {"d0", "d1", "d2", "d3", "a", "a0", "nosuch"};
    const std::string pad = indent(depth);
    int kind = depth >= kMaxDepth ? 0 : next() % 9;
    switch (kind) {
      case 0: {
        // At the innermost repeat's variable, so that instances differ.
        out_ += pad + "<sphere radius=\"" + pick(kRadii) + "\" center=\"" +
                (vars_.empty() ? "0" : "${" + vars_.back() + "}") + " 0 0\"";
        std::string id = pick(ids);
        if (!id.empty()) out_ += " id=\"" + id + "\"";
        out_ += "/>\n";
        return 1;
      }
      case 1:
      case 2: {
        std::string name = kind == 1 ? "group" : next() % 2 ? "union" : "difference";
        std::string id = pick(ids);
        out_ += pad + "<" + name + (id.empty() ? "" : " id=\"" + id + "\"") + ">\n";
        double w = 1 + children(depth, inDefs);
        out_ += pad + "</" + name + ">\n";
        return w;
      }
      case 3:
      case 4: {
        vars_.push_back(pick(vars));
        std::string count = pick(counts);
        const bool big = count == kBig;
        // A count of 5000 is written only as the outer of two nested ones, which make more
        // than the node limit whatever else the bodies hold: the scene must be refused, and
        // at once. Other counts are cut down when the repeat would make too much.
        out_ += pad + "<repeat var=\"" + vars_.back() + "\" count=\"";
        const size_t countAt = out_.size();
        out_ += count + "\">\n";
        double max = big               ? 5000
                     : count[0] == '$' ? expressionMax()
                                       : std::max(0.0, std::atof(count.c_str()));
        if (count.size() > 9) max = 0;  // beyond the limit: refused
        counts_.push_back(max);
        if (big) ++big_;
        double body = children(depth, inDefs);
        if (big) --big_;
        if (big && big_ == 0)
          out_ += pad + "  <repeat var=\"q" + std::to_string(depth) + "\" count=\"" + kBig +
                  "\"><sphere radius=\"1\"/></repeat>\n";
        counts_.pop_back();
        vars_.pop_back();
        out_ += pad + "</repeat>\n";
        if (big || big_ > 0) return 0;
        double w = max * (1 + body);
        if (w > kRepeatBudget) {
          const std::string fit = std::to_string(static_cast<int>(kRepeatBudget / (1 + body)));
          out_.replace(countAt, count.size(), fit);
          w = std::atof(fit.c_str()) * (1 + body);
        }
        return w;
      }
      case 5: {
        out_ += pad + "<if test=\"" + pick(tests) + "\">\n";
        double w = children(depth, inDefs);
        out_ += pad + "</if>\n";
        return w;
      }
      case 6: {
        out_ += pad + "<use ref=\"" + pick(refs) + "\"/>\n";
        return 1;
      }
      case 7: {
        const std::string ref = pick(refs);
        out_ += pad + "<use ref=\"" + ref + "\">\n";
        for (int n = next() % 3; n > 0; --n) param(depth + 1);
        out_ += pad + "</use>\n";
        // The copy of a definition written before; any other (one later, itself) at most
        // what a repeat may make.
        double target = kRepeatBudget;
        if (ref.size() == 2 && ref[0] == 'd' && defWeights_[ref[1] - '0'] > 0)
          target = defWeights_[ref[1] - '0'];
        return 1 + target;
      }
      default: {
        if (depth == 0 && !inDefs && next() % 2) {
          out_ += pad + "<light type=\"point\" position=\"" +
                  (vars_.empty() ? "0" : "${" + vars_.back() + "}") + " 5 0\"/>\n";
          return 1;
        }
        param(depth);
        return 0;
      }
    }
  }

  double children(int depth, bool inDefs) {
    double w = 0;
    for (int n = next() % 4; n > 0 && elements_ < kMaxElements; --n)
      w += element(depth + 1, inDefs);
    return w;
  }

  static std::string indent(int depth) { return std::string(2 * depth, ' '); }

  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
  int elements_ = 0;
  std::vector<std::string> vars_;  // of the repeats around the element being written
  std::vector<double> counts_;     // their largest counts
  int big_ = 0;                    // how many repeats of kBig are around it
  double defWeights_[4] = {0, 0, 0, 0};
  std::string out_;
};

inline std::string expansionScene(const uint8_t* data, size_t size) {
  return ExpansionSceneWriter(data, size).scene();
}

}  // namespace lucent::fuzz
