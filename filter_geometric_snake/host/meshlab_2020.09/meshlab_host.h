// Geometric Snakes for MeshLab: the host adapter for MeshLab 2020.09's plugin API (Debian 12,
// Ubuntu 24.04). CMake picks this file or its twin host/meshlab_2022.02/meshlab_host.h from the
// MeshLab source it builds against (GS_MESHLAB_API); the plugin code includes "meshlab_host.h"
// and is written once, against the host-neutral API below (MeshLab 2022.02's names):
//   gs::FilterPluginBase  filters: filterName, pythonFilterName, filterInfo (ActionIDType);
//                         getClass, filterArity, getPreConditions, getRequirements,
//                         postCondition (const QAction *); initParameterList returns the list;
//                         bool apply(...) is the filter body; filterError(msg) sets the error
//                         the host shows (GUI, meshlabserver, PyMeshLab) and returns false;
//                         addFilterAction(id, action); Log(...).
//   gs::EditPluginBase    edit tool factory: addEditAction, getEditTool, getEditToolDescription.
//   gs::EditToolBase      edit tool: startEdit, endEdit, decorate, layerChanged (lower case),
//                         the mouse and key events, Log(...).
//   GS_FILTER_PLUGIN / GS_EDIT_PLUGIN  in the class body, after Q_OBJECT (plugin metadata).
//   gs::host::Meshes(md)  the layers; gs::host::HasMesh(md, m)  whether m is still one of them
//                         (m may be dangling);
//   gs::host::UpdateBoxAndNormals(m);  gs::host::kApi  "2020.09".

#ifndef GS_MESHLAB_HOST_H
#define GS_MESHLAB_HOST_H

#include <list>
#include <vector>

#include <QAction>
#include <QList>
#include <QString>

#include <common/interfaces.h>

namespace gs {
namespace host {
constexpr const char *kApi = "2020.09";

inline bool HasMesh(const MeshDocument &md, const MeshModel *m) { return md.meshList.contains(const_cast<MeshModel *>(m)); }

/// The layers of the document, in order.
inline std::vector<MeshModel *> Meshes(MeshDocument &md) { return std::vector<MeshModel *>(md.meshList.begin(), md.meshList.end()); }

/// Removes the layer m (the edit tool's undo of its split).
inline bool DeleteLayer(MeshDocument &md, MeshModel *m) { return md.delMesh(m); }
inline void UpdateBoxAndNormals(MeshModel &m) { m.UpdateBoxAndNormals(); }
} // namespace host

/// Filters: the 2022.02 signatures, forwarded from MeshFilterInterface's.
class FilterPluginBase : public MeshFilterInterface
{
public:
	typedef FilterIDType ActionIDType;
	typedef FILTER_ARITY FilterArity;

	virtual QString pluginName() const override = 0;
	virtual QString filterName(ActionIDType) const override = 0;
	/// PyMeshLab's name of the filter (MeshLab 2022.02 and later; unused by 2020.09).
	virtual QString pythonFilterName(ActionIDType) const { return QString(); }
	virtual QString filterInfo(ActionIDType) const override = 0;
	virtual FilterClass getClass(const QAction *) const = 0;
	virtual FilterArity filterArity(const QAction *) const = 0;
	virtual int getPreConditions(const QAction *) const { return MeshModel::MM_NONE; }
	virtual int getRequirements(const QAction *) { return MeshModel::MM_NONE; }
	virtual int postCondition(const QAction *) const { return MeshModel::MM_ALL; }
	virtual RichParameterList initParameterList(const QAction *, const MeshModel &) { return RichParameterList(); }
	/// The filter body. Returns false after filterError(msg); may also throw (the plugin catches).
	virtual bool apply(const QAction *, const RichParameterList &, MeshDocument &, vcg::CallBackPos *) = 0;

	using MeshFilterInterface::ID;
	ActionIDType ID(const QAction *a) const { return MeshFilterInterface::ID(const_cast<QAction *>(a)); }

protected:
	void addFilterAction(ActionIDType id, QAction *a)
	{
		typeList << id;
		actionList << a;
	}
	/// The filter's error message for the host (meshlabserver and the GUI show it). Returns false.
	bool filterError(const QString &msg)
	{
		errorMessage = msg;
		return false;
	}

private:
	FilterClass getClass(QAction *a) final { return getClass(static_cast<const QAction *>(a)); }
	FILTER_ARITY filterArity(QAction *a) const final { return filterArity(static_cast<const QAction *>(a)); }
	int getPreConditions(QAction *a) const final { return getPreConditions(static_cast<const QAction *>(a)); }
	int getRequirements(QAction *a) final { return getRequirements(static_cast<const QAction *>(a)); }
	int postCondition(QAction *a) const final { return postCondition(static_cast<const QAction *>(a)); }
	void initParameterSet(QAction *a, MeshModel &m, RichParameterList &par) final
	{
		par = initParameterList(a, m);
	}
	bool applyFilter(QAction *a, MeshDocument &md, const RichParameterList &par, vcg::CallBackPos *cb) final
	{
		errorMessage.clear();
		return apply(a, par, md, cb);
	}
};

class EditToolBase;

/// Edit tool factory (MeshEditInterfaceFactory).
class EditPluginBase : public MeshEditInterfaceFactory
{
public:
	virtual QString pluginName() const = 0;
	virtual EditToolBase *getEditTool(const QAction *) = 0;
	virtual QString getEditToolDescription(const QAction *) = 0;

protected:
	void addEditAction(QAction *a) { editActions << a; }

private:
	QList<QAction *> editActions;
	QList<QAction *> actions() const final { return editActions; }
	MeshEditInterface *getMeshEditInterface(QAction *a) final;
	QString getEditToolDescription(QAction *a) final { return getEditToolDescription(static_cast<const QAction *>(a)); }
};

/// Edit tool (MeshEditInterface): the 2022.02 lower-case names, forwarded.
class EditToolBase : public MeshEditInterface
{
public:
	virtual bool startEdit(MeshModel &, GLArea *, MLSceneGLSharedDataContext *) { return true; }
	virtual bool startEdit(MeshDocument &md, GLArea *gla, MLSceneGLSharedDataContext *cont)
	{
		return md.mm() != nullptr && startEdit(*md.mm(), gla, cont);
	}
	virtual void endEdit(MeshModel &, GLArea *, MLSceneGLSharedDataContext *) {}
	virtual void endEdit(MeshDocument &, GLArea *, MLSceneGLSharedDataContext *) {}
	virtual void layerChanged(MeshDocument &md, MeshModel &old, GLArea *gla, MLSceneGLSharedDataContext *cont)
	{
		endEdit(old, gla, cont);
		startEdit(md, gla, cont);
	}
	virtual void decorate(MeshModel &m, GLArea *gla, QPainter *) { decorate(m, gla); }
	virtual void decorate(MeshModel &, GLArea *) {}

private:
	bool StartEdit(MeshModel &m, GLArea *g, MLSceneGLSharedDataContext *c) final { return startEdit(m, g, c); }
	bool StartEdit(MeshDocument &md, GLArea *g, MLSceneGLSharedDataContext *c) final { return startEdit(md, g, c); }
	void EndEdit(MeshModel &m, GLArea *g, MLSceneGLSharedDataContext *c) final { endEdit(m, g, c); }
	void EndEdit(MeshDocument &md, GLArea *g, MLSceneGLSharedDataContext *c) final { endEdit(md, g, c); }
	void LayerChanged(MeshDocument &md, MeshModel &old, GLArea *g, MLSceneGLSharedDataContext *c) final
	{
		layerChanged(md, old, g, c);
	}
	void Decorate(MeshModel &m, GLArea *g, QPainter *p) final { decorate(m, g, p); }
	void Decorate(MeshModel &m, GLArea *g) final { decorate(m, g); }
};

inline MeshEditInterface *EditPluginBase::getMeshEditInterface(QAction *a) { return getEditTool(a); }

} // namespace gs

// Plugin metadata in the class body (moc expands these).
#define GS_FILTER_PLUGIN \
	MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID) \
	Q_INTERFACES(MeshFilterInterface)
#define GS_EDIT_PLUGIN \
	MESHLAB_PLUGIN_IID_EXPORTER(MESH_EDIT_INTERFACE_FACTORY_IID) \
	Q_INTERFACES(MeshEditInterfaceFactory)

#endif
