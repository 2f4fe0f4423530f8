#ifndef VCG_EXT_SNAKE_BUILDER_H
#define VCG_EXT_SNAKE_BUILDER_H

// How a new snake is built from what the user placed (Sec. 5.5): vertex seeds (the paper's
// vertex path), seeds inside faces (a curve through those points) or an open stroke completed
// into a loop round a part (paths/stroke_loop.h), on the energy's shared surface. The seed paths
// search a SeedPath::MeshIndex that is O(mesh) to build (issue 37): it is kept here across
// builds while the mesh keeps its elements, and may be built on another thread before the first
// build. The edit tool's controller (session/controller.h) decides when a snake is built and
// keeps it; this is what builds it.

#include <future>
#include <memory>
#include <vector>

#include <vcg_ext/energy/energy_source.h>
#include <vcg_ext/paths/seed_list.h>
#include <vcg_ext/paths/seed_path.h>
#include <vcg_ext/paths/stroke_loop.h>
#include <vcg_ext/snake/geometric_snake.h>
#include <vcg_ext/surface/surface_point.h>

namespace vcg {
namespace tri {

template <class MeshType>
class SnakeBuilder
{
public:
    typedef GeometricSnake<MeshType> Snake;
    typedef typename SeedPath<MeshType>::MeshIndex PathIndex;

    /// `e`: the energy and shared surface the snakes slither on. The surface must exist
    /// (SnakeEnergySource::EnsureSurface) before a build.
    SnakeBuilder(MeshType &m, SnakeEnergySource<MeshType> &e) : mesh(m), energy(e) {}
    // the background build refers to the mesh
    SnakeBuilder(const SnakeBuilder &) = delete;
    SnakeBuilder &operator=(const SnakeBuilder &) = delete;

    /// Builds the seed paths' index on another thread, for the builds to come (none is started
    /// if one is kept or under way). The mesh must not change until the next build (it waits).
    void PrepareInBackground()
    {
        if (!pathIndex && !pathIndexReady.valid()) {
            MeshType *m = &mesh;
            pathIndexReady = std::async(std::launch::async, [m] { return std::make_shared<const PathIndex>(*m); });
        }
    }

    /// The snake of a seed list: seeds inside faces (clicks) make a curve through those points;
    /// vertex seeds (and clicks exactly at vertices) the paper's vertex path.
    std::unique_ptr<Snake> FromSeeds(const SnakeSeedList<MeshType> &seeds, bool closed, const SnakeParams &params,
                                     SeedPathCost cost)
    {
        std::unique_ptr<Snake> sn(new Snake(energy.SurfacePtr(), params));
        const std::vector<SurfacePoint> pts = seeds.Points(*energy.EnsureSurface());
        if (seeds.AtVertices())
            sn->InitFromSeeds(seeds.Vertices(), closed, cost, energy.LengthScale(pts));
        else
            sn->InitFromSeedPoints(pts, closed, cost, energy.LengthScale(pts), &seedPathIndex());
        return sn;
    }

    /// The snake through seeds given as surface points: the curve starts and ends exactly at them.
    std::unique_ptr<Snake> FromSeedPoints(const std::vector<SurfacePoint> &pts, bool closed, const SnakeParams &params,
                                          SeedPathCost cost)
    {
        std::unique_ptr<Snake> sn(new Snake(energy.SurfacePtr(), params));
        sn->InitFromSeedPoints(pts, closed, cost, energy.LengthScale(pts), &seedPathIndex());
        return sn;
    }

    /// The closed snake round a part from an open stroke across it (StrokeLoop::Complete). `view`:
    /// towards the viewer (zero: the side the stroke lies on).
    std::unique_ptr<Snake> LoopFromStroke(const std::vector<SurfacePoint> &stroke, const vcg::Point3d &view,
                                          const SnakeParams &params, SeedPathCost cost)
    {
        typename StrokeLoop<MeshType>::Param lp;
        lp.cost = cost;
        lp.view = view;
        const typename StrokeLoop<MeshType>::Result r = StrokeLoop<MeshType>::Complete(mesh, stroke, lp);
        std::unique_ptr<Snake> sn(new Snake(energy.SurfacePtr(), params));
        sn->InitFromSurfacePath(r.loop, true, energy.LengthScale(r.loop));
        return sn;
    }

private:
    MeshType &mesh;
    SnakeEnergySource<MeshType> &energy;
    std::shared_ptr<const PathIndex> pathIndex;
    std::future<std::shared_ptr<const PathIndex>> pathIndexReady; // PrepareInBackground's; last: ends first

    const PathIndex &seedPathIndex()
    {
        if (pathIndexReady.valid()) pathIndex = pathIndexReady.get();
        if (!pathIndex || !pathIndex->Matches(mesh)) pathIndex = std::make_shared<const PathIndex>(mesh);
        return *pathIndex;
    }
};

} // namespace tri
} // namespace vcg

#endif
