// The command line as a new user meets it: help, misspellings, -D, --allow-path lists,
// -q, outputs that cannot be written and render's default output. Each asserts the exact
// message and exit status (the contract's: 0 ok, 1 usage, 2 invalid scene, 3 I/O).
#include "run_lucent.h"

#include <catch2/catch.hpp>

#include <fstream>

namespace fs = std::filesystem;
using namespace lucent::test;

namespace {

const std::string kValid = sourcePath("tests/bad/scenes/valid.xml");

void writeFile(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

}  // namespace

TEST_CASE("cli: a misspelled command or option gets a 'did you mean'", "[cli]") {
  LucentRun r = runLucent("rendr '" + kValid + "'");
  CHECK(r.status == 1);
  CHECK(r.err ==
        "lucent: error: unknown command 'rendr' (did you mean 'render'?); the commands are "
        "render, check, export-pov, convert, compare, preview and schema (lucent --help)\n");
  r = runLucent("nonsense");
  CHECK(r.status == 1);
  CHECK(r.err ==
        "lucent: error: unknown command 'nonsense'; the commands are render, check, "
        "export-pov, convert, compare, preview and schema (lucent --help)\n");
  r = runLucent("schem");
  CHECK(r.status == 1);
  CHECK(r.err ==
        "lucent: error: unknown command 'schem' (did you mean 'schema'?); the commands are "
        "render, check, export-pov, convert, compare, preview and schema (lucent --help)\n");
  r = runLucent("check '" + kValid + "' --widht 16");
  CHECK(r.status == 1);
  CHECK(r.err ==
        "lucent: error: The following argument was not expected: --widht (did you mean "
        "'--width'?)\nRun 'lucent check --help' for more information.\n");
  r = runLucent("render '" + kValid + "' --sample=4");
  CHECK(r.status == 1);
  CHECK(r.err ==
        "lucent: error: The following argument was not expected: --sample=4 (did you mean "
        "'--samples'?)\nRun 'lucent render --help' for more information.\n");
}

TEST_CASE("cli: help is --help in every command and -h is the height", "[cli]") {
  for (const char* cmd : {"", "render", "check", "export-pov", "compare"}) {
    INFO(cmd);
    LucentRun r = runLucent(std::string(cmd) + " --help");
    CHECK(r.status == 0);
    CHECK_THAT(r.out, Catch::Contains("  --help                      Print this help and exit"));
    CHECK_THAT(r.out, !Catch::Contains("-h,--help"));
  }
  LucentRun top = runLucent("-h");
  CHECK(top.status == 1);
  CHECK(top.err ==
        "lucent: error: -h is the image height (lucent render -h 480); help is lucent --help\n");
  // check takes -h as render does: the height it validates for.
  LucentRun r = runLucent("check '" + kValid + "' -h 7");
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("image: 32x7, 1 sample per pixel"));
}

TEST_CASE("cli: -D takes valid parameter names, each once", "[cli]") {
  LucentRun r = runLucent("check '" + kValid + "' -D 1x=3");
  CHECK(r.status == 1);
  CHECK(r.err ==
        "lucent: error: -D 1x=3: a parameter name is letters, digits and '_', not starting "
        "with a digit; got '1x'\n");
  r = runLucent("render '" + kValid + "' -D a=1 -D a=2");
  CHECK(r.status == 1);
  CHECK(r.err == "lucent: error: -D a is given twice (a=1 and a=2); give it once\n");
  r = runLucent("check '" + kValid + "' -D a=1 -D b=2");
  CHECK(r.status == 0);
}

TEST_CASE("cli: --allow-path takes a colon-separated list of folders", "[cli]") {
  TempFolder tmp("lucent-allow-path");
  fs::create_directories(tmp.path() / "scene");
  fs::create_directories(tmp.path() / "lib1");
  fs::create_directories(tmp.path() / "lib2");
  writeFile(tmp.str("lib1/a.xml"), "<scene version=\"1\"><sphere radius=\"1\"/></scene>\n");
  writeFile(tmp.str("lib2/b.xml"), "<scene version=\"1\"><box/></scene>\n");
  writeFile(tmp.str("scene/s.xml"),
            "<scene version=\"1\">\n<camera/>\n<include src=\"../lib1/a.xml\"/>\n"
            "<include src=\"../lib2/b.xml\"/>\n</scene>\n");
  const std::string scene = tmp.str("scene/s.xml");
  CHECK(runLucent("check '" + scene + "'").status == 2);
  LucentRun r = runLucent("check '" + scene + "' --allow-path '" + tmp.str("lib1") + ":" +
                          tmp.str("lib2") + "'");
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("nodes: 2 (box: 1, sphere: 1)"));
  r = runLucent("check '" + scene + "' --allow-path '" + tmp.str("lib1") + ":/nonexistent/folder'");
  CHECK(r.status == 1);
  CHECK(r.err ==
        "--allow-path: Directory does not exist: /nonexistent/folder\nRun with --help for more "
        "information.\n");
  CHECK_THAT(runLucent("check --help").out, Catch::Contains("--allow-path DIR:DIR ..."));
}

TEST_CASE("cli: -q hides progress and the closing line but keeps warnings", "[cli]") {
  TempFolder tmp("lucent-quiet");
  writeFile(tmp.str("w.xml"),
            "<scene version=\"1\">\n<camera/>\n<defs><sphere/></defs>\n</scene>\n");
  LucentRun r =
      runLucent("render '" + tmp.str("w.xml") + "' -o '" + tmp.str("w.png") + "' -w 8 -h 6 -q");
  CHECK(r.status == 0);
  CHECK(r.err ==
        tmp.str("w.xml") +
            ":3:7: warning: <sphere> in <defs> has no id, so no <use> can instantiate it\n");
  CHECK(fs::exists(tmp.str("w.png")));
}

TEST_CASE("cli: render without -o writes SCENE.png beside the scene", "[cli]") {
  TempFolder tmp("lucent-default-output");
  fs::copy_file(kValid, tmp.str("ball.xml"));
  LucentRun r = runLucent("render '" + tmp.str("ball.xml") + "' -w 8 -h 6");
  CHECK(r.status == 0);
  CHECK_THAT(r.err, Catch::StartsWith("lucent: wrote '" + tmp.str("ball.png") + "' (8x6, "));
  CHECK(fs::file_size(tmp.str("ball.png")) > 0);
}

TEST_CASE("cli: export-pov into a missing folder names the folder", "[cli]") {
  TempFolder tmp("lucent-export-missing");
  const std::string out = tmp.str("missing/x.pov");
  LucentRun r = runLucent("export-pov '" + kValid + "' -o '" + out + "'");
  CHECK(r.status == 3);
  CHECK(r.err == "lucent: error: cannot write '" + out + "': folder '" + tmp.str("missing") +
                     "' does not exist\n");
  writeFile(tmp.str("file"), "x");
  r = runLucent("export-pov '" + kValid + "' -o '" + tmp.str("file/x.pov") + "'");
  CHECK(r.status == 3);
  CHECK(r.err == "lucent: error: cannot write '" + tmp.str("file/x.pov") + "': '" +
                     tmp.str("file") + "' is not a folder\n");
  CHECK(fs::directory_iterator(tmp.path())->path().filename() == "file");  // no temporary file left
}
