#include "filter_vsa.h"

#include "vsa_run.h"

#include <vcg/complex/append.h>


#include <exception>
#include <new>

FilterVsaPlugin::FilterVsaPlugin()
{
    typeList << FP_VSA;
    for (FilterIDType id : typeList) actionList << new QAction(filterName(id), this);
}

QString FilterVsaPlugin::pluginName() const { return "FilterVSA"; }

QString FilterVsaPlugin::filterName(FilterIDType) const { return "Variational Shape Approximation"; }

QString FilterVsaPlugin::filterInfo(FilterIDType) const { return VsaFilterInfo(); }

MeshFilterInterface::FilterClass FilterVsaPlugin::getClass(QAction *) { return Remeshing; }

MeshFilterInterface::FILTER_ARITY FilterVsaPlugin::filterArity(QAction *) const { return SINGLE_MESH; }

int FilterVsaPlugin::getPreConditions(QAction *) const { return MeshModel::MM_FACENUMBER; }

// vcg_core builds its own flat adjacency, so no vcg topology is required of the input;
// colouring needs per-face colour and quality, enabled on demand in apply().
int FilterVsaPlugin::getRequirements(QAction *) { return MeshModel::MM_NONE; }

int FilterVsaPlugin::postCondition(QAction *) const
{
    return MeshModel::MM_FACECOLOR | MeshModel::MM_FACEQUALITY;
}

void FilterVsaPlugin::initParameterSet(QAction *, MeshModel &m, RichParameterList &parameters)
{
    DefineVsaParameters(parameters, m.cm);
}

bool FilterVsaPlugin::applyFilter(QAction *, MeshDocument &md, const RichParameterList &parameters,
                                  vcg::CallBackPos *cb)
{
    // MeshLab 2020.09 aborts when an exception leaves applyFilter: nothing may escape.
    const int layersBefore = md.meshList.size();
    MeshModel *input = md.mm();
    try {
        return apply(md, parameters, cb);
    } catch (const std::bad_alloc &) {
        errorMessage = "Variational Shape Approximation ran out of memory.";
    } catch (const std::exception &e) {
        errorMessage = QString("Variational Shape Approximation failed: %1").arg(e.what());
    } catch (...) {
        errorMessage = "Variational Shape Approximation failed with an unknown error.";
    }
    // Leave the document as it was: drop any layer this run had added.
    while (md.meshList.size() > layersBefore) md.delMesh(md.meshList.back());
    if (input) md.setCurrent(input);
    Log(GLLogStream::WARNING, qUtf8Printable(errorMessage));
    return false;
}

bool FilterVsaPlugin::apply(MeshDocument &md, const RichParameterList &parameters, vcg::CallBackPos *cb)
{
    MeshModel *input = md.mm();
    if (input == nullptr) {
        errorMessage = "Variational Shape Approximation needs a mesh: the document is empty.";
        Log(GLLogStream::WARNING, qUtf8Printable(errorMessage));
        return false;
    }
    const VsaFilterSettings settings = ReadVsaParameters(parameters);
    CMeshO approximation, anchors;
    const VsaRunOutcome outcome =
        RunVsa(input->cm, settings, approximation, settings.anchorLayer ? &anchors : nullptr, cb);
    for (const QString &line : outcome.log) Log(qUtf8Printable(line));
    if (!outcome.ok) {
        errorMessage = outcome.error;
        // meshlabserver 2020.09 prints the log but not the error message: log it too.
        Log(GLLogStream::WARNING, qUtf8Printable("Variational Shape Approximation: " + outcome.error));
        return false;
    }

    // The run succeeded: only now is the document changed.
    const QString name = ApproximationLayerName(input->label(), outcome.regionCount);
    MeshModel *output = md.addNewMesh("", name, false);
    Log(qUtf8Printable(QString("VSA: added layer \"%1\"").arg(name)));
    // MeshCopy copies only the attributes enabled on the destination.
    if (settings.colorizeRegions) output->updateDataMask(MeshModel::MM_FACECOLOR);
    vcg::tri::Append<CMeshO, CMeshO>::MeshCopy(output->cm, approximation);
    output->UpdateBoxAndNormals();
    if (settings.anchorLayer) {
        MeshModel *anchorModel = md.addNewMesh("", AnchorLayerName(input->label()), false);
        vcg::tri::Append<CMeshO, CMeshO>::MeshCopy(anchorModel->cm, anchors);
        anchorModel->UpdateBoxAndNormals();
    }
    if (settings.colorizeRegions) {
        input->updateDataMask(MeshModel::MM_FACECOLOR | MeshModel::MM_FACEQUALITY);
        ColorizeRegions(input->cm, outcome.faceRegion, outcome.regionCount);
    }
    // The new layer covers the input exactly: shown together they z-fight, so the input is hidden
    // (still in the project, one click away in the layer dialog).
    md.setVisible(input->id(), false);
    md.setCurrent(output);
    return true;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterVsaPlugin)
