// libFuzzer target: font files for <text> (FreeType's reader, the layout, the glyph prisms).
#include "fuzz/fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  lucent::fuzz::abortOnFinding(lucent::fuzz::fontReader(data, size));
  return 0;
}
