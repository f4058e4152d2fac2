// libFuzzer target: image files for <height-field> (the reader's formats and POV-Ray's
// reading of them, the grid and its pyramid).
#include "fuzz/fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  lucent::fuzz::abortOnFinding(lucent::fuzz::heightMapReader(data, size));
  return 0;
}
