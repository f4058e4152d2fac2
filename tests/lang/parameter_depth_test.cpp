// Parameters resolve one another recursively when first used: a long chain of them is an
// error at the parameter where it gets too deep, never a stack overflow.
#include "lang/parser.h"

#include <catch2/catch.hpp>

#include <string>

using namespace lucent;

namespace {
std::string chain(int n) {
  std::string xml = "<scene version=\"1\"><camera/>\n";
  for (int i = 0; i < n; ++i)
    xml += "<param name=\"p" + std::to_string(i) + "\" value=\"${p" + std::to_string(i + 1) +
           "}\"/>\n";
  xml += "<param name=\"p" + std::to_string(n) +
         "\" value=\"3\"/>\n<sphere radius=\"${p0*0.5}\"/></scene>\n";
  return xml;
}
}  // namespace

TEST_CASE("a chain of parameters resolves up to its limit and is refused beyond it",
          "[lang][parameters]") {
  ParseResult ok = parseSceneString(chain(900), "chain.xml");
  REQUIRE(ok.scene);
  CHECK(std::get<SphereSpec>(*ok.scene->root->children.at(0)->shape).radius == 1.5);

  ParseResult deep = parseSceneString(chain(100000), "chain.xml");
  CHECK_FALSE(deep.scene);
  REQUIRE(deep.diagnostics.errorCount() == 1);
  const Diagnostic& d = deep.diagnostics.all().front();
  CHECK(d.message == "<param> 'p1000': parameters refer to one another more than 1000 deep here");
  CHECK(d.loc.line == 1002);
}
