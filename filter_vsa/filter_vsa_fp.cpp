#include "filter_vsa_fp.h"

#include "vsa_run.h"

#include <algorithm>
#include <new>
#include <vector>

FilterVsaPlugin::FilterVsaPlugin()
{
    typeList = {FP_VSA};
    for (ActionIDType id : types()) actionList.push_back(new QAction(filterName(id), this));
}

QString FilterVsaPlugin::pluginName() const { return "FilterVSA"; }

// Plugin Information shows it; the default names MeshLab's own lab.
QString FilterVsaPlugin::vendor() const { return "filter_vsa authors"; }

QString FilterVsaPlugin::filterName(ActionIDType) const { return "Variational Shape Approximation"; }

// pymeshlab's name; the default would be "variational_shape_approximation", and pymeshlab's own
// remeshing filters all start with "meshing_".
QString FilterVsaPlugin::pythonFilterName(ActionIDType) const { return "meshing_variational_shape_approximation"; }

QString FilterVsaPlugin::filterInfo(ActionIDType) const { return VsaFilterInfo(); }

// The PluginManager rejects the whole plugin if a filter's class is Generic.
FilterPlugin::FilterClass FilterVsaPlugin::getClass(const QAction *) const { return Remeshing; }

FilterPlugin::FilterArity FilterVsaPlugin::filterArity(const QAction *) const { return SINGLE_MESH; }

// No pre-condition on faces: pymeshlab and MeshLab would refuse a point cloud or an empty mesh with
// "Current mesh does not have Any Faces.", where ours says what the mesh is and what the filter needs.
int FilterVsaPlugin::getPreConditions(const QAction *) const { return MeshModel::MM_NONE; }

// vcg_core builds its own flat adjacency, so no vcg topology is required of the input;
// colouring needs per-face colour and quality, enabled on demand in apply().
int FilterVsaPlugin::getRequirements(const QAction *) { return MeshModel::MM_NONE; }

int FilterVsaPlugin::postCondition(const QAction *) const
{
    return MeshModel::MM_FACECOLOR | MeshModel::MM_FACEQUALITY;
}

RichParameterList FilterVsaPlugin::initParameterList(const QAction *action, const MeshModel &m)
{
    if (ID(action) != FP_VSA) wrongActionCalled(action);
    RichParameterList parameters;
    DefineVsaParameters(parameters, m.cm);
    return parameters;
}

std::map<std::string, QVariant> FilterVsaPlugin::applyFilter(const QAction *action,
                                                             const RichParameterList &parameters, MeshDocument &md,
                                                             unsigned int &postConditionMask, vcg::CallBackPos *cb)
{
    if (ID(action) != FP_VSA) wrongActionCalled(action);
    // MeshLab and pymeshlab show an MLException's message to the user; whatever fails, the
    // document is left as it was: no new layer, the same current layer.
    std::vector<unsigned int> layersBefore;
    for (const MeshModel &m : md.meshIterator()) layersBefore.push_back(m.id());
    MeshModel *input = md.mm();
    const auto restoreDocument = [&] {
        std::vector<unsigned int> added;
        for (const MeshModel &m : md.meshIterator())
            if (std::find(layersBefore.begin(), layersBefore.end(), m.id()) == layersBefore.end())
                added.push_back(m.id());
        for (unsigned int id : added) md.delMesh(id);
        if (input) md.setCurrent(input);
    };
    try {
        return apply(md, parameters, postConditionMask, cb);
    } catch (const MLException &) {
        restoreDocument();
        throw;
    } catch (const std::bad_alloc &) {
        restoreDocument();
        throw MLException("Variational Shape Approximation ran out of memory.");
    } catch (const std::exception &e) {
        restoreDocument();
        throw MLException(QString("Variational Shape Approximation failed: %1").arg(e.what()));
    } catch (...) {
        restoreDocument();
        throw MLException("Variational Shape Approximation failed with an unknown error.");
    }
}

std::map<std::string, QVariant> FilterVsaPlugin::apply(MeshDocument &md, const RichParameterList &parameters,
                                                       unsigned int &postConditionMask, vcg::CallBackPos *cb)
{
    MeshModel *input = md.mm();
    if (input == nullptr) throw MLException("Variational Shape Approximation needs a mesh: the document is empty.");
    const VsaFilterSettings settings = ReadVsaParameters(parameters);
    CMeshO approximation, anchors;
    const VsaRunOutcome outcome =
        RunVsa(input->cm, settings, approximation, settings.anchorLayer ? &anchors : nullptr, cb);
    // std::string overload: the lines are text, not printf formats.
    for (const QString &line : outcome.log) log(line.toStdString());
    if (!outcome.ok) throw MLException(outcome.error);

    // The run succeeded: only now is the document changed. addNewMesh copies the mesh with its
    // optional components (face colour) and updates box, normals and data mask.
    const QString name = ApproximationLayerName(input->label(), outcome.regionCount);
    MeshModel *output = md.addNewMesh(approximation, name, false);  // `input` stays valid
    // addNewMesh marks per-vertex colour and quality as present, and MeshLab would then draw the
    // layer in its (white) vertex colour instead of the regions' face colours.
    output->clearDataMask(MeshModel::MM_VERTCOLOR | MeshModel::MM_VERTQUALITY);
    log(QString("VSA: added layer \"%1\"").arg(output->label()).toStdString());
    // A polygonal layer: MeshLab's OBJ and OFF writers (and pymeshlab's save_polygonal) then write
    // the regions as polygons, joined across the faux edges.
    if (settings.core.meshing.polygonal) output->updateDataMask(MeshModel::MM_POLYGONAL);
    if (settings.anchorLayer) md.addNewMesh(anchors, AnchorLayerName(input->label()), false);
    // What changed on the meshes that existed before (MeshLab refreshes their rendering).
    postConditionMask = MeshModel::MM_NONE;
    if (settings.colorizeRegions) {
        input->updateDataMask(MeshModel::MM_FACECOLOR | MeshModel::MM_FACEQUALITY);
        ColorizeRegions(input->cm, outcome.faceRegion, outcome.regionCount);
        postConditionMask = MeshModel::MM_FACECOLOR | MeshModel::MM_FACEQUALITY;
    }
    // The new layer covers the input exactly: shown together they z-fight, so the input is hidden
    // (still in the project, one click away in the layer dialog).
    md.setVisible(input->id(), false);
    md.setCurrent(output);
    return outcome.figures;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterVsaPlugin)
