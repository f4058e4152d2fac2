// libFuzzer target: the POV-Ray importer (sdl::loadSceneText), then World and one pixel.
#include "fuzz/fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  lucent::fuzz::abortOnFinding(lucent::fuzz::povImporter(
      data, size, std::string(LUCENT_SOURCE_DIR) + "/tests/data/sdl/samples"));
  return 0;
}
