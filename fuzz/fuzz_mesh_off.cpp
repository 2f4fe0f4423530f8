// libFuzzer entry point for gs_fuzz::MeshOff: the program's OFF loading (see gs_fuzz_mesh.h).
#include "gs_fuzz_mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    return gs_fuzz::MeshOff(data, size);
}
