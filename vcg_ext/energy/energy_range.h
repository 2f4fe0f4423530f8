#ifndef VCG_EXT_ENERGY_RANGE_H
#define VCG_EXT_ENERGY_RANGE_H

// The one rule that maps a feature energy (or any vertex quality driving a snake) to [0,1],
// 0 = strongest feature, 1 = flat. Every energy type and the snake's reading of the quality use
// it, so a field means the same wherever it is read.
//
// The flat end is a high percentile of all values (most of a mesh is flat), the feature end a
// low percentile (so a single spike does not squash the range). When features are fewer than
// that percentile, it falls on (or just below) the flat level: a thin crease on a fine mesh (one
// line of vertices, 0.1 % of a 1000 x 1000 grid) counted as outliers made the field constant.
// Then the feature end is the same percentile of the *non-flat* values only, of which the crease
// is all (or a clear part, beside float noise): the strongest features map to 0 whatever their
// share of the mesh, and a single spike still cannot squash the range.

#include <algorithm>
#include <cmath>
#include <vector>

namespace vcg {
namespace tri {

struct EnergyRange
{
    double lo = 0, hi = 1;
    bool constant = true; ///< no value stands out from the flat level: every vertex maps to 1

    /// The range of `vals` (finite, low = feature; reordered), `tail` the fraction of values
    /// clamped at each end (of all values at the flat end, of the non-flat ones at the feature end).
    static EnergyRange Of(std::vector<double> &vals, double tail)
    {
        EnergyRange r;
        const size_t n = vals.size();
        if (n == 0) return r;
        const size_t ih = size_t(std::ceil((1 - tail) * double(n - 1)));
        std::nth_element(vals.begin(), vals.begin() + ih, vals.end());
        r.hi = vals[ih];
        // flat: the flat level to float rounding (a planar fan's n_v . n_f is 1 - 6e-8)
        const double flat = r.hi - 1e-6 * std::max(1.0, std::fabs(r.hi));
        const size_t il = size_t(std::floor(tail * double(n - 1)));
        std::nth_element(vals.begin(), vals.begin() + il, vals.begin() + ih);
        r.lo = vals[il];
        const double least = *std::min_element(vals.begin(), vals.begin() + il + 1);
        // The features are fewer than `tail` when the percentile falls on the flat level or just
        // below it (float noise of a tessellated plane, the edge of a smoothed crease): a range
        // under 5 % of the full one. Then take them from the non-flat part.
        if (!(r.lo < flat) || r.hi - r.lo < 0.05 * (r.hi - least)) {
            const auto mid = std::partition(vals.begin(), vals.begin() + ih, [flat](double x) { return x < flat; });
            const size_t k = size_t(mid - vals.begin());
            if (k == 0) return r;
            const size_t jl = size_t(std::floor(tail * double(k - 1)));
            std::nth_element(vals.begin(), vals.begin() + jl, mid);
            r.lo = vals[jl];
        }
        r.constant = !(r.hi - r.lo > 1e-5 * std::max(1.0, std::max(std::fabs(r.lo), std::fabs(r.hi))));
        return r;
    }

    /// q in [0,1]: 0 at and below lo, 1 at and above hi; 1 for a constant range or a non-finite q.
    double Map(double q) const
    {
        if (constant || !std::isfinite(q)) return 1.0;
        return std::min(1.0, std::max(0.0, (q - lo) / (hi - lo)));
    }
};

} // namespace tri
} // namespace vcg

#endif
