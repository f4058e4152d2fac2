// libFuzzer target: the PLY mesh reader (loadMeshBytes: the checks, CGAL's reader, repair).
#include "fuzz/fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  lucent::fuzz::abortOnFinding(lucent::fuzz::meshReader(data, size, lucent::MeshFormat::Ply));
  return 0;
}
