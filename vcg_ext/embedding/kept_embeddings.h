#ifndef VCG_EXT_SNAKE_KEPT_EMBEDDINGS_H
#define VCG_EXT_SNAKE_KEPT_EMBEDDINGS_H

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include <vcg_ext/embedding/local_region.h>
#include <vcg_ext/embedding/virtual_boundary_param.h>
#include <vcg_ext/snake/curve.h>
#include <vcg_ext/snake/partition.h>
#include <vcg_ext/surface/surface_point.h>

namespace vcg {
namespace tri {

/// A local region with its planar embedding (Sec. 5.2-5.3), kept across operations while
/// the samples of a segment stay well inside it: within half its margin of its core, i.e.
/// at least half the margin from its border. A region without a margin (trimmed) serves
/// only its own segment, and only until a sample moves.
template <class MeshType>
struct SnakeEmbedding
{
    LocalRegion<MeshType> region;
    VirtualBoundaryParam::Result emb;
    std::vector<std::pair<int, int>> lookup; // (mesh face, local face), sorted
    std::vector<Eigen::Vector2d> anchor;     // the segment's samples in the plane when embedded
    std::vector<Eigen::Matrix2d> jinvT;      // per real face, computed on first use
    std::vector<char> jDone;
    double distortion = 1; // worst on the faces carrying samples when embedded
    int first = 0, count = 0, samples = 0; // the segment it was made for, of a snake of `samples`
    long used = 0;                         // the last operation it served
    bool valid = false;

    int LocalFace(int meshFace) const
    {
        auto it = std::lower_bound(lookup.begin(), lookup.end(), std::make_pair(meshFace, -1));
        return (it != lookup.end() && it->first == meshFace) ? it->second : -1;
    }
    /// The point with barycentric coordinates b in local face t, in the plane.
    template <class V>
    Eigen::Vector2d ToPlane(int t, const V &b) const
    {
        const auto &T = region.tri[t];
        return double(b[0]) * emb.uv[T[0]] + double(b[1]) * emb.uv[T[1]] + double(b[2]) * emb.uv[T[2]];
    }
    /// The width of embedded triangle t in direction d (unit vector): a step cap from the
    /// local triangle size where the sample goes, so that on long thin triangles a move across
    /// them is capped by their short side, not by their mean edge.
    double WidthAlong(int t, const Eigen::Vector2d &d) const
    {
        const auto &T = region.tri[t];
        double a = emb.uv[T[0]].dot(d), b = emb.uv[T[1]].dot(d), c = emb.uv[T[2]].dot(d);
        return std::max({a, b, c}) - std::min({a, b, c});
    }
    const Eigen::Matrix2d &JinvT(int t)
    {
        if (!jDone[t]) {
            jDone[t] = 1;
            const auto &T = region.tri[t];
            Eigen::Matrix2d J;
            J.col(0) = emb.uv[T[1]] - emb.uv[T[0]];
            J.col(1) = emb.uv[T[2]] - emb.uv[T[0]];
            jinvT[t] = std::abs(J.determinant()) > 1e-12 ? Eigen::Matrix2d(J.transpose().inverse())
                                                          : Eigen::Matrix2d::Zero();
        }
        return jinvT[t];
    }
    /// Conformal and area distortion of local face t: the larger singular value of the
    /// 3D -> plane map over the smaller one, times how far its scale is from 1/unit.
    double Distortion(int t, double unit) const
    {
        const auto &T = region.tri[t];
        const vcg::Point3d e1 = region.pos[T[1]] - region.pos[T[0]], e2 = region.pos[T[2]] - region.pos[T[0]];
        const vcg::Point3d n = e1 ^ e2;
        const double l1 = e1.Norm(), a2 = n.Norm();
        if (!(l1 > 0) || !(a2 > 0)) return 1;
        const vcg::Point3d x = e1 / l1, y = (n / a2) ^ x;
        Eigen::Matrix2d P, J;
        P << l1, e2 * x, 0, e2 * y;
        J.col(0) = emb.uv[T[1]] - emb.uv[T[0]];
        J.col(1) = emb.uv[T[2]] - emb.uv[T[0]];
        const Eigen::Vector2d sv = Eigen::JacobiSVD<Eigen::Matrix2d>(J * P.inverse()).singularValues() * unit;
        if (!(sv[1] > 0) || !std::isfinite(sv[0])) return 1e9;
        const double scale = std::sqrt(sv[0] * sv[1]);
        return sv[0] / sv[1] * std::max(scale, 1 / scale);
    }

    /// The segment's samples in this plane (lf: their local faces, X: their positions); false
    /// when one of them is no longer well inside it.
    bool Locate(const SnakeCurve &st, const SnakeSegment &seg, std::vector<int> &lf, Eigen::MatrixXd &X) const
    {
        const int k = int(seg.idx.size());
        const LocalRegion<MeshType> &R = region;
        const bool grown = R.margin > 0 && R.depth.size() == R.pos.size();
        if (!grown && (first != seg.idx.front() || count != k || int(anchor.size()) != k)) return false;
        for (int j = 0; j < k; ++j) {
            const SurfacePoint &p = st.samples[seg.idx[j]].p;
            lf[j] = LocalFace(p.face);
            if (lf[j] < 0) return false;
            X.row(j) = ToPlane(lf[j], p.bary).transpose();
            if (grown) {
                const auto &T = R.tri[lf[j]];
                if (p.bary[0] * R.depth[T[0]] + p.bary[1] * R.depth[T[1]] + p.bary[2] * R.depth[T[2]] > 0.5 * R.margin)
                    return false;
            } else if (X.row(j).transpose() != anchor[j]) {
                return false;
            }
        }
        return true;
    }
};

/// The embeddings one snake keeps across operations (Sec. 4.2: one embedding serves several
/// updates, here several operations). Each is filed under the segment it was made for and
/// serves whichever segment its samples form, as long as they stay well inside it
/// (SnakeEmbedding::Locate): the partition's borders move with the corners of the curve.
template <class MeshType>
class SnakeKeptEmbeddings
{
public:
    typedef SnakeEmbedding<MeshType> Embedding;

    void Clear() { kept.clear(); }

    /// How many embeddings are kept (one may serve several segments).
    int Count() const
    {
        std::vector<const Embedding *> e;
        for (const auto &k : kept) e.push_back(k.second.get());
        std::sort(e.begin(), e.end());
        return int(std::unique(e.begin(), e.end()) - e.begin());
    }

    /// Samples were inserted into an open snake of `before` samples (their indices now,
    /// ascending: SnakeGapRefine): the embeddings go on serving, filed under their segments
    /// renumbered, and one whose segment an inserted sample falls into holds it too (it lies on
    /// the curve between two of its samples; Locate still checks that it is well inside). A region
    /// without a margin serves only its own samples as they were: it is dropped then.
    /// Precondition: the snake is open. SnakeGapRefine inserts samples only into open snakes, and
    /// the renumbering below does not wrap round (a closed snake's segments may run past n-1).
    void SamplesInserted(const std::vector<int> &inserted, int before)
    {
        if (inserted.empty()) return;
        auto follow = [&](int i) {
            for (int k : inserted)
                if (k <= i) ++i;
            return i;
        };
        std::map<std::pair<int, int>, std::shared_ptr<Embedding>> next;
        std::vector<Embedding *> done;
        for (auto &e : kept) {
            const int f = follow(e.first.first), l = follow(e.first.first + e.first.second - 1);
            Embedding *E = e.second.get();
            if (E && std::find(done.begin(), done.end(), E) == done.end()) {
                done.push_back(E);
                if (E->samples == before) {
                    const int ef = follow(E->first), el = follow(E->first + E->count - 1);
                    if (el - ef + 1 != E->count && !(E->region.margin > 0)) E->valid = false;
                    E->first = ef;
                    E->count = el - ef + 1;
                    E->samples = before + int(inserted.size());
                } else {
                    E->valid = false;
                }
            }
            next[std::make_pair(f, l - f + 1)] = std::move(e.second);
        }
        kept.swap(next);
    }

    /// A new operation: embeddings that served neither the last one nor the one before are
    /// dropped (the partition moved on), so that the kept ones stay about one per segment.
    void BeginOperation()
    {
        ++operation;
        for (auto it = kept.begin(); it != kept.end();)
            if (!it->second || it->second->used < operation - 2) it = kept.erase(it);
            else ++it;
    }

    /// The embedding segment `seg` moves in: a kept one that holds its samples well inside it
    /// (true; lf and X: the samples in its plane), else one to build anew (false).
    bool Acquire(const SnakeCurve &st, const SnakeSegment &seg, std::vector<int> &lf, Eigen::MatrixXd &X, Embedding *&out)
    {
        std::shared_ptr<Embedding> &slot = kept[std::make_pair(seg.idx.front(), int(seg.idx.size()))];
        std::shared_ptr<Embedding> found =
            slot && slot->valid && slot->Locate(st, seg, lf, X) ? slot : adopt(st, seg, slot.get(), lf, X);
        if (found)
            slot = found;
        else if (!slot || slot.use_count() > 1)
            slot = std::make_shared<Embedding>(); // another segment still holds the old one
        slot->used = operation;
        out = slot.get();
        return bool(found);
    }

private:
    // by segment (first sample, samples); segments whose samples one embedding holds share it
    std::map<std::pair<int, int>, std::shared_ptr<Embedding>> kept;
    long operation = 0;
    std::vector<std::pair<int, const std::shared_ptr<Embedding> *>> candidates; // adopt(): no copies, no use_count

    /// A kept embedding made for another segment that holds this one's samples well inside it
    /// (the borders moved): the ones made for overlapping stretches of the snake, most overlap
    /// first. `tried`: the segment's own, which already failed.
    std::shared_ptr<Embedding> adopt(const SnakeCurve &st, const SnakeSegment &seg, const Embedding *tried,
                                     std::vector<int> &lf, Eigen::MatrixXd &X)
    {
        const int n = int(st.samples.size());
        auto &cand = candidates;
        cand.clear();
        for (const auto &e : kept) {
            const Embedding *E = e.second.get();
            if (!E || E == tried || !E->valid || E->samples != n || !(E->region.margin > 0)) continue;
            if (std::any_of(cand.begin(), cand.end(), [&](const auto &c) { return c.second->get() == E; })) continue;
            int overlap = 0;
            for (int i : seg.idx) overlap += ((i - E->first) % n + n) % n < E->count;
            if (overlap > 0) cand.emplace_back(-overlap, &e.second);
        }
        // most overlap first, ties in the map's order (by segment): never by address, which
        // would make the snake depend on the heap
        std::stable_sort(cand.begin(), cand.end(), [](const auto &a, const auto &b) { return a.first < b.first; });
        for (const auto &c : cand)
            if ((*c.second)->Locate(st, seg, lf, X)) return *c.second;
        return nullptr;
    }
};

} // namespace tri
} // namespace vcg

#endif
