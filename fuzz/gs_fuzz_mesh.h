#ifndef GS_FUZZ_GS_FUZZ_MESH_H
#define GS_FUZZ_GS_FUZZ_MESH_H

// Fuzz harness of the geometric-snake program's mesh loading (cli/cli_mesh_io.h: vcglib's OBJ,
// PLY, OFF and STL importers behind the program's own checks). The bytes are written to a file
// of the format's extension and loaded as the program loads a mesh; a loaded mesh must be whole
// (every face on live vertices of the mesh) and take the feature energy. Bad input may only end
// in a SnakeError; anything else aborts (gs_fuzz.h).
//
// vcglib's importers carry asserts that fire on files the program reads fine (the OBJ importer's
// face count check, on every file whose faces use vertex 1, which the program rebuilds): they
// are compiled out here, as in the program's release build, so the fuzzer looks for real faults.

#include <unistd.h>

#include <cstdio>
#include <string>

#include "gs_fuzz.h"

#ifndef NDEBUG
#define NDEBUG
#define GS_FUZZ_MESH_RESTORE_ASSERT
#endif
#include <cassert>
#include <cli_mesh_io.h>
#ifdef GS_FUZZ_MESH_RESTORE_ASSERT
#undef NDEBUG
#include <cassert>
#endif

#include <vcg_ext/energy/feature_energy.h>

namespace gs_fuzz {

/// Loads `data` as a mesh file of extension `ext` ("obj", "ply", "off", "stl").
inline int MeshFile(const char *ext, const uint8_t *data, size_t size)
{
    static const std::string dir = [] {
        char tmpl[] = "/tmp/gs-fuzz-mesh-XXXXXX";
        const char *d = ::mkdtemp(tmpl);
        if (!d) Fail("MeshFile", "cannot make a temporary folder");
        return std::string(d);
    }();
    const std::string path = dir + "/input." + ext;
    if (FILE *f = std::fopen(path.c_str(), "wb")) {
        if (size > 0 && std::fwrite(data, 1, size, f) != size) Fail("MeshFile", "cannot write the input");
        std::fclose(f);
    } else {
        Fail("MeshFile", "cannot write the input");
    }
    Guard("MeshFile", [&] {
        CMeshO m;
        int mask = 0;
        gs_cli::LoadMesh(path, m, mask);
        for (const auto &f : m.face) {
            if (f.IsD()) continue;
            for (int k = 0; k < 3; ++k) {
                const auto *v = f.cV(k);
                if (v == nullptr || v < &m.vert[0] || v >= &m.vert[0] + m.vert.size() || v->IsD())
                    Fail("MeshFile", "a loaded face points outside the mesh's vertices");
            }
        }
        if (m.fn > 0 && m.fn < 20000) vcg::tri::FeatureEnergy<CMeshO>::Compute(m, vcg::tri::FeatureEnergyType::NormalVariation, 1);
    });
    std::remove(path.c_str());
    return 0;
}

inline int MeshObj(const uint8_t *data, size_t size) { return MeshFile("obj", data, size); }
inline int MeshPly(const uint8_t *data, size_t size) { return MeshFile("ply", data, size); }
inline int MeshOff(const uint8_t *data, size_t size) { return MeshFile("off", data, size); }
inline int MeshStl(const uint8_t *data, size_t size) { return MeshFile("stl", data, size); }

} // namespace gs_fuzz

#endif
