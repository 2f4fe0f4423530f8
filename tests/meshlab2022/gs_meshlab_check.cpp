// Drives MeshLab 2022.02's own library (libmeshlab-common), the way MeshLab and PyMeshLab do,
// since 2022.02 has no meshlabserver: checks and loads the installed plugins with MeshLab's
// PluginManager, lists them, opens a mesh with MeshLab's I/O plugins, and applies the
// filters with the parameters given on the command line. Run by scripts/debian13.sh inside
// the Debian 13 root, under Xvfb (QActions need a QApplication).
//
//   gs_meshlab_check PLUGIN_DIR MESH OUT_DIR [FILTER_NAME [Param=Value ...]] [-- FILTER ...]
//
// Prints the plugin list, the Log and one "RESULT" line per filter; after the energy filter
// writes the per-vertex quality to OUT_DIR/quality_<n>.txt, and after every filter the selected
// vertices ("SELECTED"), the selected faces and their area ("FACES") and the coordinates of each
// added layer (OUT_DIR/layer_<n>_<k>.txt). A
// filter named "!NAME" must fail (MeshLab's MLException), its message is printed. Exit status 0 = every check held.

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <QApplication>
#include <QDir>
#include <QFileInfo>

#include <common/globals.h>
#include <common/mlexception.h>
#include <common/plugins/plugin_manager.h>
#include <common/utilities/load_save.h>

namespace {

int failures = 0;

void check(bool ok, const QString &what)
{
	std::printf("%s %s\n", ok ? "PASS" : "FAIL", qUtf8Printable(what));
	if (!ok) ++failures;
}

void setParam(RichParameterList &par, const QString &name, const QString &text)
{
	if (!par.hasParameter(name)) throw MLException("no parameter " + name);
	const Value &v = par.getParameterByName(name).value();
	if (v.isBool()) par.setValue(name, BoolValue(text == "true" || text == "1"));
	else if (v.isInt()) par.setValue(name, IntValue(text.toInt())); // RichInt and RichEnum
	else if (v.isFloat()) par.setValue(name, FloatValue(text.toFloat()));
	else if (v.isString()) par.setValue(name, StringValue(text));
	else throw MLException("unsupported parameter type: " + name);
}

void printLog(MeshDocument &md, int &shown)
{
	const auto &lines = md.Log.logStringList();
	for (; shown < lines.size(); ++shown) std::printf("LOG %d %s\n", lines[shown].first, qUtf8Printable(lines[shown].second));
}

} // namespace

int main(int argc, char **argv)
{
	QApplication app(argc, argv);
	if (argc < 4) {
		std::fprintf(stderr, "usage: %s PLUGIN_DIR MESH OUT_DIR [FILTER [Param=Value ...]] [-- FILTER ...]\n", argv[0]);
		return 2;
	}
	const QDir pluginDir(QString::fromLocal8Bit(argv[1]));
	const QString mesh = QString::fromLocal8Bit(argv[2]);
	const QString outDir = QString::fromLocal8Bit(argv[3]);
	std::printf("MeshLab %s (%s precision), plugins in %s\n", meshlab::meshlabVersion().c_str(),
	            meshlab::builtWithDoublePrecision() ? "double" : "single", qUtf8Printable(pluginDir.absolutePath()));

	// 1. MeshLab's own acceptance test of each of our plugin files (version, precision, type,
	//    filter classes and arities), then the whole folder as MeshLab loads it at start.
	for (const char *file : {"libfilter_geometric_snake.so", "libedit_geometric_snake.so"}) {
		const QString path = pluginDir.absoluteFilePath(file);
		try {
			MeshLabPluginType type = PluginManager::checkPlugin(path);
			check(type.isValid(), QString("%1 is a valid MeshLab plugin (%2)").arg(file, type.pluginTypeString()));
		} catch (const MLException &e) {
			check(false, QString("%1 loads: %2").arg(file, e.what()));
		}
	}
	PluginManager &pm = meshlab::pluginManagerInstance();
	try {
		pm.loadPlugins(pluginDir);
		check(true, "every plugin of the folder loads");
	} catch (const MLException &e) {
		// MeshLab would show this in a dialog at start; a broken host fails the test too.
		const QString msg = e.what();
		check(!msg.contains("geometric_snake"), "our plugins are not among the plugins that failed to load");
		check(false, "every plugin of the folder loads: " + msg);
	}

	// 2. MeshLab lists them: the filters (with their PyMeshLab names) and the edit tool.
	FilterPlugin *filters = nullptr;
	for (FilterPlugin *fp : pm.filterPluginIterator())
		if (fp->pluginName() == "FilterGeometricSnake") filters = fp;
	check(filters != nullptr, "MeshLab lists the filter plugin FilterGeometricSnake");
	if (filters == nullptr) return 1;
	for (QAction *a : filters->actions())
		std::printf("FILTER \"%s\" python=%s class=0x%x arity=%d\n", qUtf8Printable(a->text()),
		            qUtf8Printable(filters->pythonFilterName(a)), unsigned(filters->getClass(a)), int(filters->filterArity(a)));
	check(filters->actions().size() == 5, "the filter plugin has 5 filters");
	bool tool = false;
	for (EditPlugin *ep : pm.editPluginFactoryIterator()) {
		if (ep->pluginName() != "EditGeometricSnake") continue;
		for (QAction *a : ep->actions()) {
			EditTool *t = ep->getEditTool(a);
			std::printf("EDIT \"%s\": %s\n", qUtf8Printable(a->text()), qUtf8Printable(ep->getEditToolDescription(a).left(60)));
			tool = tool || (t != nullptr && a->text() == "Geometric Snake");
			delete t;
		}
	}
	check(tool, "MeshLab lists the edit tool Geometric Snake and makes one");

	// 3. Each filter of the command line on a freshly opened mesh document (as a new PyMeshLab
	//    MeshSet would), with MeshLab's pre-filter steps (log, requirements).
	std::vector<std::vector<QString>> runs(1);
	for (int i = 4; i < argc; ++i) {
		if (std::string(argv[i]) == "--") runs.emplace_back();
		else runs.back().push_back(QString::fromLocal8Bit(argv[i]));
	}
	int n = 0;
	for (const auto &run : runs) {
		if (run.empty()) continue;
		++n;
		const bool mustFail = run[0].startsWith('!');
		const QString name = mustFail ? run[0].mid(1) : run[0];
		QAction *action = nullptr;
		for (QAction *a : filters->actions())
			if (a->text() == name) action = a;
		check(action != nullptr, "filter " + name + " exists");
		if (action == nullptr) continue;
		MeshDocument md;
		int shown = 0;
		try {
			meshlab::loadMeshWithStandardParameters(mesh, md);
		} catch (const MLException &e) {
			check(false, QString("MeshLab opens %1: %2").arg(mesh, e.what()));
			return 1;
		}
		std::printf("RUN %d \"%s\" on %s: %d vertices, %d faces\n", n, qUtf8Printable(name), qUtf8Printable(mesh),
		            md.mm()->cm.vn, md.mm()->cm.fn);
		RichParameterList par = filters->initParameterList(action, md);
		for (size_t i = 1; i < run.size(); ++i) {
			const int eq = run[i].indexOf('=');
			setParam(par, run[i].left(eq), run[i].mid(eq + 1));
		}
		filters->setLog(&md.Log);
		md.mm()->updateDataMask(filters->getRequirements(action));
		unsigned int mask = MeshModel::MM_UNKNOWN;
		try {
			filters->applyFilter(action, par, md, mask, nullptr);
			printLog(md, shown);
			check(!mustFail, "filter " + name + " succeeded");
		} catch (const MLException &e) {
			printLog(md, shown);
			std::printf("ERROR %s\n", e.what());
			check(mustFail, QString("filter %1 threw MLException: %2").arg(name, e.what()));
			continue;
		}
		const CMeshO &m = md.mm()->cm;
		std::printf("RESULT %d layers=%d vertices=%d", n, int(md.meshNumber()), m.vn);
		if (md.mm()->hasDataMask(MeshModel::MM_VERTQUALITY)) {
			const QString qpath = QDir(outDir).absoluteFilePath(QString("quality_%1.txt").arg(n));
			std::ofstream q(qpath.toStdString());
			q.precision(9); // float round trip
			float lo = 1e30f, hi = -1e30f;
			for (const auto &v : m.vert) {
				if (v.IsD()) continue;
				q << v.cQ() << "\n";
				lo = std::min(lo, v.cQ());
				hi = std::max(hi, v.cQ());
			}
			std::printf(" quality=[%.9g,%.9g] quality_file=%s", lo, hi, qUtf8Printable(qpath));
		}
		std::printf("\n");
		// The selection a filter left (the seed path's vertices, in index order) and the layers it
		// added (coordinates in OUT_DIR/layer_<n>_<k>.txt, in vertex order), for comparison.
		std::printf("SELECTED %d:", n);
		for (size_t i = 0; i < m.vert.size(); ++i)
			if (!m.vert[i].IsD() && m.vert[i].IsS()) std::printf(" %zu", i);
		std::printf("\n");
		// The faces a filter selected (the cut's "select" mode) and their area.
		int selectedFaces = 0;
		double selectedArea = 0;
		for (const auto &f : m.face)
			if (!f.IsD() && f.IsS()) {
				++selectedFaces;
				selectedArea += vcg::DoubleArea(f) / 2;
			}
		std::printf("FACES %d: faces=%d selected=%d selected_area=%.9g\n", n, m.fn, selectedFaces, selectedArea);
		int k = 0;
		for (MeshModel &layer : md.meshIterator()) {
			if (k++ == 0) continue;
			const QString lpath = QDir(outDir).absoluteFilePath(QString("layer_%1_%2.txt").arg(n).arg(k - 1));
			std::ofstream l(lpath.toStdString());
			l.precision(9);
			for (const auto &v : layer.cm.vert)
				if (!v.IsD()) l << v.cP()[0] << " " << v.cP()[1] << " " << v.cP()[2] << "\n";
			std::printf("LAYER %d %d \"%s\" vertices=%d edges=%d faces=%d file=%s\n", n, k - 1,
			            qUtf8Printable(layer.label()), layer.cm.vn, layer.cm.en, layer.cm.fn, qUtf8Printable(lpath));
		}
	}
	std::printf("%s: %d check(s) failed\n", failures ? "FAILED" : "OK", failures);
	return failures ? 1 : 0;
}
