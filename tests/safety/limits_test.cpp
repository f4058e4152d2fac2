// Limits that keep absurd or hostile values out (docs/security.md, "Limits"): numbers above
// 1e30 or (nonzero) below 1e-30 in magnitude, transforms that overflow alone or through nesting,
// scene files that are not regular files, mesh vertices beyond 1e30. Each is refused with a clear
// message, and at the attribute's file:line:col where the value comes from a scene.
#include "../support/paths.h"
#include "lang/parser.h"
#include "lang/transform_syntax.h"
#include "lang/values.h"
#include "memory/system_memory.h"
#include "meshes/mesh_files.h"
#include "meshes/mesh_repair.h"
#include "scenegraph/world.h"

#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>

using namespace lucent;

namespace {

std::string errorsOf(const std::string& xml) {
  ParseResult r = parseSceneString(xml, "limits.xml");
  std::string all;
  for (const Diagnostic& d : r.diagnostics.all()) all += d.str() + "\n";
  return all;
}

}  // namespace

TEST_CASE("limits: numbers above 1e30 in magnitude are refused, 1e30 itself and far=inf are not",
          "[limits]") {
  CHECK(*parseNumber("1e30") == 1e30);
  CHECK(*parseNumber("-1e30") == -1e30);
  CHECK(parseNumber("1.0000001e30").error ==
        "the number '1.0000001e30' is too large (the limit is 1e30 in magnitude)");
  CHECK(parseNumber("-1e300").error ==
        "the number '-1e300' is too large (the limit is 1e30 in magnitude)");
  CHECK(*parseNumber("1e300", true) == 1e300);  // a distance that may be infinite may be large
  CHECK(parseVector("0 1e31 0").error ==
        "the number '1e31' is too large (the limit is 1e30 in magnitude)");
}

TEST_CASE("limits: nonzero numbers below 1e-30 in magnitude are refused, zero is not", "[limits]") {
  CHECK(*parseNumber("1e-30") == 1e-30);
  CHECK(*parseNumber("0") == 0.0);
  CHECK(*parseNumber("-0") == 0.0);
  CHECK(parseNumber("1e-320").error ==
        "the number '1e-320' is too small (a nonzero number must be at least 1e-30 in magnitude)");
  TransformSyntaxResult tiny = parseTransformSyntax("scale(1e-31)");
  CHECK(tiny.error ==
        "'scale': the number '1e-31' is too small (a nonzero number must be at least 1e-30 in "
        "magnitude)");
}

TEST_CASE("limits: an absurd value in a scene is an error at its attribute", "[limits]") {
  CHECK(errorsOf("<scene version=\"1\">\n<camera/>\n  <sphere radius=\"1e300\"/>\n</scene>\n") ==
        "limits.xml:3:19: error: <sphere> attribute 'radius': the number '1e300' is too large (the "
        "limit is 1e30 in magnitude)\n");
  CHECK(errorsOf("<scene version=\"1\">\n<camera position=\"0 0 1e31\"/>\n</scene>\n") ==
        "limits.xml:2:19: error: <camera> attribute 'position': the number '1e31' is too large "
        "(the limit is 1e30 in magnitude)\n");
}

TEST_CASE("limits: transform numbers above 1e30 and products beyond double range are refused",
          "[limits]") {
  TransformSyntaxResult big = parseTransformSyntax("translate(0 0 2e30)");
  CHECK_FALSE(big.ok);
  CHECK(big.error ==
        "'translate': the number '2e30' is too large (the limit is 1e30 in magnitude)");
  CHECK(big.errorOffset == 14);
  CHECK(parseTransformSyntax("scale(1e30) scale(1e30)").ok);  // 1e60: large, finite, invertible
  std::string many;
  for (int i = 0; i < 11; ++i) many += "scale(1e30) ";  // 1e330 overflows
  TransformSyntaxResult over = parseTransformSyntax(many);
  CHECK_FALSE(over.ok);
  CHECK(over.error ==
        "the transform overflows (its operations multiply to numbers beyond double range)");
}

TEST_CASE("limits: nested transforms whose product overflows stop the world build at the node",
          "[limits]") {
  std::string xml = "<scene version=\"1\">\n<camera/>\n";
  for (int i = 0; i < 11; ++i) xml += "<group transform=\"scale(1e30)\">\n";
  xml += "<sphere radius=\"1\"/>\n";
  for (int i = 0; i < 11; ++i) xml += "</group>\n";
  xml += "</scene>\n";
  ParseResult r = parseSceneString(xml, "nested.xml");
  REQUIRE(r.scene);  // each transform alone is fine
  try {
    World world(*r.scene);
    FAIL("the world was built");
  } catch (const std::runtime_error& e) {
    // The 11th group (line 13) is where the product first leaves double range.
    CHECK(std::string(e.what()) ==
          "nested.xml:13:1: error: the transforms down to this node multiply beyond double range");
  }
}

TEST_CASE("limits: a scene file must be a regular file", "[limits]") {
  ParseResult zero = parseSceneFile("/dev/zero");  // endless: must not be read
  CHECK(zero.ioFailure);
  REQUIRE(zero.diagnostics.errorCount() == 1);
  CHECK(zero.diagnostics.all()[0].message ==
        "cannot read the scene file: it is not a regular file");
  ParseResult folder = parseSceneFile(std::string(lucentSourceDir()) + "/examples");
  CHECK(folder.ioFailure);
  CHECK(folder.diagnostics.all()[0].message ==
        "cannot read the scene file: it is a folder, not a file");
}

TEST_CASE("limits: mesh vertices beyond 1e30 are refused", "[limits]") {
  const std::string off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 2e30 0\n3 0 1 2\n";
  CHECK_THROWS_WITH(loadMeshBytes(off, MeshFormat::Off),
                    "vertex 2 (counting from 0) has a coordinate beyond 1e30 in magnitude");
  const std::string ok = "OFF\n3 1 0\n0 0 0\n1e30 0 0\n0 1e30 0\n3 0 1 2\n";
  CHECK(loadMeshBytes(ok, MeshFormat::Off)->triangles.size() == 1);
}

TEST_CASE("limits: the memory available is known on Linux and formatted in decimal units",
          "[limits]") {
  auto available = availableMemoryBytes();
  REQUIRE(available);
  CHECK(*available > 0);
  CHECK(formatBytes(999) == "999 bytes");
  CHECK(formatBytes(1500) == "1.5 kB");
  CHECK(formatBytes(154618822656ull) == "154.6 GB");
}
