// The token stream as the scene reader sees it (sdl/token_stream.h): tokens with every
// directive done, the parse functions, and items read through the ItemReader seam.
#include <catch2/catch.hpp>

#include "sdl/token_stream.h"

#include <memory>
#include <string>
#include <vector>

using namespace lucent::sdl;

namespace {

struct Ball : Item {
  std::array<double, 3> centre{};
  double radius = 0;
  std::string_view kind() const override { return "sphere"; }
};

// Reads `sphere { <centre>, radius }` and `object { Identifier }`, as a scene reader would.
class BallReader : public ItemReader {
 public:
  ItemPtr read(const Token& t, TokenStream& in) override {
    if (t.text() == "object") {
      in.expect("{");
      const Token& id = in.next();
      ItemPtr item = id.value() ? id.value()->item : nullptr;
      if (!item) in.error(id, "expected an object identifier, found " + id.describe());
      in.expect("}");
      return item;
    }
    if (t.text() != "sphere") return nullptr;
    auto b = std::make_shared<Ball>();
    in.expect("{");
    b->centre = in.parseVector();
    in.parseComma();
    b->radius = in.parseFloat();
    in.expect("}");
    return b;
  }
};

std::vector<const Ball*> readBalls(TokenStream& in, BallReader& reader,
                                   std::vector<ItemPtr>& keep) {
  std::vector<const Ball*> out;
  for (;;) {
    const Token& t = in.next();
    if (t.kind == TokenKind::End) break;
    ItemPtr item = reader.read(t, in);
    if (!item) in.error(t, "not an item");
    keep.push_back(item);
    out.push_back(static_cast<const Ball*>(item.get()));
  }
  return out;
}

}  // namespace

TEST_CASE("sdl token stream: a loop of items with expressions, read by an ItemReader",
          "[sdl][tokens]") {
  BallReader reader;
  TokenStream in(Options{}, &reader);
  in.openText("balls.pov",
              "#declare R = 0.5;\n"
              "#declare Big = sphere { <0, 1, 2>, R * 4 }\n"
              "#for (I, 1, 3)\n"
              "  sphere { x * I, R / I }\n"
              "#end\n"
              "object { Big }\n",
              ".");
  std::vector<ItemPtr> keep;
  auto balls = readBalls(in, reader, keep);
  REQUIRE(balls.size() == 4);
  CHECK(balls[0]->centre == std::array<double, 3>{1, 0, 0});  // x * I
  CHECK(balls[0]->radius == 0.5);
  CHECK(balls[2]->centre == std::array<double, 3>{3, 0, 0});
  CHECK(balls[2]->radius == Approx(0.5 / 3));
  CHECK(balls[3]->centre == std::array<double, 3>{0, 1, 2});
  CHECK(balls[3]->radius == 2.0);
  REQUIRE(in.lookup("Big"));
  CHECK(in.lookup("Big")->type == ValueType::Item);
  CHECK(typeName(*in.lookup("Big")) == "sphere identifier");
}

TEST_CASE("sdl token stream: next, peek and the parse functions", "[sdl][tokens]") {
  TokenStream in(Options{});
  in.openText("t.pov",
              "#declare C = rgb <1, 0.5, 0>;\n"
              "camera { 1 + 2, <1, 2, 3> * 2, C filter 0.5, concat(\"a\", \"b\") (1 < 2) }",
              ".");
  const Token& cam = in.peek();
  CHECK(cam.kind == TokenKind::Keyword);
  CHECK(cam.text() == "camera");
  CHECK(in.next().text() == "camera");
  in.expect("{");
  CHECK(in.parseFloat() == 3.0);
  in.parseComma();
  CHECK(in.parseVector() == std::array<double, 3>{2, 4, 6});
  in.parseComma();
  CHECK(in.parseColour() == std::array<double, 5>{1, 0.5, 0, 0.5, 0});
  in.parseComma();
  CHECK(in.parseString() == "ab");
  Value v = in.parseExpression();
  CHECK(v.type == ValueType::Float);
  CHECK(v.v[0] == 1.0);
  CHECK(in.allow("}"));
  CHECK(in.next().kind == TokenKind::End);
  CHECK(in.next().kind == TokenKind::End);
}

TEST_CASE("sdl token stream: errors of the scene reader are located", "[sdl][tokens]") {
  TokenStream in(Options{});
  in.openText("t.pov", "#macro Open() { #end\nbox Open() 1 ]", ".");
  CHECK(in.next().text() == "box");
  in.expect("{");
  CHECK(in.parseFloat() == 1.0);
  try {
    in.expect("}");
    FAIL("no error");
  } catch (const SdlError& e) {
    CHECK(std::string(e.what()) == "t.pov:2:14: error: expected '}', found ']'");
  }
}
