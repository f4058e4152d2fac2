// Reads a value back out of the tables' readers (shape fields, the finish table, the camera
// and light tables), so that the scene writer needs no list of attributes of its own: every
// reader of those tables passes the value already in the object as its default
// (`s.*m = in.number(name, s.*m, rule)`), so an input that answers every getter with its
// default learns, per attribute, the object's value. What a reader asks through a getter
// that has no default to give back (lists, files, functions, child elements) is recorded as
// not writable: the writer writes it from the parameters itself (a shape's lists, files,
// function and children: scene_writer_shapes.cpp) or reports it, instead of guessing.
#pragma once

#include "scenegraph/attribute_input.h"

#include <string>
#include <utility>
#include <vector>

namespace lucent {

class AttributeProbe : public AttributeInput {
 public:
  // The attributes the reader asked for and the text of each value, in reading order (an
  // attribute asked twice keeps its first value).
  std::vector<std::pair<std::string, std::string>> values;
  // The attributes whose values the probe could not learn.
  std::vector<std::string> unwritable;

  bool has(const char* attr) const override;
  double number(const char* attr, double def, const NumberRule& rule) override;
  long long integer(const char* attr, long long def, long long min, long long max) override;
  Vec3 vector(const char* attr, const Vec3& def) override;
  Vec3 direction(const char* attr, const Vec3& def) override;
  bool boolean(const char* attr, bool def) override;
  Color color(const char* attr, const Color& def, bool* scalar) override;
  Color signedColor(const char* attr, const Color& def, bool* scalar) override {
    return color(attr, def, scalar);
  }
  size_t choice(const char* attr, size_t def, const std::vector<std::string_view>& names) override;
  Mat4 transform(const char* attr, const Mat4& def) override;
  std::optional<std::string> text(const char* attr) override;
  std::optional<std::vector<double>> numbers(const char* attr) override;
  std::optional<std::vector<long long>> integers(const char* attr) override;
  std::optional<FunctionInput> function(const char* attr,
                                        const std::vector<std::string>& variables) override;
  std::shared_ptr<const MeshData> meshFile(const char* attr, bool* firstRead) override;
  std::shared_ptr<const HeightMap> heightMapFile(const char* attr, std::string& resolved) override;
  std::optional<std::string> filePath(const char* attr) override;
  std::optional<uint32_t> material(const char* attr) override;
  void forEachChild(const char* element, const std::function<void(AttributeInput&)>& read) override;
  void attrError(const char*, const std::string&) override {}
  void error(const std::string&) override {}
  void warning(const std::string&) override {}
  bool failed() const override { return false; }

  // The text of an attribute's value, or nullptr if the reader did not ask for it.
  const std::string* find(const std::string& attr) const;

 private:
  void record(const char* attr, std::string text);
  void cannot(const char* attr);
};

}  // namespace lucent
