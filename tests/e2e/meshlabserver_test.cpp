// End-to-end tests: the shipped .mlx scripts and bad inputs through the real meshlabserver
// 2020.09 with our plugin, checking the files it writes and what it logs.
#include <vsa/indexed_mesh.h>
#include <vsa/mesh_validity.h>

#include "../unit/test_meshes.h"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using vsa_test::TMesh;

namespace {

const std::string kResources = VSA_RESOURCES;
const std::string kFandisk = kResources + "/meshes/fandisk.off";

struct ServerRun
{
    int exitCode = -1;    ///< meshlabserver's exit status; -1 if it did not run
    std::string output;   ///< everything it printed, log included
};

std::string Quote(const std::string &s) { return "'" + s + "'"; }

std::string ReadFile(const fs::path &path)
{
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

fs::path WorkDir(const std::string &name)
{
    const fs::path dir = fs::path(VSA_E2E_WORK) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

/// Runs `command` in the shell, everything it prints going to `output`; returns its exit
/// status, or -1 if it did not exit normally.
int RunCommand(const std::string &command, const fs::path &output)
{
    const int status = std::system((command + " > " + Quote(output.string()) + " 2>&1").c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// Runs meshlabserver under its own Xvfb with `arguments` (already quoted where needed).
ServerRun RunServer(const fs::path &dir, const std::string &arguments)
{
    const fs::path output = dir / "meshlabserver.out";
    const fs::path script = dir / "meshlabserver.sh";
    const fs::path status = dir / "meshlabserver.status";
    // meshlabserver's own exit status, written from inside xvfb-run: xvfb-run's may be its own
    // (exit 5 when removing its temporary folder fails) whatever meshlabserver did.
    std::ofstream(script) << Quote(VSA_MESHLABSERVER) << " " << arguments << "\necho $? > " << Quote(status.string())
                          << "\n";
    fs::remove(status);
    RunCommand(std::string(VSA_XVFB_RUN) + " -a sh " + Quote(script.string()), output);
    ServerRun run;
    run.output = ReadFile(output);
    const std::string code = ReadFile(status);
    if (!code.empty()) run.exitCode = std::stoi(code);
    return run;
}

/// The VSA filter's parameters as a script would give them (every one must be present).
std::map<std::string, std::string> DefaultVsaParameters()
{
    return {{"ProxyNum", "50"},         {"TargetError", "0"},     {"Metric", "0"},          {"Init", "1"},
            {"MaxIterations", "50"},    {"RandomSeed", "1"},      {"Teleport", "false"},    {"AnchorThreshold", "0.2"},
            {"ProjectAnchors", "true"}, {"Polygonal", "true"},
            {"ColorizeRegions", "true"}, {"AnchorLayer", "false"}};
}

fs::path WriteVsaScript(const fs::path &dir, const std::map<std::string, std::string> &overrides)
{
    std::map<std::string, std::string> p = DefaultVsaParameters();
    for (const auto &[name, value] : overrides) p[name] = value;
    const fs::path script = dir / "vsa.mlx";
    std::ofstream out(script);
    out << "<!DOCTYPE FilterScript>\n<FilterScript>\n <filter name=\"Variational Shape Approximation\">\n"
        << "  <Param type=\"RichInt\" value=\"" << p["ProxyNum"] << "\" name=\"ProxyNum\"/>\n"
        << "  <Param type=\"RichFloat\" value=\"" << p["TargetError"] << "\" name=\"TargetError\"/>\n"
        << "  <Param type=\"RichEnum\" value=\"" << p["Metric"]
        << "\" name=\"Metric\" enum_cardinality=\"2\" enum_val0=\"L2,1\" enum_val1=\"L2\"/>\n"
        << "  <Param type=\"RichEnum\" value=\"" << p["Init"]
        << "\" name=\"Init\" enum_cardinality=\"3\" enum_val0=\"Random\" enum_val1=\"Farthest\""
           " enum_val2=\"Hierarchical\"/>\n";
    for (const char *name : {"MaxIterations", "RandomSeed"})
        out << "  <Param type=\"RichInt\" value=\"" << p[name] << "\" name=\"" << name << "\"/>\n";
    out << "  <Param type=\"RichBool\" value=\"" << p["Teleport"] << "\" name=\"Teleport\"/>\n"
        << "  <Param type=\"RichFloat\" value=\"" << p["AnchorThreshold"] << "\" name=\"AnchorThreshold\"/>\n";
    for (const char *name : {"ProjectAnchors", "Polygonal", "ColorizeRegions", "AnchorLayer"})
        out << "  <Param type=\"RichBool\" value=\"" << p[name] << "\" name=\"" << name << "\"/>\n";
    out << " </filter>\n</FilterScript>\n";
    return script;
}

bool Load(TMesh &m, const fs::path &path)
{
    std::string error;
    const bool ok = vsa_test::LoadMesh(m, path.string(), &error);
    EXPECT_TRUE(ok) << path << ": " << error;
    return ok;
}

std::set<unsigned> DistinctFaceColors(const TMesh &m)
{
    std::set<unsigned> colors;
    for (const auto &f : m.face)
        if (!f.IsD()) colors.insert(f.cC()[0] | f.cC()[1] << 8 | f.cC()[2] << 16);
    return colors;
}

fs::path WriteOff(const fs::path &dir, const std::string &name, const std::string &text)
{
    const fs::path path = dir / name;
    std::ofstream(path) << text;
    return path;
}

/// Runs `script` on `mesh`, saving the approximation (current layer) and the coloured input.
struct ScriptCase
{
    ServerRun run;
    fs::path approximation, regions;
};

ScriptCase RunScript(const fs::path &dir, const fs::path &mesh, const fs::path &script)
{
    ScriptCase c;
    c.approximation = dir / "approximation.ply";
    c.regions = dir / "regions.ply";
    c.run = RunServer(dir, "-i " + Quote(mesh.string()) + " -s " + Quote(script.string()) + " -o " +
                               Quote(c.approximation.string()) + " -m fc -o " + Quote(c.regions.string()) +
                               " -l 0 -m fc fq");
    return c;
}

/// Checks a successful run: a closed input gives a closed, manifold, oriented approximation
/// with about k' faces per region, k <= k' <= max(k + 1, 2k) (the meshable partition splits
/// regions that would not mesh as one polygon, and the log says so); the input is coloured with
/// exactly one colour per region.
void ExpectGoodApproximation(const ScriptCase &c, int kAsked, bool inputClosed)
{
    ASSERT_EQ(c.run.exitCode, 0) << c.run.output;
    std::smatch layer;
    ASSERT_TRUE(std::regex_search(c.run.output, layer, std::regex("VSA k=([0-9]+)"))) << c.run.output;
    const int k = std::stoi(layer[1]);
    EXPECT_GE(k, kAsked);
    EXPECT_LE(k, std::max(kAsked + 1, 2 * kAsked));
    const std::string raised = "k raised from " + std::to_string(kAsked) + " to " + std::to_string(k) + ": ";
    EXPECT_EQ(c.run.output.find(raised) != std::string::npos, k > kAsked) << c.run.output;
    TMesh out, regions;
    ASSERT_TRUE(Load(out, c.approximation));
    ASSERT_TRUE(Load(regions, c.regions));
    const vcg::tri::vsa::MeshValidity validity = vcg::tri::vsa::CheckMeshValidity(out);
    EXPECT_TRUE(validity.IsTwoManifold()) << validity.Summary();
    EXPECT_TRUE(validity.IsOriented()) << validity.Summary();
    EXPECT_EQ(validity.degenerateFaces, 0) << validity.Summary();
    if (inputClosed) {
        EXPECT_TRUE(validity.IsClosed()) << validity.Summary();
    }
    // A region becomes at least one triangle; far fewer faces than the input.
    EXPECT_GE(out.FN(), k);
    EXPECT_LT(out.FN(), regions.FN() / 4);
    // The approximation carries the region colours too: one per region.
    EXPECT_EQ(DistinctFaceColors(out).size(), size_t(k));
    // The input layer: one colour per region, quality = region index in [0, k).
    EXPECT_EQ(DistinctFaceColors(regions).size(), size_t(k));
    std::set<int> regionIds;
    for (const auto &f : regions.face) regionIds.insert(int(f.cQ()));
    EXPECT_EQ(regionIds.size(), size_t(k));
    EXPECT_EQ(*regionIds.begin(), 0);
    EXPECT_EQ(*regionIds.rbegin(), k - 1);
}

}  // namespace

TEST(MeshLabServer, DumpListsTheFilterWithItsParameters)
{
    const fs::path dir = WorkDir("dump");
    const ServerRun run = RunServer(dir, "-d " + Quote((dir / "filters.txt").string()));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const std::string dump = ReadFile(dir / "filters.txt");
    ASSERT_NE(dump.find("Variational Shape Approximation"), std::string::npos);
    // The dump shows each parameter by its description.
    for (const char *description : {"Number of proxies (k)", "Target error", "Metric", "Initialization",
                                    "Max iterations", "Random seed", "Teleport proxies", "Anchor threshold",
                                    "Project anchors on proxies", "Polygonal output", "Colorize regions on the input",
                                    "Add anchor layer"})
        EXPECT_NE(dump.find(description), std::string::npos) << description;
    EXPECT_NE(dump.find("Cohen-Steiner"), std::string::npos);
}

class ShippedScript : public testing::TestWithParam<std::string> {};

TEST_P(ShippedScript, ApproximatesFandisk)
{
    const fs::path dir = WorkDir("script_" + GetParam());
    const ScriptCase c = RunScript(dir, kFandisk, kResources + "/scripts/" + GetParam() + ".mlx");
    ExpectGoodApproximation(c, 50, true);
}

INSTANTIATE_TEST_SUITE_P(MeshLabServer, ShippedScript,
                         testing::Values("vsa_l21_random", "vsa_l21_farthest", "vsa_l21_hierarchical",
                                         "vsa_l2_random", "vsa_l2_farthest", "vsa_l2_hierarchical"));

TEST(MeshLabServer, HausdorffScriptMeasuresBothWays)
{
    const fs::path dir = WorkDir("hausdorff");
    const ServerRun run = RunServer(dir, "-i " + Quote(kFandisk) + " -s " +
                                             Quote(kResources + "/scripts/vsa_hausdorff.mlx"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    // MeshLab logs "min : a max b mean : c RMS : d" twice per run: absolute, then over the diagonal.
    const std::regex line(R"(Values w\.r\.t\. BBox Diag \(([0-9.eE+-]+)\)\s*\n)"
                          R"(\s*min : ([0-9.eE+-]+)\s+max ([0-9.eE+-]+))");
    // meshlabserver prints the whole (never cleared) log after each filter: the last two
    // measurements are the two directions.
    std::vector<double> maxima;
    for (auto it = std::sregex_iterator(run.output.begin(), run.output.end(), line); it != std::sregex_iterator(); ++it)
        maxima.push_back(std::stod((*it)[3]));
    ASSERT_GE(maxima.size(), 2u) << run.output;
    maxima.erase(maxima.begin(), maxima.end() - 2);
    for (double relativeMax : maxima) {
        EXPECT_GT(relativeMax, 0.0);
        EXPECT_LT(relativeMax, 0.03);  // 50 planes keep fandisk within 3% of its diagonal
    }
}

namespace {

/// The Newell normal of `polygon` (corners indexing `positions`): twice its area times its normal.
vcg::Point3d PolygonNormal(const std::vector<vcg::Point3d> &positions, const std::vector<int> &polygon)
{
    vcg::Point3d n(0, 0, 0);
    for (size_t c = 0; c < polygon.size(); ++c)
        n += positions[polygon[c]] ^ positions[polygon[(c + 1) % polygon.size()]];
    return n;
}

/// Whether triangle (a, b, c) of `positions` turns against `normal`.
bool TurnsAgainst(const std::vector<vcg::Point3d> &positions, int a, int b, int c, const vcg::Point3d &normal)
{
    return ((positions[b] - positions[a]) ^ (positions[c] - positions[a])) * normal < 0;
}

/// Whether the fan of `polygon` from its corner `apex` turns a triangle against `normal`, the
/// polygon's.
bool FanFolds(const std::vector<vcg::Point3d> &positions, const std::vector<int> &polygon, const vcg::Point3d &normal,
              int apex)
{
    const int n = int(polygon.size());
    for (int k = 1; k + 1 < n; ++k)
        if (TurnsAgainst(positions, polygon[apex], polygon[(apex + k) % n], polygon[(apex + k + 1) % n], normal))
            return true;
    return false;
}

/// Checks that meshlabserver reads the polygons back whole, each as its own triangles, and not
/// as fans of their first corners: each polygon that is the fan of one corner but not of
/// another is written starting at the latter, where a fan reader turns a triangle over. None of
/// those may come back as that fan, and fewer triangles than those polygons may be turned: a
/// fan reader turns at least one in each, while MeshLab's own triangulation can still turn one
/// in a bent polygon (README, "Saving the polygons").
void ExpectReadBackWhole(const fs::path &dir, const std::vector<vcg::Point3d> &positions,
                         std::vector<std::vector<int>> polygons)
{
    std::vector<char> checked(polygons.size(), 0);
    std::vector<vcg::Point3d> normals;
    size_t triangleCount = 0;
    for (size_t p = 0; p < polygons.size(); ++p) {
        std::vector<int> &polygon = polygons[p];
        const int n = int(polygon.size());
        triangleCount += size_t(n - 2);
        normals.push_back(PolygonNormal(positions, polygon));
        int folding = -1, flat = -1;
        for (int apex = 0; apex < n; ++apex) (FanFolds(positions, polygon, normals[p], apex) ? folding : flat) = apex;
        if (folding < 0 || flat < 0) continue;
        std::rotate(polygon.begin(), polygon.begin() + folding, polygon.end());
        checked[p] = 1;
    }
    const int startsFolding = int(std::count(checked.begin(), checked.end(), 1));
    ASSERT_GT(startsFolding, 0) << "every polygon is a fan of each corner: nothing to check";
    const fs::path folding = dir / "folding_fans.off", back = dir / "read_back.ply";
    {
        std::ofstream out(folding);
        out.precision(17);
        out << "OFF\n" << positions.size() << " " << polygons.size() << " 0\n";
        for (const vcg::Point3d &p : positions) out << p[0] << " " << p[1] << " " << p[2] << "\n";
        for (const std::vector<int> &polygon : polygons) {
            out << polygon.size();
            for (int v : polygon) out << " " << v;
            out << "\n";
        }
    }
    const ServerRun run = RunServer(dir, "-i " + Quote(folding.string()) + " -o " + Quote(back.string()));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    TMesh triangles;
    ASSERT_TRUE(Load(triangles, back));
    ASSERT_EQ(size_t(triangles.VN()), positions.size());
    ASSERT_EQ(size_t(triangles.FN()), triangleCount);
    std::vector<std::vector<int>> polygonsOf(positions.size());
    for (int p = 0; p < int(polygons.size()); ++p)
        for (int v : polygons[p]) polygonsOf[v].push_back(p);
    int outside = 0, turned = 0;
    std::vector<std::set<std::set<int>>> trianglesOf(polygons.size());
    for (const auto &f : triangles.face) {
        int corner[3];
        for (int i = 0; i < 3; ++i) corner[i] = int(vcg::tri::Index(triangles, f.cV(i)));
        int owner = -1;  // the polygon holding all three corners
        for (int p : polygonsOf[corner[0]]) {
            const auto &polygon = polygons[p];
            const auto holds = [&](int v) { return std::count(polygon.begin(), polygon.end(), v) > 0; };
            if (holds(corner[1]) && holds(corner[2])) owner = p;
        }
        if (owner < 0) {
            ++outside;
        } else if (checked[owner]) {
            turned += TurnsAgainst(positions, corner[0], corner[1], corner[2], normals[owner]);
            trianglesOf[owner].insert({corner[0], corner[1], corner[2]});
        }
    }
    EXPECT_EQ(outside, 0) << "triangles across polygons";
    int readAsFans = 0;
    for (size_t p = 0; p < polygons.size(); ++p) {
        if (!checked[p]) continue;
        std::set<std::set<int>> fan;
        const std::vector<int> &polygon = polygons[p];
        for (size_t k = 1; k + 1 < polygon.size(); ++k) fan.insert({polygon[0], polygon[k], polygon[k + 1]});
        readAsFans += trianglesOf[p] == fan;
    }
    EXPECT_EQ(readAsFans, 0) << "of " << startsFolding << " polygons read as fans of a corner whose fan folds";
    EXPECT_LT(turned, startsFolding) << "triangles turned over in the polygons that start at a corner whose fan folds";
}

}  // namespace

TEST(MeshLabServer, PolygonalOutputKeepsRegionsAsPolygons)
{
    // meshlabserver 2020.09 cannot save the polygons itself (its polygonal OFF writes vertex
    // flags for indices, and it aborts on polygonal OBJ): the PLY keeps the faux-edge flags, and
    // polygons_from_ply.py turns them into polygons. Checked: the polygons make a closed,
    // consistently oriented polygon mesh of fandisk's topology, about one polygon per region.
    const fs::path dir = WorkDir("polygonal");
    const fs::path ply = dir / "approximation.ply", flagless = dir / "no_flags.ply", off = dir / "polygons.off";
    const ServerRun run = RunServer(dir, "-i " + Quote(kFandisk) + " -s " +
                                             Quote(WriteVsaScript(dir, {{"ProxyNum", "30"}}).string()) + " -o " +
                                             Quote(ply.string()) + " -l 1 -m ff -o " + Quote(flagless.string()) +
                                             " -l 1");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    auto convert = [&](const fs::path &from) {
        return RunCommand(std::string(VSA_PYTHON3) + " " + Quote(VSA_POLYGONS_FROM_PLY) + " " + Quote(from.string()) +
                              " " + Quote(off.string()),
                          dir / "convert.out");
    };
    EXPECT_EQ(convert(flagless), 1) << "a PLY without face flags has no polygons to recover";
    EXPECT_NE(ReadFile(dir / "convert.out").find("no face flags"), std::string::npos);
    // MeshLab reads the flags back: the PLY reopened and saved again keeps the same polygons.
    const fs::path reopened = dir / "reopened.ply";
    const ServerRun again = RunServer(dir, "-i " + Quote(ply.string()) + " -o " + Quote(reopened.string()) + " -m ff");
    ASSERT_EQ(again.exitCode, 0) << again.output;
    ASSERT_EQ(convert(reopened), 0) << ReadFile(dir / "convert.out");
    const std::string reopenedPolygons = ReadFile(off);
    ASSERT_EQ(convert(ply), 0) << ReadFile(dir / "convert.out");
    EXPECT_EQ(ReadFile(off), reopenedPolygons);

    std::ifstream in(off);
    std::string header;
    int vertices = 0, polygons = 0, edgesUnused = 0;
    in >> header >> vertices >> polygons >> edgesUnused;
    ASSERT_EQ(header, "OFF");
    std::vector<vcg::Point3d> positions(vertices);
    for (vcg::Point3d &p : positions) in >> p[0] >> p[1] >> p[2];
    int largerThanTriangles = 0;
    std::set<std::pair<int, int>> halfEdges;
    std::vector<char> used(vertices, 0);
    std::vector<std::vector<int>> polygonList;
    for (int p = 0; p < polygons; ++p) {
        int corners = 0;
        in >> corners;
        std::vector<int> &polygon = polygonList.emplace_back(corners);
        for (int &index : polygon) in >> index;
        ASSERT_TRUE(in) << "truncated OFF";
        largerThanTriangles += corners > 3;
        for (int c = 0; c < corners; ++c) {
            const int from = polygon[c], to = polygon[(c + 1) % corners];
            ASSERT_TRUE(from >= 0 && from < vertices && from != to) << "polygon " << p;
            used[from] = 1;
            EXPECT_TRUE(halfEdges.insert({from, to}).second) << "edge " << from << "-" << to << " in two polygons";
        }
    }
    for (const auto &[from, to] : halfEdges)
        EXPECT_TRUE(halfEdges.count({to, from})) << "open at " << from << "-" << to;
    EXPECT_EQ(std::count(used.begin(), used.end(), 1), vertices);
    EXPECT_EQ(vertices - int(halfEdges.size()) / 2 + polygons, 2);  // fandisk is a sphere
    // One polygon per region, except a region with a hole or a ring, cut into discs.
    EXPECT_GE(polygons, 30);
    EXPECT_LE(polygons, 2 * 30);
    EXPECT_GE(largerThanTriangles, 15);
    EXPECT_NE(ReadFile(dir / "convert.out").find("misread polygons of 5 corners or more"), std::string::npos);
    ExpectReadBackWhole(dir, positions, polygonList);
}

TEST(MeshLabServer, OpenMeshKeepsItsBorder)
{
    const fs::path dir = WorkDir("open_mesh");
    const fs::path mesh = vsa_test::CgalMesh("mesh_with_border.off");
    TMesh input;
    ASSERT_TRUE(Load(input, mesh));
    vcg::tri::vsa::MeshDiagnostics inputDiag;
    vcg::tri::vsa::BuildIndexedMesh(input, &inputDiag);
    ASSERT_GT(inputDiag.borderEdges, 0);
    const ScriptCase c = RunScript(dir, mesh, WriteVsaScript(dir, {{"ProxyNum", "20"}}));
    ExpectGoodApproximation(c, 20, false);
    TMesh out;
    ASSERT_TRUE(Load(out, c.approximation));
    EXPECT_GT(vcg::tri::vsa::CheckMeshValidity(out).borderEdges, 0);
}

TEST(MeshLabServer, EveryComponentIsApproximated)
{
    const fs::path dir = WorkDir("components");
    const fs::path mesh = vsa_test::CgalMesh("blobby_3cc.off");
    const ScriptCase c = RunScript(dir, mesh, WriteVsaScript(dir, {{"ProxyNum", "30"}}));
    ExpectGoodApproximation(c, 30, false);  // blobby_3cc's three components are open
    TMesh out;
    ASSERT_TRUE(Load(out, c.approximation));
    const vcg::tri::vsa::MeshValidity validity = vcg::tri::vsa::CheckMeshValidity(out);
    EXPECT_EQ(validity.components, 3);
    EXPECT_GT(validity.borderEdges, 0);
}

namespace {
/// The filter's own defaults but for k and farthest seeding: what a user gets from the dialog.
std::map<std::string, std::string> DialogDefaultsFarthest(const std::string &k)
{
    return {{"ProxyNum", k}, {"Init", "1"}, {"MaxIterations", "30"}, {"RandomSeed", "0"}, {"Teleport", "true"}};
}

const char kClosePairsWarning[] = "face pairs of the output come closer than text files";
}  // namespace

// MeshLab writes OFF with 7 significant digits; a reader in double (pymeshlab, CGAL, ...) gets
// those decimals, a few units in the last place of a float away from what was checked. On
// cheese at k=20 (farthest) faces 1e-8 apart then met: 4 intersecting pairs. The meshing now
// keeps faces farther apart than that rounding moves them.
TEST(MeshLabServer, OutputSavedAsOffStaysFreeOfSelfIntersectionsReadInDoubleOrFloat)
{
    const fs::path dir = WorkDir("saved_as_off");
    const fs::path off = dir / "cheese_vsa.off";
    const ServerRun run = RunServer(dir, "-i " + Quote(vsa_test::CgalMesh("cheese.off")) + " -s " +
                                             Quote(WriteVsaScript(dir, DialogDefaultsFarthest("20")).string()) +
                                             " -o " + Quote(off.string()) + " -l 1");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_EQ(run.output.find(kClosePairsWarning), std::string::npos) << run.output;
    vsa_test::BareMesh inDouble;
    int mask = 0;
    ASSERT_EQ(vcg::tri::io::Importer<vsa_test::BareMesh>::Open(inDouble, off.string().c_str(), mask), 0);
    const vcg::tri::vsa::MeshValidity doubleValidity = vcg::tri::vsa::CheckMeshValidity(inDouble);
    EXPECT_GT(doubleValidity.faces, 1000);
    EXPECT_EQ(doubleValidity.selfIntersections, 0) << doubleValidity.Summary();
    TMesh inFloat;
    ASSERT_TRUE(Load(inFloat, off));
    EXPECT_EQ(vcg::tri::vsa::CheckMeshValidity(inFloat).selfIntersections, 0);
}

// Where faces stay closer than text files keep them apart, the log says so: two tetrahedra whose
// facing sides are 1e-6 apart (under the 2e-6 that float coordinates saved as text may move).
// Triceratops at k=100 did this until the meshable partition gave it cleaner regions.
TEST(MeshLabServer, LogsFacePairsTooCloseForTextFiles)
{
    const fs::path dir = WorkDir("close_pairs");
    const fs::path twoTetrahedra =
        WriteOff(dir, "two_tetrahedra.off",
                 "OFF\n8 8 0\n0 0 0\n1 0 0\n0 1 0\n0.2 0.2 1\n0 0 -0.000001\n1 0 -0.000001\n"
                 "0 1 -0.000001\n0.2 0.2 -1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n3 4 5 6\n3 4 7 5\n"
                 "3 5 7 6\n3 6 7 4\n");
    const ServerRun run = RunServer(dir, "-i " + Quote(twoTetrahedra.string()) + " -s " +
                                             Quote(WriteVsaScript(dir, DialogDefaultsFarthest("4")).string()));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const std::regex warning(std::string(R"(VSA: warning: ([0-9]+) )") + kClosePairsWarning);
    std::smatch match;
    ASSERT_TRUE(std::regex_search(run.output, match, warning)) << run.output;
    EXPECT_GT(std::stoi(match[1]), 0);
    EXPECT_NE(run.output.find("binary PLY keeps them exactly"), std::string::npos);
}

namespace {
/// A bad input must fail cleanly: meshlabserver reports the failed filter and exits with its
/// error status (255), not a crash, and the log carries our message.
void ExpectCleanFailure(const ServerRun &run, const std::string &message)
{
    EXPECT_EQ(run.exitCode, 255) << run.output;
    EXPECT_NE(run.output.find("Problem with filter: Variational Shape Approximation"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find(message), std::string::npos) << "expected '" << message << "' in\n" << run.output;
}

/// Runs the filter on `mesh` with ProxyNum = k, every other parameter at its default.
ServerRun RunWithProxyNum(const fs::path &dir, const fs::path &mesh, const std::string &k)
{
    return RunServer(dir, "-i " + Quote(mesh.string()) + " -s " +
                              Quote(WriteVsaScript(dir, {{"ProxyNum", k}}).string()));
}
}  // namespace

/// A bad input: its name, its OFF text (empty: fandisk), ProxyNum, and the message expected.
struct BadInput
{
    const char *name;
    const char *off;
    const char *proxyNum;
    const char *message;
};
void PrintTo(const BadInput &bad, std::ostream *os) { *os << bad.name; }

const BadInput kBadInputs[] = {
    {"ProxyNumBelowOne", "", "0", "at least 1"},
    {"ProxyNumAboveFaceCount", "", "20000", "exceeds the number of faces (12946)"},
    {"PointCloud", "OFF\n4 0 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n", "1", "point cloud"},
    // Three triangles sharing the edge 0-1.
    {"NonManifoldEdge", "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n", "2",
     "non-manifold"},
    // Two triangles walking their shared edge 1-2 the same way.
    {"InconsistentOrientation", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 2 3\n", "1",
     "not consistently oriented"},
    {"NaNCoordinates", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\nnan 1 0\n3 0 1 2\n3 2 1 3\n", "1", "NaN"},
    {"EmptyMesh", "OFF\n0 0 0\n", "1", "The mesh is empty."},
};

class MeshLabServerBadInput : public testing::TestWithParam<BadInput> {};

TEST_P(MeshLabServerBadInput, FailsCleanlyWithItsMessage)
{
    const BadInput &bad = GetParam();
    const fs::path dir = WorkDir(std::string("bad_") + bad.name);
    const fs::path mesh = *bad.off ? WriteOff(dir, "input.off", bad.off) : fs::path(kFandisk);
    ExpectCleanFailure(RunWithProxyNum(dir, mesh, bad.proxyNum), bad.message);
}

INSTANTIATE_TEST_SUITE_P(MeshLabServer, MeshLabServerBadInput, testing::ValuesIn(kBadInputs),
                         [](const testing::TestParamInfo<BadInput> &info) { return std::string(info.param.name); });

namespace {
/// An extreme but finite input gives an output whose every coordinate is finite, saved by
/// meshlabserver and read back; returns its face count.
int ExpectFiniteOutput(const fs::path &dir, const fs::path &mesh, const std::map<std::string, std::string> &params)
{
    const fs::path out = dir / "out.ply";
    const ServerRun run = RunServer(dir, "-i " + Quote(mesh.string()) + " -s " +
                                             Quote(WriteVsaScript(dir, params).string()) + " -o " +
                                             Quote(out.string()) + " -l 1");
    TMesh m;
    EXPECT_EQ(run.exitCode, 0) << run.output;
    EXPECT_TRUE(Load(m, out)) << run.output;
    EXPECT_GT(m.FN(), 0) << run.output;
    for (const auto &v : m.vert) EXPECT_TRUE(vcg::tri::vsa::IsFinite(vcg::Point3d::Construct(v.cP()))) << run.output;
    return m.FN();
}
}  // namespace

// The fuzzing's findings (issue 32): a flat square far from the origin gave the grids a zero cell
// size (NaN cell indices), a tetrahedron near FLT_MAX infinite anchors. Both give a valid output.
TEST(MeshLabServerExtremeInput, FlatSquareFarFromTheOrigin)
{
    const fs::path dir = WorkDir("extreme_far_flat");
    const fs::path square = WriteOff(dir, "square.off",
                                     "OFF\n4 2 0\n0 0 1e12\n1 0 1e12\n1 1 1e12\n0 1 1e12\n3 0 1 2\n3 0 2 3\n");
    EXPECT_EQ(ExpectFiniteOutput(dir, square, {{"ProxyNum", "1"}}), 2);
}

TEST(MeshLabServerExtremeInput, TetrahedronNearTheFloatLimit)
{
    const fs::path dir = WorkDir("extreme_float_limit");
    const fs::path tetra = WriteOff(dir, "tetra.off", "OFF\n4 4 0\n0 0 0\n3e38 0 0\n0 3e38 0\n0 0 3e38\n"
                                                      "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
    // L2 and random seeding, anchors projected on the planes: the fuzzed prism's settings.
    EXPECT_EQ(ExpectFiniteOutput(dir, tetra, {{"ProxyNum", "4"}, {"Metric", "1"}, {"Init", "0"}}), 4);
}
