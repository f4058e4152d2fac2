// libFuzzer target: the scene language (parseSceneString), then World and one pixel.
#include "fuzz/fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  lucent::fuzz::abortOnFinding(lucent::fuzz::sceneParser(
      data, size, std::string(LUCENT_SOURCE_DIR) + "/examples/fuzz-input.xml"));
  return 0;
}
