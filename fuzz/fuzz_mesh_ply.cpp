// libFuzzer entry point for gs_fuzz::MeshPly: the program's PLY loading (see gs_fuzz_mesh.h).
#include "gs_fuzz_mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    return gs_fuzz::MeshPly(data, size);
}
