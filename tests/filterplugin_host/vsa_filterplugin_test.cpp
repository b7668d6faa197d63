// End-to-end tests of filter_vsa built for MeshLab's FilterPlugin API (MeshLab 2022.02+, the API
// pymeshlab loads): vsa_filterplugin_host loads the plugin through MeshLab's own PluginManager
// (version and precision checks), applies the filter as pymeshlab's MeshSet.apply_filter does and
// prints JSON: these tests check the layers it leaves, the returned figures and the errors.
//
// One binary for every MeshLab tree the plugin is built for; CTest runs it once per tree with
//   --host=HOST --plugin=PLUGIN.so --meshlab-version=V [--foreign-plugin=OTHER.so]...
// (a foreign plugin: ours built for a MeshLab of the other precision, which this host must refuse).
#include <gtest/gtest.h>

#include <QByteArray>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QString>
#include <QStringList>
#include <QTextStream>

#include <algorithm>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

namespace {

struct Config
{
    QString host, plugin, meshlabVersion;
    QStringList foreignPlugins;
};
Config gConfig;

const QString kFilterName = "Variational Shape Approximation";
const QString kPythonName = "meshing_variational_shape_approximation";
const QString kFandisk = QString(VSA_RESOURCES) + "/meshes/fandisk.off";
const int kFandiskFaces = 12946;
const int kFandiskDefaultK = 129;  // vsa_parameters.cpp: faces / 100 within [20, 200]
const QString kElephantWithHoles = QString(VSA_CGAL_MESHES) + "/elephant-with-holes.off";
// MeshModel::MM_FACECOLOR | MeshModel::MM_FACEQUALITY (MeshLab 2022.02 .. 2025.07 values).
const qint64 kFaceColorAndQuality = 0x00008000 | 0x00010000;

struct HostRun
{
    int exitCode = -1;
    QJsonObject out;   ///< the host's JSON document
    QString messages;  ///< its stderr: the document's log, plugin output, errors

    QJsonObject Run() const { return out["run"].toObject(); }
    QJsonObject Figures() const { return Run()["output"].toObject(); }
    QJsonArray LayersBefore() const { return out["layers_before"].toArray(); }
    QJsonArray Layers() const { return Run()["layers"].toArray(); }
    QString Error() const { return Run().contains("error") ? Run()["error"].toString() : out["error"].toString(); }
    /// For failure messages: everything the host said.
    std::string Dump() const
    {
        return "exit " + std::to_string(exitCode) + "\n" + QJsonDocument(out).toJson().toStdString() +
               messages.toStdString();
    }
};

HostRun RunHost(const QString &plugin, const QStringList &arguments)
{
    QProcess process;
    process.start(gConfig.host, QStringList{plugin} + arguments);
    HostRun run;
    if (!process.waitForFinished(600 * 1000)) {
        process.kill();
        process.waitForFinished();
        run.messages = "the host did not finish in 10 minutes";
        return run;
    }
    run.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    run.messages = QString::fromUtf8(process.readAllStandardError());
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(process.readAllStandardOutput(), &error);
    if (error.error != QJsonParseError::NoError) run.messages += "\nstdout is not JSON: " + error.errorString();
    run.out = document.object();
    return run;
}

/// Applies our filter to `mesh` with `params` ("Name=value", MeshLab or python names).
HostRun ApplyVsa(const QString &mesh, const QStringList &params, const QStringList &extra = {})
{
    QStringList arguments{"--mesh", mesh, "--filter", kPythonName};
    for (const QString &p : params) arguments << "--param" << p;
    return RunHost(gConfig.plugin, arguments + extra);
}

QString WorkDir(const QString &name)
{
    const QString dir = QString(VSA_FP_WORK) + "/" + gConfig.meshlabVersion + "/" + name;
    QDir(dir).removeRecursively();
    QDir().mkpath(dir);
    return dir;
}

/// The layer called `name` after the run (empty if there is none).
QJsonObject Layer(const HostRun &run, const QString &name)
{
    for (const QJsonValue &layer : run.Layers())
        if (layer["name"].toString() == name) return layer.toObject();
    return {};
}

/// The regions of the run's output: the k asked for, or k' when the meshable partition split
/// regions that would not mesh as one polygon (see vcg_core/vsa/meshable_partition.h).
int OutputK(const HostRun &run) { return run.Figures()["proxy_count"].toInt(); }

/// What every successful run must show: the input untouched but for its colours, a new current
/// layer "<base> VSA k=<k'>" with far fewer faces than the input (at most `maxFaceFraction` of
/// them) but at least one per region, k <= k' <= max(k + 1, 2k) with the log saying why k grew,
/// and the figures of the run that agree with that layer.
void ExpectApproximation(const HostRun &run, const QString &inputName, const QString &baseName, int k,
                         bool inputClosed, double maxFaceFraction = 0.25)
{
    ASSERT_EQ(run.exitCode, 0) << run.Dump();
    ASSERT_GE(run.LayersBefore().size(), 1) << run.Dump();
    const QJsonObject before = run.LayersBefore()[0].toObject();
    const QJsonObject input = Layer(run, inputName);
    ASSERT_FALSE(input.isEmpty()) << run.Dump();
    EXPECT_EQ(input["geometry_checksum"], before["geometry_checksum"]) << "the input's geometry changed";
    EXPECT_EQ(input["faces"], before["faces"]);
    EXPECT_FALSE(input["current"].toBool());

    const int kOut = OutputK(run);
    EXPECT_GE(kOut, k) << run.Dump();
    EXPECT_LE(kOut, std::max(k + 1, 2 * k)) << run.Dump();
    const QString outputName = QString("%1 VSA k=%2").arg(baseName).arg(kOut);
    const QJsonObject output = Layer(run, outputName);
    ASSERT_FALSE(output.isEmpty()) << "no layer \"" << outputName.toStdString() << "\"\n" << run.Dump();
    EXPECT_TRUE(output["current"].toBool());
    const int inputFaces = before["faces"].toInt();
    const int outputFaces = output["faces"].toInt();
    EXPECT_GE(outputFaces, kOut);
    EXPECT_LT(outputFaces, maxFaceFraction * inputFaces);

    const QJsonObject figures = run.Figures();
    EXPECT_EQ(figures["faces_in"].toInt(), inputFaces);
    EXPECT_EQ(figures["faces_out"].toInt(), outputFaces);
    EXPECT_EQ(figures["vertices_out"].toInt(), output["vertices"].toInt());
    EXPECT_GT(figures["energy"].toDouble(), 0.0);
    EXPECT_GE(figures["iterations"].toInt(), 1);
    EXPECT_GE(figures["anchors"].toInt(), 3);
    EXPECT_LE(figures["anchors"].toInt(), output["vertices"].toInt());
    EXPECT_GE(figures["regions_fallback"].toInt(), 0);
    ASSERT_TRUE(figures.contains("regions_kept_as_input")) << run.Dump();
    EXPECT_LE(figures["regions_kept_as_input"].toInt(), figures["regions_fallback"].toInt());
    ASSERT_TRUE(figures.contains("cells_halved")) << run.Dump();
    EXPECT_TRUE(figures["cells_halved"].isDouble()) << run.Dump();  // a JSON number
    EXPECT_GE(figures["cells_halved"].toInt(-1), 0);
    ASSERT_TRUE(figures.contains("pieces_carved")) << run.Dump();
    EXPECT_GE(figures["pieces_carved"].toInt(-1), 0);
    ASSERT_TRUE(figures.contains("close_pairs")) << run.Dump();
    EXPECT_GE(figures["close_pairs"].toInt(-1), 0);
    EXPECT_TRUE(figures["manifold"].toBool());
    EXPECT_TRUE(figures["oriented"].toBool());
    EXPECT_EQ(figures["closed"].toBool(), inputClosed);
    EXPECT_GE(figures["meshing_passes"].toInt(), 1);
    for (const char *timing :
         {"seconds_setup", "seconds_seeding", "seconds_iterations", "seconds_meshable", "seconds_meshing"})
        EXPECT_GE(figures[timing].toDouble(-1), 0.0) << timing;
    // Every figure of a type pymeshlab's dict conversion takes (it drops others with a warning).
    const QJsonObject types = run.Run()["output_types"].toObject();
    EXPECT_EQ(types.size(), figures.size());
    for (auto type = types.begin(); type != types.end(); ++type)
        EXPECT_TRUE(QStringList({"int", "double", "float", "bool"}).contains(type.value().toString()))
            << type.key().toStdString() << " is a " << type.value().toString().toStdString();

    // The log tells the user what happened, the new layer included.
    bool loggedLayer = false, loggedK = false, loggedRaise = false;
    for (const QJsonValue &line : run.Run()["log"].toArray()) {
        const QString text = line["text"].toString();
        loggedLayer |= text.contains(QString("added layer \"%1\"").arg(outputName));
        loggedK |= text.contains(QString("k=%1 proxies").arg(kOut));
        loggedRaise |= text.contains(QString("k raised from %1 to %2: ").arg(k).arg(kOut));
    }
    EXPECT_TRUE(loggedLayer && loggedK) << run.Dump();
    EXPECT_EQ(loggedRaise, kOut > k) << run.Dump();
}

/// ColorizeRegions: the input's faces and the approximation's coloured by region, one colour per
/// region; the region index as the input's per-face quality.
void ExpectColouredByRegion(const HostRun &run, const QString &inputName, const QString &outputName, int k)
{
    const QJsonObject input = Layer(run, inputName);
    EXPECT_EQ(input["face_colors"].toInt(), k) << run.Dump();
    EXPECT_EQ(input["face_quality"].toArray(), (QJsonArray{0.0, double(k - 1)}));
    EXPECT_EQ(Layer(run, outputName)["face_colors"].toInt(), k);
    EXPECT_EQ(run.Run()["postcondition_mask"].toDouble(), double(kFaceColorAndQuality));
}

/// A failed run: MLException with `message`, and the document exactly as it was.
void ExpectCleanFailure(const HostRun &run, const QString &message)
{
    ASSERT_EQ(run.exitCode, 5) << "expected an MLException\n" << run.Dump();
    EXPECT_EQ(run.Run()["exception"].toString(), "MLException");
    EXPECT_TRUE(run.Error().contains(message)) << "message: " << run.Error().toStdString()
                                               << "\nexpected to contain: " << message.toStdString();
    EXPECT_FALSE(run.Run().contains("output"));
    ASSERT_EQ(run.Layers().size(), run.LayersBefore().size()) << "a layer was added\n" << run.Dump();
    for (int i = 0; i < run.Layers().size(); ++i) {
        // Same id, name, counts, geometry and current flag; no colour added.
        EXPECT_EQ(run.Layers()[i].toObject(), run.LayersBefore()[i].toObject()) << run.Dump();
    }
}

}  // namespace

TEST(FilterPlugin, PluginManagerAcceptsTheFilterWithItsParameters)
{
    const HostRun run = RunHost(gConfig.plugin, {"--list", "--mesh", kFandisk});
    ASSERT_EQ(run.exitCode, 0) << run.Dump();
    const QJsonObject plugin = run.out["plugin"].toObject(), host = run.out["host"].toObject();
    EXPECT_EQ(plugin["meshlab_version"].toString(), gConfig.meshlabVersion);
    EXPECT_EQ(host["meshlab_version"].toString(), gConfig.meshlabVersion);
    EXPECT_EQ(plugin["double_precision"], host["double_precision"]);
    EXPECT_EQ(plugin["name"].toString(), "FilterVSA");

    const QJsonArray filters = run.out["filters"].toArray();
    ASSERT_EQ(filters.size(), 1) << run.Dump();
    const QJsonObject filter = filters[0].toObject();
    EXPECT_EQ(filter["name"].toString(), kFilterName);
    EXPECT_EQ(filter["python_name"].toString(), kPythonName);
    EXPECT_EQ(filter["class"].toString(), "Remeshing");
    EXPECT_EQ(filter["arity"].toString(), "SINGLE_MESH");

    // The 2020.09 filter's names, in its order: .mlx scripts and pymeshlab keyword arguments
    // (lower-cased) depend on them.
    const std::vector<std::pair<QString, QString>> expected = {
        {"ProxyNum", "RichInt"},       {"TargetError", "RichFloat"}, {"Metric", "RichEnum"},
        {"Init", "RichEnum"},          {"MaxIterations", "RichInt"}, {"RandomSeed", "RichInt"},
        {"Teleport", "RichBool"},      {"AnchorThreshold", "RichFloat"}, {"ProjectAnchors", "RichBool"},
        {"Polygonal", "RichBool"},     {"ColorizeRegions", "RichBool"},  {"AnchorLayer", "RichBool"}};
    const QJsonArray parameters = filter["parameters"].toArray();
    ASSERT_EQ(parameters.size(), int(expected.size())) << run.Dump();
    for (size_t i = 0; i < expected.size(); ++i) {
        const QJsonObject p = parameters[int(i)].toObject();
        EXPECT_EQ(p["name"].toString(), expected[i].first);
        EXPECT_EQ(p["python_name"].toString(), expected[i].first.toLower());
        EXPECT_EQ(p["type"].toString(), expected[i].second) << expected[i].first.toStdString();
    }
    EXPECT_EQ(parameters[0]["default"].toInt(), kFandiskDefaultK) << "k's default is scaled to the mesh";
    EXPECT_EQ(parameters[2]["values"].toArray(), (QJsonArray{"L2,1", "L2"}));
    EXPECT_EQ(parameters[3]["values"].toArray(), (QJsonArray{"Random", "Farthest", "Hierarchical"}));
    EXPECT_EQ(parameters[10]["default"].toBool(), true) << "ColorizeRegions";
    EXPECT_EQ(parameters[11]["default"].toBool(), false) << "AnchorLayer";
}

TEST(FilterPlugin, DefaultsOnFandisk)
{
    const HostRun run = ApplyVsa(kFandisk, {});
    ExpectApproximation(run, "fandisk.off", "fandisk", kFandiskDefaultK, true);
    ExpectColouredByRegion(run, "fandisk.off", QString("fandisk VSA k=%1").arg(OutputK(run)), OutputK(run));
    EXPECT_EQ(run.Layers().size(), 2) << "no anchor layer by default";
}

TEST(FilterPlugin, DefaultsOnAMeshWithHoles)
{
    const HostRun run = ApplyVsa(kElephantWithHoles, {});
    const int faces = run.LayersBefore()[0].toObject()["faces"].toInt();
    const int k = std::clamp(faces / 100, 20, 200);
    // Every hole's border is kept (anchors along it): more faces than on a closed mesh.
    ExpectApproximation(run, "elephant-with-holes.off", "elephant-with-holes", k, false, 0.5);
    ExpectColouredByRegion(run, "elephant-with-holes.off", QString("elephant-with-holes VSA k=%1").arg(OutputK(run)),
                           OutputK(run));
}

struct MetricAndInit
{
    const char *metric, *init;
};
void PrintTo(const MetricAndInit &p, std::ostream *os) { *os << p.metric << " " << p.init; }

class MetricAndInitRun : public testing::TestWithParam<MetricAndInit> {};

TEST_P(MetricAndInitRun, ApproximatesFandisk)
{
    // Enum parameters by label, as a pymeshlab user passes them.
    const HostRun run = ApplyVsa(kFandisk, {"ProxyNum=40", QString("Metric=") + GetParam().metric,
                                            QString("Init=") + GetParam().init, "RandomSeed=3"});
    ExpectApproximation(run, "fandisk.off", "fandisk", 40, true);
    ExpectColouredByRegion(run, "fandisk.off", QString("fandisk VSA k=%1").arg(OutputK(run)), OutputK(run));
    const QJsonObject used = run.Run()["parameters"].toObject();
    EXPECT_EQ(used["Metric"].toInt(), QString(GetParam().metric) == "L2" ? 1 : 0);
    const QStringList inits{"Random", "Farthest", "Hierarchical"};
    EXPECT_EQ(used["Init"].toInt(), inits.indexOf(GetParam().init));
}

INSTANTIATE_TEST_SUITE_P(FilterPlugin, MetricAndInitRun,
                         testing::Values(MetricAndInit{"L2,1", "Random"}, MetricAndInit{"L2,1", "Farthest"},
                                         MetricAndInit{"L2,1", "Hierarchical"}, MetricAndInit{"L2", "Random"},
                                         MetricAndInit{"L2", "Farthest"}, MetricAndInit{"L2", "Hierarchical"}),
                         [](const testing::TestParamInfo<MetricAndInit> &info) {
                             return std::string(QString(info.param.metric) == "L2" ? "L2" : "L21") + "_" +
                                    info.param.init;
                         });

TEST(FilterPlugin, PythonKeywordNamesAsPymeshlabPassesThem)
{
    const HostRun run = ApplyVsa(kFandisk, {"proxynum=30", "metric=1", "init=2", "anchorthreshold=0.3",
                                            "colorizeregions=false", "polygonal=false"});
    ExpectApproximation(run, "fandisk.off", "fandisk", 30, true);
    const QJsonObject used = run.Run()["parameters"].toObject();
    EXPECT_EQ(used["ProxyNum"].toInt(), 30);
    EXPECT_EQ(used["Metric"].toInt(), 1);
    EXPECT_EQ(used["Init"].toInt(), 2);
    EXPECT_NEAR(used["AnchorThreshold"].toDouble(), 0.3, 1e-6);
    EXPECT_FALSE(used["ColorizeRegions"].toBool());
    // Not coloured: neither layer has face colours at all, and nothing is to be refreshed on the input.
    EXPECT_FALSE(Layer(run, "fandisk.off").contains("face_colors")) << run.Dump();
    EXPECT_FALSE(Layer(run, QString("fandisk VSA k=%1").arg(OutputK(run))).contains("face_colors"));
    EXPECT_EQ(run.Run()["postcondition_mask"].toDouble(-1), 0.0);
}

TEST(FilterPlugin, AnchorLayer)
{
    const HostRun run = ApplyVsa(kFandisk, {"ProxyNum=40", "AnchorLayer=true"});
    ExpectApproximation(run, "fandisk.off", "fandisk", 40, true);
    ASSERT_EQ(run.Layers().size(), 3) << run.Dump();
    const QJsonObject anchors = Layer(run, "fandisk VSA anchors");
    ASSERT_FALSE(anchors.isEmpty()) << run.Dump();
    EXPECT_EQ(anchors["faces"].toInt(), 0);
    EXPECT_EQ(anchors["vertices"].toInt(), run.Figures()["anchors"].toInt());
    EXPECT_FALSE(anchors["current"].toBool());
}

TEST(FilterPlugin, TargetErrorChoosesK)
{
    // ProxyNum is ignored when TargetError > 0: a smaller target error needs more proxies.
    const HostRun fine = ApplyVsa(kFandisk, {"TargetError=0.02", "ProxyNum=10"});
    const HostRun coarse = ApplyVsa(kFandisk, {"TargetError=0.2", "ProxyNum=10"});
    const int kFine = fine.Figures()["proxy_count"].toInt(), kCoarse = coarse.Figures()["proxy_count"].toInt();
    EXPECT_GT(kCoarse, 1) << coarse.Dump();
    EXPECT_GT(kFine, kCoarse) << fine.Dump() << coarse.Dump();
    ExpectApproximation(fine, "fandisk.off", "fandisk", kFine, true);
    ExpectApproximation(coarse, "fandisk.off", "fandisk", kCoarse, true);
}

TEST(FilterPlugin, SameSeedSameResult)
{
    const QStringList params{"ProxyNum=25", "Init=Random", "RandomSeed=11", "Teleport=true"};
    const HostRun first = ApplyVsa(kFandisk, params), second = ApplyVsa(kFandisk, params);
    ASSERT_EQ(first.exitCode, 0) << first.Dump();
    ASSERT_EQ(second.exitCode, 0) << second.Dump();
    ASSERT_EQ(OutputK(first), OutputK(second));
    const QString name = QString("fandisk VSA k=%1").arg(OutputK(first));
    const QJsonObject a = Layer(first, name), b = Layer(second, name);
    ASSERT_FALSE(a.isEmpty()) << first.Dump();
    EXPECT_EQ(a["geometry_checksum"], b["geometry_checksum"]);
    EXPECT_EQ(first.Figures()["energy"], second.Figures()["energy"]);
}

TEST(FilterPlugin, BadParametersFailCleanly)
{
    const int k = kFandiskFaces + 1;
    const struct
    {
        QString parameter, message;
    } cases[] = {
        {"ProxyNum=0", "The number of proxies must be at least 1 (got 0)."},
        {QString("ProxyNum=%1").arg(k),
         QString("The number of proxies (%1) exceeds the number of faces (%2)").arg(k).arg(kFandiskFaces)},
        {"TargetError=-1", "The target error must be a finite number >= 0"},
    };
    for (const auto &c : cases) {
        SCOPED_TRACE(c.parameter.toStdString());
        ExpectCleanFailure(ApplyVsa(kFandisk, {c.parameter}), c.message);
    }
}

// The fuzzing's findings (issue 32): a flat square far from the origin gave the grids a zero cell
// size (NaN cell indices), a tetrahedron near FLT_MAX infinite anchors. Both give a valid output
// whose coordinates are all finite.
TEST(FilterPlugin, ExtremeButFiniteInputsGiveFiniteOutputs)
{
    const QString dir = WorkDir("extreme");
    const struct
    {
        QString name, off;
        QStringList params;
        int faces;
    } cases[] = {
        {"square", "OFF\n4 2 0\n0 0 1e12\n1 0 1e12\n1 1 1e12\n0 1 1e12\n3 0 1 2\n3 0 2 3\n", {"ProxyNum=1"}, 2},
        {"tetra", "OFF\n4 4 0\n0 0 0\n3e38 0 0\n0 3e38 0\n0 0 3e38\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n",
         {"ProxyNum=4", "Metric=1", "Init=0"}, 4},
    };
    for (const auto &c : cases) {
        QFile file(dir + "/" + c.name + ".off");
        ASSERT_TRUE(file.open(QIODevice::WriteOnly | QIODevice::Text));
        file.write(c.off.toUtf8());
        file.close();
        const HostRun run = ApplyVsa(file.fileName(), c.params);
        ASSERT_EQ(run.exitCode, 0) << run.Dump();
        const QJsonObject output = Layer(run, c.name + " VSA k=" + c.params[0].section('=', 1));
        EXPECT_EQ(output["faces"].toInt(), c.faces) << run.Dump();
        EXPECT_TRUE(output["finite"].toBool()) << run.Dump();
    }
}

TEST(FilterPlugin, PointCloudFailsCleanly)
{
    // fandisk's vertices without its faces.
    const QString dir = WorkDir("point_cloud");
    const QString cloud = dir + "/fandisk_points.off";
    {
        QFile in(kFandisk), out(cloud);
        ASSERT_TRUE(in.open(QIODevice::ReadOnly | QIODevice::Text) && out.open(QIODevice::WriteOnly | QIODevice::Text));
        QTextStream read(&in), write(&out);
        QStringList lines;  // the non-empty ones: "OFF", the counts, the vertices, the faces
        while (!read.atEnd()) {
            const QString line = read.readLine().trimmed();
            if (!line.isEmpty()) lines << line;
        }
        const int vertices = lines.value(1).section(' ', 0, 0).toInt();
        ASSERT_GT(vertices, 0);
        write << "OFF\n" << vertices << " 0 0\n";
        for (int i = 0; i < vertices; ++i) write << lines[2 + i] << "\n";
    }
    // As pymeshlab and the dialog apply it (pre-conditions checked) and as MeshLab's script runner
    // does (not checked): the filter itself refuses it, saying what the mesh is.
    for (const QStringList &options : {QStringList(), QStringList{"--no-applicability-check"}})
        ExpectCleanFailure(ApplyVsa(cloud, {"ProxyNum=20"}, options),
                           "The mesh has no faces (it is a point cloud of 6475 vertices)");
}

TEST(FilterPlugin, RefusedByAMeshLabOfTheOtherPrecision)
{
    if (gConfig.foreignPlugins.isEmpty()) GTEST_SKIP() << "built for a single MeshLab precision";
    for (const QString &foreign : gConfig.foreignPlugins) {
        const HostRun run = RunHost(foreign, {"--list"});
        EXPECT_EQ(run.exitCode, 3) << run.Dump();
        EXPECT_TRUE(run.Error().contains("different floating point precision")) << run.Dump();
    }
}

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);  // for QProcess
    testing::InitGoogleTest(&argc, argv);
    for (int i = 1; i < argc; ++i) {
        const QString a = QString::fromLocal8Bit(argv[i]);
        const QString value = a.section('=', 1);
        if (a.startsWith("--host=")) gConfig.host = value;
        else if (a.startsWith("--plugin=")) gConfig.plugin = value;
        else if (a.startsWith("--meshlab-version=")) gConfig.meshlabVersion = value;
        else if (a.startsWith("--foreign-plugin=")) gConfig.foreignPlugins << value;
        else {
            fprintf(stderr, "unknown argument %s\n", argv[i]);
            return 1;
        }
    }
    // gtest_discover_tests lists the tests without the arguments the runs get.
    const bool listOnly = testing::GTEST_FLAG(list_tests);
    if (!listOnly && (gConfig.host.isEmpty() || gConfig.plugin.isEmpty() || gConfig.meshlabVersion.isEmpty())) {
        fprintf(stderr, "usage: %s --host=HOST --plugin=PLUGIN.so --meshlab-version=V [--foreign-plugin=SO]...\n",
                argv[0]);
        return 1;
    }
    return RUN_ALL_TESTS();
}
