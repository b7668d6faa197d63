// A FilterPlugin that uses no Scalarm-typed symbol of libmeshlab-common, so that it can be compiled
// with any MESHLAB_VERSION / MESHLAB_SCALAR and still be dlopen'ed by the host: it tests the
// PluginManager's own checks (same scalar precision, same version in its first 6 characters).
#include <common/plugins/interfaces/filter_plugin.h>

class FilterFpProbePlugin : public QObject, public FilterPlugin
{
    Q_OBJECT
    MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID)
    Q_INTERFACES(FilterPlugin)

public:
    FilterFpProbePlugin()
    {
        typeList = {0};
        actionList.push_back(new QAction(filterName(0), this));
    }
    QString pluginName() const override { return "FilterFpProbe"; }
    QString filterName(ActionIDType) const override { return "Probe Build Settings"; }
    QString filterInfo(ActionIDType) const override
    {
        return "Returns the MeshLab version and scalar it was built with.";
    }
    FilterClass getClass(const QAction *) const override { return FilterPlugin::Other; }
    FilterArity filterArity(const QAction *) const override { return NONE; }
    std::map<std::string, QVariant> applyFilter(const QAction *, const RichParameterList &, MeshDocument &,
                                                unsigned int &, vcg::CallBackPos *) override
    {
        std::map<std::string, QVariant> out;
        out["meshlab_version"] = QString::fromStdString(getMLVersion().first);
        out["double_precision"] = getMLVersion().second;
        return out;
    }
};

#include "filter_fp_probe.moc"
