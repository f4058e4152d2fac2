// libFuzzer target: arbitrary text as an expression, evaluated directly and inside ${...}.
#include "fuzz/fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  lucent::fuzz::abortOnFinding(lucent::fuzz::expression(data, size));
  return 0;
}
