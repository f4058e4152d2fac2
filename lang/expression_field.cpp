#include "expression_field.h"

#include "expression_functions.h"
#include "pigment_call.h"

#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace lucent {

namespace {

// One thread's compiled copy of one field.
struct ThreadParser {
  mu::Parser parser;
  double x = 0.0, y = 0.0, z = 0.0;
};

std::atomic<uint64_t> gNextFieldId{1};

class ExpressionField final : public ScalarField {
 public:
  explicit ExpressionField(FunctionText f) : f_(std::move(f)), id_(gNextFieldId.fetch_add(1)) {
    if (f_.variables.size() != 2 && f_.variables.size() != 3)
      throw std::invalid_argument("an expression field has the variables x, y, z (or u, v)");
    ThreadParser check;
    compile(check);  // throws mu::ParserError now rather than in a render thread
  }

  double value(const Vec3& p) const override {
    ThreadParser& t = local();
    t.x = p.x;
    t.y = p.y;
    t.z = p.z;
    try {
      return t.parser.Eval();
    } catch (const mu::ParserError&) {
      return std::numeric_limits<double>::quiet_NaN();
    }
  }

 private:
  void compile(ThreadParser& t) const {
    defineLanguage(t.parser, ParserRole::Plain);
    t.parser.DefineVar(f_.variables[0], &t.x);
    t.parser.DefineVar(f_.variables[1], &t.y);
    if (f_.variables.size() == 3) t.parser.DefineVar(f_.variables[2], &t.z);
    for (const auto& [name, v] : f_.constants) t.parser.DefineConst(name, v);
    definePigmentFunctions(t.parser, f_.pigments);
    t.parser.SetExpr(f_.text);
    t.parser.Eval();  // muParser compiles to its bytecode on the first evaluation
  }

  // This thread's parser for this field: the last one used is checked first (a render
  // thread mostly asks for the same field many times in a row). Fields are told apart by a
  // number never reused, so entries of fields that are gone are harmless; past a bound the
  // thread's cache is emptied and refilled on demand.
  ThreadParser& local() const {
    struct Cache {
      uint64_t lastId = 0;
      ThreadParser* last = nullptr;
      std::vector<std::pair<uint64_t, std::unique_ptr<ThreadParser>>> all;
    };
    thread_local Cache cache;
    if (cache.lastId == id_) return *cache.last;
    ThreadParser* found = nullptr;
    for (auto& [id, parser] : cache.all)
      if (id == id_) found = parser.get();
    if (!found) {
      if (cache.all.size() >= 256) cache.all.clear();
      auto parser = std::make_unique<ThreadParser>();
      compile(*parser);
      found = parser.get();
      cache.all.emplace_back(id_, std::move(parser));
    }
    cache.lastId = id_;
    cache.last = found;
    return *found;
  }

  FunctionText f_;
  uint64_t id_;
};

}  // namespace

std::shared_ptr<const ScalarField> makeExpressionField(FunctionText f) {
  return std::make_shared<ExpressionField>(std::move(f));
}

}  // namespace lucent
