// libFuzzer's entry for one target, named by WALKRAD_FUZZ_TARGET (a namespace of
// fuzz_targets.h) when it is compiled.
#include "tests/fuzz/fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzz::WALKRAD_FUZZ_TARGET::fuzzOne(data, size);
  return 0;
}
