#ifndef VCG_EXT_SNAKE_PARTITION_H
#define VCG_EXT_SNAKE_PARTITION_H

// Partitioning of a snake into segments, Lee & Lee 2002 Section 5.1: a long snake is moved
// piece by piece, each piece in the plane of its own local embedding, and overlapping pieces
// across the borders smooth the joints (Fig. 2). Only sample indices are computed here; the
// operation (snake/operation.h) builds the regions and moves the samples.

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include <vcg/space/point3.h>

#include <vcg_ext/snake/error.h>

namespace vcg {
namespace tri {

/// Consecutive samples of a snake moved in one embedding. On a closed snake the indices wrap
/// from n-1 to 0. The first / last sample is held when the flag is set (a border, Sec. 5.1).
struct SnakeSegment
{
    std::vector<int> idx;
    bool fixFirst = false, fixLast = false;
};

/// Splits a snake of n samples into segments of about `segmentSamples` samples plus one
/// overlapping segment across each border. Borders keep away from sharp corners, where the
/// snake bends most and a held border sample would spoil the bend. Pins need no special care:
/// the engine holds a pinned sample wherever it lies in a segment.
///
/// Correct by construction: borders are placed left to right inside bounds that leave every
/// later segment at least 3 samples, so every index lies in [0, n) and the segments cover every
/// sample and every gap; Check() verifies it.
class SnakePartition
{
public:
    struct Result
    {
        std::vector<SnakeSegment> segments; ///< cover the snake, consecutive segments share a border
        std::vector<SnakeSegment> overlaps; ///< one across each border, ends held
    };

    /// Samples where the curve turns by more than 60 degrees (the ends of an open snake are not corners).
    static std::vector<int> Corners(const std::vector<vcg::Point3d> &p, bool closed)
    {
        const int n = int(p.size());
        std::vector<int> corners;
        if (n < 3) return corners;
        for (int i = 0; i < n; ++i) {
            if (!closed && (i == 0 || i == n - 1)) continue;
            const vcg::Point3d a = p[i] - p[(i - 1 + n) % n], b = p[(i + 1) % n] - p[i];
            const double na = a.Norm(), nb = b.Norm();
            if (na > 0 && nb > 0 && (a * b) / (na * nb) < 0.5) corners.push_back(i);
        }
        return corners;
    }

    /// Segments of a snake of n samples; `corners` are sample indices (any order, repeats allowed).
    static Result Compute(int n, bool closed, int segmentSamples, std::vector<int> corners)
    {
        Result r;
        if (n < 1) return r;
        if (segmentSamples < 6) throw SnakeError("Snake partition: segments need at least 6 samples.");
        const int S = segmentSamples;
        corners.erase(std::remove_if(corners.begin(), corners.end(), [n](int c) { return c < 0 || c >= n; }),
                      corners.end());
        std::sort(corners.begin(), corners.end());
        corners.erase(std::unique(corners.begin(), corners.end()), corners.end());

        if ((!closed && n <= S) || (closed && n < 6)) { // one segment; a tiny closed snake as one loop
            SnakeSegment s;
            for (int i = 0; i < n; ++i) s.idx.push_back(i);
            r.segments.push_back(s);
            return r;
        }
        // K segments: each has at least 3 samples, so K <= (n-1)/2 open and K <= n/2 closed.
        int K = closed ? std::max(2, (n + S - 1) / S) : (n - 1 + S - 2) / (S - 1);
        K = std::min(K, closed ? n / 2 : (n - 1) / 2);
        const int64_t span = closed ? n : n - 1; // border positions, unwrapped, run over [b0, b0 + span]
        const int w = std::max(1, int(span / (2 * K))); // how far a border may move from its even place

        // Where a border lies farthest from the corners within reach of its even place, between lo and hi.
        auto place = [&](int64_t ideal, int64_t lo, int64_t hi) -> int64_t {
            int64_t from = std::max(lo, ideal - w), to = std::min(hi, ideal + w);
            if (from > to) return std::min(hi, std::max(lo, ideal));
            int64_t best = std::min(hi, std::max(lo, ideal));
            int bestScore = -1;
            for (int64_t c = from; c <= to; ++c) {
                const int score = std::min(w, cornerDistance(corners, int(((c % n) + n) % n), n, closed));
                if (score > bestScore || (score == bestScore && std::abs(c - ideal) < std::abs(best - ideal))) {
                    bestScore = score;
                    best = c;
                }
            }
            return best;
        };
        std::vector<int64_t> b(K + 1);
        b[0] = closed ? place(0, -w, w) : 0;
        b[K] = b[0] + span;
        for (int k = 1; k < K; ++k)
            b[k] = place(b[0] + int64_t(k) * span / K, b[k - 1] + 2, b[K] - 2 * int64_t(K - k));
        for (int k = 0; k < K; ++k) {
            SnakeSegment s;
            for (int64_t i = b[k]; i <= b[k + 1]; ++i) s.idx.push_back(wrap(i, n));
            s.fixFirst = closed || k != 0;
            s.fixLast = closed || k != K - 1;
            r.segments.push_back(s);
        }
        // Overlapping segments across each border, with their own ends held (Fig. 2).
        const int half = std::max(3, S / 4); // enough on each side to smooth the border
        for (int k = closed ? 0 : 1; k < K; ++k) {
            int64_t from = b[k] - half, to = b[k] + half;
            if (!closed) {
                from = std::max<int64_t>(0, from);
                to = std::min<int64_t>(n - 1, to);
            } else if (to - from + 1 >= n) { // small loop: all but one sample, the border in the middle
                from = b[k] - n / 2 + 1;
                to = from + n - 2;
            }
            SnakeSegment s;
            for (int64_t i = from; i <= to; ++i) s.idx.push_back(wrap(i, n));
            s.fixFirst = closed || from > 0;
            s.fixLast = closed || to < n - 1;
            r.overlaps.push_back(s);
        }
        return r;
    }

    /// True for the single segment of a tiny closed snake, which the engine moves as a loop.
    static bool IsWholeLoop(const SnakeSegment &s, int n, bool closed)
    {
        return closed && int(s.idx.size()) == n && !s.idx.empty() && s.idx.front() == 0 && !s.fixFirst;
    }

    /// The invariant the engine relies on: every segment is a run of 2..n consecutive samples
    /// inside [0, n), and the segments cover every sample and every gap between samples.
    /// Throws SnakeError (an internal error) otherwise, before any sample is touched.
    static void Check(const Result &r, int n, bool closed)
    {
        auto fail = [&](const std::string &why) {
            throw SnakeError("Geometric snake: internal error in partitioning (" + why + ", " + std::to_string(n) +
                             (closed ? " samples, closed)." : " samples, open)."));
        };
        const int gaps = closed ? n : std::max(0, n - 1);
        std::vector<char> sample(std::max(n, 0), 0), gap(std::max(gaps, 0), 0);
        auto checkOne = [&](const SnakeSegment &s, const std::string &what, bool cover) {
            const int k = int(s.idx.size());
            if (k > n || (k < 2 && n >= 2) || k < 1) fail(what + " has " + std::to_string(k) + " samples");
            for (int j = 0; j < k; ++j) {
                const int i = s.idx[j];
                if (i < 0 || i >= n) fail(what + " holds sample " + std::to_string(i));
                if (j > 0 && !(i == s.idx[j - 1] + 1 || (closed && s.idx[j - 1] == n - 1 && i == 0)))
                    fail(what + " is not consecutive at position " + std::to_string(j));
                if (!cover) continue;
                sample[i] = 1;
                if (j > 0) gap[s.idx[j - 1]] = 1;
            }
            if (cover && IsWholeLoop(s, n, closed) && gaps > 0) gap[n - 1] = 1;
        };
        for (size_t k = 0; k < r.segments.size(); ++k) checkOne(r.segments[k], "segment " + std::to_string(k), true);
        for (size_t k = 0; k < r.overlaps.size(); ++k) checkOne(r.overlaps[k], "overlap " + std::to_string(k), false);
        for (int i = 0; i < n; ++i)
            if (!sample[i]) fail("sample " + std::to_string(i) + " is in no segment");
        for (int g = 0; g < gaps; ++g)
            if (!gap[g]) fail("gap " + std::to_string(g) + " is in no segment");
    }

private:
    static int wrap(int64_t i, int n) { return int(((i % n) + n) % n); }

    /// Distance (in samples) from i to the nearest corner; cyclic on closed snakes. `corners` sorted.
    static int cornerDistance(const std::vector<int> &corners, int i, int n, bool closed)
    {
        if (corners.empty()) return n;
        auto it = std::lower_bound(corners.begin(), corners.end(), i);
        int d = n;
        if (it != corners.end()) d = std::min(d, *it - i);
        if (it != corners.begin()) d = std::min(d, i - *(it - 1));
        if (closed) {
            d = std::min(d, corners.front() + n - i);
            d = std::min(d, i + n - corners.back());
        }
        return d;
    }
};

} // namespace tri
} // namespace vcg

#endif
