// POV-Ray INI files (--pov-ini): the keys that change the scene, read as POV-Ray reads them.
#include "sdl/pov_ini.h"

#include "scenegraph/located_error.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::sdl;

namespace {

std::string errorOf(const std::string& text, const std::string& section = {}) {
  try {
    readPovIniText("a.ini", text, section);
  } catch (const LocatedError& e) {
    return e.loc().str() + ": " + e.message();
  }
  return "";
}

}  // namespace

TEST_CASE("INI: the animation, size, declarations and folders of a sample scene's file",
          "[sdl][ini]") {
  // As POV-Ray's animations/camera2/camera2.ini and portfolio/*.ini write them.
  const PovIni ini = readPovIniText("a.ini", R"(; comment
Antialias=On
Antialias_Threshold=0.2
+w200 +h150
Input_File_Name=camera2.pov
Initial_Frame=1
Final_Frame=30
Initial_Clock=0
Final_Clock=1   ; trailing comment
Cyclic_Animation=on
Declare=Size=2.5
Library_Path="../inc"
)");
  CHECK(ini.width == 200);
  CHECK(ini.height == 150);
  CHECK(ini.inputFile == "camera2.pov");
  CHECK(ini.initialFrame == 1);
  CHECK(ini.finalFrame == 30);
  CHECK(ini.initialClock == 0.0);
  CHECK(ini.finalClock == 1.0);
  CHECK(ini.cyclic);
  CHECK(ini.animated());
  CHECK(ini.declared.at("Size") == 2.5);
  REQUIRE(ini.library.size() == 1);
  CHECK(ini.library[0] == "../inc");
  // Antialiasing changes how POV-Ray samples, not the scene: listed as not taken, located.
  REQUIRE(ini.notTaken.size() == 2);
  CHECK(ini.notTaken[0].first == "Antialias");
  CHECK(ini.notTaken[0].second.line == 2);
}

TEST_CASE("INI: switches, keys in any case, and sections", "[sdl][ini]") {
  const PovIni ini = readPovIniText("a.ini",
                                    "width=64\nHEIGHT=48\n+KFI5 +KFF9 +KI0.5 +KF2 +K0.25\n"
                                    "[hi]\nWidth=800\n");
  CHECK(ini.width == 64);  // [hi] is not read when no section is asked
  CHECK(ini.height == 48);
  CHECK(ini.initialFrame == 5);
  CHECK(ini.finalFrame == 9);
  CHECK(ini.initialClock == 0.5);
  CHECK(ini.finalClock == 2.0);
  CHECK(ini.clock == 0.25);
  const PovIni hi = readPovIniText("a.ini", "Width=64\n[Hi]\nWidth=800\n[lo]\nWidth=10\n", "hi");
  CHECK(hi.width == 800);
  CHECK_FALSE(readPovIniText("a.ini", "Final_Frame=1\n").animated());
}

TEST_CASE("INI: malformed values are errors at their line", "[sdl][ini][errors]") {
  CHECK(errorOf("Width=64\nHeight=tall\n") ==
        "a.ini:2:1: Height=tall: a number was expected, not 'tall'");
  CHECK(errorOf("Width=0\n") == "a.ini:1:1: Width=0: an image size is at least 1 pixel");
  CHECK(errorOf("Cyclic_Animation=maybe\n") ==
        "a.ini:1:1: Cyclic_Animation=maybe: on or off was expected");
  CHECK(errorOf("Declare=X\n") == "a.ini:1:1: Declare=X: NAME=VALUE was expected");
  CHECK(errorOf("+KFF2.5\n") == "a.ini:1:1: +KFF2.5=2.5: a whole number from 0 was expected");
  CHECK(errorOf("Width=1\n", "nope") == "a.ini: the INI file has no section [nope]");
  CHECK(errorOf("[open\n") == "a.ini:1:1: a section label has no closing ']'");
  CHECK(errorOf("Initial_Frame=5\nFinal_Frame=2\n") ==
        "a.ini: Final_Frame is before Initial_Frame: no frame to render");
}
