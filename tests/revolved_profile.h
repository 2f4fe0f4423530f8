#ifndef GS_TESTS_REVOLVED_PROFILE_H
#define GS_TESTS_REVOLVED_PROFILE_H

// Generated parts on a body whose boundary is known exactly: closed surfaces revolved round z
// from a profile of straight runs (a limb of even width, a short stub). Shared by
// test_part_boundary and bench_edit_response (BM_PartEndTowardBody).

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <snake_test_util.h>

namespace gs_test {

/// A corner of a revolved profile, (r, z), reached from the previous corner by k points evenly
/// spaced (k <= 0: as many as make them about the profile's step apart; the first corner's k is
/// unused).
struct ProfileCorner
{
    double r, z;
    int k;
};

/// A closed surface revolved round z with n vertices a ring, its profile through `corners` from
/// the top axis to the bottom axis (r = 0 at both: a pole of one vertex), quads split by one
/// diagonal, outward normals. Returns the index of the first vertex of each ring at radius `tube`
/// with z >= 0, by its height in steps (ring[j]: z = j step), `rings` entries (-1 where none is).
inline std::vector<int> MakeRevolvedProfile(CMeshO &m, const std::vector<ProfileCorner> &corners, int n, double step,
                                            double tube, int rings)
{
    std::vector<std::pair<double, double>> prof; // (r, z), from the top axis to the bottom axis
    prof.push_back({corners[0].r, corners[0].z});
    for (size_t c = 1; c < corners.size(); ++c) { // the previous corner excluded, this one included
        const double r0 = corners[c - 1].r, z0 = corners[c - 1].z, r1 = corners[c].r, z1 = corners[c].z;
        int k = corners[c].k;
        if (k <= 0) k = std::max(1, int(std::lround(std::hypot(r1 - r0, z1 - z0) / step)));
        for (int i = 1; i <= k; ++i) prof.push_back({r0 + (r1 - r0) * i / k, z0 + (z1 - z0) * i / k});
    }
    std::vector<int> ring(rings, -1), first(prof.size());
    for (size_t j = 0; j < prof.size(); ++j) {
        const double r = prof[j].first, z = prof[j].second;
        first[j] = int(m.vert.size());
        if (r < 1e-12) { // a pole: one vertex
            vcg::tri::Allocator<CMeshO>::AddVertex(m, Point3m(0, 0, z));
            continue;
        }
        const long at = std::lround(z / step);
        if (std::fabs(r - tube) < 1e-9 && z > -1e-9 && at < rings) ring[at] = first[j];
        auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(m, n);
        for (int k = 0; k < n; ++k, ++vi) vi->P() = Point3m(r * std::cos(2 * M_PI * k / n), r * std::sin(2 * M_PI * k / n), z);
    }
    auto V = [&](size_t j, int k) { return &m.vert[prof[j].first < 1e-12 ? first[j] : first[j] + k % n]; };
    for (size_t j = 0; j + 1 < prof.size(); ++j)
        for (int k = 0; k < n; ++k) { // outward normals: the profile runs top to bottom
            if (prof[j].first >= 1e-12) vcg::tri::Allocator<CMeshO>::AddFace(m, V(j, k), V(j + 1, k), V(j, k + 1));
            if (prof[j + 1].first >= 1e-12) vcg::tri::Allocator<CMeshO>::AddFace(m, V(j, k + 1), V(j + 1, k), V(j + 1, k + 1));
        }
    gs_test::EnableSnakeAdjacency(m);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
    return ring;
}

/// A short thin part on a body (issue 33, session 27; cf. the fourleg 381's ears, 5 rings deep),
/// n vertices a ring: a tube of radius 0.2 from z = 0 to 0.3 (rings `step` apart), a flat cone
/// tip to (0, 0, 0.35) in 0.3 / step rings (at least 3), the body opening at 45 degrees
/// below z = 0 (a concave crease round the part's base, the answer) to radius 1.2, down to
/// z = -2, closed. Returns the index of each tube ring's first vertex by its height in steps.
inline std::vector<int> MakeStubOnBody(CMeshO &m, int n, double step)
{
    const double r = 0.2, top = 0.3;
    const int tip = std::max(3, int(std::lround(0.3 / step)));
    return MakeRevolvedProfile(m,
                               {{0.0, top + 0.05, 0},
                                {r, top, tip},         // the tip
                                {r, 0.0, 0},           // the part
                                {1.2, r - 1.2, 0},     // the body opens at 45 degrees
                                {1.2, -2.0, 0},
                                {0.0, -2.0, 0}},
                               n, step, r, int(std::lround(top / step)) + 1);
}

} // namespace gs_test

#endif
