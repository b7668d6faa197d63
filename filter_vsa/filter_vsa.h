// The MeshLab 2020.09 (MeshFilterInterface) glue of the Variational Shape Approximation filter.
#ifndef FILTER_VSA_PLUGIN_H
#define FILTER_VSA_PLUGIN_H

#include <common/interfaces.h>

class FilterVsaPlugin : public QObject, public MeshFilterInterface
{
    Q_OBJECT
    MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
    Q_INTERFACES(MeshFilterInterface)

public:
    enum { FP_VSA };

    FilterVsaPlugin();

    QString pluginName() const override;
    QString filterName(FilterIDType filter) const override;
    QString filterInfo(FilterIDType filter) const override;
    FilterClass getClass(QAction *) override;
    FILTER_ARITY filterArity(QAction *) const override;
    int getPreConditions(QAction *) const override;
    int getRequirements(QAction *) override;
    int postCondition(QAction *) const override;
    void initParameterSet(QAction *, MeshModel &m, RichParameterList &parameters) override;
    bool applyFilter(QAction *, MeshDocument &md, const RichParameterList &parameters, vcg::CallBackPos *cb) override;

private:
    bool apply(MeshDocument &md, const RichParameterList &parameters, vcg::CallBackPos *cb);
};

#endif  // FILTER_VSA_PLUGIN_H
