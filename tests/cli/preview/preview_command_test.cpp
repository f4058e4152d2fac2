// `lucent preview`'s bad input, refused before anything is served: each with its exact
// message and the contract's exit status (1 usage, 3 input/output). A preview that starts
// is tested in a browser (tests/gallery/preview_in_browser.py).
#include "../run_lucent.h"

#include <catch2/catch.hpp>

using namespace lucent::test;

namespace {

const std::string kValid = sourcePath("tests/bad/scenes/valid.xml");

}  // namespace

TEST_CASE("cli: preview refuses a missing scene, a bad port and a bad option", "[cli][preview]") {
  LucentRun r = runLucent("preview '/nonexistent/scene.xml'");
  CHECK(r.status == 3);
  CHECK(r.err == "lucent: error: cannot read the scene '/nonexistent/scene.xml': no such file\n");
  r = runLucent("preview '" + sourcePath("tests") + "'");
  CHECK(r.status == 3);
  CHECK(r.err ==
        "lucent: error: cannot read the scene '" + sourcePath("tests") + "': not a file\n");
  r = runLucent("preview '" + kValid + "' --port 70000");
  CHECK(r.status == 1);
  CHECK(r.err == "lucent: error: --port 70000: must be 1 to 65535 (or none: a free port)\n");
  r = runLucent("preview '" + kValid + "' -w 0");
  CHECK(r.status == 1);
  CHECK(r.err.find("--width") != std::string::npos);
  r = runLucent("preview '" + kValid + "' --opne");
  CHECK(r.status == 1);
  CHECK(r.err ==
        "lucent: error: The following argument was not expected: --opne (did you mean "
        "'--open'?)\nRun 'lucent preview --help' for more information.\n");
  r = runLucent("previw '" + kValid + "'");
  CHECK(r.status == 1);
  CHECK(r.err.find("unknown command 'previw' (did you mean 'preview'?)") != std::string::npos);
  // An address that is not this machine's: nothing can listen there.
  r = runLucent("preview '" + kValid + "' --bind 192.0.2.1 --port 8080");
  CHECK(r.status == 3);
  CHECK(r.err ==
        "lucent: error: cannot serve the preview on 192.0.2.1 port 8080: Cannot assign requested "
        "address\n");
}
