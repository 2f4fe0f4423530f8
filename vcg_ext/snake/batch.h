#ifndef VCG_EXT_SNAKE_BATCH_H
#define VCG_EXT_SNAKE_BATCH_H

// One snake from seeds to convergence, without a user: what the "Geometric Snake from Seed
// Vertices" filter and the command-line tool's `snake` command both do once their inputs are
// read and checked. Keeping it here makes the two front ends give the same curve for the same
// inputs (tests/cli compares them), and leaves them only the translation of parameters,
// progress and messages.

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <vcg_ext/session/controller.h>
#include <vcg_ext/session/param_defs.h>
#include <vcg_ext/snake/part_boundary_end.h>

namespace vcg {
namespace tri {

template <class MeshType>
class SnakeBatch
{
public:
    typedef SnakeController<MeshType> Controller;

    /// What the run needs besides the mesh. Either `seeds` (vertex indices) or `seedPoints`
    /// (surface points, already snapped) start the snake; points win when there are any.
    struct Settings
    {
        bool useQuality = false; ///< the vertex quality is the energy (any field MeshLab computes)
        FeatureEnergyType energy = FeatureEnergyType::NormalVariation;
        int smoothingSteps = 0;
        double creaseAngle = 30;
        SnakeParams params;
        std::vector<int> seeds;
        std::vector<SurfacePoint> seedPoints;
        bool closed = false;
        /// The seeds are an open stroke across a part: complete it into a loop round the part
        /// (paths/stroke_loop.h) and run a closed snake from there.
        bool completeLoop = false;
        int maxOperations = 1000;
        double timeLimit = 0; ///< seconds of the run (0: none)
        /// The caller's FF/VF adjacency build (MeshLab's updateDataMask), if it is still to do:
        /// run while the energy is computed (SnakeEnergySource::ComputeBeside).
        std::function<void()> adjacency;
    };

    struct Result
    {
        std::vector<vcg::Point3d> curve; ///< the traced polyline
        double length = 0;               ///< of the curve (closing segment included)
        std::vector<std::string> energyWarnings;
        /// The run's warnings, each once, with how often it was given (a frozen segment repeats
        /// its warning at every operation).
        std::vector<std::pair<std::string, int>> runWarnings;
        SnakeStop stop = SnakeStop::Running; ///< why the run ended (snake/stop.h)
        std::string stopMessage;
    };

    /// The settings the values of the snake operation's table give (session/param_defs.h): the
    /// one reading of them for the filter and the program. The hosts add the seed points, their
    /// adjacency build and their own checks.
    static Settings FromValues(const ParamValues &v, const std::vector<int> &seeds)
    {
        Settings b;
        b.useQuality = v.Bool("UseQuality");
        b.energy = FeatureEnergyType(v.Enum("EnergyType"));
        b.smoothingSteps = SnakeParamDefs::DefaultSmoothingSteps();
        b.creaseAngle = v.Real("CreaseAngle");
        b.params = SnakeParamDefs::ToSnakeParams(v);
        b.seeds = seeds;
        b.closed = v.Bool("Closed");
        b.maxOperations = v.Int("MaxOperations");
        b.timeLimit = v.Real("TimeLimit");
        b.completeLoop = v.Bool("CompleteLoop");
        return b;
    }

    /// Configures `ctl` (energy, parameters, seeds), runs its snake and traces the curve.
    /// `progress(op)` is called after every operation; false stops the run. Throws SnakeError.
    static Result Run(Controller &ctl, const Settings &s, const std::function<bool(int)> &progress = nullptr)
    {
        if (s.useQuality) {
            ctl.UseQualityAsEnergy();
        } else {
            ctl.SetCreaseAngle(s.creaseAngle);
            ctl.SetEnergySettings(s.energy, s.smoothingSteps);
        }
        if (s.adjacency) ctl.ComputeEnergyBeside(s.adjacency);
        ctl.SetParams(s.params);
        if (s.completeLoop) {
            if (s.closed) throw SnakeError("Geometric snake: a stroke completed into a loop is an open set of seeds: leave Closed off.");
            std::vector<SurfacePoint> stroke = s.seedPoints;
            if (stroke.empty())
                for (int v : s.seeds) stroke.push_back(ctl.EnsureSurface().VertexPoint(v));
            ctl.CreateLoopFromStroke(stroke);
        } else if (s.seedPoints.empty()) {
            ctl.SetSeeds(s.seeds);
            ctl.CloseSeeds(s.closed);
        } else {
            ctl.CreateSnakeFromSeedPoints(s.seedPoints, s.closed);
        }
        Result r;
        r.energyWarnings = ctl.EnergyWarnings();
        GeometricSnake<MeshType> &snake = ctl.Get(0);
        SnakeRunLimits lim;
        lim.maxOperations = s.maxOperations;
        lim.seconds = s.timeLimit;
        const auto seeded = PartBoundaryEnd<MeshType>::Seeded::Of(snake); // a loop that shrinks far is searched from it
        r.stop = snake.Run(lim, progress);
        PartBoundaryEnd<MeshType>::FinishRun(snake, ctl.EnergyType(), ctl.EnergyFromQuality(), ctl.RunEndParam(), &seeded);
        r.stopMessage = snake.Stats().stopMessage;
        r.curve = snake.PolylinePositions();
        for (const auto &x : r.curve)
            if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
                throw SnakeError("The snake produced invalid coordinates (please report this with the mesh).");
        r.length = Length(r.curve, snake.Closed());
        for (const auto &w : snake.Stats().warnings) {
            auto it = std::find_if(r.runWarnings.begin(), r.runWarnings.end(),
                                   [&](const std::pair<std::string, int> &d) { return d.first == w; });
            if (it == r.runWarnings.end()) r.runWarnings.push_back({w, 1});
            else ++it->second;
        }
        return r;
    }

    static double Length(const std::vector<vcg::Point3d> &curve, bool closed)
    {
        double len = 0;
        for (size_t i = 1; i < curve.size(); ++i) len += (curve[i] - curve[i - 1]).Norm();
        if (closed && curve.size() > 2) len += (curve.front() - curve.back()).Norm();
        return len;
    }
};

} // namespace tri
} // namespace vcg

#endif // VCG_EXT_SNAKE_BATCH_H
