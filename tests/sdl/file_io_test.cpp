// #fopen, #read, #write and #fclose, against what POV-Ray 3.7 writes and reads (checked
// with povray: a #write of 5, 0.1, 1/3, 1e-7, 123456789, <1,2.5,3>, -0 and <1,2> gives
// "5|0.1|0.333333|1e-07|1.23457e+08|<1,2.5,3> |-0|<1,2> |", and the file identifier is
// undefined once #read has taken the last value).
#include "sdl_test_support.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

using namespace lucent;

namespace {

struct TempFolder {
  std::filesystem::path path;
  TempFolder() {
    path = std::filesystem::temp_directory_path() /
           ("lucent-sdl-io-" + std::to_string(reinterpret_cast<std::uintptr_t>(this)));
    std::filesystem::create_directories(path);
  }
  ~TempFolder() { std::filesystem::remove_all(path); }
  std::string text(const std::string& name) const {
    std::ifstream in(path / name);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
};

}  // namespace

TEST_CASE("#write writes floats as %g and vectors as <a,b,c> with a blank, as POV-Ray",
          "[sdl][io]") {
  TempFolder tmp;
  sdl::Options options;
  options.writeFolders = {tmp.path};
  const std::string file = (tmp.path / "out.txt").string();
  sdltest::debugOf(
      "#fopen F \"" + file +
          "\" write\n"
          "#write (F, 5, \"|\", 0.1, \"|\", 1/3, \"|\", 1e-7, \"|\", 123456789, \"|\", "
          "<1,2.5,3>, \"|\", -0.0, \"|\", <1,2>, \"|\", concat(\"a\", \"b\"), \"\\n\")\n"
          "#write (F \"no comma\")\n"
          "#fclose F\n",
      nullptr, options);
  CHECK(tmp.text("out.txt") ==
        "5|0.1|0.333333|1e-07|1.23457e+08|<1,2.5,3> |-0|<1,2> |ab\nno comma");
}

TEST_CASE("#read takes floats, vectors and strings, and undefines the file at its end",
          "[sdl][io]") {
  const std::string out = sdltest::debugOf(R"(
#fopen G "io_values.txt" read
#read (G, A, B, C)
#debug concat(str(A,0,2), " ", vstr(3,B,",",0,1), " ", C, "\n")
#ifdef (G) #debug "open\n" #end
#read (G, D)
#ifndef (G) #debug "closed\n" #end
#debug str(D,0,2)
#fclose G
)");
  CHECK(out == "1.50 1.0,2.0,3.0 hello\nopen\nclosed\n2.50");
}

TEST_CASE("#read in a loop while the file is defined, as POV-Ray scenes read data", "[sdl][io]") {
  const std::string out = sdltest::debugOf(R"(
#fopen G "io_values.txt" read
#declare N = 0;
#while (defined(G))
  #read (G, V)
  #declare N = N + 1;
#end
#debug concat(str(N,0,0), " ", str(V,0,1))
)");
  CHECK(out == "4 2.5");
}

TEST_CASE("file input and output: refusals, each located", "[sdl][io][errors]") {
  // Writing without --allow-write: refused at the directive.
  CHECK(sdltest::errorOf("#fopen F \"x.txt\" write\n")
            .find("test.pov:1:1: error: #fopen F \"x.txt\" write: writing files is refused unless "
                  "--allow-write names a folder that holds it") == 0);
  TempFolder tmp;
  sdl::Options options;
  options.writeFolders = {tmp.path};
  // Outside the allowed folder, even with one.
  CHECK(sdltest::errorOf("#fopen F \"../escape.txt\" append\n", options).find("refused") !=
        std::string::npos);
  CHECK(sdltest::errorOf("#fopen F \"nothing-here.txt\" read\n")
            .find("test.pov:1:1: error: #fopen: no file 'nothing-here.txt' to read") == 0);
  CHECK(sdltest::errorOf("#fopen F \"io_values.txt\" readonly\n")
            .find("test.pov:1:26: error: expected read, write or append") == 0);
  // A malformed value is located in the data file.
  CHECK(sdltest::errorOf("#fopen F \"io_broken.txt\" read #read (F, S)\n")
            .find("io_broken.txt:1:1: error: #read: the string has no closing quote") !=
        std::string::npos);
  CHECK(sdltest::errorOf("#declare F = 1; #read (F, S)\n")
            .find("expected a file identifier (opened by #fopen) in #read, found float identifier "
                  "'F'") != std::string::npos);
  CHECK(sdltest::errorOf("#fopen F \"io_values.txt\" read #write (F, 1)\n")
            .find("#write: 'F' was opened for reading") != std::string::npos);
  // A bounded amount of writing.
  options.limits.fileBytes = 100;
  const std::string file = (tmp.path / "big.txt").string();
  CHECK(sdltest::errorOf(
            "#fopen F \"" + file + "\" write #while (1) #write (F, \"0123456789\") #end\n", options)
            .find("#write: more than 100 bytes written") != std::string::npos);
}
