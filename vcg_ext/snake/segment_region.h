#ifndef VCG_EXT_SNAKE_SEGMENT_REGION_H
#define VCG_EXT_SNAKE_SEGMENT_REGION_H

#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include <vcg_ext/embedding/conformal_param.h>
#include <vcg_ext/embedding/kept_embeddings.h>
#include <vcg_ext/embedding/local_region.h>
#include <vcg_ext/embedding/virtual_boundary_param.h>
#include <vcg_ext/snake/curve.h>
#include <vcg_ext/snake/partition.h>
#include <vcg_ext/surface/face_path.h>
#include <vcg_ext/surface/snake_surface.h>
#include <vcg_ext/surface/surface_point.h>

namespace vcg {
namespace tri {

/// The local region of a snake segment and its planar embedding (Sec. 5.2 - 5.3), made when no
/// kept one serves the segment (SnakeKeptEmbeddings): the faces the segment crosses plus a band
/// around them (LocalRegion), embedded conformally or, failing that, with the paper's virtual
/// boundary; grown, or narrowed, where it is too distorted at the samples. SnakeSegmentMotion
/// moves the samples in it.
template <class MeshType>
class SnakeSegmentRegion
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef SnakeSurface<MeshType> Surface;
    typedef SnakeEmbedding<MeshType> Embedding;

    explicit SnakeSegmentRegion(std::shared_ptr<Surface> s) : surf(std::move(s)) {}

    int conformalFallbacks = 0; ///< embeddings that fell back to the virtual boundary

    /// The region and embedding `E` of segment `seg` of `st` (its first `gapsInSeg` gaps inside
    /// it), with the samples' local faces `lf` and plane positions `X`; a gap not traced yet
    /// gets its face path. False when no region or embedding could be made (E's errors say why).
    bool Build(SnakeCurve &st, const SnakeSegment &seg, int gapsInSeg, double unit, Embedding &E, std::vector<int> &lf,
               Eigen::MatrixXd &X)
    {
        const int k = int(seg.idx.size());
        // Sec. 5.2: the faces the segment crosses ...
        core.clear();
        for (int j = 0; j < k; ++j) { // in curve order: the region numbers its vertices by it
            core.push_back(st.samples[seg.idx[j]].p.face);
            if (j >= gapsInSeg) continue;
            int g = st.GapIndex(seg.idx[j], seg.idx[(j + 1) % k]);
            if (g < 0) continue;
            SnakeGap &gap = st.gaps[g];
            if (gap.faces.empty())
                gap.faces = FacePath<MeshType>::Find(*surf, st.samples[seg.idx[j]].p.face, st.samples[seg.idx[(j + 1) % k]].p.face);
            core.insert(core.end(), gap.faces.begin(), gap.faces.end());
        }
        // ... plus a band around them (LocalRegion), then Sec. 5.3.
        return build(st, seg, core, unit, E, lf, X);
    }

private:
    /// A new region around `core` and its embedding; its margin (a distance on each side) is at
    /// least twice the sample spacing and 1.5 times the longest edge the segment crosses. When the
    /// faces carrying samples are embedded with a distortion above kMaxDistortion, the region grows once.
    bool build(const SnakeCurve &st, const SnakeSegment &seg, const std::vector<int> &core, double unit, Embedding &E,
               std::vector<int> &lf, Eigen::MatrixXd &X)
    {
        const int k = int(seg.idx.size());
        // the region with the given margin, its embedding, and the samples in it
        auto attempt = [&](double margin) {
            lf.resize(k);
            X.resize(k, 2);
            if (!E.region.Build(*surf, core, 60000, margin)) return false;
            if (!embed(st.params, unit, E.region, E.emb)) return false;
            E.lookup.clear();
            for (int t = 0; t < E.region.RealFaces(); ++t) E.lookup.emplace_back(E.region.faces[t], t);
            std::sort(E.lookup.begin(), E.lookup.end());
            E.distortion = 1;
            for (int j = 0; j < k; ++j) {
                const SurfacePoint &p = st.samples[seg.idx[j]].p;
                lf[j] = E.region.LocalFace(*surf, p.face);
                if (lf[j] < 0) return false; // cannot happen: sample faces are in the core
                X.row(j) = E.ToPlane(lf[j], p.bary).transpose();
                E.distortion = std::max(E.distortion, E.Distortion(lf[j], unit));
            }
            return true;
        };
        const double minMargin = 2 * st.params.spacing * unit;
        const double margin = std::max(minMargin, 1.5 * longestCrossed(st, seg));
        if (!attempt(margin)) return false;
        // Too distorted where the samples are: grow the region once (a wider band moves the
        // free border, or the virtual boundary, away from them); keep the better of the two.
        // The first is set aside meanwhile, not built again: on bunny00's 300-sample loop growing
        // made 40 of 50 regions worse, and each of those was built twice.
        if (!(E.distortion <= kMaxDistortion) && E.region.margin > 0) {
            auto &a = aside;
            auto swapAside = [&] {
                std::swap(E.region, a.region);
                std::swap(E.emb, a.emb);
                E.lookup.swap(a.lookup);
                lf.swap(a.lf);
                X.swap(a.X);
                std::swap(E.distortion, a.distortion);
            };
            swapAside();
            if (!attempt(2 * margin)) return false;
            if (!(E.distortion <= a.distortion)) swapAside();
            // Still too distorted, and the margin was set by long edges: slivers spanning a
            // curved part made the region reach around it (a strip-tessellated CAD cap: its
            // slivers span the cap, so the margin took the cap and its side walls, a cup,
            // embedded with distortion 13.5 on the cap's faces), and growing does not help. The
            // narrowest margin (the sample spacing's) keeps the region near the samples' own
            // faces, and it is still kept while they stay in it. The cup's embedding, kept, had
            // served a closed snake there for its whole run, which stayed 0.6-1.6 h off the rim.
            if (!(E.distortion <= kMaxDistortion) && margin > minMargin) {
                swapAside();
                if (!attempt(minMargin) || !(E.distortion < a.distortion)) swapAside();
            }
        }
        E.jinvT.resize(E.region.RealFaces());
        E.jDone.assign(E.region.RealFaces(), 0);
        E.anchor.resize(k);
        for (int j = 0; j < k; ++j) E.anchor[j] = X.row(j).transpose();
        E.first = seg.idx.front();
        E.count = k;
        E.samples = int(st.samples.size());
        E.valid = true;
        return true;
    }

    /// The longest mesh edge the segment's polyline crosses (shared by consecutive faces of a
    /// traced gap), or the longest edge of the sample faces when no gap is traced.
    double longestCrossed(const SnakeCurve &st, const SnakeSegment &seg) const
    {
        const MeshType &m = surf->Mesh();
        const int k = int(seg.idx.size());
        double longest = 0;
        auto edge = [&](const FaceType &f, int e) { // in double: a float square overflows at 1e30
            return vcg::Distance(vcg::Point3d::Construct(f.cP(e)), vcg::Point3d::Construct(f.cP((e + 1) % 3)));
        };
        auto sharedEdge = [&](int a, int b) {
            for (int e = 0; e < 3; ++e)
                if (m.face[a].cFFp(e) == &m.face[b]) longest = std::max(longest, edge(m.face[a], e));
        };
        for (int j = 0; j + 1 < k; ++j) {
            const int g = st.GapIndex(seg.idx[j], seg.idx[j + 1]);
            if (g < 0) continue;
            const std::vector<int> &f = st.gaps[g].faces;
            for (size_t i = 0; i + 1 < f.size(); ++i)
                if (f[i] != f[i + 1]) sharedEdge(f[i], f[i + 1]);
        }
        if (longest > 0) return longest;
        for (int j = 0; j < k; ++j) {
            const auto &f = m.face[st.samples[seg.idx[j]].p.face];
            for (int e = 0; e < 3; ++e) longest = std::max(longest, edge(f, e));
        }
        return longest;
    }

    /// The local embedding (Sec. 5.3): least-squares conformal first, which embeds developable
    /// regions exactly; if it flips a triangle, the paper's convex combination with a virtual
    /// boundary, which is injective whatever the geometry.
    bool embed(const SnakeParams &params, double unit, const LocalRegion<MeshType> &region,
               VirtualBoundaryParam::Result &emb)
    {
        emb = VirtualBoundaryParam::Result();
        std::string err;
        if (ConformalParam::Embed(region.pos, region.tri, region.boundary, unit, emb.uv, err, conformal,
                                  region.arc.empty() ? nullptr : &region.arc) &&
            VirtualBoundaryParam::CountFlipped(emb.uv, region.tri) == 0)
            return true;
        ++conformalFallbacks;
        return VirtualBoundaryParam::Embed(region.pos, region.tri, region.boundary, unit, params.virtualLayers, emb);
    }

    /// Distortion (angle times scale, Embedding::Distortion) of a sample's face above which a
    /// region grows: on a curved strip the conformal map alone reaches 2, and growing cannot
    /// undo curvature, so only embeddings spoiled by their border (the virtual one) grow.
    static constexpr double kMaxDistortion = 3.0;
    std::shared_ptr<Surface> surf;
    ConformalParam::Workspace conformal;
    std::vector<int> core; // Build(): reused, no allocation in the steady state
    struct Aside // build(): the first region while a grown one is tried
    {
        LocalRegion<MeshType> region;
        VirtualBoundaryParam::Result emb;
        std::vector<std::pair<int, int>> lookup;
        std::vector<int> lf;
        Eigen::MatrixXd X;
        double distortion = 1;
    } aside;
};

} // namespace tri
} // namespace vcg

#endif
