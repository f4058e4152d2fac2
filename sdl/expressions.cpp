// Expressions as POV-Ray 3.7 evaluates them: every value is up to five numbers, and an
// operation between values of different sizes first widens the smaller (a float is
// copied into every component, a vector padded with zeros). Precedence, loosest first:
// `?:`; `&` and `|` (one level, left to right); comparisons; `+ -`; `* /`; unary `- + !`;
// `.x`-style component access. The comparisons, `&`, `|` and `?:` are read only inside
// parentheses (POV-Ray reads a bare float or vector without them).
#include "token_stream.h"

#include <cmath>

namespace lucent::sdl {

namespace {

constexpr double kEpsilon = 1e-10;

bool truth(double f) { return std::fabs(f) > kEpsilon; }

// Widens `e` from `from` terms to `to` (nothing when it has as many already).
void promote(double* e, int& from, int to) {
  if (from >= to) return;
  if (from == 1)
    for (int i = 1; i < to; ++i) e[i] = e[0];
  else
    for (int i = from; i < to; ++i) e[i] = 0.0;
  from = to;
}

void fill(double* e, int terms, double v) {
  for (int i = 0; i < terms; ++i) e[i] = v;
}

}  // namespace

bool startsExpression(const Token& t) {
  switch (t.kind) {
    case TokenKind::Number:
      return true;
    case TokenKind::Punct:
      return t.is("(") || t.is("<") || t.is("+") || t.is("-") || t.is("!");
    case TokenKind::Keyword:
      return isFloatFunction(t.kw) || isVectorFunction(t.kw) || isColourKey(t.kw) ||
             t.kw == Kw::k_u || t.kw == Kw::k_v || t.kw == Kw::k_color || t.kw == Kw::k_colour;
    case TokenKind::Identifier: {
      const Value* v = t.value();
      return v && (v->isNumeric() || v->type == ValueType::Function ||
                   (v->type == ValueType::Spline && t.call));
    }
    default:
      return false;
  }
}

// One operand (POV-Ray's Parse_Num_Factor), then `.x`-style access.
void TokenStream::factor(Express& e, int& terms) {
  Nesting nesting(*this);
  const bool prevOk = okToDeclare_;
  okToDeclare_ = true;
  getToken();
  while (cur_.is("+")) getToken();  // a unary plus is nothing
  if (cur_.is("-") || cur_.is("!")) {
    const bool negate = cur_.is("-");
    okToDeclare_ = prevOk;
    factor(e, terms);
    for (int i = 0; i < terms; ++i) e.v[i] = negate ? -e.v[i] : (truth(e.v[i]) ? 0.0 : 1.0);
    return;
  }
  factorValue(e, terms);
  okToDeclare_ = prevOk;
  componentAccess(e, terms);
}

void TokenStream::factorValue(Express& e, int& terms) {
  switch (cur_.kind) {
    case TokenKind::Number:
      fill(e.v, terms, cur_.number());
      return;
    case TokenKind::Identifier:
      identifierFactor(e, terms);
      return;
    case TokenKind::Punct:
      if (cur_.is("(")) {
        express(e, terms);
        expect(")");
        return;
      }
      if (cur_.is("<")) {
        vectorLiteral(e, terms);
        return;
      }
      break;
    case TokenKind::Keyword:
      if (isFloatFunction(cur_.kw)) {
        fill(e.v, terms, floatFunction(cur_.kw));
        return;
      }
      if (isVectorFunction(cur_.kw)) {
        std::array<double, 3> v = vectorFunction(cur_.kw);
        if (terms < 3) terms = 3;
        for (int i = 0; i < 5; ++i) e.v[i] = i < 3 ? v[i] : 0.0;
        return;
      }
      if (cur_.kw == Kw::k_t || cur_.kw == Kw::k_u || cur_.kw == Kw::k_v) {
        const int axis = cur_.kw == Kw::k_t ? 3 : cur_.kw == Kw::k_u ? 0 : 1;
        for (double& x : e.v) x = 0;
        e.v[axis] = 1;
        terms = cur_.kw == Kw::k_t ? 4 : 2;
        return;
      }
      break;
    case TokenKind::Undeclared:
      error(cur_, "expected a numeric expression, found undeclared identifier '" +
                      std::string(cur_.text()) + "'");
    default:
      break;
  }
  error(cur_, "expected a numeric expression, found " + cur_.describe());
}

void TokenStream::identifierFactor(Express& e, int& terms) {
  const Value* v = cur_.value();
  if (v && v->type == ValueType::Spline) {
    splineCall(e, terms, *v->spline, true);
    return;
  }
  if (v && v->type == ValueType::Function && v->function->kind == FunctionValue::Kind::Spline) {
    splineCall(e, terms, *v->function->spline, false);
    return;
  }
  if (v && v->type == ValueType::Function) {
    functionCall(e, terms);
    return;
  }
  if (!v || !v->isNumeric()) {
    if (v && v->type == ValueType::Item) notEvaluated(cur_);
    error(cur_, "expected a numeric expression, found " + cur_.describe());
  }
  switch (v->type) {
    case ValueType::Float:
      fill(e.v, terms, v->v[0]);
      return;
    case ValueType::Vector:
      if (terms < 3) terms = 3;
      for (int i = 0; i < 5; ++i) e.v[i] = i < 3 ? v->v[i] : 0.0;
      return;
    default:  // uv, 4d and colour values keep their size
      terms = v->terms();
      for (int i = 0; i < 5; ++i) e.v[i] = i < terms ? v->v[i] : 0.0;
      return;
  }
}

// `<a, b [, c [, d [, e]]]>`: commas are optional, as everywhere in POV-Ray.
void TokenStream::vectorLiteral(Express& e, int& terms) {
  e.v[0] = parseFloat();
  parseComma();
  e.v[1] = parseFloat();
  parseComma();
  terms = 2;
  while (terms < 5) {
    getToken();
    unget_ = true;
    if (!startsExpression(cur_)) break;
    e.v[terms++] = parseFloat();
    if (terms < 5) parseComma();
  }
  expect(">");
}

void TokenStream::componentAccess(Express& e, int& terms) {
  getToken();
  if (!cur_.is(".")) {
    unget_ = true;
    return;
  }
  getToken();
  int i = -1;
  if (cur_.kind == TokenKind::Keyword) {
    switch (cur_.kw) {
      case Kw::k_x:
      case Kw::k_u:
      case Kw::k_red:
        i = 0;
        break;
      case Kw::k_y:
      case Kw::k_v:
      case Kw::k_green:
        i = 1;
        break;
      case Kw::k_z:
      case Kw::k_blue:
        i = 2;
        break;
      case Kw::k_t:
      case Kw::k_filter:
        i = 3;
        break;
      case Kw::k_transmit:
        i = 4;
        break;
      case Kw::k_gray:
        e.v[0] = 0.297 * e.v[0] + 0.589 * e.v[1] + 0.114 * e.v[2];  // POV-Ray's grey
        terms = 1;
        return;
      default:
        break;
    }
  }
  if (i < 0)
    error(cur_,
          "expected x, y, z, t, u, v or a colour component after '.', found " + cur_.describe());
  if (i >= terms)
    error(cur_, "'." + std::string(cur_.text()) + "' of a value of " + std::to_string(terms) +
                    " component" + (terms == 1 ? "" : "s"));
  e.v[0] = e.v[i];
  terms = 1;
}

void TokenStream::term(Express& e, int& terms) {
  factor(e, terms);
  int lt = terms;
  for (;;) {
    getToken();
    const bool mul = cur_.is("*");
    if (!mul && !cur_.is("/")) {
      unget_ = true;
      return;
    }
    const Token op = cur_;
    Express le;
    factor(le, lt);
    if (lt > terms) promote(e.v, terms, lt);
    else promote(le.v, lt, terms);
    for (int i = 0; i < terms; ++i) {
      if (mul) {
        e.v[i] *= le.v[i];
      } else if (le.v[i] == 0.0) {
        e.v[i] = HUGE_VAL;
        warning(op.loc(), "divide by zero");
      } else {
        e.v[i] /= le.v[i];
      }
    }
  }
}

void TokenStream::sum(Express& e, int& terms) {
  term(e, terms);
  int lt = terms;
  for (;;) {
    getToken();
    const bool add = cur_.is("+");
    if (!add && !cur_.is("-")) {
      unget_ = true;
      return;
    }
    Express le;
    term(le, lt);
    if (lt > terms) promote(e.v, terms, lt);
    else promote(le.v, lt, terms);
    for (int i = 0; i < terms; ++i) e.v[i] += add ? le.v[i] : -le.v[i];
  }
}

// Comparisons (of two strings too); `<=`, `=`, `>=` and `!=` within POV-Ray's 1e-10.
void TokenStream::relation(Express& e, int& terms) {
  const bool prevOk = okToDeclare_;
  okToDeclare_ = true;
  std::string lhs;
  const bool isString = stringExpression(lhs, false, false);
  okToDeclare_ = prevOk;
  if (isString) {
    getToken();
    const Token op = cur_;
    std::string rhs;
    stringExpression(rhs, false, true);
    const int c = lhs.compare(rhs);
    bool r = false;
    if (op.is("<")) r = c < 0;
    else if (op.is("<=")) r = c <= 0;
    else if (op.is("=")) r = c == 0;
    else if (op.is("!=")) r = c != 0;
    else if (op.is(">=")) r = c >= 0;
    else if (op.is(">")) r = c > 0;
    else error(op, "expected a string comparison operator, found " + op.describe());
    fill(e.v, terms, r ? 1.0 : 0.0);
    return;
  }
  sum(e, terms);
  int lt = terms;
  for (;;) {
    getToken();
    const Token op = cur_;
    if (!(op.is("<") || op.is("<=") || op.is("=") || op.is("!=") || op.is(">=") || op.is(">"))) {
      unget_ = true;
      return;
    }
    Express le;
    sum(le, lt);
    promote(e.v, terms, lt);
    for (int i = 0; i < terms; ++i) {
      const double a = e.v[i], b = le.v[i];
      bool r = false;
      if (op.is("<")) r = a < b;
      else if (op.is("<=")) r = a <= b || !truth(a - b);
      else if (op.is("=")) r = !truth(a - b);
      else if (op.is("!=")) r = truth(a - b);
      else if (op.is(">=")) r = a >= b || !truth(a - b);
      else r = a > b;
      e.v[i] = r ? 1.0 : 0.0;
    }
  }
}

void TokenStream::logical(Express& e, int& terms) {
  relation(e, terms);
  int lt = terms;
  for (;;) {
    getToken();
    const bool conj = cur_.is("&");
    if (!conj && !cur_.is("|")) {
      unget_ = true;
      return;
    }
    Express le;
    relation(le, lt);
    promote(e.v, terms, lt);
    for (int i = 0; i < terms; ++i) {
      const bool a = truth(e.v[i]), b = truth(le.v[i]);
      e.v[i] = (conj ? (a && b) : (a || b)) ? 1.0 : 0.0;
    }
  }
}

// A full expression, with `c ? a : b` (both branches are evaluated, as in POV-Ray).
void TokenStream::express(Express& e, int& terms) {
  int t1 = 1;
  logical(e, t1);
  getToken();
  if (!cur_.is("?")) {
    unget_ = true;
    promote(e.v, t1, terms);
    terms = t1;
    return;
  }
  if (t1 != 1) error(cur_, "the condition of '?:' must be a float");
  Express a, b;
  int ta = terms, tb = terms;
  express(a, ta);
  expect(":");
  express(b, tb);
  const bool c = truth(e.v[0]);
  e = c ? a : b;
  terms = c ? ta : tb;
}

int TokenStream::unknownVector(Express& e) {
  int terms = 1;
  e = Express{};
  sum(e, terms);
  return terms;
}

double TokenStream::parseFloat() {
  Express e;
  int terms = 1;
  sum(e, terms);
  if (terms > 1) error(cur_, "float expected but vector or color expression found");
  return e.v[0];
}

std::array<double, 3> TokenStream::parseVector() {
  Express e;
  int terms = 3;
  sum(e, terms);
  if (terms > 3) error(cur_, "vector expected but color expression found");
  return {e.v[0], e.v[1], e.v[2]};
}

Value TokenStream::parseExpression() {
  Express e;
  int terms = unknownVector(e);
  return Value::numeric(e.v, terms);
}

double TokenStream::floatParam() {
  expect("(");
  Express e;
  int terms = 1;
  express(e, terms);
  if (terms > 1) error(cur_, "float expected but vector or color expression found");
  expect(")");
  return e.v[0];
}

void TokenStream::floatParam2(double& a, double& b) {
  expect("(");
  a = parseFloat();
  parseComma();
  b = parseFloat();
  expect(")");
}

std::array<double, 3> TokenStream::vectorParam() {
  expect("(");
  std::array<double, 3> v = parseVector();
  expect(")");
  return v;
}

void TokenStream::vectorParam2(std::array<double, 3>& a, std::array<double, 3>& b) {
  expect("(");
  a = parseVector();
  parseComma();
  b = parseVector();
  expect(")");
}

std::array<double, 5> TokenStream::parseColour() {
  std::array<double, 5> c = colour(true);
  for (double& x : c) x = static_cast<float>(x);  // POV-Ray's colours are single precision
  return c;
}

// POV-Ray's colour: an optional `color`, then colour keys (`rgb <...>`, `red 1`,
// `filter 0.5`...) or one expression, in any order the keys allow.
std::array<double, 5> TokenStream::colour(bool expectFilterTransmit) {
  std::array<double, 5> c{};
  getToken();
  if (!(cur_.kind == TokenKind::Keyword && (cur_.kw == Kw::k_color || cur_.kw == Kw::k_colour)))
    unget_ = true;
  bool started = false;
  for (;;) {
    getToken();
    if (cur_.kind == TokenKind::Keyword && isColourKey(cur_.kw)) {
      if (!colourKey(cur_.kw, c, started)) {
        unget_ = true;
        return c;
      }
      started = true;
      continue;
    }
    if (!startsExpression(cur_) || started) {
      unget_ = true;
      return c;
    }
    const Token first = cur_;
    unget_ = true;
    Express e;
    int terms = expectFilterTransmit ? 5 : 3;
    express(e, terms);
    const Value* v = first.value();
    if (!(v && v->type == ValueType::Colour)) {
      if (expectFilterTransmit && terms != 5)
        error(first, "color expression expected but float or vector expression found");
      if (!expectFilterTransmit && (terms < 3 || terms > 5))
        error(first, "RGB color expression expected but float or vector expression found");
    }
    for (int i = 0; i < terms && i < 5; ++i) c[i] = e.v[i];
    started = true;
  }
}

// One colour key and its value. False when the key must end this colour (an `rgb` after
// the colour has started belongs to what follows).
bool TokenStream::colourKey(Kw kw, std::array<double, 5>& c, bool started) {
  auto whole = [&](int terms, const char* word) {
    if (started) return false;
    const Token at = cur_;
    Express e;
    int t = terms;
    express(e, t);
    if (t != terms) warning(at.loc(), std::string("suspicious expression after ") + word);
    for (int i = 0; i < t && i < 5; ++i) c[i] = e.v[i];
    return true;
  };
  auto srgb = [&] {
    if (assumedGamma_ <= 0)
      error(cur_, "cannot parse sRGB colors before assumed_gamma has been set");
    if (srgbWorking_) return;  // decoded from sRGB and encoded with it again
    for (int i = 0; i < 3; ++i) {
      double x = c[i];
      x = x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4);
      c[i] = assumedGamma_ == 1.0 ? x : std::pow(x, 1.0 / assumedGamma_);
    }
  };
  switch (kw) {
    case Kw::k_alpha:
    case Kw::k_filter:
      c[3] = parseFloat();
      return true;
    case Kw::k_red:
      c[0] = parseFloat();
      return true;
    case Kw::k_green:
      c[1] = parseFloat();
      return true;
    case Kw::k_blue:
      c[2] = parseFloat();
      return true;
    case Kw::k_transmit:
      c[4] = parseFloat();
      return true;
    case Kw::k_rgb:
      return whole(3, "rgb");
    case Kw::k_rgbf:
      return whole(4, "rgbf");
    case Kw::k_rgbft:
      return whole(5, "rgbft");
    case Kw::k_rgbt:
      if (!whole(4, "rgbt")) return false;
      c[4] = c[3];
      c[3] = 0;
      return true;
    case Kw::k_srgb:
    case Kw::k_srgbf:
    case Kw::k_srgbt:
    case Kw::k_srgbft: {
      if (started) return false;
      if (assumedGamma_ <= 0)
        error(cur_, "cannot parse sRGB colors before assumed_gamma has been set");
      const int terms = kw == Kw::k_srgb ? 3 : kw == Kw::k_srgbft ? 5 : 4;
      whole(terms, "srgb");
      if (kw == Kw::k_srgbt) {
        c[4] = c[3];
        c[3] = 0;
      }
      srgb();
      return true;
    }
    default:
      return true;  // `gray` does nothing here (as in POV-Ray 3.7)
  }
}

}  // namespace lucent::sdl
