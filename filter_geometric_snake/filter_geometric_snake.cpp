/****************************************************************************
* Geometric Snakes for MeshLab 2020.09                                      *
* Filters after Y. Lee, S. Lee, "Geometric Snakes for Triangular Meshes",   *
* Computer Graphics Forum (Eurographics 2002) 21(3).                        *
****************************************************************************/

#include "filter_geometric_snake.h"

#include <cmath>
#include <exception>
#include <string>
#include <vector>

#include <QElapsedTimer>

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/color.h>
#include <vcg/complex/algorithms/update/selection.h>
#include <vcg/complex/algorithms/stat.h>

#include <vcg_ext/feature_energy.h>
#include <vcg_ext/mesh_validation.h>
#include <vcg_ext/seed_path.h>
#include <vcg_ext/snake_error.h>

using namespace vcg;

namespace {

const char *const kEnergyNames[] = {"normal variation", "curvature norm", "quadric error"};
constexpr int kDefaultSmoothingSteps = 2;

QStringList energyTypeLabels()
{
	return QStringList() << "Normal variation" << "Curvature norm" << "Quadric error";
}

QString paperReference()
{
	return "<br><br>See: <br><i>Yunjin Lee, Seungyong Lee</i><br>"
	       "<b>\"Geometric Snakes for Triangular Meshes\"</b><br>"
	       "Computer Graphics Forum (Eurographics 2002), 21(3), pp. 229-238.";
}

/// The algorithms index vertices and faces by their position in the vectors: make
/// sure there are no deleted elements in between (file order = vector order).
bool compactIfNeeded(CMeshO &m)
{
	if (m.vn == int(m.vert.size()) && m.fn == int(m.face.size()) && m.en == int(m.edge.size()))
		return false;
	tri::Allocator<CMeshO>::CompactEveryVector(m);
	return true;
}

} // namespace

FilterGeometricSnakePlugin::FilterGeometricSnakePlugin()
{
	typeList << FP_FEATURE_ENERGY << FP_SEED_PATH;
	for (FilterIDType tt : types())
		actionList << new QAction(filterName(tt), this);
}

QString FilterGeometricSnakePlugin::pluginName() const
{
	return "FilterGeometricSnake";
}

QString FilterGeometricSnakePlugin::filterName(FilterIDType filterId) const
{
	switch (filterId) {
	case FP_FEATURE_ENERGY: return "Compute Geometric Snake Feature Energy";
	case FP_SEED_PATH: return "Geometric Snake Seed Path";
	default: assert(0); return "";
	}
}

QString FilterGeometricSnakePlugin::filterInfo(FilterIDType filterId) const
{
	switch (filterId) {
	case FP_FEATURE_ENERGY:
		return "Computes the per-vertex <b>feature energy</b> that drives a geometric snake and stores it "
		       "in the vertex quality, normalised to [0,1]: <b>0 on features</b> (creases, sharp edges, "
		       "ridges) and <b>1 on flat regions</b>. A snake slides towards low energy.<br>"
		       "<i>Normal variation</i> is the paper's measure (normal changes of the faces around a "
		       "vertex); <i>curvature norm</i> and <i>quadric error</i> are alternatives. Optionally "
		       "colours the vertices with MeshLab's quality ramp (red = feature, blue = flat).<br>"
		       "The Log reports the raw energy range before normalisation and the time taken." +
		       paperReference();
	case FP_SEED_PATH:
		return "Joins the given <b>seed vertices</b> (0-based vertex indices, in file order) by shortest "
		       "paths along mesh edges, in the given order, optionally closing the loop. This is the "
		       "initial position of a geometric snake.<br>"
		       "The vertex selection is replaced by the vertices of the path (the face selection is "
		       "left untouched; MeshLab has no per-edge selection on triangle meshes). Optionally the "
		       "path is also added as a new layer made of vertices and edges (the current layer does "
		       "not change: in meshlabserver save it with <code>-l x</code>).<br>"
		       "With the <i>feature</i> cost, edges through low vertex quality (the feature energy) "
		       "are cheaper, so the path follows features; if the mesh has no vertex quality yet, "
		       "the normal-variation energy is computed first." +
		       paperReference();
	default: assert(0); return "";
	}
}

MeshFilterInterface::FilterClass FilterGeometricSnakePlugin::getClass(QAction *a)
{
	switch (ID(a)) {
	case FP_FEATURE_ENERGY: return FilterClass(MeshFilterInterface::Quality | MeshFilterInterface::VertexColoring);
	case FP_SEED_PATH: return MeshFilterInterface::Selection;
	default: return MeshFilterInterface::Generic;
	}
}

MeshFilterInterface::FILTER_ARITY FilterGeometricSnakePlugin::filterArity(QAction *) const
{
	return SINGLE_MESH;
}

int FilterGeometricSnakePlugin::getPreConditions(QAction *) const
{
	// Greys out the menu entries for point clouds; applyFilter checks again (meshlabserver
	// does not look at preconditions).
	return MeshModel::MM_FACENUMBER;
}

int FilterGeometricSnakePlugin::getRequirements(QAction *)
{
	// Topology is (re)built inside applyFilter, after validation and compaction.
	return MeshModel::MM_NONE;
}

int FilterGeometricSnakePlugin::postCondition(QAction *a) const
{
	switch (ID(a)) {
	case FP_FEATURE_ENERGY: return MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR;
	case FP_SEED_PATH: return MeshModel::MM_VERTFLAGSELECT | MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR;
	default: return MeshModel::MM_ALL;
	}
}

void FilterGeometricSnakePlugin::initParameterSet(QAction *a, MeshModel & /*m*/, RichParameterList &par)
{
	switch (ID(a)) {
	case FP_FEATURE_ENERGY:
		par.addParam(RichEnum("EnergyType", 0, energyTypeLabels(), "Energy type",
		    "How features are measured at each vertex. <b>Normal variation</b> (paper): how much the "
		    "normals of the faces around the vertex differ. <b>Curvature norm</b>: the norm of the "
		    "principal curvatures. <b>Quadric error</b>: the distance error of the vertex's "
		    "face-plane quadric. In every case the result is normalised to [0,1], 0 = feature."));
		par.addParam(RichInt("SmoothingSteps", kDefaultSmoothingSteps, "Smoothing steps",
		    "Number of Laplacian smoothing passes over the per-vertex energy before normalisation "
		    "(0 = none, at most 10000). A little smoothing removes noise and widens the basin of "
		    "attraction of features."));
		par.addParam(RichBool("Colorize", true, "Colorize by energy",
		    "Also colour the vertices by the energy with MeshLab's quality colour ramp over [0,1] "
		    "(red = feature, blue = flat). Adds per-vertex colour to the mesh."));
		break;
	case FP_SEED_PATH:
		par.addParam(RichString("Seeds", "", "Seed vertices",
		    "Comma-separated 0-based vertex indices, in file order (the order of the vertices in the "
		    "loaded file), e.g. <code>0, 57, 112</code>. At least two; the path visits them in "
		    "this order."));
		par.addParam(RichBool("Closed", false, "Closed path",
		    "Also join the last seed back to the first one (a closed snake)."));
		par.addParam(RichEnum("Cost", 0, QStringList() << "Length" << "Feature", "Path cost",
		    "<b>Length</b>: shortest path along edges. <b>Feature</b>: edge lengths weighted by the "
		    "vertex quality (the feature energy, expected in [0,1]) so the path prefers features; "
		    "if the mesh has no vertex quality, the normal-variation energy is computed first and "
		    "stored in the vertex quality."));
		par.addParam(RichBool("NewLayer", true, "Add path as new layer",
		    "Also add the path as a new layer named \"Seed path\" made of its vertices and edges. "
		    "The current layer stays the input mesh."));
		break;
	default: break;
	}
}

bool FilterGeometricSnakePlugin::fail(const QString &msg)
{
	errorMessage = msg;
	Log(GLLogStream::WARNING, "Geometric snake error: %s", qUtf8Printable(msg));
	return false;
}

bool FilterGeometricSnakePlugin::applyFilter(QAction *filter, MeshDocument &md, const RichParameterList &par,
                                             vcg::CallBackPos * /*cb*/)
{
	errorMessage.clear();
	if (md.mm() == nullptr)
		return fail("No mesh is loaded.");
	try {
		switch (ID(filter)) {
		case FP_FEATURE_ENERGY: return applyFeatureEnergy(md, par);
		case FP_SEED_PATH: return applySeedPath(md, par);
		default: return fail("Unknown filter.");
		}
	} catch (const vcg::tri::SnakeError &e) {
		return fail(QString::fromStdString(e.what()));
	} catch (const std::bad_alloc &) {
		return fail("Out of memory.");
	} catch (const std::exception &e) {
		return fail(QString("Internal error: %1").arg(e.what()));
	} catch (...) {
		return fail("Internal error (unknown exception).");
	}
}

bool FilterGeometricSnakePlugin::applyFeatureEnergy(MeshDocument &md, const RichParameterList &par)
{
	MeshModel &m = *md.mm();
	const int type = par.getEnum("EnergyType");
	const int steps = par.getInt("SmoothingSteps");
	const bool colorize = par.getBool("Colorize");

	if (type < 0 || type > 2)
		return fail(QString("EnergyType must be 0 (normal variation), 1 (curvature norm) or 2 (quadric "
		                    "error), not %1.").arg(type));
	if (steps < 0 || steps > kMaxSmoothingSteps)
		return fail(QString("SmoothingSteps must be between 0 and %1, not %2.").arg(kMaxSmoothingSteps).arg(steps));

	tri::MeshValidation<CMeshO>::RequireSurface(m.cm);
	// FeatureEnergy needs no optional component (no adjacency, no curvature fields):
	// only the (always allocated) vertex quality, which the mask marks as meaningful.
	m.updateDataMask(MeshModel::MM_VERTQUALITY);

	QElapsedTimer timer;
	timer.start();
	const auto stats = tri::FeatureEnergy<CMeshO>::Compute(m.cm, tri::FeatureEnergyType(type), steps);

	if (colorize) {
		m.updateDataMask(MeshModel::MM_VERTCOLOR);
		// Fixed [0,1] range (not the data's min/max): red = feature, blue = flat, comparable
		// across meshes and runs.
		tri::UpdateColor<CMeshO>::PerVertexQualityRamp(m.cm, 0.0f, 1.0f);
	}
	const auto q = tri::Stat<CMeshO>::ComputePerVertexQualityMinMax(m.cm);

	Log("Feature energy (%s, %d smoothing steps) on %d vertices: raw range [%g, %g], stored in vertex "
	    "quality normalised to [%g, %g] (0 = feature, 1 = flat)%s.",
	    kEnergyNames[type], steps, m.cm.vn, double(stats.rawMin), double(stats.rawMax), double(q.first),
	    double(q.second), colorize ? ", coloured by the quality ramp" : "");
	if (stats.nonManifoldVertices > 0 || stats.degenerateFaces > 0)
		Log(GLLogStream::WARNING, "Feature energy: %d non-manifold vertices, %d degenerate faces (handled, but "
		    "the energy may be unreliable there).", stats.nonManifoldVertices, stats.degenerateFaces);
	Log("Feature energy computed in %.2f ms (%.2f ms including colouring).", stats.seconds * 1e3,
	    timer.nsecsElapsed() * 1e-6);
	return true;
}

bool FilterGeometricSnakePlugin::applySeedPath(MeshDocument &md, const RichParameterList &par)
{
	MeshModel &m = *md.mm();
	const std::string seedText = par.getString("Seeds").toStdString();
	const bool closed = par.getBool("Closed");
	const int cost = par.getEnum("Cost");
	const bool newLayer = par.getBool("NewLayer");

	if (cost < 0 || cost > 1)
		return fail(QString("Cost must be 0 (length) or 1 (feature), not %1.").arg(cost));

	const std::vector<int> seeds = tri::SeedPath<CMeshO>::ParseSeeds(seedText);
	tri::MeshValidation<CMeshO>::RequireSurface(m.cm);
	if (compactIfNeeded(m.cm))
		Log("Compacted the mesh (it had deleted elements); vertex indices refer to the compacted order.");
	for (int s : seeds)
		if (s < 0 || s >= m.cm.vn)
			return fail(QString("Seed vertex %1 does not exist: the mesh has %2 vertices (valid indices 0..%3).")
			                .arg(s).arg(m.cm.vn).arg(m.cm.vn - 1));

	m.updateDataMask(MeshModel::MM_FACEFACETOPO | MeshModel::MM_VERTFACETOPO);

	if (cost == int(tri::SeedPathCost::Feature)) {
		if (!m.hasDataMask(MeshModel::MM_VERTQUALITY)) {
			m.updateDataMask(MeshModel::MM_VERTQUALITY);
			const auto stats = tri::FeatureEnergy<CMeshO>::Compute(m.cm, tri::FeatureEnergyType::NormalVariation,
			                                                       kDefaultSmoothingSteps);
			Log("The mesh had no vertex quality: computed the normal-variation feature energy first (%d "
			    "smoothing steps, %.2f ms) and stored it in the vertex quality.", kDefaultSmoothingSteps,
			    stats.seconds * 1e3);
		} else {
			const auto q = tri::Stat<CMeshO>::ComputePerVertexQualityMinMax(m.cm);
			if (q.first < 0.0f || q.second > 1.0f || !std::isfinite(q.first) || !std::isfinite(q.second))
				Log(GLLogStream::WARNING, "Vertex quality range [%g, %g] is not the [0,1] feature energy; run "
				    "\"Compute Geometric Snake Feature Energy\" first for a meaningful feature cost.",
				    double(q.first), double(q.second));
		}
	}

	const auto path = tri::SeedPath<CMeshO>::Compute(m.cm, seeds, closed, tri::SeedPathCost(cost));
	if (path.vertices.empty())
		return fail("No path was found between the seeds.");

	// Selection: exactly the path's vertices.
	tri::UpdateSelection<CMeshO>::VertexClear(m.cm);
	for (int vi : path.vertices)
		m.cm.vert[vi].SetS();
	m.updateDataMask(MeshModel::MM_VERTFLAGSELECT);

	if (newLayer) {
		MeshModel *pl = md.addNewMesh("", "Seed path", false);
		CMeshO &pm = pl->cm;
		const int n = int(path.vertices.size());
		auto vi = tri::Allocator<CMeshO>::AddVertices(pm, n);
		for (int i = 0; i < n; ++i, ++vi) {
			vi->P() = m.cm.vert[path.vertices[i]].cP();
			vi->N() = m.cm.vert[path.vertices[i]].cN();
			vi->Q() = m.cm.vert[path.vertices[i]].cQ();
		}
		const int ne = (closed && n >= 3) ? n : n - 1;
		if (ne > 0) {
			auto ei = tri::Allocator<CMeshO>::AddEdges(pm, ne);
			for (int i = 0; i < ne; ++i, ++ei) {
				ei->V(0) = &pm.vert[i];
				ei->V(1) = &pm.vert[(i + 1) % n];
			}
		}
		pm.Tr = m.cm.Tr;
		tri::UpdateBounding<CMeshO>::Box(pm);
		pl->updateDataMask(MeshModel::MM_VERTQUALITY);
		Log("Added layer \"%s\": %d vertices, %d edges.", qUtf8Printable(pl->label()), n, ne);
	}

	Log("Seed path (%s, %s cost) through %d seeds: %d vertices selected, length %g.",
	    path.closed ? "closed" : "open", cost == 0 ? "length" : "feature", int(seeds.size()),
	    int(path.vertices.size()), path.length);
	return true;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterGeometricSnakePlugin)
