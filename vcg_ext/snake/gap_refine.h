#ifndef VCG_EXT_SNAKE_GAP_REFINE_H
#define VCG_EXT_SNAKE_GAP_REFINE_H

// An open snake that lengthens keeps the sample density it was built with (beyond the paper,
// whose snakes keep the samples they were built with, Sec. 7). The spline energy of Eq. 2 is
// discrete: its pull on a sample grows with the distance to its neighbours, so a snake seeded
// on a cap 4 edge lengths inside its rim, which must stretch 1.6-2.6x to reach the rim, ends
// with samples 2-4 spacings apart whose tension and rigidity outweigh the feature force: on a
// CAD cap of long slivers the middle of the curve stayed 4-5 edge lengths inside the rim. Here
// a gap (two consecutive samples) longer than kSplit times the reference spacing gets a sample
// at its middle on the curve, before an operation.
//
// The reference is the larger of the Spacing parameter and the spacing the snake was built
// (or restored) with: the parameter applies when a snake is built, so lowering it on an
// existing snake (0.05 edge lengths: 20x the samples) does not densify that snake.

#include <algorithm>
#include <utility>
#include <vector>

#include <vcg/space/point3.h>

#include <vcg_ext/paths/initial_curve.h>
#include <vcg_ext/snake/curve.h>
#include <vcg_ext/snake/polyline.h>
#include <vcg_ext/surface/snake_surface.h>

namespace vcg {
namespace tri {

template <class MeshType>
class SnakeGapRefine
{
public:
    typedef SnakeSurface<MeshType> Surface;
    typedef SnakePolyline<MeshType> Line;

    /// A gap longer than this many reference spacings is split in two.
    static constexpr double kSplit = 2.0;
    /// At most this many samples per reference spacing of the curve's length.
    static constexpr double kBudget = 2.0;

    /// The median distance between consecutive samples, in length units (0 with fewer than two).
    static double MedianGap(const Surface &surf, const SnakeCurve &c)
    {
        const int n = int(c.samples.size()), gaps = c.NumGaps();
        std::vector<double> d;
        for (int g = 0; g < gaps; ++g)
            d.push_back((c.samples[(g + 1) % n].p.Pd(surf.Mesh()) - c.samples[g].p.Pd(surf.Mesh())).Norm() / c.unit);
        if (d.empty()) return 0;
        std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
        return d[d.size() / 2];
    }

    /// The spacing (length units) the snake keeps: the larger of its parameter and the spacing it
    /// was built with.
    static double Reference(const SnakeCurve &c) { return std::max(c.params.spacing, c.builtSpacing); }

    /// Splits every gap of an open snake whose samples are more than kSplit reference spacings
    /// apart (straight in space) at its middle on the curve (SnakePolyline::GapMiddle): at most
    /// one new sample per gap and call, none past Initial::MaxSamples(). The new samples are
    /// free, start where the curve is, and are held on level 0 when both neighbours are. Their
    /// gaps are untraced. Returns their indices, ascending (SnakeGapRefine::Follow maps the
    /// older ones).
    static std::vector<int> Refine(const Surface &surf, SnakeCurve &c)
    {
        std::vector<int> inserted;
        const int n = int(c.samples.size());
        if (c.closed || n < 2 || !(c.unit > 0)) return inserted;
        const double ref = Reference(c) * c.unit, limit = kSplit * ref;
        std::vector<std::pair<double, int>> longGaps;
        double L = 0;
        for (int g = 0; g + 1 < n; ++g) {
            const double d = (c.samples[g + 1].p.Pd(surf.Mesh()) - c.samples[g].p.Pd(surf.Mesh())).Norm();
            L += d;
            if (d > limit) longGaps.emplace_back(-d, g);
        }
        // at most twice the density of the reference spacing
        const long budget = std::min<long>(SnakeInitialCurve<MeshType>::MaxSamples(), long(kBudget * L / ref) + 1) - n;
        if (budget <= 0 || longGaps.empty()) return inserted;
        std::sort(longGaps.begin(), longGaps.end()); // longest first
        if (long(longGaps.size()) > budget) longGaps.resize(budget);
        std::vector<int> split;
        for (const auto &lg : longGaps) split.push_back(lg.second);
        std::sort(split.begin(), split.end());
        std::vector<SnakeSample> mids;
        for (int g : split) {
            SnakeSample s;
            s.p = Line::GapMiddle(surf, c, g);
            const SnakeSample &a = c.samples[g], &b = c.samples[g + 1];
            s.trust = std::min(a.trust, b.trust);
            s.heldFine = a.heldFine && b.heldFine;
            mids.push_back(s);
        }
        for (size_t k = 0; k < split.size(); ++k) { // ascending: earlier insertions shift later ones by k
            const int at = split[k] + 1 + int(k);
            c.samples.insert(c.samples.begin() + at, mids[k]);
            Line::SplitGap(c, at - 1);
            inserted.push_back(at);
        }
        return inserted;
    }

    /// Where sample i is after the samples `inserted` (Refine's answer) were inserted (-1 stays -1).
    static int Follow(int i, const std::vector<int> &inserted)
    {
        if (i < 0) return i;
        for (int k : inserted)
            if (k <= i) ++i;
        return i;
    }
};

} // namespace tri
} // namespace vcg

#endif
