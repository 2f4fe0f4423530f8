/****************************************************************************
* Geometric Snakes for MeshLab (2020.09 and 2022.02)                        *
* Filters after Y. Lee, S. Lee, "Geometric Snakes for Triangular Meshes",   *
* Computer Graphics Forum (Eurographics 2002) 21(3).                        *
****************************************************************************/

#include "filter_geometric_snake.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <string>
#include <vector>

#include <QElapsedTimer>

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/color.h>
#include <vcg/complex/algorithms/update/selection.h>
#include <vcg/complex/algorithms/stat.h>

#include <vcg_ext/cut/cut_curve_io.h>
#include <vcg_ext/cut/cut_session_map.h>
#include <vcg_ext/cut/mesh_cut.h>
#include <vcg_ext/energy/feature_energy.h>
#include <vcg_ext/io/safe_file_write.h>
#include <vcg_ext/io/seed_list_text.h>
#include <vcg_ext/io/snake_io.h>
#include <vcg_ext/paths/seed_path.h>
#include <vcg_ext/paths/seed_points.h>
#include <vcg_ext/session/controller.h>
#include <vcg_ext/session/mesh_store.h>
#include <vcg_ext/session/param_defs.h>
#include <vcg_ext/snake/batch.h>
#include <vcg_ext/snake/error.h>
#include <vcg_ext/surface/mesh_validation.h>
#include <vcg_ext/surface/triangle_soup.h>

#include <QFileInfo>
#include <fstream>

using namespace vcg;

namespace {

const int kDefaultSmoothingSteps = tri::SnakeParamDefs::DefaultSmoothingSteps();

/// MeshLab parameters from the shared definitions (vcg_ext/session/param_defs.h), which the
/// geometric-snake program reads too: same names, defaults, ranges and help.
void addParams(RichParameterList &par, const std::vector<tri::ParamDef> &defs)
{
	for (const tri::ParamDef &d : defs) {
		const QString name = QString::fromStdString(d.name), label = QString::fromStdString(d.label);
		QString help = QString::fromStdString(d.help);
		if (d.kind == tri::ParamDef::Int || d.kind == tri::ParamDef::Real)
			help += QString(" Range %1.").arg(QString::fromStdString(d.RangeText()));
		switch (d.kind) {
		case tri::ParamDef::Bool: par.addParam(RichBool(name, d.value != 0, label, help)); break;
		case tri::ParamDef::Int: par.addParam(RichInt(name, int(d.value), label, help)); break;
		case tri::ParamDef::Real: par.addParam(RichFloat(name, float(d.value), label, help)); break;
		case tri::ParamDef::Text: par.addParam(RichString(name, QString::fromStdString(d.text), label, help)); break;
		case tri::ParamDef::Enum: {
			QStringList labels;
			for (const auto &c : d.choices) labels << QString::fromStdString(c.label);
			par.addParam(RichEnum(name, int(d.value), labels, label, help));
			break;
		}
		}
	}
}

/// The filter's values, checked against the shared ranges (SnakeError on a bad one).
tri::ParamValues readParams(const RichParameterList &par, const std::vector<tri::ParamDef> &defs)
{
	tri::ParamValues v(defs);
	for (const tri::ParamDef &d : defs) {
		const QString name = QString::fromStdString(d.name);
		switch (d.kind) {
		case tri::ParamDef::Bool: v.SetNumber(d.name, par.getBool(name) ? 1 : 0); break;
		case tri::ParamDef::Int: v.SetNumber(d.name, par.getInt(name)); break;
		case tri::ParamDef::Real: v.SetNumber(d.name, par.getFloat(name)); break;
		case tri::ParamDef::Enum: v.SetNumber(d.name, par.getEnum(name)); break;
		case tri::ParamDef::Text: v.SetText(d.name, par.getString(name).toStdString()); break;
		}
	}
	v.Check();
	return v;
}

/// Files no output of these filters may replace: every mesh loaded in the document, with its
/// snake sidecar and the sidecar's backup.
std::vector<tri::ProtectedFile> protectedFiles(MeshDocument &md)
{
	std::vector<tri::ProtectedFile> keep;
	for (MeshModel *mm : gs::host::Meshes(md)) {
		if (mm == nullptr || mm->fullName().isEmpty()) continue;
		const std::string path = QFileInfo(mm->fullName()).absoluteFilePath().toStdString();
		for (auto &k : tri::SnakeSidecar::ProtectedFiles(path, mm->label().toStdString())) keep.push_back(k);
	}
	return keep;
}

/// Refuses a bad output file before any work is done (format by extension, folder, protected files).
void checkOutput(const std::string &out, const std::vector<tri::ProtectedFile> &keep)
{
	tri::SnakeIO<CMeshO>::FormatOf(out);
	tri::SafeFileWrite::CheckTarget(out, keep);
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
	for (ActionIDType id : {FP_FEATURE_ENERGY, FP_SEED_PATH, FP_SNAKE, FP_EXPORT, FP_CUT})
		addFilterAction(id, new QAction(filterName(id), this));
}

QString FilterGeometricSnakePlugin::pluginName() const
{
	return "FilterGeometricSnake";
}

QString FilterGeometricSnakePlugin::filterName(ActionIDType filterId) const
{
	switch (filterId) {
	case FP_FEATURE_ENERGY: return "Compute Geometric Snake Feature Energy";
	case FP_SEED_PATH: return "Geometric Snake Seed Path";
	case FP_SNAKE: return "Geometric Snake from Seed Vertices";
	case FP_EXPORT: return "Export Geometric Snake Curves";
	case FP_CUT: return "Cut Mesh along Geometric Snake";
	default: assert(0); return "";
	}
}

// PyMeshLab (MeshLab 2022.02 and later): ms.<name>(...) or ms.apply_filter("<name>", ...), with
// the same parameter names as the .mlx scripts, in PyMeshLab's verb-first style.
QString FilterGeometricSnakePlugin::pythonFilterName(ActionIDType filterId) const
{
	switch (filterId) {
	case FP_FEATURE_ENERGY: return "compute_scalar_by_geometric_snake_feature_energy";
	case FP_SEED_PATH: return "compute_selection_by_geometric_snake_seed_path";
	case FP_SNAKE: return "compute_geometric_snake_from_seed_vertices";
	case FP_EXPORT: return "save_geometric_snake_curves";
	case FP_CUT: return "meshing_cut_along_geometric_snake";
	default: assert(0); return "";
	}
}

QString FilterGeometricSnakePlugin::filterInfo(ActionIDType filterId) const
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
	case FP_SNAKE:
		return "Runs a <b>geometric snake</b> from seed vertices until it has slithered onto a nearby "
		       "feature curve (a crease, a rim, a sharp edge). The seeds (0-based vertex indices, in "
		       "file order) are joined by shortest edge paths; samples are taken along that path and "
		       "moved by the paper's method: each operation embeds the local region around the snake "
		       "in the plane (convex combination with a virtual boundary) and solves the snake's "
		       "equation of motion there (Eq. 4), up to 5 times, then maps back onto the surface. "
		       "The alternative method updates in 3D and projects onto the surface after every step.<br>"
		       "Seeds can also be 3D points (<i>Seed points</i>) or a MeshLab Pick Points file "
		       "(<i>Seed file</i>), snapped onto the surface: the curve then starts and ends exactly at "
		       "them, inside faces, which is what CAD tessellations need (all their vertices lie on "
		       "creases).<br>"
		       "The feature energy is the vertex quality if <i>Use vertex quality</i> is on (any "
		       "quality field works: low = feature), else the energy of <i>Energy type</i> (normal "
		       "variation by default; <i>crease distance</i> for CAD parts; <i>part boundary</i> for "
		       "loops around parts of organic meshes) is computed and stored in "
		       "the vertex quality.<br>"
		       "The curve can be written to a file (.json with samples, curve and timings; .obj; "
		       ".ply) and added as a layer of edges. It is also kept on the mesh, so the Geometric "
		       "Snake edit tool shows it and <i>Export Geometric Snake Curves</i> can write it." +
		       paperReference();
	case FP_EXPORT:
		return "Writes the geometric snakes kept on the current mesh (made with the Geometric Snake "
		       "edit tool or the <i>Geometric Snake from Seed Vertices</i> filter) to a file: "
		       "<b>.json</b> (surface points with face and barycentric coordinates, and the curve), "
		       "<b>.obj</b> (<code>l</code> records) or <b>.ply</b> (vertices and edges), chosen by "
		       "the extension. If the mesh holds no snakes, the edit tool's sidecar file next to the "
		       "mesh (<code>&lt;mesh&gt;.snakes.json</code>) is read instead." +
		       paperReference();
	case FP_CUT:
		return "Cuts the mesh along a closed geometric snake, or an open one from boundary to boundary. The "
		       "snake's curve is embedded exactly: a vertex at every crossing of a mesh edge and at its points "
		       "inside faces (colour, quality, normals and texture coordinates interpolated), none closer to "
		       "a vertex than a millionth of the edge. <b>Select</b>: the faces of the chosen side become the "
		       "selection (and their vertices the vertex selection); each face's side is in its quality (1 "
		       "inside, 0 outside). <b>Select only</b>: selects the faces whose centroid is on that side, "
		       "without changing the mesh. <b>Split</b>: two new layers, inside and outside. <b>Cut open</b>: "
		       "the curve's edges become boundary edges (an open snake ending inside makes a slit).<br>"
		       "The snake comes from a curve file, or else the snakes kept on the mesh (the edit tool's "
		       "session). A loop that does not separate the surface (around a handle), a curve that crosses "
		       "itself or was made on another mesh, or a non-manifold cut is refused and the mesh is left as it "
		       "was.";
	default: assert(0); return "";
	}
}

FilterGeometricSnakePlugin::FilterClass FilterGeometricSnakePlugin::getClass(const QAction *a) const
{
	switch (ID(a)) {
	case FP_FEATURE_ENERGY: return FilterClass(Quality | VertexColoring);
	case FP_SEED_PATH: return Selection;
	case FP_SNAKE: return Quality;
	case FP_EXPORT: return Layer; // Generic has no menu: MeshLab refuses it
	case FP_CUT: return FilterClass(Selection | Remeshing);
	default: return Generic;
	}
}

FilterGeometricSnakePlugin::FilterArity FilterGeometricSnakePlugin::filterArity(const QAction *) const
{
	return SINGLE_MESH;
}

int FilterGeometricSnakePlugin::getPreConditions(const QAction *) const
{
	// Greys out the menu entries for point clouds; applyFilter checks again (meshlabserver
	// does not look at preconditions).
	return MeshModel::MM_FACENUMBER;
}

int FilterGeometricSnakePlugin::getRequirements(const QAction *)
{
	// Topology is (re)built inside applyFilter, after validation and compaction.
	return MeshModel::MM_NONE;
}

int FilterGeometricSnakePlugin::postCondition(const QAction *a) const
{
	switch (ID(a)) {
	case FP_FEATURE_ENERGY: return MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR;
	case FP_SEED_PATH: return MeshModel::MM_VERTFLAGSELECT | MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR;
	case FP_SNAKE: return MeshModel::MM_VERTQUALITY;
	case FP_EXPORT: return MeshModel::MM_NONE;
	case FP_CUT: return MeshModel::MM_ALL;
	default: return MeshModel::MM_ALL;
	}
}

RichParameterList FilterGeometricSnakePlugin::initParameterList(const QAction *a, const MeshModel & /*m*/)
{
	RichParameterList par;
	switch (ID(a)) {
	case FP_FEATURE_ENERGY: addParams(par, tri::SnakeParamDefs::FeatureEnergy()); break;
	case FP_SEED_PATH: addParams(par, tri::SnakeParamDefs::SeedPath()); break;
	case FP_SNAKE: addParams(par, tri::SnakeParamDefs::Snake()); break;
	case FP_EXPORT: addParams(par, tri::SnakeParamDefs::Export()); break;
	case FP_CUT: addParams(par, tri::SnakeParamDefs::Cut()); break;
	default: break;
	}
	return par;
}

bool FilterGeometricSnakePlugin::fail(const QString &msg)
{
	Log(GLLogStream::WARNING, "Geometric snake error: %s", qUtf8Printable(msg));
	return filterError(msg);
}

bool FilterGeometricSnakePlugin::apply(const QAction *filter, const RichParameterList &par, MeshDocument &md,
                                       vcg::CallBackPos *cb)
{
	if (md.mm() == nullptr)
		return fail("No mesh is loaded.");
	try {
		switch (ID(filter)) {
		case FP_FEATURE_ENERGY: return applyFeatureEnergy(md, par, cb);
		case FP_SEED_PATH: return applySeedPath(md, par);
		case FP_SNAKE: return applySnake(md, par, cb);
		case FP_EXPORT: return applyExport(md, par);
		case FP_CUT: return applyCut(md, par);
		default: return fail("Unknown filter.");
		}
	} catch (const vcg::tri::SnakeError &e) {
		return fail(QString::fromStdString(e.what()));
	} catch (const nlohmann::json::exception &e) {
		return fail(QString("Snake data: %1.").arg(QString::fromStdString(tri::SnakeIO<CMeshO>::JsonErrorText(e))));
	} catch (const std::bad_alloc &) {
		return fail("Out of memory.");
	} catch (const std::exception &e) {
		return fail(QString("Internal error: %1").arg(e.what()));
	} catch (...) {
		return fail("Internal error (unknown exception).");
	}
}

std::vector<vcg::Point3d> FilterGeometricSnakePlugin::seedPointsWanted(const tri::ParamValues &v,
                                                                       const std::vector<int> &seeds, QString &source)
{
	if (!seeds.empty()) {
		if (!QString::fromStdString(v.Text("SeedPoints")).trimmed().isEmpty() ||
		    !QString::fromStdString(v.Text("SeedFile")).trimmed().isEmpty())
			Log(GLLogStream::WARNING, "Geometric snake: seed vertices are given, so SeedPoints and SeedFile are ignored.");
		return {};
	}
	std::string src;
	std::vector<vcg::Point3d> pts = tri::SeedPointsParser::FromTextOrFile(v.Text("SeedPoints"), v.Text("SeedFile"), src);
	if (pts.empty())
		throw tri::SnakeError("No seeds given: fill Seed vertices (vertex indices), Seed points (\"x y z; x y z\") "
		                      "or Seed file (a MeshLab Pick Points .pp file).");
	source = QString::fromStdString(src);
	return pts;
}

void FilterGeometricSnakePlugin::logSnap(const vcg::tri::SeedPointSnap<CMeshO>::Result &snap, const QString &source)
{
	double worst = 0;
	for (double d : snap.distances) worst = std::max(worst, d);
	Log("%d seed points from %s, moved onto the surface by at most %g (%.2g%% of the bounding box diagonal).",
	    int(snap.points.size()), qUtf8Printable(source), worst, 100.0 * worst / std::max(snap.bboxDiagonal, 1e-300));
}

void FilterGeometricSnakePlugin::handleSoup(MeshModel &m, bool merge)
{
	const int vn = m.cm.vn;
	const int merged = tri::TriangleSoup<CMeshO>::Handle(m.cm, merge);
	if (merged < 0) return;
	m.clearDataMask(MeshModel::MM_FACEFACETOPO | MeshModel::MM_VERTFACETOPO);
	tri::UpdateBounding<CMeshO>::Box(m.cm);
	Log("The mesh was a triangle soup: merged %d duplicate vertices (%d -> %d vertices, %d faces); vertex indices "
	    "now refer to the merged mesh.", merged, vn, m.cm.vn, m.cm.fn);
}

bool FilterGeometricSnakePlugin::applyFeatureEnergy(MeshDocument &md, const RichParameterList &par,
                                                    vcg::CallBackPos *cb)
{
	MeshModel &m = *md.mm();
	const tri::ParamValues v = readParams(par, tri::SnakeParamDefs::FeatureEnergy());
	const int type = v.Enum("EnergyType");
	const int steps = v.Int("SmoothingSteps");
	const bool colorize = v.Bool("Colorize");
	const double creaseAngle = v.Real("CreaseAngle");

	tri::MeshValidation<CMeshO>::RequireSurface(m.cm);
	handleSoup(m, v.Bool("MergeDuplicateVertices"));
	// FeatureEnergy needs no optional component (no adjacency, no curvature fields):
	// only the (always allocated) vertex quality, which the mask marks as meaningful.
	m.updateDataMask(MeshModel::MM_VERTQUALITY);

	QElapsedTimer timer;
	timer.start();
	// The smoothing rounds report to the host's progress bar (meshlabserver prints each call:
	// at most ~4 per second), and a host callback answering false cancels them.
	qint64 lastShown = -1000;
	const tri::FeatureEnergy<CMeshO>::Progress progress = [&](int pct) {
		if (cb == nullptr || (pct < 100 && timer.elapsed() - lastShown < 250)) return true;
		lastShown = timer.elapsed();
		return cb(pct, "Smoothing the feature energy...");
	};
	const auto stats = tri::FeatureEnergy<CMeshO>::Compute(m.cm, tri::FeatureEnergyType(type), steps, creaseAngle,
	                                                       progress);

	if (colorize) {
		m.updateDataMask(MeshModel::MM_VERTCOLOR);
		// Fixed [0,1] range (not the data's min/max): red = feature, blue = flat, comparable
		// across meshes and runs.
		tri::UpdateColor<CMeshO>::PerVertexQualityRamp(m.cm, 0.0f, 1.0f);
	}
	const auto q = tri::Stat<CMeshO>::ComputePerVertexQualityMinMax(m.cm);

	Log("Feature energy (%s, %d smoothing steps) on %d vertices: raw range [%g, %g], stored in vertex "
	    "quality normalised to [%g, %g] (0 = feature, 1 = flat)%s.",
	    tri::FeatureEnergyName(tri::FeatureEnergyType(type)), steps, m.cm.vn, double(stats.rawMin), double(stats.rawMax), double(q.first),
	    double(q.second), colorize ? ", coloured by the quality ramp" : "");
	if (type == int(tri::FeatureEnergyType::Crease))
		Log("Crease energy: %d sharp edges (dihedral angle above %g degrees).", stats.creases, creaseAngle);
	if (stats.constant)
		Log(GLLogStream::WARNING, "%s", tri::FeatureEnergy<CMeshO>::ConstantWarning(tri::FeatureEnergyType(type)).c_str());
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
	const tri::ParamValues v = readParams(par, tri::SnakeParamDefs::SeedPath());
	const std::string seedText = v.Text("Seeds");
	const bool closed = v.Bool("Closed");
	const int cost = v.Enum("Cost");
	const bool newLayer = v.Bool("NewLayer");

	const std::vector<int> seeds = tri::SeedListText::Parse(seedText);
	QString pointSource;
	const std::vector<vcg::Point3d> seedPts = seedPointsWanted(v, seeds, pointSource);
	tri::MeshValidation<CMeshO>::RequireSurface(m.cm);
	handleSoup(m, v.Bool("MergeDuplicateVertices"));
	if (compactIfNeeded(m.cm))
		Log("Compacted the mesh (it had deleted elements); vertex indices refer to the compacted order.");
	for (int s : seeds)
		if (s < 0 || s >= m.cm.vn)
			return fail(QString("Seed vertex %1 does not exist: the mesh has %2 vertices (valid indices 0..%3).")
			                .arg(s).arg(m.cm.vn).arg(m.cm.vn - 1));

	// SeedPath builds its own vertex adjacency: no optional component is needed.

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

	// The path: through seed vertices, or from surface point to surface point.
	std::vector<int> pathVertices;
	std::vector<tri::SurfacePoint> pathPoints;
	double pathLength = 0;
	int seedCount = int(seeds.size());
	if (seedPts.empty()) {
		const auto path = tri::SeedPath<CMeshO>::Compute(m.cm, seeds, closed, tri::SeedPathCost(cost));
		pathVertices = path.vertices;
		pathLength = path.length;
		std::vector<tri::SurfacePoint> corner(m.cm.vert.size()); // each vertex in one of its faces
		for (size_t f = 0; f < m.cm.face.size(); ++f)
			if (!m.cm.face[f].IsD())
				for (int k = 0; k < 3; ++k) corner[tri::Index(m.cm, m.cm.face[f].cV(k))] = tri::SurfacePoint::AtCorner(int(f), k);
		for (int vtx : path.vertices) pathPoints.push_back(corner[vtx]);
	} else {
		const auto snap = tri::SeedPointSnap<CMeshO>::Snap(m.cm, seedPts, closed ? 3 : 2, closed);
		logSnap(snap, pointSource);
		const auto path = tri::SeedPath<CMeshO>::ComputeFromPoints(m.cm, snap.points, closed, tri::SeedPathCost(cost));
		pathVertices = path.vertices;
		pathPoints = path.points;
		pathLength = path.length;
		seedCount = int(seedPts.size());
	}
	if (pathPoints.empty())
		return fail("No path was found between the seeds.");

	// Selection: exactly the path's vertices.
	tri::UpdateSelection<CMeshO>::VertexClear(m.cm);
	for (int vi : pathVertices)
		m.cm.vert[vi].SetS();
	m.updateDataMask(MeshModel::MM_VERTFLAGSELECT);

	if (newLayer) {
		MeshModel *pl = md.addNewMesh("", "Seed path", false);
		CMeshO &pm = pl->cm;
		const int n = int(pathPoints.size());
		auto vi = tri::Allocator<CMeshO>::AddVertices(pm, n);
		for (int i = 0; i < n; ++i, ++vi) {
			const tri::SurfacePoint &sp = pathPoints[i];
			const CFaceO &f = m.cm.face[sp.face];
			const Scalarm b0 = Scalarm(sp.bary[0]), b1 = Scalarm(sp.bary[1]), b2 = Scalarm(sp.bary[2]);
			vi->P() = sp.P(m.cm);
			vi->N() = f.cV(0)->cN() * b0 + f.cV(1)->cN() * b1 + f.cV(2)->cN() * b2;
			vi->Q() = f.cV(0)->cQ() * b0 + f.cV(1)->cQ() * b1 + f.cV(2)->cQ() * b2;
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
	    closed ? "closed" : "open", cost == 0 ? "length" : "feature", seedCount, int(pathVertices.size()), pathLength);
	return true;
}

void FilterGeometricSnakePlugin::addCurveLayer(MeshDocument &md, const MeshModel &src, const QString &name,
                                               const std::vector<std::vector<vcg::Point3d>> &curves,
                                               const std::vector<bool> &closed)
{
	MeshModel *pl = md.addNewMesh("", name, false);
	CMeshO &pm = pl->cm;
	int nv = 0, ne = 0;
	for (size_t c = 0; c < curves.size(); ++c) {
		const auto &pts = curves[c];
		if (pts.size() < 2) continue;
		const int base = int(pm.vert.size());
		auto vi = tri::Allocator<CMeshO>::AddVertices(pm, pts.size());
		for (const auto &p : pts) (vi++)->P() = Point3m::Construct(p);
		const int n = int(pts.size()), m = (closed[c] && n >= 3) ? n : n - 1;
		auto ei = tri::Allocator<CMeshO>::AddEdges(pm, m);
		for (int i = 0; i < m; ++i, ++ei) {
			ei->V(0) = &pm.vert[base + i];
			ei->V(1) = &pm.vert[base + (i + 1) % n];
		}
		nv += n;
		ne += m;
	}
	pm.Tr = src.cm.Tr;
	tri::UpdateBounding<CMeshO>::Box(pm);
	Log("Added layer \"%s\": %d vertices, %d edges.", qUtf8Printable(pl->label()), nv, ne);
}

bool FilterGeometricSnakePlugin::applySnake(MeshDocument &md, const RichParameterList &par, vcg::CallBackPos *cb)
{
	typedef tri::SnakeController<CMeshO> Controller;
	MeshModel &m = *md.mm();
	const std::vector<int> seeds = tri::SeedListText::Parse(par.getString("Seeds").toStdString());
	const tri::ParamValues v = readParams(par, tri::SnakeParamDefs::Snake());
	tri::SnakeBatch<CMeshO>::Settings b = tri::SnakeBatch<CMeshO>::FromValues(v, seeds);
	const bool closed = b.closed, useQuality = b.useQuality;
	const int method = int(b.params.method);
	const int maxOps = b.maxOperations;
	const std::string out = QString::fromStdString(v.Text("OutputFile")).trimmed().toStdString();
	const std::vector<tri::ProtectedFile> keep = protectedFiles(md);
	if (!out.empty()) checkOutput(out, keep); // before the work, not after it
	QString pointSource;
	const std::vector<vcg::Point3d> seedPts = seedPointsWanted(v, seeds, pointSource);

	tri::MeshValidation<CMeshO>::RequireSurface(m.cm);
	handleSoup(m, v.Bool("MergeDuplicateVertices"));
	if (compactIfNeeded(m.cm))
		Log("Compacted the mesh (it had deleted elements); vertex indices refer to the compacted order.");
	for (int s : seeds)
		if (s < 0 || s >= m.cm.vn)
			return fail(QString("Seed vertex %1 does not exist: the mesh has %2 vertices (valid indices 0..%3).")
			                .arg(s).arg(m.cm.vn).arg(m.cm.vn - 1));
	if (useQuality && !m.hasDataMask(MeshModel::MM_VERTQUALITY))
		return fail("UseQuality is on, but the mesh has no vertex quality. Compute one first (e.g. \"Compute "
		            "Geometric Snake Feature Energy\" or any quality filter), or turn UseQuality off.");
	tri::MeshValidation<CMeshO>::RequireAdjacencySafe(m.cm); // before MeshLab builds the adjacency
	m.updateDataMask(MeshModel::MM_VERTQUALITY);

	QElapsedTimer timer;
	timer.start();
	Controller ctl(m.cm);
	// MeshLab's adjacency build runs while the energy is computed (on large meshes, on two cores).
	b.adjacency = [&m] { m.updateDataMask(MeshModel::MM_FACEFACETOPO | MeshModel::MM_VERTFACETOPO); };
	if (!seedPts.empty()) {
		const auto snap = tri::SeedPointSnap<CMeshO>::Snap(m.cm, seedPts, closed ? 3 : 2, closed);
		logSnap(snap, pointSource);
		b.seedPoints = snap.points;
	}
	if (!useQuality)
		Log("Geometric snake: %s energy (%d smoothing steps) stored in the vertex quality.",
		    tri::FeatureEnergyName(b.energy), kDefaultSmoothingSteps);
	int shown = -1;
	const tri::SnakeBatch<CMeshO>::Result res = tri::SnakeBatch<CMeshO>::Run(ctl, b, [&](int op) {
		const int pct = maxOps > 0 ? std::min(99, 100 * (op + 1) / maxOps) : 99;
		if (cb != nullptr && pct / 10 != shown) { // meshlabserver prints every call: every 10 %
			shown = pct / 10;
			cb(pct, "Geometric snake...");
		}
		return true;
	});
	for (const auto &w : res.energyWarnings) Log(GLLogStream::WARNING, "Geometric snake: %s", w.c_str());
	tri::GeometricSnake<CMeshO> &snake = ctl.Get(0);
	const tri::SnakeStats &st = snake.Stats();

	if (!out.empty()) {
		std::vector<tri::GeometricSnake<CMeshO> *> list{&snake};
		tri::SnakeIO<CMeshO>::WriteCurves(out, list, keep);
		Log("Wrote the curve to %s.", out.c_str());
	}
	if (v.Bool("NewLayer")) addCurveLayer(md, m, "Geometric snake", {res.curve}, {snake.Closed()});

	// Keep the snake on the mesh with any the user already has there: curves are never lost.
	nlohmann::json session = ctl.ToJson();
	const std::string stored = tri::SnakeMeshStore<CMeshO>::Get(m.cm);
	if (!stored.empty()) {
		try {
			nlohmann::json old = nlohmann::json::parse(stored);
			if (old.value("format", std::string()) == Controller::SessionFile::FormatName() && old.contains("snakes") &&
			    old["mesh"] == session["mesh"]) {
				for (const auto &sn : session["snakes"]) old["snakes"].push_back(sn);
				old["selected"] = int(old["snakes"].size()) - 1;
				session = old;
			}
		} catch (const std::exception &) {
			Log(GLLogStream::WARNING, "Geometric snake: the snakes stored on the mesh were unreadable and were replaced.");
		}
	}
	tri::SnakeMeshStore<CMeshO>::Set(m.cm, session.dump());

	Log("Geometric snake (%s, %s): %d samples, %d operations, %s, curve of %d points and length %g.",
	    snake.Closed() ? "closed" : "open", method == 0 ? "local embedding" : "3D update + projection", snake.SampleCount(),
	    st.operations, tri::SnakeStopSummary(res.stop),
	    int(res.curve.size()), res.length);
	Log("Geometric snake length scale: %g (median edge length along the seed path; spacing, step caps and tolerances "
	    "are measured in it; the mesh's mean edge length is %g).", snake.LengthScale(), ctl.EnsureSurface().MeanEdge());
	Log("Geometric snake timing: %.1f ms total, median %.3f ms per operation, %.3f ms per embedding, %.4f ms per "
	    "update (%d embeddings, %d updates).", timer.nsecsElapsed() * 1e-6,
	    tri::SnakeStats::Median(st.msOperation), tri::SnakeStats::Median(st.msEmbedding),
	    tri::SnakeStats::Median(st.msUpdate), st.embeddings, st.updates);
	for (const auto &d : res.runWarnings)
		Log(GLLogStream::WARNING, "Geometric snake: %s%s", d.first.c_str(),
		    d.second > 1 ? qUtf8Printable(QString(" (%1 times in this run)").arg(d.second)) : "");
	return true;
}

bool FilterGeometricSnakePlugin::applyExport(MeshDocument &md, const RichParameterList &par)
{
	MeshModel &m = *md.mm();
	const tri::ParamValues v = readParams(par, tri::SnakeParamDefs::Export());
	const std::string out = QString::fromStdString(v.Text("OutputFile")).trimmed().toStdString();
	if (out.empty()) return fail("OutputFile is empty: give a .json, .obj or .ply file name.");
	const bool all = v.Enum("Which") == 0;
	const std::vector<tri::ProtectedFile> keep = protectedFiles(md);
	checkOutput(out, keep);

	nlohmann::json j;
	QString source = "the mesh";
	const std::string stored = tri::SnakeMeshStore<CMeshO>::Get(m.cm);
	if (!stored.empty()) {
		try {
			j = nlohmann::json::parse(stored);
		} catch (const nlohmann::json::exception &e) {
			return fail(QString("The snakes kept on the mesh are unreadable: %1.")
			                .arg(QString::fromStdString(tri::SnakeIO<CMeshO>::JsonErrorText(e))));
		}
	} else if (!m.fullName().isEmpty()) {
		const std::string side =
		    tri::SnakeSidecar::Path(QFileInfo(m.fullName()).absoluteFilePath().toStdString());
		if (QFileInfo::exists(QString::fromStdString(side))) {
			j = tri::SnakeIO<CMeshO>::ParseFileLean(side); // only what a restore reads: memory ~ file size
			source = QString::fromStdString(side);
		}
	}
	if (j.is_null())
		return fail("This mesh holds no geometric snakes (make some with the Geometric Snake edit tool or the "
		            "\"Geometric Snake from Seed Vertices\" filter).");
	if (!j.is_object() || !j.contains("snakes") || !j["snakes"].is_array())
		return fail(QString("%1 holds no list of \"snakes\": it is not a geometric snake session.").arg(source));
	if (j["snakes"].empty()) return fail("This mesh holds no geometric snakes.");
	if (!j.contains("mesh") || !j["mesh"].is_object())
		return fail(QString("%1 does not say which mesh its snakes belong to.").arg(source));

	// Rebuild the snakes on the mesh (the curve is traced again from the samples); the
	// energy is not needed for that, so the mesh is left untouched.
	tri::MeshValidation<CMeshO>::RequireSurface(m.cm);
	const auto &jm = j["mesh"];
	if (tri::SnakeIO<CMeshO>::IntFrom(jm, "vertices", -1) != int(m.cm.vert.size()) ||
	    tri::SnakeIO<CMeshO>::IntFrom(jm, "faces", -1) != int(m.cm.face.size()))
		return fail("The stored snakes were made on another version of this mesh (its vertex or face count "
		            "changed); they cannot be placed on it.");
	tri::MeshValidation<CMeshO>::RequireAdjacencySafe(m.cm);
	m.updateDataMask(MeshModel::MM_FACEFACETOPO | MeshModel::MM_VERTFACETOPO);
	auto surf = std::make_shared<tri::SnakeSurface<CMeshO>>(m.cm, 0);
	std::vector<std::unique_ptr<tri::GeometricSnake<CMeshO>>> snakes;
	const int selected = tri::SnakeIO<CMeshO>::IntFrom(j, "selected", 0);
	for (int i = 0; i < int(j["snakes"].size()); ++i) {
		if (!all && i != selected) continue;
		std::unique_ptr<tri::GeometricSnake<CMeshO>> s(new tri::GeometricSnake<CMeshO>(surf));
		tri::SnakeIO<CMeshO>::FromJson(*s, j["snakes"][i]);
		snakes.push_back(std::move(s));
	}
	if (snakes.empty()) return fail("No snake is selected.");
	std::vector<tri::GeometricSnake<CMeshO> *> list;
	std::vector<std::vector<vcg::Point3d>> curves;
	std::vector<bool> closed;
	for (auto &s : snakes) {
		list.push_back(s.get());
		curves.push_back(s->PolylinePositions());
		closed.push_back(s->Closed());
	}
	tri::SnakeIO<CMeshO>::WriteCurves(out, list, keep);
	if (v.Bool("NewLayer")) addCurveLayer(md, m, "Geometric snake curves", curves, closed);
	Log("Exported %d geometric snake(s) from %s to %s.", int(list.size()), qUtf8Printable(source), out.c_str());
	return true;
}

bool FilterGeometricSnakePlugin::applyCut(MeshDocument &md, const RichParameterList &par)
{
	MeshModel &m = *md.mm();
	const tri::ParamValues v = readParams(par, tri::SnakeParamDefs::Cut());
	const std::string file = QString::fromStdString(v.Text("CurveFile")).trimmed().toStdString();
	tri::MeshValidation<CMeshO>::RequireSurface(m.cm);
	tri::MeshValidation<CMeshO>::RequireAdjacencySafe(m.cm);
	m.updateDataMask(MeshModel::MM_FACEFACETOPO | MeshModel::MM_VERTFACETOPO);
	QElapsedTimer timer;
	timer.start();
	tri::CutCurve curve;
	QString source;
	if (!file.empty()) {
		curve = tri::CutCurveIO<CMeshO>::FromSnakeFile(m.cm, file, v.Int("SnakeIndex"));
		source = QString::fromStdString(file);
	} else {
		// the snakes kept on the mesh, else the edit tool's session file beside it (as the export)
		const std::string stored = tri::SnakeMeshStore<CMeshO>::Get(m.cm);
		nlohmann::json j;
		if (!stored.empty()) {
			j = nlohmann::json::parse(stored);
			source = "the snakes kept on the mesh";
		} else if (!m.fullName().isEmpty()) {
			const std::string side = tri::SnakeSidecar::Path(QFileInfo(m.fullName()).absoluteFilePath().toStdString());
			if (QFileInfo::exists(QString::fromStdString(side))) {
				j = tri::SnakeIO<CMeshO>::ParseFileLean(side);
				source = QString::fromStdString(side);
			}
		}
		if (j.is_null())
			return fail("No snake to cut along: give a CurveFile, or make a snake with the Geometric Snake edit tool "
			            "or the \"Geometric Snake from Seed Vertices\" filter.");
		curve = tri::CutCurveIO<CMeshO>::FromJson(m.cm, j, v.Int("SnakeIndex"), source.toStdString());
	}
	tri::MeshCut<CMeshO>::Param p;
	const int mode = v.Enum("Mode");
	p.mode = v.Bool("Split") ? tri::CutMode::Split : tri::CutMode(mode);
	p.side = tri::CutSide(v.Enum("Side"));
	tri::MeshCut<CMeshO>::Result r;
	if (p.mode == tri::CutMode::Split) {
		CMeshO inside, outside;
		r = tri::MeshCut<CMeshO>::Split(m.cm, {curve}, p, inside, outside);
		for (int part = 0; part < 2; ++part) {
			MeshModel *layer = md.addNewMesh("", part == 0 ? "inside" : "outside", false);
			layer->updateDataMask(&m);
			tri::Append<CMeshO, CMeshO>::MeshCopy(layer->cm, part == 0 ? inside : outside);
			layer->cm.Tr = m.cm.Tr;
			tri::UpdateBounding<CMeshO>::Box(layer->cm);
		}
	} else {
		r = tri::MeshCut<CMeshO>::Apply(m.cm, {curve}, p);
		if (p.mode != tri::CutMode::SelectOnly) {
			m.updateDataMask(MeshModel::MM_FACEQUALITY);
			for (size_t f = 0; f < m.cm.face.size(); ++f) m.cm.face[f].Q() = r.faceSide[f];
			tri::UpdateTopology<CMeshO>::FaceFace(m.cm);
			tri::UpdateTopology<CMeshO>::VertexFace(m.cm);
			tri::UpdateBounding<CMeshO>::Box(m.cm);
		}
	}
	Log("Cut (%s) along a %s snake from %s: %d vertices and %d faces added, %d on the curve; inside %d faces, area "
	    "%g (outside %g); %.1f ms (embedding %.1f, sides %.1f, check %.1f, commit %.1f).",
	    tri::MeshCut<CMeshO>::ModeName(p.mode).c_str(), curve.closed ? "closed" : "open", qUtf8Printable(source),
	    r.addedVertices, r.addedFaces, r.curveVertices, r.facesInside, r.areaInside, r.areaOutside,
	    timer.nsecsElapsed() * 1e-6, r.msEmbed, r.msSides, r.msCheck, r.msCommit);
	if ((p.mode == tri::CutMode::Select || p.mode == tri::CutMode::CutOpen) && (r.addedVertices > 0 || r.addedFaces > 0)) {
		// the edit tool's snakes kept on the mesh: moved onto the new faces
		const std::string kept = tri::SnakeMeshStore<CMeshO>::Get(m.cm);
		if (!kept.empty()) {
			try {
				tri::SnakeMeshStore<CMeshO>::Set(m.cm,
				    tri::CutSessionMap<CMeshO>::Map(nlohmann::json::parse(kept), r.points, m.cm).dump());
			} catch (const std::exception &e) {
				Log(GLLogStream::WARNING, "Geometric snake: the cut changed the mesh; the snakes kept on it refer to "
				    "the mesh as it was (%s).", e.what());
			}
		}
	}
	return true;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterGeometricSnakePlugin)
