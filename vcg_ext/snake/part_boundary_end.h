#ifndef VCG_EXT_PART_BOUNDARY_END_H
#define VCG_EXT_PART_BOUNDARY_END_H

// The end of a part-boundary Run (issue 33): the rule every host follows (the program, the
// filters, the edit tool, bench/eval/gs_parts) once a closed snake has converged on the
// part-boundary energy. The snake, smooth and held by its tension and rigidity, settles where
// its own energy balances; people cut a part along the cheapest loop of edges in its valley
// (valley_loop.h). The Run therefore ends on the valley loop round the snake, its band narrowed
// while it is no ring round a short part's tip, descended over bands and chosen by part
// salience (part_salience.h); when the loop shrank far, or no band round it holds a ring, also
// round the loop the Run started from (Seeded), and when no band round that one holds a ring
// either, from the seeds' ring towards the body (TowardBody); last, the loop kept gives way to
// a neighbour towards the body or the part that the surface bends across more (Across,
// loop_bend.h, session 28). The search itself (its cost, its band, its descent) is ValleyLoop's;
// this class is the choice of where to search and which loop to keep.

#include <functional>
#include <memory>
#include <unordered_map>
#include <utility>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/energy/feature_energy.h>
#include <vcg_ext/snake/crease_normals.h>
#include <vcg_ext/snake/loop_bend.h>
#include <vcg_ext/snake/part_salience.h>
#include <vcg_ext/snake/stop.h>
#include <vcg_ext/snake/valley_loop.h>

namespace vcg {
namespace tri {

template <class MeshType>
class PartBoundaryEnd
{
public:
    typedef ValleyLoop<MeshType> VL;
    typedef typename MeshType::FaceType FaceType;

    struct Param
    {
        /// The valley loop's search (band, length and concavity weights, descent).
        typename ValleyLoop<MeshType>::Param valley;
        /// A closed snake that converged shorter than this fraction of the loop it was seeded
        /// with (FinishRun's `seeded`, kept by the host) may have slid past the part's valley
        /// (an outside loop through the narrowing onto the part): the valley loop is also
        /// searched round the seeded loop and taken when it is cheaper per length. On
        /// bench/eval/gs_parts (--energy part --rings 2,3, session 25) against 156/220: 157
        /// (+1 -0: fourleg 381 part 3 outside 2). The seeded search's loop taken whenever the
        /// band holds a ring: 0.4 156, 0.5 158 (+2 -0), 0.6 159 (+3 -0), 0.75 157 (+3 -2), but
        /// a loop seeded far out on a featureless body would be pulled back there
        /// (ValleyLoop.SearchesRoundTheSeededLoopWhenTheSnakeShrankFar). Session 27: also
        /// when no band round the loop holds a ring, and when none round the seeded loop does
        /// either, from the seeds' ring towards the body (TowardBody): 161 -> 164/220 (+3 -0).
        double seededShrink = 0.5;
        /// TowardBody when no band round the seeded loop holds a ring either (session 27); false
        /// only to measure it (gs_parts --no-toward-body).
        bool towardBody = true;
        /// The bend across the loop (session 28, LoopBend::Bend, measured crossDist units to
        /// each side): the minima rule's direction. The cheapest loops round the level loops
        /// crossStep, 2 crossStep, ... (crossSteps of them) units towards the body and towards
        /// the part (a band of salience.profileBand units, not descended: the descent slides them
        /// back) replace the Run's loop when they bend more than crossBend times and crossGain h
        /// more than the best so far, and cost at most crossPrice times the loop's cost per
        /// length: a ring up a limb with a wrinkle is as deep by the energy as the limb's base, but
        /// the surface does not bend across it. Only at the Run's end (FinishRun), on its final
        /// loop. On bench/eval/gs_parts (--energy part --rings 2,3) against 164/220: 167 (+4 -1:
        /// hand 181 part 0 and octopus 121 part 2 seeded inside gained, hand 181 part 1 outside 2
        /// lost); crossBend 1.0-1.3 and crossGain 0.05-0.1 the same rows; crossGain 0.2 166
        /// (+2 -0); crossPrice 1.0, 1.1: 165, 166; crossDist 3: 162; crossSteps 3: 163 (+4 -5:
        /// the bend towards the body grows as the body opens). 0: off.
        double crossBend = 1.2;
        double crossPrice = 1.05;
        double crossGain = 0.1;
        int crossSteps = 2;
        double crossStep = 1.0;
        double crossDist = 2.0;
        int crossDirs = 3; ///< 1: towards the body, 2: towards the part, 3: both (1 alone: the same rows)
        /// Session 29: after the bend rule, the candidate that bends most among those that bend
        /// more than the loop kept and cost no more per length replaces it, whatever the gain
        /// (crossBend and crossGain pay for crossPrice's allowance; a loop better on both counts
        /// needs none; no threshold). On bench/eval/gs_parts (--energy part --rings 2,3) against
        /// 167/220: 168 (+1 -0: hand 181 part 3 inside 3; 10 rows change loop). false: off.
        bool crossDominant = true;
        /// Session 35: a loop convex across (bend below 0, no valley across it by LoopBend) gives
        /// the bend rules nothing to hold it by; when neither took a candidate, the one of its
        /// neighbours cheapest per length, below the loop's own, replaces it (the valley loop's
        /// own choice among them). On bench/eval/gs_parts (--energy part --rings 2,3) against
        /// 171/220: 172 (+1 -0: human 3 part 1 inside 2). false: off.
        bool crossConvex = true;
        /// Session 36: a loop across costs at most crossTotal times the loop's whole cost, not
        /// only per length: towards the body a loop grows, and a longer one may be cheaper per
        /// length and bend more while dearer in all (hand 181 finger 1 seeded outside 2: 31.8 h
        /// against the people's 28.1 h ring, 0.99x per length, 1.12x in all). On bench/eval/
        /// gs_parts (--energy part --rings 2,3; success_h0 on the variants) against 173/220: 1.1
        /// 174 (+1 -0: that row), graded 170 (+1 -0: the same row); 1.05 171 (+1 -3: the bend's
        /// own gains, hand 181 part 0 inside, 1.06x in all, and human 3 part 1 inside 2). 0: off.
        double crossTotal = 1.1;
        /// Part salience after the descent (part_salience.h); its exponent 0 turns it off.
        typename PartSalience<MeshType>::Param salience;
        /// Diagnostics (bench/eval/gs_parts GS_PARTS_CHAIN, session 32): called once per FinishRun
        /// that gets past its checks with the concavity reference its loops are priced with
        /// (FinishFrom's round the snake's loop, its last band's; the descent and salience do not
        /// change it), next to valley.record's loops. Empty: nothing is recorded, nothing changes.
        std::function<void(double)> recordReference;
        /// A Run that ran out of operations (SnakeStop::MaxOperations) ends on its valley loop as a
        /// converged one does (session 34). On a CAD mesh a loop on a strip of long faces (an
        /// annulus or a chamfer one face wide: two vertex rings, the energy linear across each
        /// face) has no rest between the rings and hops, never passing the convergence test,
        /// although it lies in the valley's band: bearing 341 part 1 outside 2 ran its 400
        /// operations on the annulus beside the groove's crease (capture 0.89) and was left there.
        /// The Run's end's searches keep only a cheaper loop, as after convergence. On
        /// bench/eval/gs_parts (--end-max-ops 1) it gains that row and moves no other (no row of
        /// the 9 meshes or the variants runs out of operations; collapsed loops stop otherwise).
        /// Left off (false) for the lead: a Run cut short by its budget has been left as it is
        /// by design (ValleyLoop.EndsAConvergedLoopOnTheValleysEdgesAndKeepsTheRun, a Run of one
        /// operation), and a host may stop a Run to be continued (docs/method.md, session 34).
        bool endAtMaxOperations = false;
        /// On a surface with a handle (valley.planar 0), when no band round the Run's loop nor
        /// round the seeded one holds a ring (not even narrowed, nor TowardBody's), the search
        /// round the Run's loop again in a band this many times as wide (session 35): a loop
        /// beside a handle's tunnel may have no separating ring within its band (its loops all
        /// run through the tunnel, ValleyLoop::Param::separating), while a wider band reaches
        /// round the tunnel's other side. On bench/eval/gs_parts (--energy part --rings 2,3;
        /// success_h0 on the variants; only the octopus has a handle) against main: 1.5 the 9
        /// meshes 171 -> 172 (+1 -0: octopus 121 part 1 outside 2, 1.00/0.84 -> 1.00/0.95), no
        /// row moves on refine, graded, noise nor CAD-like (2 the same rows). 1: off.
        double handleWiden = 1.5;
    };

    /// The loop a Run started from (its polyline and its samples' faces), kept by the host
    /// for FinishRun (Param::seededShrink): a loop that shrank far is searched from it.
    struct Seeded
    {
        std::vector<vcg::Point3d> loop;
        std::vector<int> faces;
        template <class SnakeType>
        static Seeded Of(SnakeType &s)
        {
            Seeded r;
            r.loop = s.PolylinePositions();
            for (const auto &x : s.Samples()) r.faces.push_back(x.p.face);
            return r;
        }
    };

    /// par with the measures of mesh m that the crease filter reads filled in (those still < 0:
    /// CreaseNormals::Measured, the noise level and the median face angle), and whether the
    /// surface has a handle (ValleyLoop::Param::planar; then its LoopTopology, ::topology). They are the mesh's,
    /// not the Run's (~20 ms on bunny00's 70k faces, session 33): a host takes them once per
    /// mesh (SnakeSession::RunEndParam, bench/eval/gs_parts) and passes them to every FinishRun
    /// on it; FinishRun takes those still missing itself, all but the LoopTopology (`topology`
    /// false): it only makes the separation test faster, and building it (~1 s on 1.2M faces)
    /// pays only over the many Runs of one mesh; without it the flood gives the same answers.
    static Param Measured(const MeshType &m, Param par, bool topology = true)
    {
        par.valley.creaseFilter = CreaseNormals<MeshType>::Measured(m, par.valley.creaseFilter);
        if (par.valley.separating && par.valley.planar < 0) par.valley.planar = LoopTopology<MeshType>::Planar(m) ? 1 : 0;
        if (topology && par.valley.separating && par.valley.planar == 0 && !par.valley.topology)
            par.valley.topology = std::make_shared<const LoopTopology<MeshType>>(m);
        return par;
    }

    /// A closed snake that converged on the part-boundary energy (or ran out of operations,
    /// Param::endAtMaxOperations) ends on the cheapest loop of edges round it. Returns true when
    /// the snake was replaced by that loop (it is kept as it is when the band holds no loop, or
    /// only one shorter than half the snake).
    /// `seeded`: the loop the Run started from (Seeded::Of before the Run), or null.
    template <class SnakeType>
    static bool FinishRun(SnakeType &s, FeatureEnergyType type, bool energyFromQuality, const Param &parIn = Param(),
                          const Seeded *seeded = nullptr)
    {
        const SnakeStop stop = s.Stats().stop;
        if (!s.Closed() || energyFromQuality || type != FeatureEnergyType::PartBoundary ||
            !(stop == SnakeStop::Converged || (parIn.endAtMaxOperations && stop == SnakeStop::MaxOperations)))
            return false;
        const MeshType &m = s.GetSurface().Mesh(); // its VF adjacency is current (SnakeSurface)
        const auto &energy = s.GetSurface().Energy();
        const double h = s.LengthScale();
        // the crease filter's measures of the mesh (its noise, its median angle), for every
        // search below: the host's (Measured, once per mesh), else taken here
        const Param par = Measured(m, parIn, false);
        const Seeded own = Seeded::Of(s); // the loop where the Run ended
        double ref = -1, cost = 0;
        std::vector<int> vl = FinishFrom(m, own.loop, own.faces, energy, h, par, ref, cost);
        if (par.recordReference) par.recordReference(ref);
        VL::Record(par.valley, "end:salience", vl);
        // a loop that converged at less than seededShrink of the length it was seeded with may
        // have slid past the valley onto the part (issue 33, session 25), and one round which no
        // band holds a ring has shrunk towards a short part's tip (session 27): the valley loop
        // is also searched round the loop the user seeded
        if (seeded && seeded->loop.size() >= 3 && par.seededShrink > 0 &&
            (VL::PolyLength(own.loop) < par.seededShrink * VL::PolyLength(seeded->loop) || vl.empty())) {
            double ref2 = -1, cost2 = 0;
            VL::Record(par.valley, "seeded", {});
            std::vector<int> v2 = FinishFrom(m, seeded->loop, seeded->faces, energy, h, par, ref2, cost2);
            // taken when it is a deeper valley per length (both priced with one concavity
            // reference): a seeded loop far out on a featureless body does not pull a loop
            // that shrank onto a rim back to the body
            const double r = ref >= 0 ? ref : ref2;
            // no band round the seeded loop holds a ring either (it covers a short part's tip):
            // from the seeds' ring towards the body (session 27)
            if (v2.empty() && par.towardBody)
                VL::Record(par.valley, "toward", {}), v2 = TowardBody(m, *seeded, energy, h, par, r);
            if (!v2.empty() &&
                (vl.empty() || VL::PerLength(m, v2, energy, r, par.valley) < VL::PerLength(m, vl, energy, r, par.valley)))
                vl = v2;
        }
        // no band round either loop holds a separating ring, on a surface with a handle: the
        // loop runs beside the handle's tunnel, and a wider band reaches round its other side
        if (vl.empty() && par.handleWiden > 1 && par.valley.separating && par.valley.planar == 0) {
            Param pw = par;
            pw.valley.bandWidth *= par.handleWiden;
            VL::Record(par.valley, "widened", {});
            double ref3 = -1, cost3 = 0;
            vl = FinishFrom(m, own.loop, own.faces, energy, h, pw, ref3, cost3);
            if (ref < 0) ref = ref3;
        }
        VL::Record(par.valley, "end:seeded", vl);
        // the user's seeds may lie on either side of the boundary: the loop's neighbours towards
        // the body and the part, by the bend across (session 28)
        if (!vl.empty() && par.crossBend > 0) vl = Across(m, vl, energy, h, par, ref >= 0 ? ref : -1);
        VL::Record(par.valley, "end:bend", vl);
        if (vl.empty()) return false;
        s.SetClosedVertexLoop(vl);
        return true;
    }

    /// The valley loop round `loop` (its band narrowed while it is no ring), descended and
    /// chosen by salience; empty when no band holds a ring at least half as long as `loop`.
    template <class EnergyVector>
    static std::vector<int> FinishFrom(const MeshType &m, const std::vector<vcg::Point3d> &loop, const std::vector<int> &faces,
                                       const EnergyVector &energy, double h, const Param &parIn, double &ref, double &cost)
    {
        Param par = parIn; // its band narrowed below, for the descent and salience's candidates too
        std::vector<int> vl = VL::FindAt(m, loop, faces, energy, h, par.valley, ref, cost);
        VL::Record(par.valley, "band", vl);
        const double len0 = VL::PolyLength(loop);
        // a band that covers a short part's tip is no ring round it (its cheapest "loop" circles
        // the tip's middle): narrower bands, down to 1 unit, until one is (issue 33, session 24)
        while ((vl.size() < 3 || !(VL::LengthOf(m, vl) > 0.5 * len0)) && par.valley.bandWidth * kNarrow >= 1.0) {
            par.valley.bandWidth *= kNarrow;
            ref = -1;
            vl = VL::FindAt(m, loop, faces, energy, h, par.valley, ref, cost);
            VL::Record(par.valley, "band", vl);
        }
        if (vl.size() < 3 || !(VL::LengthOf(m, vl) > 0.5 * len0))
            vl.clear();
        else
            vl = VL::Descend(m, vl, cost, energy, h, par.valley, ref, 0.5 * len0);
        VL::Record(par.valley, "end:descent", vl);
        if (!vl.empty() && par.salience.exponent > 0) {
            // candidates round the same part, each found and descended like this loop, but only
            // those mostly beyond the band the descent searched: within it its choice stands
            std::vector<vcg::Point3d> pl;
            for (int v : vl) pl.push_back(vcg::Point3d::Construct(m.vert[v].cP()));
            const typename VL::LoopIndex band(pl, par.valley.bandWidth * h);
            vl = Salient(m, vl, cost, energy, h, par, ref, [&](const vcg::Point3d &p) {
                double at = -1;
                return band.Dist(p, at) <= band.w;
            });
        }
        return vl;
    }

    /// Part salience's choice (PartSalience::Choose) from edge loop vl (cost `cost` with
    /// concavity reference ref): candidates found round guides moved into the body, each
    /// descended, and the width profile's ring. inBand(p): p lies where vl was already chosen.
    template <class EnergyVector, class InBand>
    static std::vector<int> Salient(const MeshType &m, const std::vector<int> &vl, double cost, const EnergyVector &energy,
                                    double h, const Param &par, double ref, InBand inBand)
    {
        const double minLen = 0.5 * VL::LengthOf(m, vl);
        auto find = [&](const std::vector<vcg::Point3d> &guide, const std::vector<int> &guideFaces, double &c, bool narrow,
                        std::vector<int> *refused, double *refusedCost) {
            double r = ref;
            if (narrow) {
                typename VL::Param pn = par.valley;
                pn.bandWidth = par.salience.profileBand;
                std::vector<int> cand = VL::FindAt(m, guide, guideFaces, energy, h, pn, r, c);
                VL::Record(par.valley, "profile", cand);
                return cand;
            }
            std::vector<int> cand = VL::FindAt(m, guide, guideFaces, energy, h, par.valley, r, c);
            VL::Record(par.valley, "salience", cand);
            if (cand.size() >= 3) cand = VL::Descend(m, cand, c, energy, h, par.valley, ref, minLen, refused, refusedCost);
            return cand;
        };
        return PartSalience<MeshType>::Choose(m, vl, cost, h, par.salience, find, inBand);
    }

    /// For a loop that shrank towards a part's tip (FinishRun), when no band round the seeded
    /// loop holds a ring (a short part: the band covers its tip): the edge ring along the seeded
    /// loop (a band of kHug units), then part salience's candidates moved from it into the body.
    /// Empty when no candidate beats that ring (the seeds' own ring is no valley).
    template <class EnergyVector>
    static std::vector<int> TowardBody(const MeshType &m, const Seeded &seeded, const EnergyVector &energy, double h,
                                       const Param &par, double ref)
    {
        if (!(par.salience.exponent > 0)) return {};
        typename VL::Param pn = par.valley;
        pn.bandWidth = kHug;
        double r = ref, c = 0;
        const std::vector<int> ring = VL::FindAt(m, seeded.loop, seeded.faces, energy, h, pn, r, c);
        VL::Record(par.valley, "band", ring);
        if (ring.size() < 3 || !(VL::LengthOf(m, ring) > 0.5 * VL::PolyLength(seeded.loop))) return {};
        double len;
        const double cost = VL::Cost(m, ring, energy, ref, par.valley, len); // priced as the candidates are
        const std::vector<int> best = Salient(m, ring, cost, energy, h, par, ref, [](const vcg::Point3d &) { return false; });
        return best == ring ? std::vector<int>() : best;
    }

    /// Param::crossBend (session 28): the loop round a level loop towards the body or the part
    /// that bends most across, more than vl does and cheap enough per length; vl when none.
    /// ref: the concavity reference vl was priced with (< 0: measured round vl). The sides are
    /// flooded until the body is known and the distances only crossSteps units: the cost
    /// follows the part, not the mesh.
    template <class EnergyVector>
    static std::vector<int> Across(const MeshType &m, const std::vector<int> &vl, const EnergyVector &energy, double h,
                                   const Param &par, double ref)
    {
        typedef PartSalience<MeshType> PS;
        typedef LoopBend<MeshType> LB;
        if (vl.size() < 3) return vl;
        typename PS::Sides s(m, vl); // flooded once: for vl's bend and for the level loops
        const int body = LB::Body(s);
        bool ok = false;
        const double b0 = LB::Bend(m, vl, s, body, h, par.crossDist, &ok);
        VL::Record(par.valley, "crossfrom", vl); // the loop the bend starts from (bench/eval's oracle)
        if (!ok) return vl; // body < 0 too: the loop cuts nothing off
        if (ref < 0) {
            double c = 0;
            std::vector<vcg::Point3d> pl;
            std::vector<int> pf;
            PS::Guide(m, vl, pl, pf);
            VL::FindAt(m, pl, pf, energy, h, par.valley, ref, c);
        }
        const double L0 = VL::LengthOf(m, vl), p0 = VL::PerLength(m, vl, energy, ref, par.valley);
        std::vector<std::vector<int>> cands;       // the candidates whose bend was measured
        std::vector<std::pair<double, double>> bp; // theirs: (bend, cost per length)
        int best = -1;                             // in cands; -1: vl
        double bestBend = b0, bestP = p0;
        for (int dir = 0; dir < 2; ++dir) {
            if (!(par.crossDirs & (1 << dir))) continue;
            auto isSide = [&](int v) {
                const int c = s.Side(v);
                return dir == 0 ? (c == body || c == -2) : (c >= 0 && c != body);
            };
            // the edge distance as far as the level loops below read it (as salience's guides)
            const std::unordered_map<int, double> dist = PS::DistanceFrom(m, vl, isSide, par.crossSteps * par.crossStep * h);
            // the cheapest loop round each level loop (a narrow band, not descended: the
            // descent would slide it back), taken when it bends more across, cheap enough
            for (int k = 1; k <= par.crossSteps; ++k) {
                std::vector<vcg::Point3d> guide;
                std::vector<int> gf;
                PS::Guide(m, PS::LevelLoop(m, isSide, dist, k * par.crossStep * h), guide, gf);
                if (guide.size() < 3) continue;
                typename VL::Param pn = par.valley;
                pn.bandWidth = par.salience.profileBand;
                double r = ref, c = 0;
                std::vector<int> cand = VL::FindAt(m, guide, gf, energy, h, pn, r, c);
                VL::Record(par.valley, "across", cand);
                if (cand.size() < 3) continue;
                const double L = VL::LengthOf(m, cand);
                if (!(L > 0.5 * L0) || L > par.salience.growth * L0 || !(c / L <= par.crossPrice * p0)) continue;
                if (par.crossTotal > 0 && !(c <= par.crossTotal * p0 * L0)) continue;
                const double b = LB::Bend(m, cand, h, par.crossDist, &ok);
                if (!ok) continue;
                cands.push_back(std::move(cand));
                bp.push_back({b, c / L});
                if (b > par.crossBend * bestBend && b > bestBend + par.crossGain) best = int(cands.size()) - 1, bestBend = b, bestP = c / L;
            }
        }
        // Param::crossDominant: the one that bends most among those better on both counts
        // (bestBend only grows: bending more than it is bending more than the loop kept)
        if (par.crossDominant) {
            const double p1 = bestP;
            for (size_t i = 0; i < cands.size(); ++i)
                if (bp[i].second <= p1 && bp[i].first > bestBend) best = int(i), bestBend = bp[i].first;
        }
        // Param::crossConvex: nothing bends across the loop kept, so the price decides
        if (par.crossConvex && best < 0 && b0 < 0)
            for (size_t i = 0, n = cands.size(); i < n; ++i)
                if (bp[i].second < (best < 0 ? p0 : bp[best].second)) best = int(i);
        return best < 0 ? vl : std::move(cands[best]);
    }

private:
    /// Band narrowing factor when a band is no ring (2.5 -> 1.5 units with the default band).
    static constexpr double kNarrow = 0.6;
    /// Half-width of the band that holds the edge ring along a seeded loop (TowardBody), units.
    static constexpr double kHug = 0.5;
};

} // namespace tri
} // namespace vcg

#endif
