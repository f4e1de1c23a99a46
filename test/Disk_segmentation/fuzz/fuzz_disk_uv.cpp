// libFuzzer target: the whole disk_uv pipeline on arbitrary bytes (see
// fuzz_pipeline.h). Built by scripts/run_fuzzer.sh with clang.

#include "fuzz_pipeline.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  // Large inputs only slow the search down: small meshes reach every branch.
  if(size > 1 << 16)
    return -1;
  fuzz_pipeline::run(data, size);
  return 0;
}
