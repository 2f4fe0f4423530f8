// libFuzzer entry point for gs_fuzz::MeshStl: the program's STL loading (see gs_fuzz_mesh.h).
#include "gs_fuzz_mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    return gs_fuzz::MeshStl(data, size);
}
