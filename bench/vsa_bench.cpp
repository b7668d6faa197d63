// vsa-bench: times our VSA (ApproximateShape: partitioning, then meshing) on one mesh and
// prints one JSON line (bench/README.md).
//   vsa-bench --mesh FILE --k N --metric l21|l2 --init random|farthest|hierarchical
//             --iterations N --seed S [--target-error E] [--tolerance T] [--relaxations R]
//             [--teleport 0|1] [--anchor-threshold A] [--chord-gap G] [--chord-error F]
//             [--repair-rounds R] [--halving-rounds H] [--project-anchors 0|1] [--planar-polygons 0|1]
//             [--polygonal 0|1] [--out FILE] [--polygon-labels FILE]
// The tolerance defaults to 0 so that --iterations Lloyd iterations run (unless the partition
// cycles), like CGAL's run(N): per-iteration timings compare. --out writes the approximating
// mesh with each face coloured by its region (format from the extension: ply, off, obj).
// max_progress_gap_s is the longest the progress callback went unheard from the set-up's first
// report to the end of the pipeline (loading the file excluded), max_progress_gap_at where, and
// max_progress_gap_<stage>_s the longest within each stage (known by its reports' text; the gap
// up to a stage's first report is its own).
#include "off_file.h"
#include "output_quality.h"

#include <vsa/approximate_shape.h>
#include <vsa/approximation.h>
#include <vsa/meshable_partition.h>
#include <vsa/meshing.h>
#include <vsa/parallel.h>

#include <vcg/complex/complex.h>
#include <wrap/io_trimesh/export.h>
#include <wrap/io_trimesh/import.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace {

// Float coordinates like MeshLab's CMeshO, with a face colour for --out.
class BVertex;
class BFace;
struct BUsedTypes : public vcg::UsedTypes<vcg::Use<BVertex>::AsVertexType, vcg::Use<BFace>::AsFaceType> {};
class BVertex : public vcg::Vertex<BUsedTypes, vcg::vertex::Coord3f, vcg::vertex::Normal3f, vcg::vertex::BitFlags> {};
class BFace : public vcg::Face<BUsedTypes, vcg::face::VertexRef, vcg::face::Normal3f, vcg::face::Color4b,
                               vcg::face::BitFlags> {};
class BMesh : public vcg::tri::TriMesh<std::vector<BVertex>, std::vector<BFace>> {};

struct Options
{
    std::string mesh, out, polygonLabels, metric = "l21", init = "hierarchical";
    vcg::tri::vsa::ApproximationParam param;
    vcg::tri::vsa::MeshingParam meshing;
    vcg::tri::vsa::MeshablePartitionParam meshable;
};

/// "0" or "1" as a bool; anything else throws, which Parse reports as a bad value.
bool ParseFlag(const std::string &value)
{
    if (value != "0" && value != "1") throw std::invalid_argument("not 0 or 1");
    return value == "1";
}

/// Parses the command line into `o`; returns an error message, empty when all is well.
std::string Parse(int argc, char **argv, Options &o)
{
    using namespace vcg::tri::vsa;
    o.param.tolerance = 0;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (i + 1 >= argc) return "missing value after " + arg;
        const std::string value = argv[++i];
        try {
            if (arg == "--mesh") o.mesh = value;
            else if (arg == "--out") o.out = value;
            else if (arg == "--k") o.param.proxyCount = std::stoi(value);
            else if (arg == "--iterations") o.param.maxIterations = std::stoi(value);
            else if (arg == "--seed") o.param.randomSeed = std::stoull(value);
            else if (arg == "--target-error") o.param.targetError = std::stod(value);
            else if (arg == "--tolerance") o.param.tolerance = std::stod(value);
            else if (arg == "--relaxations") o.param.relaxations = std::stoi(value);
            else if (arg == "--teleport") o.param.teleport = ParseFlag(value);
            else if (arg == "--anchor-threshold") o.meshing.chordThreshold = std::stod(value);
            else if (arg == "--chord-gap") o.meshing.chordGapThreshold = std::stod(value);
            else if (arg == "--chord-error") o.meshing.chordErrorFactor = std::stod(value);
            else if (arg == "--repair-rounds") o.meshing.repairRounds = std::stoi(value);
            else if (arg == "--halving-rounds") o.meshing.halvingRounds = std::stoi(value);
            else if (arg == "--project-anchors") o.meshing.projectAnchors = ParseFlag(value);
            else if (arg == "--planar-polygons") o.meshing.planarPolygons = ParseFlag(value);
            else if (arg == "--polygonal") o.meshing.polygonal = ParseFlag(value);
            else if (arg == "--polygon-labels") o.polygonLabels = value;
            else if (arg == "--meshable") o.meshable.enabled = ParseFlag(value);
            else if (arg == "--max-proxy-factor") o.meshable.maxProxyFactor = std::stod(value);
            else if (arg == "--meshable-rounds") o.meshable.maxRounds = std::stoi(value);
            else if (arg == "--meshable-lloyd") o.meshable.lloydIterations = std::stoi(value);
            else if (arg == "--stray-factor") o.meshable.strayFactor = std::stod(value);
            else if (arg == "--metric") o.metric = value;
            else if (arg == "--init") o.init = value;
            else return "unknown option " + arg;
        } catch (const std::exception &) {
            return "bad value '" + value + "' for " + arg;
        }
    }
    if (o.mesh.empty()) return "--mesh FILE is required";
    if (o.metric == "l21") o.param.metric = MetricKind::L21;
    else if (o.metric == "l2") o.param.metric = MetricKind::L2;
    else return "--metric must be l21 or l2";
    if (o.init == "random") o.param.init = SeedingMethod::Random;
    else if (o.init == "farthest") o.param.init = SeedingMethod::Farthest;
    else if (o.init == "hierarchical") o.param.init = SeedingMethod::Hierarchical;
    else return "--init must be random, farthest or hierarchical";
    return {};
}

/// Wall-clock gaps between progress reports, counting the pipeline's end as one (issue 30: the
/// progress bar should move at least once a second): the largest per stage, and the largest of
/// all with the report that ended it.
struct ProgressGaps
{
    std::chrono::steady_clock::time_point last;
    std::string stage;
    std::vector<std::pair<std::string, double>> largestPerStage;
    double largest = 0;
    std::string where;

    void Mark(const std::string &what)
    {
        const auto now = std::chrono::steady_clock::now();
        const double gap = std::chrono::duration<double>(now - last).count();
        largestPerStage.back().second = std::max(largestPerStage.back().second, gap);
        if (gap > largest) {
            largest = gap;
            where = stage + ": " + what;
        }
        last = now;
    }

    /// Ends the current stage, if any, and starts `name`.
    void Start(const std::string &name)
    {
        if (!largestPerStage.empty()) Mark("end");
        Switch(name);
    }

    /// Starts `name`, whose first report has come: the gap up to it is its own.
    void Switch(const std::string &name)
    {
        if (largestPerStage.empty()) last = std::chrono::steady_clock::now();  // after loading
        stage = name;
        largestPerStage.emplace_back(name, 0.0);
    }
};
ProgressGaps progressGaps;

/// The stage of ApproximateShape a progress text belongs to.
std::string StageOf(const std::string &text)
{
    if (text.rfind("VSA meshing", 0) == 0) return "meshing";
    if (text == "VSA: setting up") return "setup";
    if (text == vcg::tri::vsa::detail::kSeedingText) return "seeding";
    if (text == "VSA: Lloyd iterations") return "iterations";
    return "meshable";  // "VSA: splitting regions that do not mesh as one polygon"
}

/// The peak resident set when each stage started: what the stages before it reached.
std::map<std::string, double> peakRssAtStart;

/// A vcg::CallBackPos that feeds progressGaps and notes the peak memory as each stage starts.
bool NoteProgress(const int, const char *text)
{
    const std::string stage = StageOf(text);
    if (stage != progressGaps.stage) {
        peakRssAtStart[stage] = vsa_bench::PeakRssMb();
        progressGaps.Switch(stage);
    }
    progressGaps.Mark(text);
    return true;
}

/// The approximation with each face coloured by its region.
bool WriteApproximation(BMesh &out, const std::vector<int> &faceRegion, int regionCount, const std::string &path)
{
    for (size_t f = 0; f < out.face.size(); ++f) out.face[f].C() = vcg::Color4b::Scatter(regionCount, faceRegion[f]);
    return vcg::tri::io::Exporter<BMesh>::Save(out, path.c_str(), vcg::tri::io::Mask::IOM_FACECOLOR) == 0;
}

}  // namespace

int main(int argc, char **argv)
{
    using namespace vcg::tri::vsa;
    Options o;
    vsa_bench::JsonLine json;
    json.Add("tool", "vsa");
    const std::string parseError = Parse(argc, argv, o);
    if (!parseError.empty()) {
        json.Add("error", parseError).Print();
        return 2;
    }
    json.Add("mesh", o.mesh);

    BMesh m;
    int mask = 0;
    std::string readError;
    if (vcg::tri::io::Importer<BMesh>::FileExtension(o.mesh, "off")) {  // as Importer::Open tells formats apart
        readError = vsa_bench::ReadOff(m, o.mesh, mask);
    } else {
        const int rc = vcg::tri::io::Importer<BMesh>::Open(m, o.mesh.c_str(), mask);
        if (rc != 0 && vcg::tri::io::Importer<BMesh>::ErrorCritical(rc))
            readError = vcg::tri::io::Importer<BMesh>::ErrorMsg(rc);
    }
    if (!readError.empty()) {
        json.Add("error", "cannot read mesh: " + readError).Print();
        return 1;
    }
    json.Add("faces", m.fn).Add("k", o.param.proxyCount).Add("metric", o.metric).Add("init", o.init);
    const double rssAfterLoadMb = vsa_bench::CurrentRssMb();

    try {
        ShapeApproximationParam param;
        param.partition = o.param;
        param.meshable = o.meshable;
        param.meshing = o.meshing;
        BMesh output;
        // The product's whole pipeline, as the plugin and pymeshlab run it.
        const ShapeApproximationResult result = ApproximateShape(m, output, param, &NoteProgress);
        progressGaps.Start("measuring");
        // Before the measuring below allocates its own copies and samples.
        const double peakRssMb = vsa_bench::PeakRssMb();
        if (!result.ok && result.partition.partition.faceRegion.empty()) {  // refused, or failed before meshing
            json.Add("error", result.error).Print();
            return 1;
        }
        const ApproximationResult &partition = result.partition;
        const MeshingReport &meshing = result.meshing;
        const MeshablePartitionReport &meshable = result.meshable;
        const double tSetup = result.secondsSetup, tSeed = result.secondsSeeding, tIterations = result.secondsIterations;
        const double tMeshable = result.secondsMeshable, tMesh = result.secondsMeshable + result.secondsMeshing;
        const int iterations = partition.iterations;
        const int faces = m.FN();
        const auto peakAt = [&](const char *stage) {
            const auto found = peakRssAtStart.find(stage);
            return found != peakRssAtStart.end() ? found->second : peakRssMb;
        };
        json.Add("t_seed_s", tSeed)
            .Add("t_iterations_s", tIterations)
            .Add("iterations_run", iterations)
            .Add("t_mesh_s", tMesh)
            .Add("t_meshable_s", tMeshable)
            .Add("t_total_s", tSetup + tSeed + tIterations + tMesh)
            .Add("energy", partition.energy)
            .Add("energy_asked", result.energyAsked)
            .Add("peak_rss_mb", peakRssMb)
            .Add("rss_after_load_mb", rssAfterLoadMb)
            .Add("peak_rss_partition_mb", peakAt("meshable"))
            .Add("peak_rss_meshable_mb", peakAt("meshing"))
            .Add("threads", vcg::tri::vsa::MaxThreads())
            .Add("seed", o.param.randomSeed)
            .Add("iterations", o.param.maxIterations)
            .Add("proxies", partition.proxyCount)
            .Add("t_setup_s", tSetup)
            .Add("us_per_face_iter", iterations > 0 ? 1e6 * tIterations / (double(faces) * iterations) : 0.0)
            .Add("reference_energy", partition.referenceEnergy)
            .Add("max_progress_gap_s", progressGaps.largest)
            .Add("max_progress_gap_at", progressGaps.where);
        for (const auto &stage : progressGaps.largestPerStage)
            if (stage.first != "measuring") json.Add("max_progress_gap_" + stage.first + "_s", stage.second);
        if (o.param.targetError > 0) json.Add("target_error", o.param.targetError);
        if (!meshing.ok) {
            json.Add("valid_output", false).Add("reason", meshing.error).Print();
            return 0;
        }
        json.Add("valid_output", meshing.validity.IsValid())
            .Add("anchors", meshing.anchors)
            .Add("regions_fallback", meshing.regionsByEarClipping + meshing.regionsWithSteinerVertex +
                                         meshing.regionsKeptAsInput)
            .Add("regions_kept_as_input", meshing.regionsKeptAsInput)
            .Add("mesh_passes", meshing.passes)
            .Add("mesh_output_pass", meshing.outputRepairRound + 1)
            .Add("halving_rounds", meshing.outputHalvingRound)
            .Add("cells_halved", meshing.cellsHalved)
            .Add("carving_rounds", meshing.outputCarvingRound)
            .Add("pieces_carved", meshing.piecesCarved)
            .Add("close_pairs", meshing.closePairs)
            .Add("regions_final", meshable.proxiesFinal)
            .Add("meshable_rounds", meshable.rounds)
            .Add("regions_left", meshable.regionsLeft)
            .Add("splits_strays", meshable.splits[int(RegionFault::Strays)])
            .Add("splits_intersects", meshable.splits[int(RegionFault::Intersects)])
            .Add("splits_folds", meshable.splits[int(RegionFault::Folds)])
            .Add("splits_faces_away", meshable.splits[int(RegionFault::FacesAway)])
            .Add("splits_not_disc", meshable.splits[int(RegionFault::NotDisc)])
            .Add("kept_asked", meshable.keptAsked)
            .Add("collapsed_edges", result.collapsedEdges);
        const int regionsOut = int(std::set<int>(meshing.faceRegion.begin(), meshing.faceRegion.end()).size());
        const vsa_bench::PolygonLabels polygons = vsa_bench::AddOutputQualityKeys(json, m, output, regionsOut);
        if (!o.out.empty() && !WriteApproximation(output, meshing.faceRegion, partition.proxyCount, o.out)) {
            json.Add("error", "cannot write " + o.out).Print();
            return 1;
        }
        if (!o.polygonLabels.empty() && !vsa_bench::WritePolygonLabels(o.polygonLabels, polygons)) {
            json.Add("error", "cannot write " + o.polygonLabels).Print();
            return 1;
        }
    } catch (const std::exception &e) {
        json.Add("error", e.what()).Print();
        return 1;
    }
    json.Print();
    return 0;
}
