// Geometric Snakes for MeshLab: the host adapter for MeshLab 2022.02's plugin API (Debian 13,
// Ubuntu 25.10 and 26.04; 2023.12 and 2025.07 kept these interfaces: tested with 2025.07 in
// Debian forky, float, and in PyMeshLab 2025.7, double). Twin of
// host/meshlab_2020.09/meshlab_host.h, which documents the host-neutral API; here it is
// MeshLab's own (FilterPlugin, EditPlugin, EditTool) plus:
//   - apply() is the filter body; applyFilter turns filterError(msg) into the MLException
//     MeshLab expects and returns no outputs (the post-condition mask stays postCondition());
//   - Log(...) forwards to log(...);
//   - GS_FILTER_PLUGIN / GS_EDIT_PLUGIN carry MeshLab's version and scalar type
//     (MESHLAB_PLUGIN_IID_EXPORTER, from MESHLAB_VERSION / MESHLAB_SCALAR), which the plugin
//     loader checks.

#ifndef GS_MESHLAB_HOST_H
#define GS_MESHLAB_HOST_H

#include <list>
#include <vector>
#include <map>
#include <string>
#include <utility>

#include <QAction>
#include <QString>
#include <QVariant>

#include <common/mlexception.h>
#include <common/plugins/interfaces/edit_plugin.h>
#include <common/plugins/interfaces/filter_plugin.h>

namespace gs {
namespace host {
constexpr const char *kApi = "2022.02";

inline bool HasMesh(const MeshDocument &md, const MeshModel *m)
{
	for (const MeshModel &x : md.meshIterator()) // meshList (a std::list<MeshModel>) is private
		if (&x == m) return true;
	return false;
}

/// The layers of the document, in order.
inline std::vector<MeshModel *> Meshes(MeshDocument &md)
{
	std::vector<MeshModel *> v;
	for (MeshModel &x : md.meshIterator()) v.push_back(&x);
	return v;
}

/// Removes the layer m (the edit tool's undo of its split).
inline bool DeleteLayer(MeshDocument &md, MeshModel *m) { return md.delMesh(m->id()); }
inline void UpdateBoxAndNormals(MeshModel &m) { m.updateBoxAndNormals(); }
} // namespace host

class FilterPluginBase : public FilterPlugin
{
public:
	/// The filter body. Returns false after filterError(msg); may also throw (the plugin catches).
	virtual bool apply(const QAction *, const RichParameterList &, MeshDocument &, vcg::CallBackPos *) = 0;

	template <typename... Ts>
	void Log(Ts &&...ts) const
	{
		log(std::forward<Ts>(ts)...);
	}

protected:
	void addFilterAction(ActionIDType id, QAction *a)
	{
		typeList.push_back(id);
		actionList.push_back(a);
	}
	bool filterError(const QString &msg)
	{
		error = msg;
		return false;
	}

private:
	QString error;
	std::map<std::string, QVariant> applyFilter(const QAction *a, const RichParameterList &par, MeshDocument &md,
	                                            unsigned int & /*postConditionMask: MM_UNKNOWN = postCondition()*/,
	                                            vcg::CallBackPos *cb) final
	{
		error.clear();
		if (!apply(a, par, md, cb))
			throw MLException(error.isEmpty() ? QString("%1 failed.").arg(filterName(a)) : error);
		return {};
	}
};

class EditToolBase : public EditTool
{
public:
	template <typename... Ts>
	void Log(Ts &&...ts) const
	{
		log(std::forward<Ts>(ts)...);
	}
};

class EditPluginBase : public EditPlugin
{
public:
	EditToolBase *getEditTool(const QAction *) override = 0;

protected:
	void addEditAction(QAction *a) { actionList.push_back(a); }
};

} // namespace gs

#define GS_FILTER_PLUGIN \
	MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID) \
	Q_INTERFACES(FilterPlugin)
#define GS_EDIT_PLUGIN \
	MESHLAB_PLUGIN_IID_EXPORTER(EDIT_PLUGIN_IID) \
	Q_INTERFACES(EditPlugin)

#endif
