#include "pov_ini.h"

#include "scenegraph/located_error.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

namespace lucent::sdl {

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return {};
  const size_t b = s.find_last_not_of(" \t\r");
  return s.substr(a, b - a + 1);
}

// A value in quotes loses them (POV-Ray allows "..." around file names).
std::string unquote(const std::string& s) {
  if (s.size() >= 2 && (s.front() == '"' || s.front() == '\'') && s.back() == s.front())
    return s.substr(1, s.size() - 2);
  return s;
}

class IniReader {
 public:
  IniReader(std::string name, PovIni& ini) : name_(std::move(name)), ini_(ini) {}

  void line(const std::string& raw, int number) {
    line_ = number;
    std::string text = raw;
    if (const size_t c = text.find(';'); c != std::string::npos) text.resize(c);
    text = trim(text);
    if (text.empty()) return;
    if (text[0] == '+' || text[0] == '-') return switches(text);
    const size_t eq = text.find('=');
    if (eq == std::string::npos) {
      // A line that is only a file name is the scene, as Input_File_Name.
      ini_.inputFile = unquote(text);
      return;
    }
    key(trim(text.substr(0, eq)), unquote(trim(text.substr(eq + 1))));
  }

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw LocatedError(SourceLoc{name_, line_, 1}, message);
  }

  double number(const std::string& key, const std::string& value) const {
    std::istringstream in(value);
    double v = 0;
    in >> v;
    if (!in || !(in >> std::ws).eof())
      fail(key + "=" + value + ": a number was expected, not '" + value + "'");
    return v;
  }
  int whole(const std::string& key, const std::string& value) const {
    const double v = number(key, value);
    if (v != static_cast<int>(v) || v < 0 || v > 1e9)
      fail(key + "=" + value + ": a whole number from 0 was expected");
    return static_cast<int>(v);
  }
  int size(const std::string& key, const std::string& value) const {
    const int v = whole(key, value);
    if (v < 1) fail(key + "=" + value + ": an image size is at least 1 pixel");
    return v;
  }
  bool flag(const std::string& key, const std::string& value) const {
    const std::string v = lower(value);
    if (v == "on" || v == "true" || v == "yes" || v == "1" || v.empty()) return true;
    if (v == "off" || v == "false" || v == "no" || v == "0") return false;
    fail(key + "=" + value + ": on or off was expected");
  }

  void declare(const std::string& value) {
    const size_t eq = value.find('=');
    if (eq == std::string::npos || eq == 0) fail("Declare=" + value + ": NAME=VALUE was expected");
    ini_.declared[trim(value.substr(0, eq))] = number("Declare", trim(value.substr(eq + 1)));
  }

  void key(const std::string& key, const std::string& value) {
    const std::string k = lower(key);
    if (k == "width") ini_.width = size(key, value);
    else if (k == "height") ini_.height = size(key, value);
    else if (k == "declare") declare(value);
    else if (k == "library_path") ini_.library.emplace_back(value);
    else if (k == "input_file_name") ini_.inputFile = value;
    else if (k == "initial_frame") ini_.initialFrame = whole(key, value);
    else if (k == "final_frame") ini_.finalFrame = whole(key, value);
    else if (k == "initial_clock") ini_.initialClock = number(key, value);
    else if (k == "final_clock") ini_.finalClock = number(key, value);
    else if (k == "clock") ini_.clock = number(key, value);
    else if (k == "cyclic_animation") ini_.cyclic = flag(key, value);
    else ini_.notTaken.emplace_back(key, SourceLoc{name_, line_, 1});
  }

  // Command-line switches written in the file: +W320, +H240, +K0.5, +KFI1, +KFF30, +KI0,
  // +KF1, +KC, +L/folder (a '-' before a flag turns it off).
  void switches(const std::string& text) {
    std::istringstream words(text);
    for (std::string w; words >> w;) {
      const bool on = w[0] == '+';
      const std::string body = w.substr(1);
      const std::string k = lower(body);
      auto rest = [&](size_t n) { return body.substr(n); };
      if (k.rfind("kff", 0) == 0) ini_.finalFrame = whole(w, rest(3));
      else if (k.rfind("kfi", 0) == 0) ini_.initialFrame = whole(w, rest(3));
      else if (k.rfind("kc", 0) == 0) ini_.cyclic = on;
      else if (k.rfind("ki", 0) == 0) ini_.initialClock = number(w, rest(2));
      else if (k.rfind("kf", 0) == 0) ini_.finalClock = number(w, rest(2));
      else if (k.rfind("k", 0) == 0) ini_.clock = number(w, rest(1));
      else if (k.rfind("w", 0) == 0 && k.size() > 1 &&
               std::isdigit(static_cast<unsigned char>(k[1])))
        ini_.width = size(w, rest(1));
      else if (k.rfind("h", 0) == 0 && k.size() > 1 &&
               std::isdigit(static_cast<unsigned char>(k[1])))
        ini_.height = size(w, rest(1));
      else if (k.rfind("l", 0) == 0 && k.size() > 1) ini_.library.emplace_back(unquote(rest(1)));
      else if (k.rfind("declare=", 0) == 0) declare(rest(8));
      else ini_.notTaken.emplace_back(w, SourceLoc{name_, line_, 1});
    }
  }

  std::string name_;
  PovIni& ini_;
  int line_ = 0;
};

}  // namespace

PovIni readPovIniText(const std::string& name, const std::string& text,
                      const std::string& section) {
  PovIni ini;
  IniReader reader(name, ini);
  std::istringstream in(text);
  // The lines before the first [label] when no section is asked; else that section's.
  bool reading = section.empty();
  bool found = section.empty();
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    const std::string t = trim(line);
    if (!t.empty() && t[0] == '[') {
      const size_t close = t.find(']');
      if (close == std::string::npos)
        throw LocatedError(SourceLoc{name, number, 1}, "a section label has no closing ']'");
      const bool match = lower(t.substr(1, close - 1)) == lower(section);
      reading = !section.empty() && match;
      found = found || reading;
      continue;
    }
    if (reading) reader.line(line, number);
  }
  if (!found)
    throw LocatedError(SourceLoc{name, 0, 0}, "the INI file has no section [" + section + "]");
  if (ini.initialFrame && ini.finalFrame && *ini.finalFrame < *ini.initialFrame)
    throw LocatedError(SourceLoc{name, 0, 0},
                       "Final_Frame is before Initial_Frame: no frame to render");
  return ini;
}

PovIni readPovIni(const std::filesystem::path& path, const std::string& section) {
  std::ifstream in(path, std::ios::binary);
  if (!in || std::filesystem::is_directory(path))
    throw LocatedError(SourceLoc{path.string(), 0, 0}, "cannot read the INI file");
  std::ostringstream text;
  text << in.rdbuf();
  PovIni ini = readPovIniText(path.string(), text.str(), section);
  // Folders and the scene are named relative to the INI file's folder.
  const std::filesystem::path folder = path.parent_path();
  for (std::filesystem::path& dir : ini.library)
    if (dir.is_relative()) dir = folder / dir;
  if (ini.inputFile && std::filesystem::path(*ini.inputFile).is_relative() && !folder.empty())
    ini.inputFile = (folder / *ini.inputFile).string();
  return ini;
}

}  // namespace lucent::sdl
