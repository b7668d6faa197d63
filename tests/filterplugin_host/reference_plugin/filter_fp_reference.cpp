#include "filter_fp_reference.h"

#include <vcg/complex/algorithms/update/color.h>
#include <vcg/complex/algorithms/update/quality.h>

#include <algorithm>
#include <stdexcept>

namespace {
const QStringList kMetricNames = {"L2,1", "L2"};
const QStringList kFailureKinds = {"MLException", "std::runtime_error"};
}  // namespace

FilterFpReferencePlugin::FilterFpReferencePlugin()
{
    // 2022.02+: typeList / actionList are std::list (2020.09: QList, filled with <<).
    typeList = {FP_REFERENCE_PARTITION, FP_REFERENCE_FAIL};
    for (ActionIDType id : types()) actionList.push_back(new QAction(filterName(id), this));
}

QString FilterFpReferencePlugin::pluginName() const { return "FilterFpReference"; }

QString FilterFpReferencePlugin::vendor() const { return "meshlab_vsa tests"; }

QString FilterFpReferencePlugin::filterName(ActionIDType filter) const
{
    switch (filter) {
    case FP_REFERENCE_PARTITION: return "Reference Face Partition";
    case FP_REFERENCE_FAIL: return "Reference Failing Filter";
    }
    return QString();
}

// pymeshlab's name of the filter; the default (FilterPlugin::pythonFilterName) lower-cases the
// filterName and turns ' ', '/' and '-' into '_' ("reference_face_partition").
QString FilterFpReferencePlugin::pythonFilterName(ActionIDType filter) const
{
    switch (filter) {
    case FP_REFERENCE_PARTITION: return "reference_face_partition";
    case FP_REFERENCE_FAIL: return "reference_failing_filter";
    }
    return QString();
}

QString FilterFpReferencePlugin::filterInfo(ActionIDType filter) const
{
    switch (filter) {
    case FP_REFERENCE_PARTITION:
        return "Splits the faces, in storage order, into <i>ProxyNum</i> contiguous regions, adds a copy of the "
               "mesh (offset along X) colored by region, and returns figures of the partition. A test "
               "fixture of the FilterPlugin API, not a useful filter.";
    case FP_REFERENCE_FAIL:
        return "Always fails, by throwing the chosen exception type: tests the host's error path.";
    }
    return QString();
}

// checkFilterPlugin() rejects the whole plugin when a filter's class is Generic.
FilterPlugin::FilterClass FilterFpReferencePlugin::getClass(const QAction *action) const
{
    return ID(action) == FP_REFERENCE_PARTITION ? FilterPlugin::Remeshing : FilterPlugin::Other;
}

// ...and when its arity is UNKNOWN_ARITY, or a requirement / pre- / post-condition is MM_UNKNOWN.
FilterPlugin::FilterArity FilterFpReferencePlugin::filterArity(const QAction *) const { return SINGLE_MESH; }

int FilterFpReferencePlugin::getPreConditions(const QAction *) const { return MeshModel::MM_FACENUMBER; }

// Enabled on the current mesh by the host (MeshModel::updateDataMask) before applyFilter.
int FilterFpReferencePlugin::getRequirements(const QAction *) { return MeshModel::MM_NONE; }

int FilterFpReferencePlugin::postCondition(const QAction *) const { return MeshModel::MM_NONE; }

RichParameterList FilterFpReferencePlugin::initParameterList(const QAction *action, const MeshModel &m)
{
    RichParameterList parameters;  // 2020.09: filled a RichParameterList& argument instead
    switch (ID(action)) {
    case FP_REFERENCE_PARTITION:
        parameters.addParam(RichInt("ProxyNum", std::clamp(m.cm.fn / 100, 1, 200), "Number of regions (k)",
                                    "How many regions; must be in [1, face count]."));
        parameters.addParam(RichFloat("TargetError", 0, "Target error", "Unused; must not be negative."));
        parameters.addParam(RichEnum("Metric", 0, kMetricNames, "Metric",
                                     "L2,1: area x squared normal deviation; L2: area x squared distance."));
        parameters.addParam(RichBool("ColorizeRegions", true, "Colorize regions on the input",
                                     "Also color the input's faces by region (per-face quality = region)."));
        // RichPercentage (2020.09: RichAbsPerc): an absolute value within [min, max], shown as a
        // percentage; its stringType() is still "RichAbsPerc", its Python type PercentageValue.
        parameters.addParam(RichPercentage("Offset", m.cm.bbox.Diag() * 1.1f, 0, 2 * m.cm.bbox.Diag(),
                                           "Offset of the copy", "Translation of the new layer along X."));
        break;
    case FP_REFERENCE_FAIL:
        parameters.addParam(RichEnum("Kind", 0, kFailureKinds, "Exception type", "What applyFilter throws."));
        break;
    default: wrongActionCalled(action);  // throws MLException
    }
    return parameters;
}

std::map<std::string, QVariant> FilterFpReferencePlugin::applyFilter(const QAction *action,
                                                                    const RichParameterList &parameters,
                                                                    MeshDocument &md,
                                                                    unsigned int &postConditionMask,
                                                                    vcg::CallBackPos *cb)
{
    if (ID(action) == FP_REFERENCE_FAIL) {
        if (parameters.getEnum("Kind") == 0)
            throw MLException("Reference Failing Filter: failed on purpose (MLException).");
        throw std::runtime_error("Reference Failing Filter: failed on purpose (std::runtime_error).");
    }
    if (ID(action) != FP_REFERENCE_PARTITION) wrongActionCalled(action);

    // Errors: throw MLException (2020.09: set errorMessage and return false). Nothing may be
    // changed in the document before the checks pass.
    MeshModel *input = md.mm();
    if (input == nullptr) throw MLException("Reference Face Partition needs a mesh: the document is empty.");
    const int k = parameters.getInt("ProxyNum");
    const CMeshO &cm = input->cm;
    if (k < 1 || k > cm.fn)
        throw MLException(QString("Reference Face Partition: ProxyNum must be in [1, %1], got %2.").arg(cm.fn).arg(k));
    if (parameters.getFloat("TargetError") < 0)
        throw MLException("Reference Face Partition: TargetError must not be negative.");
    const int metric = parameters.getEnum("Metric");
    const bool colorize = parameters.getBool("ColorizeRegions");
    const Scalarm offset = parameters.getAbsPerc("Offset");

    std::vector<int> region(cm.face.size(), -1);
    std::vector<Point3m> normalSum(k, Point3m(0, 0, 0));
    std::vector<Point3m> centroidSum(k, Point3m(0, 0, 0));
    std::vector<double> regionArea(k, 0.0);
    int live = 0;
    double area = 0;
    Point3m barycenter(0, 0, 0);
    for (size_t i = 0; i < cm.face.size(); ++i) {
        const CFaceO &f = cm.face[i];
        if (f.IsD()) continue;
        const int r = int((long long)live * k / cm.fn);
        region[i] = r;
        ++live;
        const Point3m n = vcg::TriangleNormal(f);  // |n| = 2 area
        const double a = n.Norm() / 2;
        const Point3m c = vcg::Barycenter(f);
        normalSum[r] += n;
        centroidSum[r] += c * Scalarm(a);
        regionArea[r] += a;
        area += a;
        barycenter += c * Scalarm(a);
        if (cb && live % 4096 == 0) cb(int(50.0 * live / cm.fn), "Partitioning faces");
    }
    if (area > 0) barycenter /= Scalarm(area);
    double distortion = 0;
    for (size_t i = 0; i < cm.face.size(); ++i) {
        const int r = region[i];
        if (r < 0) continue;
        const CFaceO &f = cm.face[i];
        const Point3m n = vcg::TriangleNormal(f);
        const double a = n.Norm() / 2;
        if (a <= 0) continue;
        const Point3m proxyNormal = normalSum[r].Norm() > 0 ? normalSum[r] / normalSum[r].Norm() : Point3m(0, 0, 1);
        if (metric == 0) {
            distortion += a * (n / n.Norm() - proxyNormal).SquaredNorm();
        } else {
            const Point3m proxyPoint = centroidSum[r] / Scalarm(regionArea[r]);
            const double d = (vcg::Barycenter(f) - proxyPoint) * proxyNormal;
            distortion += a * d * d;
        }
    }

    // A new layer: addNewMesh(const CMeshO&, label, setAsCurrent) copies the mesh and updates
    // its bounding box, normals and data mask (2020.09: addNewMesh(fullPath, label, setAsCurrent)
    // and vcg::tri::Append::MeshCopy). The label is made unique by the document.
    const QString label = QFileInfo(input->label()).completeBaseName() + QString(" ref k=%1").arg(k);
    MeshModel *output = md.addNewMesh(cm, label, true);  // `input` stays valid: std::list storage
    output->updateDataMask(MeshModel::MM_FACECOLOR | MeshModel::MM_FACEQUALITY);
    for (size_t i = 0; i < output->cm.face.size(); ++i) {
        if (region[i] < 0) continue;
        output->cm.face[i].Q() = Scalarm(region[i]);
        output->cm.face[i].C() = vcg::Color4b::Scatter(k, region[i]);
    }
    for (CVertexO &v : output->cm.vert)
        if (!v.IsD()) v.P()[0] += offset;
    output->updateBoxAndNormals();  // 2020.09: UpdateBoxAndNormals()
    unsigned int changed = MeshModel::MM_NONE;
    if (colorize) {
        input->updateDataMask(MeshModel::MM_FACECOLOR | MeshModel::MM_FACEQUALITY);
        for (size_t i = 0; i < input->cm.face.size(); ++i) {
            if (region[i] < 0) continue;
            input->cm.face[i].Q() = Scalarm(region[i]);
            input->cm.face[i].C() = vcg::Color4b::Scatter(k, region[i]);
        }
        changed |= MeshModel::MM_FACECOLOR | MeshModel::MM_FACEQUALITY;
    }
    // What this run changed on the current mesh (the host falls back to postCondition()).
    postConditionMask = changed;

    // Logging: log(...) printf-style, optionally with a GLLogStream level (2020.09: Log(...)).
    log("Reference Face Partition: %d faces in %d regions, area %g, %s distortion %g", live, k, area,
        qUtf8Printable(kMetricNames[metric]), distortion);
    if (k == 1) log(GLLogStream::WARNING, "Reference Face Partition: a single region");
    if (cb) cb(100, "Done");

    // The figures pymeshlab returns as a dict (int, double, float, bool, Point3m, ... as QVariant).
    std::map<std::string, QVariant> figures;
    figures["regions"] = k;
    figures["faces"] = live;
    figures["area"] = area;
    figures["distortion"] = distortion;
    figures["metric"] = metric;
    figures["colorized"] = colorize;
    figures["offset"] = QVariant::fromValue(offset);
    figures["barycenter"] = QVariant::fromValue(barycenter);
    figures["output_layer_id"] = output->id();
    return figures;
}

// Nothing to export in 2022.02+ (kept for source compatibility; an empty macro).
MESHLAB_PLUGIN_NAME_EXPORTER(FilterFpReferencePlugin)
