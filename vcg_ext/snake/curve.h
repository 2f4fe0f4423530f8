#ifndef VCG_EXT_SNAKE_CURVE_H
#define VCG_EXT_SNAKE_CURVE_H

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include <vcg_ext/snake/error.h>
#include <vcg_ext/snake/stop.h>
#include <vcg_ext/surface/surface_point.h>

namespace vcg {
namespace tri {

/// How the snake is kept on the surface.
enum class SnakeMethod {
    LocalEmbedding = 0, ///< the paper's method: Eq. 4 in the plane of a local embedding (Sec. 4.2, 5)
    Projection3D = 1    ///< the naive method the paper rejected: Eq. 4 in space, then project (Sec. 4.2)
};

/// Snake parameters. Positions are measured in units of the snake's local length scale (the
/// median edge length along its seed path) and the energy lies in [0,1], so every parameter is
/// scale-free: the same values work on any mesh, whatever its size and mix of edge lengths.
struct SnakeParams
{
    double alpha = 0.05;         ///< tension, Eq. 2
    double beta = 0.5;           ///< rigidity, Eq. 2
    double gamma = 1.0;          ///< inverse time step of Eq. 4 (larger = smaller, stabler steps)
    double externalWeight = 1.0; ///< weight of the feature force f_x
    double spacing = 1.0;        ///< sample spacing, in local edge lengths
    int updatesPerOperation = 5; ///< Eq. 4 updates per embedding (Sec. 7)
    int segmentSamples = 64;     ///< partition size (Sec. 5.1)
    int virtualLayers = 3;       ///< rings of virtual vertices of the embedding (Sec. 5.3)
    double maxStep = 0.5;        ///< cap on one update's move, in local edge lengths
    double convergenceTol = 0.02;///< converged: largest move per operation below this (edge lengths) ...
    int convergenceWindow = 3;   ///< ... for this many operations in a row
    double balloon = 0;          ///< closed snakes: pressure along the outward normal (> 0 inflates, < 0 deflates)
    SnakeMethod method = SnakeMethod::LocalEmbedding;

    /// Refuses absurd values with a message for the user.
    void Validate() const
    {
        auto bad = [](const std::string &what) { throw SnakeError("Geometric snake: " + what); };
        auto finite = [](double v) { return std::isfinite(v); };
        if (!finite(alpha) || alpha < 0 || alpha > 1e4) bad("Alpha must be in [0, 10000].");
        if (!finite(beta) || beta < 0 || beta > 1e4) bad("Beta must be in [0, 10000].");
        if (!finite(gamma) || gamma <= 0 || gamma > 1e6) bad("Gamma must be in (0, 1e6].");
        if (!finite(externalWeight) || externalWeight < 0 || externalWeight > 1e4)
            bad("ExternalWeight must be in [0, 10000].");
        if (!finite(spacing) || spacing < 0.05 || spacing > 1000) bad("Spacing must be in [0.05, 1000] edge lengths.");
        if (updatesPerOperation < 1 || updatesPerOperation > 1000) bad("Updates per operation must be in [1, 1000].");
        if (segmentSamples < 6 || segmentSamples > 100000) bad("Segment size must be in [6, 100000] samples.");
        if (virtualLayers < 1 || virtualLayers > 10) bad("Virtual layers must be in [1, 10].");
        if (!finite(maxStep) || maxStep <= 0 || maxStep > 10) bad("Max step must be in (0, 10] edge lengths.");
        if (!finite(convergenceTol) || convergenceTol <= 0 || convergenceTol > 10)
            bad("Convergence tolerance must be in (0, 10] edge lengths.");
        if (convergenceWindow < 1 || convergenceWindow > 1000) bad("Convergence window must be in [1, 1000].");
        if (!finite(balloon) || balloon < -10 || balloon > 10) bad("Balloon must be in [-10, 10].");
    }
};

struct SnakeSample
{
    SurfacePoint p;
    bool fixed = false;
    /// Step control (not saved): the move cap of this sample halves when an update raised
    /// its energy by more than the noise (it overshot a well) and grows back otherwise, so
    /// samples settle in wells; reset to 1 whenever the energy level changes.
    double trust = 1.0;
    /// Held on level 0 while the snake is still on a coarse level (not saved): the sample
    /// crossed a feature-like well of level 0 across the curve (SnakeMotionRules::HoldAtWell).
    bool heldFine = false;
};

/// The clock of SnakeStats' timings.
struct SnakeClock
{
    typedef std::chrono::steady_clock clock;
    typedef clock::time_point time_point;
    static time_point Now() { return clock::now(); }
    static double MsSince(time_point t0) { return std::chrono::duration<double, std::milli>(clock::now() - t0).count(); }
};

/// Timings and counters, for the Log, the JSON output and the benchmarks.
struct SnakeStats
{
    int operations = 0, updates = 0, embeddings = 0, regionFailures = 0;
    int reuses = 0; ///< segment moves served by an embedding kept from an earlier operation (Sec. 4.2)
    bool converged = false;
    bool stopped = false; ///< stopped without converging (a closed snake collapsing): see warnings
    /// Why the last run ended (Running while it goes on): the engine's verdict after every
    /// operation (Converged, Collapsed, LeftPart), or the run's limit (SnakeRunLimits), or Cancelled.
    SnakeStop stop = SnakeStop::Running;
    std::string stopMessage; ///< what the hosts show for `stop` (empty for Running)
    double secondsTotal = 0;
    double lastMaxMove = 0; ///< in local edge lengths (the snake's LengthScale)
    std::vector<double> msEmbedding, msUpdate, msOperation;
    std::vector<std::string> warnings;

    static double Median(std::vector<double> v)
    {
        if (v.empty()) return 0;
        std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
        return v[v.size() / 2];
    }
};

/// The polyline between sample i and i+1 (Sec. 4.1): the faces it crosses and the
/// edge-crossing points, both valid after a trace.
struct SnakeGap
{
    std::vector<int> faces;
    std::vector<SurfacePoint> crossings;
    bool traced = false;
    /// The crossings still lie on the straight segment of the embedding: the shortest path
    /// through the same faces (paths/path_tighten.h) is taken when the polyline is read, between the
    /// ends the gap was traced between. The motion reads only `faces`, so tightening every
    /// gap of every operation (half of an operation, issue 12) changed nothing it used.
    bool tightenPending = false;
    SurfacePoint tracedFrom, tracedTo;
};

/// The state of one snake that undo restores: samples, the traced gaps between them, the
/// topology and the parameters.
struct SnakeCurve
{
    std::vector<SnakeSample> samples;
    std::vector<SnakeGap> gaps;
    bool closed = false;
    SnakeParams params;
    double unit = 1; ///< the length unit of positions, spacing, step caps and tolerances (local scale)
    /// The spacing of the samples when the snake was built or restored (length units; 0:
    /// unknown): an open snake that lengthens keeps that density (SnakeGapRefine).
    double builtSpacing = 0;

    int NumGaps() const
    {
        int n = int(samples.size());
        return closed ? n : std::max(0, n - 1);
    }
    /// The gap between samples a and b when b follows a, else -1.
    int GapIndex(int a, int b) const
    {
        int n = int(samples.size());
        if (b == (a + 1) % n && (closed || a + 1 < n)) return a;
        return -1;
    }
    /// End samples of an open snake (their end condition: see SnakeSegmentMotion).
    bool IsOpenEnd(int i) const { return !closed && (i == 0 || i == int(samples.size()) - 1); }
};

/// What one operation needs besides the curve: the energy level and the gain of its force
/// (a coarse level's slopes are gentler by its reach: see SnakeEnergyField::Reach), the length unit, and for
/// the balloon force the side of a closed curve that is outside (+1: the curve runs
/// counter-clockwise seen from the surface's front, so outside is on its right; 0: no balloon).
struct SnakeMotionFrame
{
    int level = 0;
    double gain = 1;
    double unit = 1;
    double outside = 0;
};

} // namespace tri
} // namespace vcg

#endif
