// libFuzzer entry point for gs_fuzz::PickPoints (see gs_fuzz.h and fuzz/CMakeLists.txt).
#include "gs_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    return gs_fuzz::PickPoints(data, size);
}
