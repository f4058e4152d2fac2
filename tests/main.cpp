// The test program's entry point: Catch2's, with two warnings that are errors in every run,
// so that no runner can leave them out. NoAssertions: a test case or section that checks
// nothing fails, since a test that cannot fail is a defect. NoTests: a name filter that
// matches no test case fails (CTest runs each test case by name, and a ';' or '[' in a name
// makes CMake split or merge names). Catch2 v2 takes a single -w on its command line,
// which is why they are set here.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "register.h"

int main(int argc, char* argv[]) {
  lucent::registerPovLibrary();  // `pov:` names in the XML scenes tests parse
  Catch::Session session;
  session.configData().warnings = static_cast<Catch::WarnAbout::What>(
      Catch::WarnAbout::NoAssertions | Catch::WarnAbout::NoTests);
  if (const int status = session.applyCommandLine(argc, argv); status != 0) return status;
  return session.run();
}
