#ifndef VCG_EXT_SNAKE_CONTROLLER_H
#define VCG_EXT_SNAKE_CONTROLLER_H

// The logic of the interactive edit tool, without Qt or OpenGL (so it is unit-testable):
// several snakes on one mesh (one selected), the seeds being placed, step/run, point
// editing (move, pin, insert, delete), undo/redo, export, and the session (snakes, pins,
// parameters, energy settings) saved to / restored from JSON, e.g. the sidecar file
// <mesh>.snakes.json next to the mesh, with a throttled autosave.
//
// Undo works in the units a user thinks in: every user action is one step of a history of
// whole-session snapshots (vcg_ext/snake_undo.h, bounded by memory). A Run, a drag (moves
// grouped with BeginAction/EndAction), a Build, a seed click are each one step; the
// snapshots share the snakes an action did not touch.
//
// Every user input is validated: bad input throws vcg::tri::SnakeError with a message
// for the user, and leaves the controller unchanged.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <vcg_ext/crease_energy.h>
#include <vcg_ext/feature_energy.h>
#include <vcg_ext/geometric_snake.h>
#include <vcg_ext/safe_file_write.h>
#include <vcg_ext/seed_path.h>
#include <vcg_ext/seed_points.h>
#include <vcg_ext/snake_error.h>
#include <vcg_ext/snake_io.h>
#include <vcg_ext/snake_surface.h>
#include <vcg_ext/snake_undo.h>
#include <vcg_ext/surface_point.h>

namespace vcg {
namespace tri {

template <class MeshType>
class SnakeController
{
public:
    typedef GeometricSnake<MeshType> Snake;
    typedef SnakeSurface<MeshType> Surface;
    typedef SnakeIO<MeshType> IO;
    typedef nlohmann::json json;

    static const char *FormatName() { return "geometric-snake-session"; }
    static int FormatVersion() { return 1; }
    /// Largest selection "use selected vertices" accepts (the ordering is quadratic).
    static int MaxSelectedSeeds() { return 5000; }

    explicit SnakeController(MeshType &m) : mesh(m) {}

    MeshType &Mesh() { return mesh; }

    // ================================================================ energy
    /// Computes the feature energy into the vertex quality (low = feature) and makes every
    /// snake slither on it. Throws on a bad type/smoothing or an unusable mesh.
    void ComputeEnergy(FeatureEnergyType type, int smoothing)
    {
        if (int(type) < 0 || int(type) >= FeatureEnergyTypeCount()) throw SnakeError("Geometric snake: unknown energy type.");
        if (smoothing < 0 || smoothing > 1000) throw SnakeError("Geometric snake: energy smoothing must be in [0, 1000].");
        FeatureEnergy<MeshType>::Compute(mesh, type, smoothing, creaseAngle);
        energyFromQuality = false;
        energyType = type;
        energySmoothing = smoothing;
        energyComputed = true;
        if (surface) {
            surface->SetEnergyFromQuality();
            applyEnergyField();
            for (auto &s : snakes) s->EnergyChanged();
        }
        saved.assign(snakes.size(), nullptr);
        touch("energy");
    }
    /// Any quality field can drive a snake: take the current vertex quality as the energy
    /// (low = feature) instead of computing one. Saved sessions remember it.
    void UseQualityAsEnergy()
    {
        energyFromQuality = true;
        energyComputed = true;
        if (surface) {
            surface->SetEnergyFromQuality();
            for (auto &s : snakes) s->EnergyChanged();
        }
        saved.assign(snakes.size(), nullptr);
        touch("energy");
    }
    bool EnergyFromQuality() const { return energyFromQuality; }
    bool EnergyComputed() const { return energyComputed; }
    FeatureEnergyType EnergyType() const { return energyType; }
    /// Dihedral angle (degrees) above which an edge is a crease, for the crease energy.
    double CreaseAngle() const { return creaseAngle; }
    void SetCreaseAngle(double deg)
    {
        if (!std::isfinite(deg) || deg <= 0 || deg >= 180)
            throw SnakeError("Geometric snake: the crease angle must be between 0 and 180 degrees.");
        const bool changed = deg != creaseAngle;
        creaseAngle = deg;
        if (changed && energyComputed && !energyFromQuality && energyType == FeatureEnergyType::Crease)
            ComputeEnergy(energyType, energySmoothing);
    }
    int EnergySmoothing() const { return energySmoothing; }
    /// Energy settings used when the energy is computed on demand (first snake).
    void SetEnergySettings(FeatureEnergyType type, int smoothing)
    {
        if (int(type) < 0 || int(type) >= FeatureEnergyTypeCount()) throw SnakeError("Geometric snake: unknown energy type.");
        if (smoothing < 0 || smoothing > 1000) throw SnakeError("Geometric snake: energy smoothing must be in [0, 1000].");
        if (energyComputed && (type != energyType || smoothing != energySmoothing)) ComputeEnergy(type, smoothing);
        energyType = type;
        energySmoothing = smoothing;
    }

    /// The shared surface; computes the energy first if that was not done yet.
    Surface &EnsureSurface()
    {
        if (!energyComputed) ComputeEnergy(energyType, energySmoothing);
        if (!surface) {
            surface = std::make_shared<Surface>(mesh);
            applyEnergyField();
        }
        return *surface;
    }
    bool HasSurface() const { return bool(surface); }
    /// Warnings about the energy the snakes read, for the Log: those of the vertex energy,
    /// or, for the crease energy (read at the samples), that it found no crease at all.
    std::vector<std::string> EnergyWarnings()
    {
        Surface &s = EnsureSurface();
        if (energyFromQuality || energyType != FeatureEnergyType::Crease) return s.Warnings();
        const auto *f = dynamic_cast<const CreaseEnergyField<MeshType> *>(&s.EnergyField());
        if (f && f->Creases().CreaseCount() == 0)
            return {"no edge has a dihedral angle above " + std::to_string(int(std::lround(creaseAngle))) +
                    " degrees: the crease energy is flat and the snake will not move (lower the crease angle, "
                    "or choose another energy type)."};
        return {};
    }
    /// False when the mesh lost or gained elements since the snakes were built on it.
    bool MeshMatches() const { return !surface || surface->MatchesMesh(); }
    double MeanEdge() { return EnsureSurface().MeanEdge(); }
    /// The length unit of new snakes (spacing, step caps, tolerances), 0 = the engine's own
    /// (from the edges along the seed path). With the crease energy: its basin width without
    /// smoothing, since on a CAD tessellation the edges are slivers as long as the part and
    /// say nothing about the features; smoothing widens the basin, never the sampling (the
    /// corners of a pocket's rim are cut by about one sample spacing).
    double LengthScale() const
    {
        if (energyFromQuality || energyType != FeatureEnergyType::Crease) return 0;
        return CreaseEnergyField<MeshType>::Widths(mesh, 0)[0];
    }

    // ================================================================ seeds
    /// The vertex of face `face` nearest to the surface point (face, bary): the seed a click
    /// on the surface places (Sec. 5.5).
    int SeedVertexFromPick(int face, const vcg::Point3d &bary) const
    {
        if (face < 0 || face >= int(mesh.face.size()) || mesh.face[face].IsD())
            throw SnakeError("Geometric snake: the click is not on the mesh.");
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(bary[k]) || bary[k] < -0.01 || bary[k] > 1.01)
                throw SnakeError("Geometric snake: the picked point is outside the picked triangle.");
        SurfacePoint sp(face, bary);
        sp.Normalize();
        const auto &f = mesh.face[face];
        vcg::Point3d p = sp.Pd(mesh);
        int best = -1;
        double bd = std::numeric_limits<double>::max();
        for (int k = 0; k < 3; ++k) {
            vcg::Point3d q = vcg::Point3d::Construct(f.cV(k)->cP());
            double d = (q - p).SquaredNorm();
            if (!std::isfinite(d)) continue;
            if (d < bd) { bd = d; best = int(f.cV(k) - &mesh.vert[0]); }
        }
        if (best < 0) throw SnakeError("Geometric snake: the picked triangle has invalid coordinates.");
        return best;
    }

    /// Adds the seed for a click: the surface point hit (face + barycentric), where the curve
    /// will start or pass exactly; on a CAD tessellation every vertex lies on some crease, so
    /// the seed must not jump to one. Returns the nearest vertex of the hit triangle (the
    /// seed's vertex in Seeds()), or -1 if the click repeats the last seed.
    int AddSeedFromPick(int face, const vcg::Point3d &bary)
    {
        const int v = SeedVertexFromPick(face, bary);
        SurfacePoint sp(face, bary);
        sp.Normalize();
        if (!seeds.empty() && SeedPosition(int(seeds.size()) - 1) == sp.Pd(mesh)) return -1;
        record("seed");
        seeds.push_back(v);
        seedAt.push_back(sp);
        touch("seed");
        return v;
    }

    int AddSeedVertex(int v)
    {
        checkVertex(v);
        if (!seeds.empty() && seeds.back() == v && seedAt.back().face < 0) return -1;
        record("seed");
        seeds.push_back(v);
        seedAt.push_back(SurfacePoint());
        touch("seed");
        return v;
    }

    /// A painted stroke (surface points in drawing order): seeds along it, at least
    /// `minSpacing` mean edge lengths apart (the shortest paths between them follow the
    /// stroke closely). Returns the number of seeds added.
    int AddSeedsFromStroke(const std::vector<SurfacePoint> &stroke, double minSpacing = 3.0)
    {
        if (!std::isfinite(minSpacing) || minSpacing < 0) throw SnakeError("Geometric snake: bad stroke spacing.");
        std::vector<int> verts;
        std::vector<SurfacePoint> at; // the stroke's point where it reached each vertex's triangle
        for (const auto &p : stroke) {
            int v;
            try { v = SeedVertexFromPick(p.face, p.bary); }
            catch (const SnakeError &) { continue; } // stroke points off the mesh are skipped
            if (verts.empty() || verts.back() != v) {
                verts.push_back(v);
                at.push_back(SurfacePoint(p.face, p.bary));
                at.back().Normalize();
            }
        }
        if (verts.empty()) throw SnakeError("Geometric snake: the stroke does not touch the mesh.");
        double h = meanEdgeNoSurface();
        std::vector<int> kept;
        std::vector<SurfacePoint> keptAt;
        int last = seeds.empty() ? -1 : seeds.back();
        for (size_t i = 0; i < verts.size(); ++i) {
            int v = verts[i];
            bool isLast = (i + 1 == verts.size());
            if (v == last) continue;
            if (last >= 0 && !isLast && vdist(v, last) < minSpacing * h) continue;
            kept.push_back(v);
            keptAt.push_back(at[i]);
            last = v;
        }
        if (!kept.empty()) record("stroke");
        seeds.insert(seeds.end(), kept.begin(), kept.end());
        seedAt.insert(seedAt.end(), keptAt.begin(), keptAt.end());
        if (!kept.empty()) touch("stroke");
        return int(kept.size());
    }

    /// Seeds from the selected vertices, ordered into a chain (nearest neighbour from the
    /// selected vertex farthest from their centroid). Replaces the current seeds.
    int SeedsFromSelection()
    {
        std::vector<int> sel;
        for (size_t i = 0; i < mesh.vert.size(); ++i)
            if (!mesh.vert[i].IsD() && mesh.vert[i].IsS()) sel.push_back(int(i));
        if (sel.size() < 2) throw SnakeError("Geometric snake: select at least 2 vertices to use them as seeds.");
        if (int(sel.size()) > MaxSelectedSeeds())
            throw SnakeError("Geometric snake: " + std::to_string(sel.size()) + " vertices are selected; use at most " +
                             std::to_string(MaxSelectedSeeds()) + " as seeds.");
        vcg::Point3d c(0, 0, 0);
        for (int v : sel) c += P(v);
        c /= double(sel.size());
        size_t start = 0;
        for (size_t i = 1; i < sel.size(); ++i)
            if ((P(sel[i]) - c).SquaredNorm() > (P(sel[start]) - c).SquaredNorm()) start = i;
        std::vector<int> order{sel[start]};
        std::vector<char> used(sel.size(), 0);
        used[start] = 1;
        for (size_t k = 1; k < sel.size(); ++k) {
            int bi = -1;
            double bd = std::numeric_limits<double>::max();
            for (size_t i = 0; i < sel.size(); ++i)
                if (!used[i]) {
                    double d = (P(sel[i]) - P(order.back())).SquaredNorm();
                    if (d < bd) { bd = d; bi = int(i); }
                }
            used[bi] = 1;
            order.push_back(sel[bi]);
        }
        record("selection seeds");
        seeds = order;
        seedAt.assign(seeds.size(), SurfacePoint());
        touch("selection seeds");
        return int(seeds.size());
    }

    /// Replaces the seeds (e.g. vertices picked with another tool); validated.
    void SetSeeds(const std::vector<int> &s)
    {
        for (int v : s) checkVertex(v);
        record("seeds");
        seeds = s;
        seedAt.assign(seeds.size(), SurfacePoint());
        touch("seeds");
    }

    /// Replaces the seeds by surface points (e.g. a Pick Points file snapped with
    /// SeedPointSnap): the curve will pass exactly through them. Validated.
    void SetSeedPoints(const std::vector<SurfacePoint> &pts)
    {
        std::vector<int> v;
        std::vector<SurfacePoint> at;
        for (const auto &p : pts) {
            checkSurfacePoint(p);
            v.push_back(SeedVertexFromPick(p.face, p.bary));
            at.push_back(p);
            at.back().Normalize();
        }
        record("seeds");
        seeds = v;
        seedAt = at;
        touch("seeds");
    }

    void RemoveSeed(int i)
    {
        if (i < 0 || i >= int(seeds.size())) throw SnakeError("Geometric snake: no seed " + std::to_string(i) + ".");
        record("remove seed");
        seeds.erase(seeds.begin() + i);
        seedAt.erase(seedAt.begin() + i);
        touch("remove seed");
    }
    bool RemoveLastSeed()
    {
        if (seeds.empty()) return false;
        record("remove seed");
        seeds.pop_back();
        seedAt.pop_back();
        touch("remove seed");
        return true;
    }
    void ClearSeeds()
    {
        if (seeds.empty()) return;
        record("clear seeds");
        seeds.clear();
        seedAt.clear();
        touch("clear seeds");
    }
    /// The seed nearest to p, within maxDist (-1 if none).
    int NearestSeed(const vcg::Point3d &p, double maxDist = std::numeric_limits<double>::max()) const
    {
        int best = -1;
        double bd = maxDist;
        for (size_t i = 0; i < seeds.size(); ++i) {
            double d = (SeedPosition(int(i)) - p).Norm();
            if (d <= bd) { bd = d; best = int(i); }
        }
        return best;
    }
    const std::vector<int> &Seeds() const { return seeds; }
    /// Where seed i is: the clicked surface point, or its vertex.
    vcg::Point3d SeedPosition(int i) const
    {
        const SurfacePoint &sp = seedAt.at(i);
        return sp.face >= 0 ? sp.Pd(mesh) : P(seeds.at(i));
    }
    /// Seed i as a surface point, or an invalid point (face -1) for a seed placed as a vertex.
    const SurfacePoint &SeedPoint(int i) const { return seedAt.at(i); }

    /// Closes the seed list: builds the initial snake at once (Sec. 5.5), selects it and
    /// clears the seeds. On error nothing changes (the seeds stay, to be fixed).
    int CloseSeeds(bool closed)
    {
        size_t need = closed ? 3 : 2;
        if (seeds.size() < need)
            throw SnakeError(std::string("Geometric snake: a ") + (closed ? "closed" : "open") + " snake needs at least " +
                             std::to_string(need) + " seeds (" + std::to_string(seeds.size()) + " placed).");
        std::vector<int> s = seeds;
        std::vector<SurfacePoint> at = seedAt;
        EnsureSurface();
        checkMesh();
        // Seeds inside faces (clicks) make a curve through those points; vertex seeds (and
        // clicks exactly at vertices) the paper's vertex path.
        bool atVertices = true;
        for (size_t i = 0; i < at.size(); ++i)
            if (at[i].face >= 0 && at[i].Pd(mesh) != P(s[i])) atVertices = false;
        std::unique_ptr<Snake> sn(new Snake(surface, params));
        if (atVertices) {
            sn->InitFromSeeds(s, closed, seedCost, LengthScale());
        } else {
            for (size_t i = 0; i < at.size(); ++i)
                if (at[i].face < 0) at[i] = vertexPoint(s[i]);
            sn->InitFromSeedPoints(at, closed, seedCost, LengthScale());
        }
        record("build");
        snakes.push_back(std::move(sn));
        saved.push_back(nullptr);
        selected = int(snakes.size()) - 1;
        seeds.clear();
        seedAt.clear();
        touch("create snake");
        return selected;
    }

    /// Builds a snake from seeds given as surface points (e.g. snapped from coordinates or a
    /// Pick Points file, SeedPointSnap): the curve starts and ends exactly at them. Selects it.
    int CreateSnakeFromSeedPoints(const std::vector<SurfacePoint> &pts, bool closed)
    {
        EnsureSurface();
        checkMesh();
        std::unique_ptr<Snake> sn(new Snake(surface, params));
        sn->InitFromSeedPoints(pts, closed, seedCost, LengthScale());
        record("build");
        snakes.push_back(std::move(sn));
        saved.push_back(nullptr);
        selected = int(snakes.size()) - 1;
        touch("create snake");
        return selected;
    }

    // ================================================================ snakes
    int SnakeCount() const { return int(snakes.size()); }
    int Selected() const { return selected; }
    void Select(int i)
    {
        checkSnake(i);
        selected = i;
        touch("select");
    }
    Snake &Get(int i)
    {
        checkSnake(i);
        return *snakes[i];
    }
    Snake *SelectedSnake() { return (selected >= 0 && selected < int(snakes.size())) ? snakes[selected].get() : nullptr; }
    void DeleteSnake(int i)
    {
        checkSnake(i);
        record("delete snake");
        snakes.erase(snakes.begin() + i);
        saved.erase(saved.begin() + i);
        if (selected >= int(snakes.size())) selected = int(snakes.size()) - 1;
        touch("delete snake");
    }
    void DeleteAllSnakes()
    {
        if (snakes.empty()) return;
        record("delete all snakes");
        snakes.clear();
        saved.clear();
        selected = -1;
        touch("delete all snakes");
    }

    /// One operation of the selected snake; returns its largest move (mean edge lengths).
    double Step()
    {
        Snake &s = sel();
        checkMesh();
        const bool pushed = record("step");
        auto t0 = std::chrono::steady_clock::now();
        double mv;
        try {
            mv = s.Step();
        } catch (...) {
            if (pushed) history.DropLast();
            throw;
        }
        lastOpMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        computeMs += lastOpMs;
        for (const auto &x : s.Samples()) {
            vcg::Point3d p = x.p.Pd(mesh);
            if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]) || !std::isfinite(mv)) {
                s.Undo(); // the engine's own one-operation step back
                if (pushed) history.DropLast();
                throw SnakeError("Geometric snake: the operation produced invalid coordinates and was undone.");
            }
        }
        touch("step");
        return mv;
    }
    /// Operations of the selected snake until it converges or maxOps; returns operations done.
    int Run(int maxOps)
    {
        if (maxOps < 0 || maxOps > 1000000) throw SnakeError("Geometric snake: the operation limit must be in [0, 1000000].");
        Action run(*this, "run");
        int ops = 0;
        while (ops < maxOps && !sel().Converged()) {
            Step();
            ++ops;
        }
        return ops;
    }
    bool Converged() { return SelectedSnake() && SelectedSnake()->Converged(); }

    /// The sample nearest to p (3D), over all snakes (ties: the selected one first).
    bool NearestSample(const vcg::Point3d &p, int &snake, int &sample,
                       double maxDist = std::numeric_limits<double>::max()) const
    {
        snake = sample = -1;
        double bd = maxDist;
        for (int k = 0; k < int(snakes.size()); ++k) {
            int si = (selected >= 0) ? (k + selected) % int(snakes.size()) : k;
            const auto &smp = snakes[si]->Samples();
            for (int i = 0; i < int(smp.size()); ++i) {
                double d = (smp[i].p.Pd(mesh) - p).Norm();
                if (d < bd) { bd = d; snake = si; sample = i; }
            }
        }
        return snake >= 0;
    }

    // --- point editing on the selected snake (Sec. 5.5)
    void MoveSample(int i, const SurfacePoint &p, bool pin)
    {
        checkSurfacePoint(p);
        Snake &s = sel();
        if (i < 0 || i >= s.SampleCount()) throw SnakeError("Geometric snake: no sample " + std::to_string(i) + ".");
        record("move sample");
        s.MoveSample(i, p, pin);
        touch("move sample");
    }
    void SetFixed(int i, bool fixed)
    {
        Snake &s = sel();
        if (i < 0 || i >= s.SampleCount()) throw SnakeError("Geometric snake: no sample " + std::to_string(i) + ".");
        record(fixed ? "pin" : "unpin");
        s.SetFixed(i, fixed);
        touch(fixed ? "pin" : "unpin");
    }
    bool TogglePin(int i)
    {
        Snake &s = sel();
        if (i < 0 || i >= s.SampleCount()) throw SnakeError("Geometric snake: no sample " + std::to_string(i) + ".");
        bool f = !s.Samples()[i].fixed;
        SetFixed(i, f);
        return f;
    }
    /// Inserts a sample after sample i (before it for the last sample of an open snake).
    int InsertSampleAfter(int i)
    {
        Snake &s = sel();
        if (i < 0 || i >= s.SampleCount()) throw SnakeError("Geometric snake: no sample " + std::to_string(i) + ".");
        int gap = (!s.Closed() && i == s.SampleCount() - 1) ? i - 1 : i;
        const bool pushed = record("insert sample");
        int r;
        try { r = s.InsertSample(gap); }
        catch (...) { if (pushed) history.DropLast(); throw; }
        touch("insert sample");
        return r;
    }
    void DeleteSample(int i)
    {
        Snake &s = sel();
        if (i < 0 || i >= s.SampleCount()) throw SnakeError("Geometric snake: no sample " + std::to_string(i) + ".");
        if (s.SampleCount() <= (s.Closed() ? 3 : 2))
            throw SnakeError("Geometric snake: cannot delete, the snake would have too few samples.");
        record("delete sample");
        s.DeleteSample(i);
        touch("delete sample");
    }

    // --- undo / redo of whole user actions
    /// Groups every change until the matching EndAction into one undo step (a Run, a drag);
    /// groups nest. An action that changes nothing leaves no step.
    void BeginAction(const std::string &label)
    {
        if (actionDepth++ == 0) {
            actionLabel = label;
            actionRecorded = false;
        }
    }
    void EndAction()
    {
        if (actionDepth > 0) --actionDepth;
    }
    bool InAction() const { return actionDepth > 0; }
    /// BeginAction / EndAction for a scope.
    struct Action
    {
        SnakeController &c;
        Action(SnakeController &ctl, const std::string &label) : c(ctl) { c.BeginAction(label); }
        ~Action() { c.EndAction(); }
    };

    bool CanUndo() const { return history.CanUndo(); }
    bool CanRedo() const { return history.CanRedo(); }
    /// The action Undo / Redo would take back / do again, e.g. "run" ("" if none).
    std::string UndoLabel() const { return history.UndoLabel(); }
    std::string RedoLabel() const { return history.RedoLabel(); }
    /// Returns to the session as it was before the last action (all snakes, seeds, selection).
    bool Undo()
    {
        Session cur = snapshot();
        size_t b = sessionBytes(cur);
        if (!history.Undo(cur, b)) return false;
        restore(cur);
        touch("undo");
        return true;
    }
    bool Redo()
    {
        Session cur = snapshot();
        size_t b = sessionBytes(cur);
        if (!history.Redo(cur, b)) return false;
        restore(cur);
        touch("redo");
        return true;
    }
    /// Memory bound of the history (default 100 MB) and its current estimate.
    void SetUndoLimit(size_t bytes) { history.SetLimit(bytes); }
    size_t UndoBytes() const { return history.Bytes(); }
    size_t UndoSteps() const { return history.UndoCount(); }
    /// Compute time of all operations so far (ms): a Run's wall time is compared to it.
    double ComputeMs() const { return computeMs; }

    /// Parameters of new snakes; also applied to the selected snake.
    void SetParams(const SnakeParams &p)
    {
        p.Validate();
        Snake *s = SelectedSnake();
        const bool same = IO::ParamsJson(p) == IO::ParamsJson(params) && (!s || IO::ParamsJson(s->Params()) == IO::ParamsJson(p));
        if (same) return;
        record("parameters");
        if (s) s->SetParams(p);
        params = p;
        touch("parameters");
    }
    const SnakeParams &Params() const { return params; }
    /// Parameters of the snakes built from now on only (the selected snake keeps its own,
    /// and its convergence).
    void SetNewSnakeParams(const SnakeParams &p)
    {
        p.Validate();
        params = p;
    }
    void SetSeedCost(SeedPathCost c)
    {
        if (int(c) < 0 || int(c) > 1) throw SnakeError("Geometric snake: unknown seed path cost.");
        seedCost = c;
    }
    SeedPathCost SeedCost() const { return seedCost; }

    // ================================================================ output
    /// Curves by extension (.json/.obj/.ply): the selected snake or all.
    void Export(const std::string &path, bool all, const std::vector<ProtectedFile> &keep = {})
    {
        std::vector<Snake *> out;
        if (all) for (auto &s : snakes) out.push_back(s.get());
        else if (SelectedSnake()) out.push_back(SelectedSnake());
        if (out.empty()) throw SnakeError("Geometric snake: there is no snake to export.");
        if (path.empty()) throw SnakeError("Geometric snake: no file name given.");
        IO::WriteCurves(path, out, keep);
    }

    /// The whole session: energy settings, parameters, seeds, snakes with pins.
    json ToJson()
    {
        json j;
        j["format"] = FormatName();
        j["version"] = FormatVersion();
        j["mesh"] = {{"vertices", int(mesh.vert.size())}, {"faces", int(mesh.face.size())}};
        j["energy"] = {{"type", energyFromQuality ? -1 : int(energyType)}, {"smoothing", energySmoothing},
                       {"crease_angle", creaseAngle}};
        j["params"] = IO::ParamsJson(params);
        j["seed_cost"] = int(seedCost);
        j["selected"] = selected;
        j["seeds"] = seeds;
        // where each seed was clicked (null: the vertex itself)
        j["seed_points"] = json::array();
        for (const auto &sp : seedAt) j["seed_points"].push_back(sp.face >= 0 ? IO::PointJson(mesh, sp) : json());
        j["snakes"] = json::array();
        for (auto &s : snakes) j["snakes"].push_back(IO::ToJson(*s));
        return j;
    }

    /// Restores a session saved by ToJson on this mesh. All or nothing: on error (other
    /// mesh, broken file) the controller is unchanged and a SnakeError says why.
    void FromJson(const json &j)
    {
        try {
            if (!j.is_object() || j.value("format", std::string()) != FormatName())
                throw SnakeError("Geometric snake: not a snake session file.");
            if (IO::IntFrom(j, "version", 0) > FormatVersion())
                throw SnakeError("Geometric snake: the session file is from a newer version.");
            if (!j.contains("mesh")) throw SnakeError("Geometric snake: the session file does not say which mesh it belongs to.");
            const json &jm = j["mesh"];
            const int nv = IO::IntFrom(jm, "vertices", -1), nf = IO::IntFrom(jm, "faces", -1);
            if (nv != int(mesh.vert.size()) || nf != int(mesh.face.size()))
                throw SnakeError("Geometric snake: the session was saved on another mesh (" +
                                 std::to_string(nv) + " vertices, " +
                                 std::to_string(nf) + " faces; this mesh has " +
                                 std::to_string(mesh.vert.size()) + " and " + std::to_string(mesh.face.size()) + ").");
            SnakeParams np = j.contains("params") ? IO::ParamsFromJson(j["params"]) : SnakeParams();
            const json &je = j.contains("energy") ? j["energy"] : json::object();
            const int etype = IO::IntFrom(je, "type", 0); // -1: the vertex quality as it is
            FeatureEnergyType et = FeatureEnergyType(std::max(0, etype));
            int es = IO::IntFrom(je, "smoothing", 2);
            if (etype < -1 || etype >= FeatureEnergyTypeCount() || es < 0 || es > 1000)
                throw SnakeError("Geometric snake: bad energy settings in the session file.");
            int sc = IO::IntFrom(j, "seed_cost", 0);
            if (sc < 0 || sc > 1) throw SnakeError("Geometric snake: bad seed cost in the session file.");
            std::vector<int> ns;
            if (j.contains("seeds")) {
                if (!j["seeds"].is_array()) throw SnakeError("Geometric snake: \"seeds\" must be a list of vertex indices.");
                for (const json &v : j["seeds"]) ns.push_back(IO::IndexFromJson(v, "seeds"));
            }
            for (int v : ns) checkVertex(v);
            // "seeds" is what counts: "seed_points" (where each was clicked) only when it lists one
            // point (or null) per seed, so a hand-edited seed list is not refused
            std::vector<SurfacePoint> nat(ns.size());
            if (j.contains("seed_points") && j["seed_points"].is_array() && j["seed_points"].size() == ns.size()) {
                const json &jp = j["seed_points"];
                for (size_t i = 0; i < ns.size(); ++i)
                    if (!jp[i].is_null()) nat[i] = IO::SamplesFromJson(mesh, json::array({jp[i]}))[0].p;
            }

            const double ca = IO::RealFrom(je, "crease_angle", CreaseEnergy<MeshType>::DefaultAngle());
            if (!std::isfinite(ca) || ca <= 0 || ca >= 180)
                throw SnakeError("Geometric snake: bad crease angle in the session file.");

            if (etype == -1) {
                if (!energyFromQuality) UseQualityAsEnergy();
            } else if (!energyComputed || energyFromQuality || et != energyType || es != energySmoothing ||
                       (et == FeatureEnergyType::Crease && ca != creaseAngle)) {
                creaseAngle = ca;
                ComputeEnergy(et, es);
            }
            creaseAngle = ca;
            EnsureSurface();
            checkMesh();
            std::vector<std::unique_ptr<Snake>> nsn;
            if (!j.contains("snakes") || !j["snakes"].is_array())
                throw SnakeError("Geometric snake: the session file has no list of \"snakes\".");
            for (const json &js : j["snakes"]) {
                SnakeParams sp = js.is_object() && js.contains("params") ? IO::ParamsFromJson(js["params"], np) : np;
                std::unique_ptr<Snake> s(new Snake(surface, sp));
                if (!js.is_object() || !js.contains("samples"))
                    throw SnakeError("Geometric snake: a snake in the session file has no \"samples\".");
                if (js.contains("closed") && !js["closed"].is_boolean())
                    throw SnakeError("Geometric snake: \"closed\" must be true or false.");
                s->InitFromSamples(IO::SamplesFromJson(mesh, js["samples"]), js.value("closed", false),
                                   IO::LengthScaleFrom(js));
                nsn.push_back(std::move(s));
            }
            int nsel = IO::IntFrom(j, "selected", nsn.empty() ? -1 : 0);
            if (nsel < -1 || nsel >= int(nsn.size())) nsel = nsn.empty() ? -1 : 0;
            if (nsel < 0 && !nsn.empty()) nsel = 0;

            snakes = std::move(nsn);
            saved.assign(snakes.size(), nullptr);
            history.Clear();
            selected = nsel;
            params = np;
            seeds = ns;
            seedAt = nat;
            seedCost = SeedPathCost(sc);
            touch("load");
        } catch (const json::exception &e) {
            throw SnakeError("Geometric snake: broken session file: " + IO::JsonErrorText(e) + ".");
        }
    }

    /// The sidecar file of a mesh: "<mesh file>.snakes.json".
    static std::string SidecarPath(const std::string &meshPath)
    {
        if (meshPath.empty()) return std::string();
        return meshPath + ".snakes.json";
    }

    /// Writes the session safely (SafeFileWrite: temporary file, then rename): a crash or a
    /// full disk never leaves a half-written session behind.
    void Save(const std::string &path)
    {
        if (path.empty()) throw SnakeError("Geometric snake: no file name to save the session to.");
        SafeFileWrite::Write(path, ToJson().dump(1) + "\n");
        savedRevision = revision;
    }

    /// Loads a session file; false if there is none, throws if it is unusable. Only what the
    /// session needs is kept while reading (SnakeIO::ParseLean): memory about the file's size.
    bool Load(const std::string &path)
    {
        std::error_code ec;
        if (!std::filesystem::exists(path, ec)) return false;
        FromJson(IO::ParseFileLean(path));
        savedRevision = revision;
        return true;
    }

    /// Where a session goes when the mesh's sidecar could not be read (the sidecar is kept as
    /// it is): "<mesh>.snakes.recovered-<YYYYMMDD-HHMMSS>[-k].json", a name not yet taken.
    static std::string RecoveryPath(const std::string &meshPath, std::time_t when)
    {
        char stamp[32];
        std::tm tmv;
        localtime_r(&when, &tmv);
        std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tmv);
        std::error_code ec;
        for (int k = 1;; ++k) {
            std::string p = meshPath + ".snakes.recovered-" + stamp + (k > 1 ? "-" + std::to_string(k) : "") + ".json";
            if (!std::filesystem::exists(p, ec)) return p;
        }
    }

    /// Files of a mesh that curve exports and autosaves never overwrite: the mesh itself, its
    /// sidecar and the sidecar's backup.
    static std::vector<ProtectedFile> ProtectedFilesOf(const std::string &meshPath, const std::string &label = "")
    {
        if (meshPath.empty()) return {};
        const std::string name = label.empty() ? meshPath : label;
        return {{meshPath, "the mesh \"" + name + "\""},
                {SidecarPath(meshPath), "the snake session file (sidecar) of \"" + name + "\""},
                {SidecarPath(meshPath) + ".bak", "a backup of the snake session file of \"" + name + "\""}};
    }

    /// What OpenSidecar did, for the status line and the Log.
    struct SidecarStatus
    {
        bool restored = false;  ///< the session was restored from the sidecar
        bool unreadable = false;///< a sidecar exists but could not be used: it is kept untouched
        std::string message;    ///< for the user ("" when there is nothing to say)
    };

    /// Starts the session of the mesh file `meshPath`: restores its sidecar (if `restore` and it
    /// exists) and autosaves to it from now on. A sidecar that cannot be read (broken, truncated,
    /// made on another mesh, too large) is never touched: the session autosaves to a new
    /// RecoveryPath() file instead, and the message says so.
    SidecarStatus OpenSidecar(const std::string &meshPath, bool restore, std::time_t now = std::time(nullptr))
    {
        SidecarStatus st;
        SetAutosave(std::string());
        if (meshPath.empty()) return st;
        const std::string side = SidecarPath(meshPath);
        std::error_code ec;
        if (std::filesystem::exists(side, ec)) {
            try {
                if (restore) {
                    Load(side);
                    st.restored = true;
                    st.message = "Restored " + side + ".";
                } else {
                    IO::ParseFileLean(side); // readable? (the session itself came from the mesh)
                }
            } catch (const std::exception &e) {
                st.unreadable = true;
                const std::string rec = RecoveryPath(meshPath, now);
                st.message = std::string(e.what()) + " The file is kept unchanged; this session is saved to " + rec + ".";
                SetAutosave(rec, 1.0);
                return st;
            }
        }
        SetAutosave(side, 1.0);
        return st;
    }

    /// Autosave target (empty: none) and minimum interval between two autosaves.
    void SetAutosave(const std::string &path, double minIntervalSeconds = 1.0)
    {
        autosavePath = path;
        autosaveInterval = minIntervalSeconds;
    }
    const std::string &AutosavePath() const { return autosavePath; }
    /// Saves if something changed since the last save and (unless forced) the interval
    /// has passed. Returns true if it wrote. Throws SnakeError if writing fails.
    bool Autosave(bool force = false)
    {
        if (autosavePath.empty() || revision == savedRevision) return false;
        auto now = std::chrono::steady_clock::now();
        if (!force && lastAutosave.time_since_epoch().count() != 0 &&
            std::chrono::duration<double>(now - lastAutosave).count() < autosaveInterval)
            return false;
        lastAutosave = now;
        Save(autosavePath);
        return true;
    }
    bool Dirty() const { return revision != savedRevision; }

    // ================================================================ status
    /// Increases with every change (for redraws, autosave and auto-export).
    long Revision() const { return revision; }
    const std::string &LastOperation() const { return lastOp; }
    double LastOperationMs() const { return lastOpMs; }

private:
    MeshType &mesh;
    std::shared_ptr<Surface> surface;
    std::vector<std::unique_ptr<Snake>> snakes;
    int selected = -1;
    std::vector<int> seeds;
    std::vector<SurfacePoint> seedAt; // per seed: the clicked surface point, or face -1 (the vertex itself)
    SnakeParams params;
    SeedPathCost seedCost = SeedPathCost::Length;
    FeatureEnergyType energyType = FeatureEnergyType::NormalVariation;
    int energySmoothing = 2;
    double creaseAngle = CreaseEnergy<MeshType>::DefaultAngle();
    bool energyComputed = false;
    bool energyFromQuality = false;

    /// The crease energy is read by the snakes at each sample (CreaseEnergyField), not
    /// interpolated from the vertex values the quality holds (those are for display).
    void applyEnergyField()
    {
        if (!surface || energyFromQuality || energyType != FeatureEnergyType::Crease) return;
        surface->SetEnergyField(std::make_shared<CreaseEnergyField<MeshType>>(
            mesh, creaseAngle, CreaseEnergyField<MeshType>::Widths(mesh, energySmoothing)));
    }
    long revision = 0, savedRevision = 0;
    std::string lastOp;
    double lastOpMs = 0;
    std::string autosavePath;
    double autosaveInterval = 1.0;
    std::chrono::steady_clock::time_point lastAutosave;
    double computeMs = 0;

    // undo history: whole-session snapshots; a snake's memento is shared by all snapshots
    // until the snake changes (saved[k] == nullptr: snake k changed since its last memento)
    typedef std::shared_ptr<const typename Snake::Memento> MementoPtr;
    struct Session
    {
        std::vector<MementoPtr> snakes;
        int selected = -1;
        std::vector<int> seeds;
        std::vector<SurfacePoint> seedAt;
        SnakeParams params;
    };
    SnakeUndo<Session> history;
    std::vector<MementoPtr> saved, lastPushed;
    int actionDepth = 0;
    bool actionRecorded = false;
    std::string actionLabel;

    Session snapshot()
    {
        saved.resize(snakes.size());
        Session s;
        for (size_t k = 0; k < snakes.size(); ++k) {
            if (!saved[k]) saved[k] = std::make_shared<const typename Snake::Memento>(snakes[k]->Save());
            s.snakes.push_back(saved[k]);
        }
        s.selected = selected;
        s.seeds = seeds;
        s.seedAt = seedAt;
        s.params = params;
        return s;
    }
    /// Snakes are restored in place (references to them stay valid while they exist).
    void restore(const Session &s)
    {
        if (!s.snakes.empty()) EnsureSurface();
        snakes.resize(std::min(snakes.size(), s.snakes.size()));
        saved.resize(snakes.size());
        for (size_t k = 0; k < s.snakes.size(); ++k) {
            if (k >= snakes.size()) {
                snakes.emplace_back(new Snake(surface, s.params));
                saved.push_back(nullptr);
            }
            if (saved[k] != s.snakes[k]) snakes[k]->Restore(*s.snakes[k]);
            saved[k] = s.snakes[k];
        }
        selected = s.selected;
        seeds = s.seeds;
        seedAt = s.seedAt;
        params = s.params;
    }
    static size_t mementoBytes(const typename Snake::Memento &m)
    {
        size_t b = sizeof(m) + m.curve.samples.capacity() * sizeof(SnakeSample) +
                   (m.initialSamples.capacity()) * sizeof(SnakeSample) +
                   m.initialPolyline.capacity() * sizeof(SurfacePoint) + m.seeds.capacity() * sizeof(int);
        for (const auto &g : m.curve.gaps)
            b += sizeof(g) + g.faces.capacity() * sizeof(int) + g.crossings.capacity() * sizeof(SurfacePoint);
        b += (m.stats.msEmbedding.capacity() + m.stats.msUpdate.capacity() + m.stats.msOperation.capacity()) * sizeof(double);
        for (const auto &p : m.positions) b += p.capacity() * sizeof(vcg::Point3d);
        return b;
    }
    /// The memory a snapshot adds: its snakes' mementos, except those it shares with
    /// `previous` (the snakes the last action did not touch).
    size_t sessionBytes(const Session &s, const std::vector<MementoPtr> *previous = nullptr) const
    {
        size_t b = sizeof(Session) + s.seeds.capacity() * sizeof(int) + s.seedAt.capacity() * sizeof(SurfacePoint);
        for (const auto &m : s.snakes)
            if (!previous || std::find(previous->begin(), previous->end(), m) == previous->end()) b += mementoBytes(*m);
        return b;
    }
    /// Called before a change: the first change of an action records the session as it
    /// was. Returns true if this call pushed an undo step.
    bool record(const char *label)
    {
        if (actionDepth > 0) {
            if (actionRecorded) {
                markSelectedChanged();
                return false;
            }
            actionRecorded = true;
        }
        Session s = snapshot();
        history.Push(s, sessionBytes(s, &lastPushed), actionDepth > 0 ? actionLabel : std::string(label));
        lastPushed = s.snakes;
        markSelectedChanged();
        return true;
    }
    /// Every change goes through the selected snake (or adds / removes snakes, which
    /// resizes `saved`): its memento is outdated.
    void markSelectedChanged()
    {
        if (selected >= 0 && selected < int(saved.size())) saved[selected] = nullptr;
    }

    void touch(const char *op)
    {
        ++revision;
        lastOp = op;
    }
    vcg::Point3d P(int v) const { return vcg::Point3d::Construct(mesh.vert[v].cP()); }
    /// Vertex v as a surface point (a corner of one of its faces).
    SurfacePoint vertexPoint(int v) const
    {
        for (size_t f = 0; f < mesh.face.size(); ++f)
            if (!mesh.face[f].IsD())
                for (int k = 0; k < 3; ++k)
                    if (mesh.face[f].cV(k) == &mesh.vert[v]) return SurfacePoint::AtCorner(int(f), k);
        throw SnakeError("Geometric snake: seed vertex " + std::to_string(v) + " belongs to no face.");
    }
    double vdist(int a, int b) const { return (P(a) - P(b)).Norm(); }
    double meanEdgeNoSurface() const
    {
        if (surface) return surface->MeanEdge();
        double h = MeshValidation<MeshType>::MeanEdgeLength(mesh);
        return (h > 0 && std::isfinite(h)) ? h : 1.0;
    }
    void checkVertex(int v) const
    {
        if (v < 0 || v >= int(mesh.vert.size()) || mesh.vert[v].IsD())
            throw SnakeError("Geometric snake: vertex " + std::to_string(v) + " is not on the mesh.");
        vcg::Point3d p = P(v);
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
            throw SnakeError("Geometric snake: vertex " + std::to_string(v) + " has invalid coordinates.");
    }
    void checkSnake(int i) const
    {
        if (i < 0 || i >= int(snakes.size()))
            throw SnakeError("Geometric snake: no snake " + std::to_string(i) + " (there are " +
                             std::to_string(snakes.size()) + ").");
    }
    void checkSurfacePoint(const SurfacePoint &p) const
    {
        if (!p.IsValid() || p.face >= int(mesh.face.size()) || mesh.face[p.face].IsD())
            throw SnakeError("Geometric snake: the point is not on the mesh.");
        for (int k = 0; k < 3; ++k)
            if (p.bary[k] < -0.01 || p.bary[k] > 1.01)
                throw SnakeError("Geometric snake: the point is outside its triangle.");
    }
    void checkMesh() const
    {
        if (!MeshMatches())
            throw SnakeError("Geometric snake: the mesh changed (vertices or faces were added or removed) since the "
                             "snakes were built; restart the tool.");
    }
    Snake &sel()
    {
        Snake *s = SelectedSnake();
        if (!s) throw SnakeError("Geometric snake: no snake selected (place seeds and close them first).");
        return *s;
    }
};

} // namespace tri
} // namespace vcg

#endif
