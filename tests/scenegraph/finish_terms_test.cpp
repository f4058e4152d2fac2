// The finish table (scenegraph/finish_terms.cpp) and what is derived from it: the parser's
// attribute check and reads, the schema's materialAttributes, the hints for POV-Ray's words
// and the finish keywords the exporter takes from the rows.
#include "scenegraph/finish_terms.h"
#include "../povray/pov_test_support.h"
#include "../support/scene_text.h"
#include "lang/schema.h"

#include <catch2/catch.hpp>

#include <set>
#include <string>

using namespace lucent;
using namespace lucent::test;

namespace {

// Answers every getter with its default and records the attributes asked for.
class RecordingInput final : public AttributeInput {
 public:
  bool has(const char* attr) const override {
    asked.insert(attr);
    return false;
  }
  double number(const char* attr, double def, const NumberRule&) override { return ask(attr, def); }
  long long integer(const char* attr, long long def, long long, long long) override {
    return ask(attr, def);
  }
  Vec3 vector(const char* attr, const Vec3& def) override { return ask(attr, def); }
  Vec3 direction(const char* attr, const Vec3& def) override { return ask(attr, def); }
  bool boolean(const char* attr, bool def) override { return ask(attr, def); }
  Color color(const char* attr, const Color& def, bool*) override { return ask(attr, def); }
  Color signedColor(const char* attr, const Color& def, bool*) override { return ask(attr, def); }
  size_t choice(const char* attr, size_t def, const std::vector<std::string_view>&) override {
    return ask(attr, def);
  }
  Mat4 transform(const char* attr, const Mat4& def) override { return ask(attr, def); }
  std::optional<std::string> text(const char* attr) override {
    return ask(attr, std::optional<std::string>());
  }
  std::optional<std::vector<double>> numbers(const char* attr) override {
    return ask(attr, std::optional<std::vector<double>>());
  }
  std::optional<std::vector<long long>> integers(const char* attr) override {
    return ask(attr, std::optional<std::vector<long long>>());
  }
  std::optional<FunctionInput> function(const char* attr,
                                        const std::vector<std::string>&) override {
    return ask(attr, std::optional<FunctionInput>());
  }
  std::shared_ptr<const MeshData> meshFile(const char* attr, bool*) override {
    return ask(attr, std::shared_ptr<const MeshData>());
  }
  std::shared_ptr<const HeightMap> heightMapFile(const char* attr, std::string&) override {
    return ask(attr, std::shared_ptr<const HeightMap>());
  }
  std::optional<std::string> filePath(const char* attr) override {
    return ask(attr, std::optional<std::string>());
  }
  std::optional<uint32_t> material(const char* attr) override {
    return ask(attr, std::optional<uint32_t>());
  }
  void forEachChild(const char* element, const std::function<void(AttributeInput&)>&) override {
    asked.insert(std::string("<") + element + ">");
  }
  void attrError(const char*, const std::string&) override {}
  void error(const std::string&) override {}
  void warning(const std::string&) override {}
  bool failed() const override { return false; }

  mutable std::set<std::string> asked;

 private:
  template <class T>
  T ask(const char* attr, T def) {
    asked.insert(attr);
    return def;
  }
};

class RecordingFinish final : public PovFinishOut {
 public:
  void line(std::string_view text) override { lines.emplace_back(text); }
  std::string number(double v) const override { return std::to_string(v); }
  std::vector<std::string> lines;
};

// A value of the attribute's type the parser accepts.
std::string sampleValue(const AttributeInfo& a) {
  if (a.type == AttrType::Boolean) return "true";
  if (a.type == AttrType::Number) return "0.5";  // within every range
  return "0.25 0.5 0.75";
}

}  // namespace

TEST_CASE("finish table: names unique and documented, none of them the parser's own",
          "[finish][table]") {
  std::set<std::string> names{"id", "base", "default"};
  for (const FinishTerm& t : finishTerms()) {
    INFO(t.info.name);
    CHECK(names.insert(t.info.name).second);
    CHECK_FALSE(t.info.doc.empty());
    CHECK_FALSE(t.pov.empty());
    CHECK(t.read);
  }
}

TEST_CASE("finish table: each row reads its own attribute and no other", "[finish][table]") {
  for (const FinishTerm& t : finishTerms()) {
    INFO(t.info.name);
    RecordingInput in;
    Material m;
    t.read(m, in);
    CHECK(in.asked == std::set<std::string>{t.info.name});
  }
}

TEST_CASE("finish table: the parser takes every term and reports a bad value at it",
          "[finish][table][lang]") {
  for (const FinishTerm& t : finishTerms()) {
    const std::string good = "<material id=\"m\" " + t.info.name + "=\"" + sampleValue(t.info) +
                             "\"/><sphere center=\"0 0 -5\" material=\"m\"/>";
    INFO(good);
    parseClean(good);
    ParseResult r = parseBody("<material id=\"m\" " + t.info.name + "=\"oops\"/>", "m.xml");
    INFO(messages(r));
    CHECK(r.diagnostics.errorCount() == 1);
    CHECK(messages(r).find("m.xml:1:") == 0);
    CHECK(messages(r).find("<material> attribute '" + t.info.name + "'") != std::string::npos);
  }
}

TEST_CASE("finish table: the schema declares every term among the material attributes",
          "[finish][table][schema]") {
  const std::string xsd = schemaText();
  const size_t begin = xsd.find("<xs:attributeGroup name=\"materialAttributes\">");
  REQUIRE(begin != std::string::npos);
  const std::string group = xsd.substr(begin, xsd.find("</xs:attributeGroup>", begin) - begin);
  for (const FinishTerm& t : finishTerms()) {
    INFO(t.info.name);
    CHECK(group.find("<xs:attribute name=\"" + t.info.name + "\"") != std::string::npos);
  }
  CHECK(group.find("<xs:attribute name=\"base\"") != std::string::npos);
}

TEST_CASE("finish table: POV-Ray's words on a material name the term's attribute",
          "[finish][table][lang]") {
  size_t hints = 0;
  for (const FinishTerm& t : finishTerms())
    for (const PovHint& h : t.povHints) {
      ++hints;
      const std::string word(h.word);
      ParseResult r = parseBody("<material id=\"m\" " + word + "=\"1\"/>");
      INFO(messages(r));
      CHECK(messages(r).find("unknown attribute '" + word + "' (POV-Ray's '" + word + "' is '" +
                             t.info.name + "'") != std::string::npos);
    }
  CHECK(hints >= 9);  // color, colour, rgb, roughness, reflection, filter, transmit, ...
  ParseResult r = parseBody("<material id=\"m\" roughness=\"0.1\"/>");
  CHECK(messages(r).find("(POV-Ray's 'roughness' is 'shininess' (1/roughness) in Lucent)") !=
        std::string::npos);
}

TEST_CASE("finish table: a row that writes POV-Ray lines writes its own keywords",
          "[finish][table][povray]") {
  Material m;
  m.diffuse = Color(0.5f);
  m.specular = Color(0.4f);
  m.phong = Color(0.3f);
  m.metallic = true;
  m.irid = 0.3;
  size_t writers = 0;
  for (const FinishTerm& t : finishTerms()) {
    if (!t.writePov) continue;
    ++writers;
    INFO(t.info.name);
    RecordingFinish out;
    t.writePov(m, out);
    CHECK_FALSE(out.lines.empty());
    for (const std::string& line : out.lines) {
      const std::string keyword = line.substr(0, line.find(' '));
      CHECK(t.pov.find(keyword) != std::string_view::npos);
    }
  }
  CHECK(writers >= 4);  // roughness, phong_size, brilliance, metallic
}

TEST_CASE("finish table: the exporter's finish holds each written row's lines",
          "[finish][table][povray]") {
  Exported e = exportScene(
      "<material id=\"m\" diffuse=\"0.5\" phong=\"0.3\" phong-size=\"12\" brilliance=\"2\" "
      "specular=\"0.4\" shininess=\"8\" metallic=\"true\"/><sphere material=\"m\"/>");
  REQUIRE(e.pov.ok());
  CHECK(e.has("    roughness 0.125\n    phong_size 12\n    brilliance 2\n    metallic\n  }\n"));
}
