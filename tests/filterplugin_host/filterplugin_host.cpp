// A headless host for MeshLab FilterPlugin plugins (MeshLab 2022.02 .. 2025.07, the API pymeshlab
// loads), linked to the libmeshlab-common that scripts/setup_filterplugin.sh builds.
//
// It loads a plugin through MeshLab's own PluginManager (meshlab::pluginManagerInstance(), the
// singleton MeshLab and pymeshlab use; PluginManager::loadPlugin runs checkPlugin: Qt plugin, a
// MeshLabPlugin, same scalar precision, same MeshLab version, a known plugin type and, for filter
// plugins, a class, arity, requirements and pre/post-conditions for every filter), lists its
// filters and their parameters, loads a mesh with MeshLab's IO plugins (io_base) into a
// MeshDocument, runs one filter the way pymeshlab's MeshSet.apply_filter does, and prints one JSON
// document on stdout. Messages, the document's log and anything plugins print go to stderr.
//
// Exit codes: 0 success; 1 bad command line; 2 mesh/IO error; 3 plugin rejected by the
// PluginManager (or not a filter plugin); 4 unknown filter or bad parameter;
// 5 the filter threw MLException; 6 the filter threw another std::exception.

#include <common/globals.h>
#include <common/mlexception.h>
#include <common/parameters/rich_parameter_list.h>
#include <common/plugins/interfaces/filter_plugin.h>
#include <common/plugins/plugin_manager.h>
#include <common/utilities/load_save.h>

#include <vcg/complex/algorithms/create/platonic.h>
#include <vcg/complex/algorithms/stat.h>
#include <vcg/complex/algorithms/update/selection.h>

#include <QApplication>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unistd.h>
#include <cstdlib>
#include <iostream>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace {

enum ExitCode {
    kOk = 0,
    kUsage = 1,
    kMeshError = 2,
    kPluginRejected = 3,
    kBadFilterOrParameter = 4,
    kFilterMLException = 5,
    kFilterOtherException = 6,
};

struct Options
{
    QString plugin;
    QStringList ioPlugins;
    QString mesh;
    QString filter;
    std::vector<std::pair<QString, QString>> params;
    QString save;
    bool list = false;
    bool progress = false;
    bool checkApplicability = true;
};

#ifndef VSA_FP_DEFAULT_IO_PLUGIN
#define VSA_FP_DEFAULT_IO_PLUGIN ""
#endif

void Usage()
{
    std::cerr
        << "usage: vsa_filterplugin_host PLUGIN.so [--io-plugin FILE.so]... [--list]\n"
           "           [--mesh FILE] [--filter NAME] [--param NAME=VALUE]... [--save FILE] [--progress]\n"
           "  PLUGIN.so        the FilterPlugin to load (MeshLab's PluginManager checks it)\n"
           "  --io-plugin      MeshLab IO plugin(s) used to load/save meshes (default: "
        << VSA_FP_DEFAULT_IO_PLUGIN
        << ")\n"
           "  --list           list the plugin's filters and parameters (defaults computed on the mesh,\n"
           "                   or on a 1x1x1 cube like pymeshlab when no --mesh is given)\n"
           "  --filter NAME    apply the filter with this MeshLab name or python name\n"
           "  --param N=V      override a parameter (by MeshLab or python name); bool: true/false/1/0,\n"
           "                   enum: index or label, RichAbsPerc: absolute value or N% of its range\n"
           "  --save FILE      save the current layer after the filter (format from the extension)\n"
           "  --no-applicability-check\n"
           "                   apply the filter even if the current mesh lacks its pre-conditions, as\n"
           "                   MeshLab's script runner does (pymeshlab and the dialogs check first)\n";
}

bool ParseArgs(const QStringList &args, Options &o)
{
    for (int i = 1; i < args.size(); ++i) {
        const QString &a = args[i];
        auto next = [&](QString &out) {
            if (i + 1 >= args.size()) return false;
            out = args[++i];
            return true;
        };
        QString v;
        if (a == "--io-plugin") {
            if (!next(v)) return false;
            o.ioPlugins << v;
        } else if (a == "--mesh") {
            if (!next(o.mesh)) return false;
        } else if (a == "--filter") {
            if (!next(o.filter)) return false;
        } else if (a == "--param") {
            if (!next(v)) return false;
            const int eq = v.indexOf('=');
            if (eq <= 0) return false;
            o.params.emplace_back(v.left(eq), v.mid(eq + 1));
        } else if (a == "--save") {
            if (!next(o.save)) return false;
        } else if (a == "--list") {
            o.list = true;
        } else if (a == "--progress") {
            o.progress = true;
        } else if (a == "--no-applicability-check") {
            o.checkApplicability = false;
        } else if (a == "-h" || a == "--help") {
            return false;
        } else if (!a.startsWith("--") && o.plugin.isEmpty()) {
            o.plugin = a;
        } else {
            return false;
        }
    }
    if (o.ioPlugins.isEmpty() && QString(VSA_FP_DEFAULT_IO_PLUGIN).size() > 0)
        o.ioPlugins << QString(VSA_FP_DEFAULT_IO_PLUGIN);
    return !o.plugin.isEmpty();
}

bool gProgress = false;
bool ProgressCallback(const int pos, const char *str)
{
    if (gProgress) std::fprintf(stderr, "  [%3d%%] %s\n", pos, str);
    return true;
}

QJsonValue ToJson(const QVariant &v)
{
    const std::string type = v.typeName() ? v.typeName() : "";
    if (type == "int" || type == "uint" || type == "qlonglong" || type == "qulonglong")
        return QJsonValue(v.toLongLong());
    if (type == "double" || type == "float") return QJsonValue(v.toDouble());
    if (type == "bool") return QJsonValue(v.toBool());
    if (type == "QString") return QJsonValue(v.toString());
    auto point = [](const auto &p, int n) {
        QJsonArray a;
        for (int i = 0; i < n; ++i) a.append(double(p[i]));
        return a;
    };
    if (v.canConvert<Point2m>()) return point(v.value<Point2m>(), 2);
    if (v.canConvert<Point3m>()) return point(v.value<Point3m>(), 3);
    if (v.canConvert<Box3m>()) {
        const Box3m b = v.value<Box3m>();
        return QJsonObject{{"min", point(b.min, 3)}, {"max", point(b.max, 3)}};
    }
    if (v.canConvert<Matrix33m>()) {
        const Matrix33m m = v.value<Matrix33m>();
        QJsonArray rows;
        for (int r = 0; r < 3; ++r) rows.append(QJsonArray{double(m[r][0]), double(m[r][1]), double(m[r][2])});
        return rows;
    }
    if (v.canConvert<Matrix44m>()) {
        const Matrix44m m = v.value<Matrix44m>();
        QJsonArray rows;
        for (int r = 0; r < 4; ++r)
            rows.append(QJsonArray{double(m[r][0]), double(m[r][1]), double(m[r][2]), double(m[r][3])});
        return rows;
    }
    if (v.canConvert<Eigen::VectorXd>()) {
        const Eigen::VectorXd e = v.value<Eigen::VectorXd>();
        QJsonArray a;
        for (Eigen::Index i = 0; i < e.size(); ++i) a.append(e[i]);
        return a;
    }
    return QJsonValue(QString("<%1> %2").arg(QString::fromStdString(type), v.toString()));
}

QJsonValue ParameterValueJson(const RichParameter &p)
{
    const Value &v = p.value();
    if (v.isBool()) return v.getBool();
    if (v.isInt()) return v.getInt();
    if (v.isFloat()) return double(v.getFloat());
    if (v.isString()) return v.getString();
    if (v.isPoint3()) {
        const Point3m q = v.getPoint3();
        return QJsonArray{double(q[0]), double(q[1]), double(q[2])};
    }
    if (v.isColor()) return v.getColor().name(QColor::HexArgb);
    return QJsonValue(QString("<%1>").arg(p.stringType()));
}

QJsonObject ParameterJson(const RichParameter &p)
{
    QJsonObject o{{"name", p.name()},
                  {"python_name", p.pythonName()},
                  {"type", p.stringType()},
                  {"python_type", p.pythonType()},
                  {"default", ParameterValueJson(p)},
                  {"description", p.fieldDescription()},
                  {"advanced", p.isAdvanced()}};
    if (const auto *e = dynamic_cast<const RichEnum *>(&p)) o["values"] = QJsonArray::fromStringList(e->enumvalues);
    if (const auto *pc = dynamic_cast<const RichPercentage *>(&p)) {
        o["min"] = double(pc->min);
        o["max"] = double(pc->max);
    }
    if (const auto *d = dynamic_cast<const RichDynamicFloat *>(&p)) {
        o["min"] = double(d->min);
        o["max"] = double(d->max);
    }
    return o;
}

QString FilterClassNames(int c)
{
    static const std::pair<int, const char *> names[] = {
        {FilterPlugin::Selection, "Selection"}, {FilterPlugin::Cleaning, "Cleaning"},
        {FilterPlugin::Remeshing, "Remeshing"}, {FilterPlugin::FaceColoring, "FaceColoring"},
        {FilterPlugin::VertexColoring, "VertexColoring"}, {FilterPlugin::MeshColoring, "MeshColoring"},
        {FilterPlugin::MeshCreation, "MeshCreation"}, {FilterPlugin::Smoothing, "Smoothing"},
        {FilterPlugin::Quality, "Quality"}, {FilterPlugin::Layer, "Layer"},
        {FilterPlugin::RasterLayer, "RasterLayer"}, {FilterPlugin::Normal, "Normal"},
        {FilterPlugin::Sampling, "Sampling"}, {FilterPlugin::Texture, "Texture"},
        {FilterPlugin::RangeMap, "RangeMap"}, {FilterPlugin::PointSet, "PointSet"},
        {FilterPlugin::Measure, "Measure"}, {FilterPlugin::Polygonal, "Polygonal"},
        {FilterPlugin::Camera, "Camera"}, {FilterPlugin::Other, "Other"}};
    QStringList out;
    for (const auto &n : names)
        if (c & n.first) out << n.second;
    return out.isEmpty() ? "Generic" : out.join('|');
}

const char *ArityName(FilterPlugin::FilterArity a)
{
    switch (a) {
    case FilterPlugin::NONE: return "NONE";
    case FilterPlugin::SINGLE_MESH: return "SINGLE_MESH";
    case FilterPlugin::FIXED: return "FIXED";
    case FilterPlugin::VARIABLE: return "VARIABLE";
    default: return "UNKNOWN_ARITY";
    }
}

// FNV-1a over the live vertices' coordinates and the faces' vertex indices: equal before and
// after a filter iff the layer's geometry was left alone.
QString GeometryChecksum(const CMeshO &cm)
{
    std::uint64_t h = 1469598103934665603ull;
    auto add = [&h](const void *data, size_t size) {
        for (size_t i = 0; i < size; ++i) h = (h ^ static_cast<const unsigned char *>(data)[i]) * 1099511628211ull;
    };
    for (const CVertexO &v : cm.vert)
        if (!v.IsD()) add(&v.cP()[0], 3 * sizeof(Scalarm));
    for (const CFaceO &f : cm.face) {
        if (f.IsD()) continue;
        for (int i = 0; i < 3; ++i) {
            const std::int64_t index = vcg::tri::Index(cm, f.cV(i));
            add(&index, sizeof(index));
        }
    }
    return QString::number(h, 16);
}

QJsonArray LayersJson(const MeshDocument &md)
{
    QJsonArray layers;
    for (const MeshModel &m : md.meshIterator()) {
        QJsonObject layer{{"id", int(m.id())},
                          {"name", m.label()},
                          {"vertices", m.cm.vn},
                          {"faces", m.cm.fn},
                          {"edges", m.cm.en},
                          {"current", md.mm() == &m},
                          {"geometry_checksum", GeometryChecksum(m.cm)},
                          {"finite", std::all_of(m.cm.vert.begin(), m.cm.vert.end(), [](const CVertexO &v) {
                               return v.IsD() || (std::isfinite(v.cP()[0]) && std::isfinite(v.cP()[1]) &&
                                                  std::isfinite(v.cP()[2]));
                           })}};
        // Per-face attributes, only when the layer has them (filters that colour faces enable them).
        if (m.hasDataMask(MeshModel::MM_FACECOLOR)) {
            std::set<unsigned int> colors;
            for (const CFaceO &f : m.cm.face)
                if (!f.IsD()) colors.insert(f.cC()[0] | f.cC()[1] << 8 | f.cC()[2] << 16 | unsigned(f.cC()[3]) << 24);
            layer["face_colors"] = int(colors.size());
        }
        if (m.hasDataMask(MeshModel::MM_FACEQUALITY) && m.cm.fn > 0) {
            const std::pair<Scalarm, Scalarm> range = vcg::tri::Stat<CMeshO>::ComputePerFaceQualityMinMax(m.cm);
            layer["face_quality"] = QJsonArray{double(range.first), double(range.second)};
        }
        layers.append(layer);
    }
    return layers;
}

// Sets `text` into the parameter, by its MeshLab type (as pymeshlab does from python values).
void SetParameter(RichParameter &p, const QString &text)
{
    const QString type = p.stringType();
    bool ok = true;
    if (type == "RichBool") {
        const QString t = text.toLower();
        if (t != "true" && t != "false" && t != "1" && t != "0") ok = false;
        else p.setValue(BoolValue(t == "true" || t == "1"));
    } else if (type == "RichInt" || type == "RichMesh") {
        const int v = text.toInt(&ok);
        if (ok) p.setValue(IntValue(v));
    } else if (type == "RichFloat") {
        const double v = text.toDouble(&ok);
        if (ok) p.setValue(FloatValue(Scalarm(v)));
    } else if (type == "RichDynamicFloat") {
        const auto &d = dynamic_cast<const RichDynamicFloat &>(p);
        const double v = text.toDouble(&ok);
        if (ok) p.setValue(FloatValue(std::clamp(Scalarm(v), d.min, d.max)));
    } else if (type == "RichAbsPerc") {
        const auto &pc = dynamic_cast<const RichPercentage &>(p);
        double v;
        if (text.endsWith('%')) {
            v = text.chopped(1).toDouble(&ok);
            v = pc.min + (pc.max - pc.min) * v / 100.0;
        } else {
            v = text.toDouble(&ok);
        }
        if (ok) p.setValue(FloatValue(Scalarm(v)));
    } else if (type == "RichEnum") {
        const auto &e = dynamic_cast<const RichEnum &>(p);
        int v = text.toInt(&ok);
        if (!ok) {
            v = e.enumvalues.indexOf(text);
            ok = v >= 0;
        }
        if (ok && (v < 0 || v >= e.enumvalues.size())) ok = false;
        if (ok) p.setValue(IntValue(v));
        else
            throw MLException(QString("Parameter %1: '%2' is not one of 0..%3 or %4")
                                  .arg(p.name(), text)
                                  .arg(e.enumvalues.size() - 1)
                                  .arg(e.enumvalues.join(", ")));
    } else if (type == "RichString" || type == "RichOpenFile" || type == "RichSaveFile") {
        p.setValue(StringValue(text));
    } else {
        throw MLException(QString("Parameter %1: type %2 is not supported by this host").arg(p.name(), type));
    }
    if (!ok) throw MLException(QString("Parameter %1 (%2): cannot read '%3'").arg(p.name(), type, text));
}

QAction *FindFilter(FilterPlugin &fp, const QString &name)
{
    for (QAction *a : fp.actions())
        if (fp.filterName(a) == name || fp.pythonFilterName(a) == name || a->text() == name) return a;
    return nullptr;
}

void DumpLog(const MeshDocument &md, int &printed)
{
    const auto &entries = md.Log.logStringList();
    for (int i = printed; i < entries.size(); ++i)
        std::cerr << "  log[" << entries[i].first << "] " << entries[i].second.toStdString() << "\n";
    printed = entries.size();
}

}  // namespace

int main(int argc, char *argv[])
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    Options opt;
    if (!ParseArgs(app.arguments(), opt)) {
        Usage();
        return kUsage;
    }
    gProgress = opt.progress;

    QJsonObject out;
    out["host"] = QJsonObject{{"meshlab_version", QString::fromStdString(meshlab::meshlabVersion())},
                              {"double_precision", meshlab::builtWithDoublePrecision()}};
    // Plugins and vcglib print to stdout (e.g. vcg::MissingComponentException's constructor):
    // keep stdout for the JSON document alone by sending fd 1 to stderr until the end.
    std::fflush(stdout);
    const int jsonFd = dup(STDOUT_FILENO);
    dup2(STDERR_FILENO, STDOUT_FILENO);
    auto finish = [&](int code) {
        out["exit_code"] = code;
        std::fflush(stdout);
        std::cout.flush();
        const QByteArray json = QJsonDocument(out).toJson(QJsonDocument::Indented);
        for (qint64 done = 0; done < json.size();) {
            const ssize_t n = write(jsonFd, json.constData() + done, size_t(json.size() - done));
            if (n <= 0) break;
            done += n;
        }
        return code;
    };

    PluginManager &pm = meshlab::pluginManagerInstance();
    const QString pluginPath = QFileInfo(opt.plugin).absoluteFilePath();
    for (const QString &io : opt.ioPlugins) {
        if (QFileInfo(io).absoluteFilePath() == pluginPath) continue;
        try {
            pm.loadPlugin(QFileInfo(io).absoluteFilePath());
        } catch (const MLException &e) {
            std::cerr << "IO plugin " << io.toStdString() << " rejected: " << e.what() << "\n";
            out["error"] = QString("IO plugin rejected: ") + e.what();
            return finish(kMeshError);
        }
    }

    // The same call pymeshlab.load_plugin() and MeshLab's plugin dialog make.
    MeshLabPlugin *plugin = nullptr;
    try {
        plugin = pm.loadPlugin(pluginPath);
    } catch (const MLException &e) {
        std::cerr << "plugin rejected: " << e.what() << "\n";
        out["error"] = QString("plugin rejected: ") + e.what();
        return finish(kPluginRejected);
    }
    FilterPlugin *fp = dynamic_cast<FilterPlugin *>(plugin);
    const auto mlv = plugin->getMLVersion();
    out["plugin"] = QJsonObject{{"file", pluginPath},
                                {"name", plugin->pluginName()},
                                {"vendor", plugin->vendor()},
                                {"meshlab_version", QString::fromStdString(mlv.first)},
                                {"double_precision", mlv.second},
                                {"filter_plugin", fp != nullptr}};
    if (fp == nullptr) {
        out["error"] = "not a FilterPlugin";
        return finish(kPluginRejected);
    }

    MeshDocument md;
    int logPrinted = 0;
    for (MeshLabPlugin *p : pm.pluginIterator())
        if (auto *logger = dynamic_cast<MeshLabPluginLogger *>(p)) logger->setLog(&md.Log);
    if (!opt.mesh.isEmpty()) {
        try {
            meshlab::loadMeshWithStandardParameters(QFileInfo(opt.mesh).absoluteFilePath(), md, ProgressCallback);
        } catch (const MLException &e) {
            std::cerr << "cannot load " << opt.mesh.toStdString() << ": " << e.what() << "\n";
            out["error"] = QString("cannot load mesh: ") + e.what();
            return finish(kMeshError);
        }
        out["layers_before"] = LayersJson(md);
    }

    if (opt.list) {
        // Defaults depend on the mesh: pymeshlab computes them on a 1x1x1 cube.
        MeshDocument cubeDoc;
        const MeshDocument *paramDoc = &md;
        if (md.mm() == nullptr) {
            CMeshO cube;
            vcg::tri::Box<CMeshO>(cube, Box3m(Point3m(-0.5, -0.5, -0.5), Point3m(0.5, 0.5, 0.5)));
            cubeDoc.addNewMesh(cube, "cube");
            cubeDoc.mm()->enable(vcg::tri::io::Mask::IOM_VERTQUALITY | vcg::tri::io::Mask::IOM_FACEQUALITY);
            paramDoc = &cubeDoc;
        }
        QJsonArray filters;
        for (QAction *a : fp->actions()) {
            QJsonArray params;
            try {
                for (const RichParameter &p : fp->initParameterList(a, *paramDoc)) params.append(ParameterJson(p));
            } catch (const std::exception &e) {  // MLException, vcg::MissingComponentException, ...
                params.append(QJsonObject{{"error", QString(e.what())}});
            }
            filters.append(QJsonObject{{"name", fp->filterName(a)},
                                       {"python_name", fp->pythonFilterName(a)},
                                       {"class", FilterClassNames(fp->getClass(a))},
                                       {"arity", ArityName(fp->filterArity(a))},
                                       {"preconditions", fp->getPreConditions(a)},
                                       {"requirements", fp->getRequirements(a)},
                                       {"postcondition", fp->postCondition(a)},
                                       {"parameters_on", paramDoc == &md ? md.mm()->label() : "cube"},
                                       {"parameters", params}});
        }
        out["filters"] = filters;
    }

    if (opt.filter.isEmpty()) return finish(kOk);

    QAction *action = FindFilter(*fp, opt.filter);
    if (action == nullptr) {
        out["error"] = "no filter named " + opt.filter;
        return finish(kBadFilterOrParameter);
    }
    const bool needsMesh = fp->filterArity(action) != FilterPlugin::NONE;
    if (needsMesh && md.mm() == nullptr) {
        out["error"] = "the filter needs a mesh: give --mesh";
        return finish(kMeshError);
    }
    RichParameterList rpl;
    try {
        // initParameterList(QAction*, MeshDocument&) calls the MeshModel overload on md.mm().
        if (md.mm() != nullptr) rpl = fp->initParameterList(action, md);
        for (const auto &kv : opt.params) {
            auto it = rpl.findParameter(kv.first);
            if (it == rpl.end())
                for (auto j = rpl.begin(); j != rpl.end(); ++j)
                    if (j->pythonName() == kv.first) it = j;
            if (it == rpl.end()) throw MLException("filter " + opt.filter + " has no parameter " + kv.first);
            SetParameter(*it, kv.second);
        }
    } catch (const std::exception &e) {
        out["error"] = QString(e.what());
        return finish(kBadFilterOrParameter);
    }
    QJsonObject used;
    for (const RichParameter &p : rpl) used[p.name()] = ParameterValueJson(p);
    QJsonObject run{{"filter", fp->filterName(action)}, {"python_name", fp->pythonFilterName(action)},
                    {"parameters", used}};

    // As pymeshlab's MeshSet.apply_filter (and MeshLab's MainWindow::executeFilter) do it.
    QStringList missing;
    if (opt.checkApplicability && md.mm() != nullptr && !fp->isFilterApplicable(action, *md.mm(), missing)) {
        run["error"] = "current mesh does not have " + missing.join(", ");
        out["run"] = run;
        return finish(kBadFilterOrParameter);
    }
    if (fp->requiresGLContext(action))
        std::cerr << "warning: the filter asks for an OpenGL context; this host gives it none (glContext == nullptr)\n";
    int code = kOk;
    try {
        if (md.mm() != nullptr) md.mm()->updateDataMask(fp->getRequirements(action));
        md.meshDocStateData().clear();
        md.meshDocStateData().create(md);
        md.setBusy(true);
        unsigned int postConditionMask = MeshModel::MM_UNKNOWN;
        const std::map<std::string, QVariant> result =
            fp->applyFilter(action, rpl, md, postConditionMask, ProgressCallback);
        md.setBusy(false);
        if (postConditionMask == MeshModel::MM_UNKNOWN) postConditionMask = fp->postCondition(action);
        for (MeshModel &m : md.meshIterator()) vcg::tri::Allocator<CMeshO>::CompactEveryVector(m.cm);
        if (md.mm() != nullptr) {
            md.mm()->cm.svn = int(vcg::tri::UpdateSelection<CMeshO>::VertexCount(md.mm()->cm));
            md.mm()->cm.sfn = int(vcg::tri::UpdateSelection<CMeshO>::FaceCount(md.mm()->cm));
        }
        // The values, and their QVariant types: pymeshlab turns only some of them into Python
        // values (int, double, float, bool, Point2m/3m, Box3m, Matrix33m/44m, Eigen::VectorXd).
        QJsonObject values, types;
        for (const auto &kv : result) {
            values[QString::fromStdString(kv.first)] = ToJson(kv.second);
            types[QString::fromStdString(kv.first)] = kv.second.typeName();
        }
        run["output"] = values;
        run["output_types"] = types;
        run["postcondition_mask"] = qint64(postConditionMask);
    } catch (const MLException &e) {
        md.setBusy(false);
        std::cerr << "filter failed (MLException): " << e.what() << "\n";
        run["error"] = QString(e.what());
        run["exception"] = "MLException";
        code = kFilterMLException;
    } catch (const std::exception &e) {
        md.setBusy(false);
        std::cerr << "filter failed (" << typeid(e).name() << "): " << e.what() << "\n";
        run["error"] = QString(e.what());
        run["exception"] = "std::exception";
        code = kFilterOtherException;
    }
    DumpLog(md, logPrinted);
    QJsonArray logLines;
    for (const auto &entry : md.Log.logStringList())
        logLines.append(QJsonObject{{"level", entry.first}, {"text", entry.second}});
    run["log"] = logLines;
    run["layers"] = LayersJson(md);
    out["run"] = run;

    if (code == kOk && !opt.save.isEmpty() && md.mm() != nullptr) {
        try {
            meshlab::saveMeshWithStandardParameters(QFileInfo(opt.save).absoluteFilePath(), *md.mm(), &md.Log);
            out["saved"] = QFileInfo(opt.save).absoluteFilePath();
        } catch (const MLException &e) {
            out["error"] = QString("cannot save: ") + e.what();
            return finish(kMeshError);
        }
    }
    return finish(code);
}
