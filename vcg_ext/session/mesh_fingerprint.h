#ifndef VCG_EXT_SESSION_MESH_FINGERPRINT_H
#define VCG_EXT_SESSION_MESH_FINGERPRINT_H

// What a mesh is, as far as the snakes on it are concerned: surface points are (face index,
// barycentric coordinates), so a snake stays meaningful exactly while the faces keep their
// indices, their vertices (in order) and the vertices their positions. A fingerprint is taken
// when the edit tool leaves a mesh and compared when it comes back (a filter may have run in
// between): the kept undo history is used only on the very mesh it was recorded on.
// Selection, colour and quality are not part of it (MeshLab's Select All changes nothing here).

#include <cstdint>
#include <cstring>
#include <string>

namespace vcg {
namespace tri {

struct SnakeMeshFingerprint
{
    size_t vertSlots = 0, faceSlots = 0; ///< vert.size(), face.size(): the index ranges
    int vn = 0, fn = 0;                  ///< live vertices and faces (for the message)
    uint64_t topology = 0;               ///< deleted flags, and every live face's vertex indices in order
    uint64_t geometry = 0;               ///< every live vertex's coordinates, bit for bit

    template <class MeshType>
    static SnakeMeshFingerprint Of(const MeshType &m)
    {
        SnakeMeshFingerprint f;
        f.vertSlots = m.vert.size();
        f.faceSlots = m.face.size();
        f.vn = m.vn;
        f.fn = m.fn;
        uint64_t t = 0x6a09e667f3bcc908ull, g = 0xbb67ae8584caa73bull;
        const auto *v0 = m.vert.empty() ? nullptr : &m.vert[0];
        for (const auto &v : m.vert) {
            t = mix(t, v.IsD() ? 1 : 0);
            if (v.IsD()) continue;
            for (int k = 0; k < 3; ++k) g = mix(g, bits(double(v.cP()[k])));
        }
        for (const auto &fc : m.face) {
            t = mix(t, fc.IsD() ? 1 : 0);
            if (fc.IsD()) continue;
            for (int k = 0; k < 3; ++k) t = mix(t, uint64_t(fc.cV(k) - v0));
        }
        f.topology = t;
        f.geometry = g;
        return f;
    }

    bool operator==(const SnakeMeshFingerprint &o) const
    {
        return vertSlots == o.vertSlots && faceSlots == o.faceSlots && vn == o.vn && fn == o.fn &&
               topology == o.topology && geometry == o.geometry;
    }
    bool operator!=(const SnakeMeshFingerprint &o) const { return !(*this == o); }

    /// How `now` differs from this mesh, for the user ("" if it is the same mesh).
    std::string Change(const SnakeMeshFingerprint &now) const
    {
        if (vertSlots != now.vertSlots || faceSlots != now.faceSlots || vn != now.vn || fn != now.fn)
            return "vertices or faces were added or removed (" + std::to_string(vn) + " vertices and " +
                   std::to_string(fn) + " faces then, " + std::to_string(now.vn) + " and " + std::to_string(now.fn) +
                   " now)";
        if (topology != now.topology) return "faces were changed or deleted (the same counts, other vertices)";
        if (geometry != now.geometry) return "vertices were moved";
        return std::string();
    }

private:
    // a 64-bit mix per value (splitmix64's finaliser): any change of any value changes the sum
    static uint64_t mix(uint64_t h, uint64_t x)
    {
        x += 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
        x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
        x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
        return h ^ (x ^ (x >> 31));
    }
    static uint64_t bits(double d)
    {
        uint64_t u;
        std::memcpy(&u, &d, sizeof u);
        return u;
    }
};

} // namespace tri
} // namespace vcg

#endif
