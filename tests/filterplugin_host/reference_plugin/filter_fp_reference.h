// A minimal filter written against MeshLab's FilterPlugin API (MeshLab 2022.02 .. 2025.07, the
// API pymeshlab loads). It exists to test tests/filterplugin_host before filter_vsa is ported,
// and as the reference of every piece of that API a filter like ours uses: the parameters it
// declares carry the names of filter_vsa's (ProxyNum, TargetError, Metric, ...).
#ifndef FILTER_FP_REFERENCE_H
#define FILTER_FP_REFERENCE_H

#include <common/plugins/interfaces/filter_plugin.h>

class FilterFpReferencePlugin : public QObject, public FilterPlugin
{
    Q_OBJECT
    // Declares the Qt plugin metadata (IID) *and* defines getMLVersion(), which returns the
    // MESHLAB_VERSION / MESHLAB_SCALAR this plugin was compiled with.
    MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID)
    Q_INTERFACES(FilterPlugin)

public:
    enum { FP_REFERENCE_PARTITION, FP_REFERENCE_FAIL };

    FilterFpReferencePlugin();

    QString pluginName() const override;
    QString vendor() const override;
    QString filterName(ActionIDType filter) const override;
    QString pythonFilterName(ActionIDType filter) const override;
    QString filterInfo(ActionIDType filter) const override;
    FilterClass getClass(const QAction *action) const override;
    FilterArity filterArity(const QAction *action) const override;
    int getPreConditions(const QAction *action) const override;
    int getRequirements(const QAction *action) override;
    int postCondition(const QAction *action) const override;
    RichParameterList initParameterList(const QAction *action, const MeshModel &m) override;
    std::map<std::string, QVariant> applyFilter(const QAction *action, const RichParameterList &parameters,
                                                MeshDocument &md, unsigned int &postConditionMask,
                                                vcg::CallBackPos *cb) override;
};

#endif  // FILTER_FP_REFERENCE_H
