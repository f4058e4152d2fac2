#include "pov_function.h"

#include "scenegraph/internal_functions.h"

#include <cctype>
#include <stdexcept>

namespace lucent {

namespace {

// Recursive descent over the contract's grammar, lowest precedence first. The text was
// checked by muParser when it was read, so a malformed one is a defect here (thrown).
class Writer {
 public:
  Writer(const std::string& t, const std::vector<std::pair<std::string, double>>& c,
         const std::function<std::string(double)>& number,
         const std::vector<std::shared_ptr<const PigmentFunction>>& pigments)
      : t_(t), c_(c), number_(number), pigments_(pigments) {}

  std::string all() {
    std::string r = ternary();
    skip();
    if (i_ != t_.size()) throw std::runtime_error("unexpected text at " + std::to_string(i_));
    return r;
  }

 private:
  void skip() {
    while (i_ < t_.size() && std::isspace(static_cast<unsigned char>(t_[i_]))) ++i_;
  }
  bool eat(const char* op) {
    skip();
    size_t n = std::char_traits<char>::length(op);
    if (t_.compare(i_, n, op) != 0) return false;
    // '<' is not '<=', '!' is not '!=', '=' alone is no operator of the language.
    if (n == 1 && i_ + 1 < t_.size() && t_[i_ + 1] == '=' &&
        (op[0] == '<' || op[0] == '>' || op[0] == '!'))
      return false;
    i_ += n;
    return true;
  }
  static std::string p(const std::string& s) { return "(" + s + ")"; }

  std::string ternary() {
    std::string c = orOp();
    if (!eat("?")) return c;
    std::string a = ternary();
    if (!eat(":")) throw std::runtime_error("':' expected");
    std::string b = ternary();
    return "select(-abs(" + c + "), " + a + ", " + b + ")";
  }
  std::string orOp() {
    std::string l = andOp();
    while (eat("||")) l = p(l + " | " + andOp());
    return l;
  }
  std::string andOp() {
    std::string l = equality();
    while (eat("&&")) l = p(l + " & " + equality());
    return l;
  }
  std::string equality() {
    std::string l = relation();
    for (;;) {
      if (eat("==")) l = p(l + " = " + relation());
      else if (eat("!=")) l = p(l + " != " + relation());
      else return l;
    }
  }
  std::string relation() {
    std::string l = additive();
    for (;;) {
      if (eat("<=")) l = p(l + " <= " + additive());
      else if (eat(">=")) l = p(l + " >= " + additive());
      else if (eat("<")) l = p(l + " < " + additive());
      else if (eat(">")) l = p(l + " > " + additive());
      else return l;
    }
  }
  std::string additive() {
    std::string l = multiplicative();
    for (;;) {
      if (eat("+")) l = p(l + " + " + multiplicative());
      else if (eat("-")) l = p(l + " - " + multiplicative());
      else return l;
    }
  }
  std::string multiplicative() {
    std::string l = unary();
    for (;;) {
      if (eat("*")) l = p(l + " * " + unary());
      else if (eat("/")) l = p(l + " / " + unary());
      else if (eat("%")) {
        std::string r = unary();
        l = p(l + " - " + r + " * floor(" + l + " / " + r + ")");  // floored, as the contract's
      } else return l;
    }
  }
  std::string unary() {
    if (eat("-")) return p("-" + unary());
    if (eat("!")) return p(unary() + " = 0");
    return power();
  }
  std::string power() {
    std::string b = primary();
    if (eat("^")) return "pow(" + b + ", " + unary() + ")";  // right-associative
    return b;
  }
  std::string primary() {
    skip();
    if (eat("(")) {
      std::string e = ternary();
      if (!eat(")")) throw std::runtime_error("')' expected");
      return p(e);
    }
    if (i_ < t_.size() && (std::isdigit(static_cast<unsigned char>(t_[i_])) || t_[i_] == '.')) {
      size_t j = i_;
      while (j < t_.size() && (std::isdigit(static_cast<unsigned char>(t_[j])) || t_[j] == '.'))
        ++j;
      if (j < t_.size() && (t_[j] == 'e' || t_[j] == 'E')) {
        size_t k = j + 1;
        if (k < t_.size() && (t_[k] == '+' || t_[k] == '-')) ++k;
        if (k < t_.size() && std::isdigit(static_cast<unsigned char>(t_[k]))) {
          j = k;
          while (j < t_.size() && std::isdigit(static_cast<unsigned char>(t_[j]))) ++j;
        }
      }
      std::string n = t_.substr(i_, j - i_);
      i_ = j;
      return number_(std::stod(n));
    }
    size_t j = i_;
    while (j < t_.size() && (std::isalnum(static_cast<unsigned char>(t_[j])) || t_[j] == '_')) ++j;
    if (j == i_) throw std::runtime_error("a value expected at " + std::to_string(i_));
    std::string name = t_.substr(i_, j - i_);
    i_ = j;
    if (!eat("(")) {
      for (const auto& [n, v] : c_)
        if (n == name) return p(number_(v));
      // The variables: x, y, z, or a parametric's u and v (POV-Ray's names for x and y).
      if (name == "x" || name == "y" || name == "z" || name == "u" || name == "v") return name;
      throw std::runtime_error("unknown name " + name);
    }
    std::vector<std::string> a, raw;  // each argument translated, and as written
    if (!eat(")")) {
      do {
        skip();
        const size_t from = i_;
        a.push_back(ternary());
        raw.push_back("(" + t_.substr(from, i_ - from) + ")");
      } while (eat(","));
      if (!eat(")")) throw std::runtime_error("')' expected");
    }
    // One of POV-Ray's internal functions (f_rounded_box...): its closed form written out,
    // so the exported scene needs no functions.inc.
    if (const InternalFunction* in = internalFunctionNamed(name)) {
      const std::string formula = internalFormula(*in, raw);
      return p(Writer(formula, c_, number_, pigments_).all());
    }
    return call(name, a);
  }

  std::string call(const std::string& f, const std::vector<std::string>& a) {
    auto args = [&] {
      std::string s;
      for (size_t k = 0; k < a.size(); ++k) s += (k ? ", " : "") + a[k];
      return s;
    };
    // A pigment function: its declaration's name (povPigmentFunctionName) and member.
    for (const auto& pf : pigments_)
      if (pf->name == f)
        // A pattern's value: the red of its grey map (in POV-Ray's single precision).
        return povPigmentFunctionName(*pf) + "(" + args() + ")." +
               std::string(pf->component == PigmentComponent::value
                               ? "red"
                               : pigmentComponentName(pf->component));
    // The same name and meaning in POV-Ray.
    for (const char* same : {"sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sqrt", "exp",
                             "ln", "abs", "floor", "ceil", "pow"})
      if (f == same) return f + "(" + args() + ")";
    if (f == "log10") return "log(" + a[0] + ")";
    if (f == "log2") return p("ln(" + a[0] + ") / ln(2)");
    if (f == "trunc") return "int(" + a[0] + ")";
    if (f == "sign") return "select(" + a[0] + ", -1, 0, 1)";
    if (f == "round")
      return "select(" + a[0] + ", -floor(0.5 - " + a[0] + "), floor(" + a[0] + " + 0.5))";
    if (f == "radians") return p(a[0] + " * " + number_(0.017453292519943295));
    if (f == "degrees") return p(a[0] + " * " + number_(57.29577951308232));
    if (f == "clamp") return "min(max(" + a[0] + ", " + a[1] + "), " + a[2] + ")";
    if (f == "mix") return p(a[0] + " + (" + a[1] + " - " + a[0] + ") * " + a[2]);
    if (f == "min" || f == "max") {  // pairwise
      std::string r = a.back();
      for (size_t k = a.size() - 1; k-- > 0;) r = f + "(" + a[k] + ", " + r + ")";
      return r;
    }
    if (f == "random") throw Unsupported{"random() has no POV-Ray function equivalent"};
    throw std::runtime_error("unknown function " + f);
  }

 public:
  struct Unsupported {
    std::string what;
  };

 private:
  const std::string& t_;
  const std::vector<std::pair<std::string, double>>& c_;
  std::function<std::string(double)> number_;
  const std::vector<std::shared_ptr<const PigmentFunction>>& pigments_;
  size_t i_ = 0;
};

}  // namespace

std::string povPigmentFunctionName(const PigmentFunction& f) {
  // A prefix keeps the name clear of POV-Ray's keywords (a Lucent name may be `wood`).
  return "LucentPigment_" + f.name;
}

std::optional<std::string> povFunctionText(
    const std::string& text, const std::vector<std::pair<std::string, double>>& constants,
    const std::function<std::string(double)>& number, std::string& problem,
    const std::vector<std::shared_ptr<const PigmentFunction>>& pigments) {
  try {
    return Writer(text, constants, number, pigments).all();
  } catch (const Writer::Unsupported& u) {
    problem = u.what;
  } catch (const std::exception& e) {
    problem = std::string("cannot translate the function: ") + e.what();
  }
  return std::nullopt;
}

}  // namespace lucent
