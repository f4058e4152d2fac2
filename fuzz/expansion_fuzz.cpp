// libFuzzer target: scenes of repeats, ifs, local parameters and parameterised uses, written
// by a small program that the input bytes choose (fuzz/expansion_scene.h).
#include "fuzz/fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  lucent::fuzz::abortOnFinding(lucent::fuzz::expansion(data, size));
  return 0;
}
