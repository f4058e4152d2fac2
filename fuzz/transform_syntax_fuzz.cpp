// libFuzzer target: the `transform` attribute syntax (lang/transform_syntax).
#include "fuzz/fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  lucent::fuzz::abortOnFinding(lucent::fuzz::transformSyntax(data, size));
  return 0;
}
