// The FilterPlugin glue (MeshLab 2022.02 .. 2025.07, the API pymeshlab loads) of the Variational
// Shape Approximation filter. The parameters and the run are shared with the MeshLab 2020.09 glue
// (filter_vsa.h): see vsa_parameters.h and vsa_run.h.
#ifndef FILTER_VSA_FILTERPLUGIN_H
#define FILTER_VSA_FILTERPLUGIN_H

#include <common/plugins/interfaces/filter_plugin.h>

class FilterVsaPlugin : public QObject, public FilterPlugin
{
    Q_OBJECT
    // Also defines getMLVersion(): the MESHLAB_VERSION / MESHLAB_SCALAR this plugin is compiled
    // with, which MeshLab's PluginManager compares with its own before accepting the plugin.
    MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID)
    Q_INTERFACES(FilterPlugin)

public:
    enum { FP_VSA };

    FilterVsaPlugin();

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

private:
    std::map<std::string, QVariant> apply(MeshDocument &md, const RichParameterList &parameters,
                                          unsigned int &postConditionMask, vcg::CallBackPos *cb);
};

#endif  // FILTER_VSA_FILTERPLUGIN_H
