/****************************************************************************
* Geometric Snakes for MeshLab (2020.09 and 2022.02)                        *
* Filters after Y. Lee, S. Lee, "Geometric Snakes for Triangular Meshes",   *
* Computer Graphics Forum (Eurographics 2002) 21(3).                        *
*                                                                           *
* The filters are thin Qt glue: the algorithms live in the header-only      *
* vcg_ext/ library (no Qt, no OpenGL) and throw vcg::tri::SnakeError on bad *
* input; here that becomes the filter's error message, never a crash.       *
****************************************************************************/

#ifndef FILTER_GEOMETRIC_SNAKE_H
#define FILTER_GEOMETRIC_SNAKE_H

#include "meshlab_host.h" // MeshLab 2020.09 or 2022.02, chosen by CMake
#include <vcg_ext/paths/seed_points.h>
#include <vcg_ext/session/param_defs.h>

class FilterGeometricSnakePlugin : public QObject, public gs::FilterPluginBase
{
	Q_OBJECT
	GS_FILTER_PLUGIN

public:
	// Keep the numbering append-only: .mlx scripts refer to filters by name, but the
	// ids are used internally in switches.
	enum {
		FP_FEATURE_ENERGY = 0,
		FP_SEED_PATH = 1,
		FP_SNAKE = 2,
		FP_EXPORT = 3,
		FP_CUT = 4
	};

	FilterGeometricSnakePlugin();

	QString pluginName() const override;
	QString filterName(ActionIDType filter) const override;
	QString pythonFilterName(ActionIDType filter) const override;
	QString filterInfo(ActionIDType filter) const override;
	FilterClass getClass(const QAction *a) const override;
	FilterArity filterArity(const QAction *a) const override;
	int getPreConditions(const QAction *a) const override;
	int getRequirements(const QAction *a) override;
	int postCondition(const QAction *a) const override;
	RichParameterList initParameterList(const QAction *a, const MeshModel &m) override;
	bool apply(const QAction *filter, const RichParameterList &par, MeshDocument &md, vcg::CallBackPos *cb) override;

private:
	bool applyFeatureEnergy(MeshDocument &md, const RichParameterList &par, vcg::CallBackPos *cb);
	bool applySeedPath(MeshDocument &md, const RichParameterList &par);
	bool applySnake(MeshDocument &md, const RichParameterList &par, vcg::CallBackPos *cb);
	bool applyExport(MeshDocument &md, const RichParameterList &par);
	bool applyCut(MeshDocument &md, const RichParameterList &par); // filter_geometric_snake_cut.cpp
	/// Adds a layer made of the curves' polylines as vertices and edges.
	void addCurveLayer(MeshDocument &md, const MeshModel &src, const QString &name,
	                   const std::vector<std::vector<vcg::Point3d>> &curves, const std::vector<bool> &closed);

	/// Seeds as points (SeedPoints, else SeedFile) when `seeds` (vertex indices) is empty;
	/// throws if no seed is given at all. Empty when the seed vertices are used.
	std::vector<vcg::Point3d> seedPointsWanted(const vcg::tri::ParamValues &v, const std::vector<int> &seeds,
	                                           QString &source);
	void logSnap(const vcg::tri::SeedPointSnap<CMeshO>::Result &snap, const QString &source);
	/// A triangle soup is refused with a message naming Merge Close Vertices, or merged (with
	/// a Log line) when `merge` (the MergeDuplicateVertices parameter).
	void handleSoup(MeshModel &m, bool merge);

	/// Sets the filter's error and mirrors it in the Log (meshlabserver prints the Log but
	/// not the error). Always returns false, for `return fail(...)`.
	bool fail(const QString &msg);
};

#endif
