// lucent-make-pov-library OUT.xml: the `pov:` library made from POV-Ray's standard includes
// by the importer (sdl/pov_library.h), run by the build. It fails, and the build with it,
// when the includes cannot be read (they come with Debian's povray-includes).
#include "sdl/pov_library.h"

#include "lang/parser.h"
#include "lang/pov_library.h"

#include <fmt/core.h>

#include <cstdio>
#include <exception>
#include <fstream>

namespace {

// Every material of the library read by the XML language, as a scene that names them all
// would read it: what the importer made and the language cannot read fails the build here.
bool readsBack(const lucent::sdl::PovLibraryText& lib) {
  lucent::setPovLibraryText(lib.xml);
  std::string scene = "<scene version=\"1\">\n<camera position=\"0 0 -5\" look-at=\"0 0 0\"/>\n";
  for (const std::string& name : lib.materialNames)
    scene += "<sphere radius=\"1\" material=\"" + name + "\"/>\n";
  scene += "</scene>\n";
  const lucent::ParseResult parsed = lucent::parseSceneString(scene, "pov-library-check.xml");
  if (parsed.scene) return true;
  for (const lucent::Diagnostic& d : parsed.diagnostics.all())
    fmt::print(stderr, "lucent-make-pov-library: {}\n", d.str());
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    fmt::print(stderr, "usage: lucent-make-pov-library OUT.xml\n");
    return 2;
  }
  try {
    const lucent::sdl::PovLibraryText lib = lucent::sdl::makePovLibrary(lucent::sdl::Options{});
    if (!readsBack(lib)) {
      std::ofstream(std::string(argv[1]) + ".rejected", std::ios::binary) << lib.xml;
      return 1;
    }
    std::ofstream out(argv[1], std::ios::binary);
    out << lib.xml;
    if (!out.flush()) {
      fmt::print(stderr, "lucent-make-pov-library: cannot write '{}'\n", argv[1]);
      return 1;
    }
    fmt::print("pov library: {} colours, {} materials, {} declarations left out\n", lib.colours,
               lib.materials, lib.leftOut.size());
    return 0;
  } catch (const std::exception& e) {
    fmt::print(stderr, "lucent-make-pov-library: {}\n", e.what());
    return 1;
  }
}
