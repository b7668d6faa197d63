// Progress reports (vsa/progress.h): every long stage keeps calling back from deep inside its
// passes, with positions that never go back, on the calling thread only, and reporting changes
// no result.
#include "partition_test_helpers.h"

#include <vsa/approximate_shape.h>
#include <vsa/meshable_partition.h>
#include <vsa/parallel.h>
#include <vsa/progress.h>

#include <vcg/complex/algorithms/create/platonic.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <thread>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace {

using namespace vcg::tri::vsa;
using vsa_test::Bytes;
using vsa_test::Fingerprint;
using vsa_test::TMesh;

struct Report
{
    int position;
    std::string text;
    std::thread::id thread;
};
std::vector<Report> reports;

bool Record(const int position, const char *text)
{
    reports.push_back({position, text, std::this_thread::get_id()});
    return true;
}

/// Reports at every look at the clock, every pass of two chunks or more on `threads` threads (the
/// meshes here are small); restores the defaults when it goes. Counts of reports are checked on
/// one thread: on more, the calling thread ticks only for the chunks it takes itself, and how
/// many it takes depends on the load of the machine.
struct EveryTick
{
    explicit EveryTick(const int threads)
    {
        detail::ProgressSeconds() = 0;
        detail::ParallelMinItems() = 0;
#ifdef _OPENMP
        threadsBefore = omp_get_max_threads();
        omp_set_num_threads(threads);
#else
        (void)threads;
#endif
        reports.clear();
    }
    ~EveryTick()
    {
        detail::ProgressSeconds() = kProgressSeconds;
        detail::ParallelMinItems() = kParallelMinItems;
#ifdef _OPENMP
        omp_set_num_threads(threadsBefore);
#endif
    }
    int threadsBefore = 1;
};

/// The reports with `text`, in order.
std::vector<Report> Reports(const std::string &text)
{
    std::vector<Report> with;
    for (const Report &r : reports)
        if (r.text == text) with.push_back(r);
    return with;
}

/// Whether positions never decrease and stay within [0, 100], ending at 100.
bool Monotonic(const std::vector<Report> &rs)
{
    for (size_t i = 0; i < rs.size(); ++i)
        if (rs[i].position < 0 || rs[i].position > 100 || (i > 0 && rs[i].position < rs[i - 1].position))
            return false;
    return !rs.empty() && rs.back().position == 100;
}

void Sphere(TMesh &m)
{
    vcg::tri::Sphere(m, 5);  // 20480 faces, 5 chunks
    vcg::tri::UpdateBounding<TMesh>::Box(m);
}

/// Set-up, seeding and iterations as ApproximateShape runs them, with `cb` (or none).
ApproximationResult RunPartition(const TMesh &m, const ApproximationParam &param, vcg::CallBackPos *cb)
{
    ProgressStage setup(cb, "VSA: setting up");
    setup.Step(0, 100, detail::kSetupItems * m.FN());
    Approximation approximation(BuildIndexedMesh(m), param);
    setup.Done();
    approximation.Initialize(cb);
    approximation.Run(param.maxIterations, cb);
    return approximation.Result();
}

}  // namespace

TEST(Progress, EveryStageReportsFromWithinItsPassesAndChangesNothing)
{
    TMesh m;
    Sphere(m);
    for (SeedingMethod init : {SeedingMethod::Random, SeedingMethod::Farthest, SeedingMethod::Hierarchical}) {
        ApproximationParam param;
        param.proxyCount = 40;
        param.init = init;
        param.maxIterations = 10;
        param.tolerance = 0;
        const ApproximationResult quiet = RunPartition(m, param, nullptr);
        ApproximationResult reported;
        {
            EveryTick everyTick(3);
            reported = RunPartition(m, param, &Record);
        }
        EXPECT_TRUE(Fingerprint(reported) == Fingerprint(quiet)) << int(init);
        for (const Report &r : reports) EXPECT_EQ(r.thread, std::this_thread::get_id());
        {
            EveryTick everyTick(1);
            reported = RunPartition(m, param, &Record);
        }
        EXPECT_TRUE(Fingerprint(reported) == Fingerprint(quiet)) << int(init);
        const std::vector<Report> setup = Reports("VSA: setting up"), seeding = Reports("VSA: seeding proxies"),
                                  iterations = Reports("VSA: Lloyd iterations");
        EXPECT_EQ(setup.size() + seeding.size() + iterations.size(), reports.size());
        // Each pass over the 20480 faces ticks once per chunk of 4096 at least.
        EXPECT_GE(setup.size(), 20u) << int(init);
        EXPECT_GE(seeding.size(), 10u) << int(init);
        EXPECT_GE(iterations.size(), size_t(5 * reported.iterations)) << int(init);
        for (const auto *stage : {&setup, &seeding, &iterations}) EXPECT_TRUE(Monotonic(*stage)) << int(init);
        std::map<int, int> positions;  // the bar moves within the iterations, not only between them
        for (const Report &r : iterations) ++positions[r.position];
        EXPECT_GT(int(positions.size()), 2 * reported.iterations) << int(init);
    }
}

TEST(Progress, SeedingOnPatchesReportsThroughout)
{
    const IndexedMesh im = vsa_test::LoadCgalMesh("armadillo.off");
    const FaceGeometry g = ComputeFaceGeometry(im, false);
    const L21Metric metric(g);
    const SeedingGoal goal = vsa_test::PatchesGoal(100, 2);
    ASSERT_GT(detail::PatchFaces(im.FaceCount(), goal), 1);
    const auto seed = [&](vcg::CallBackPos *cb) {
        RegionState s;
        PartitionWorkspace<L21Metric> ws;
        SeedRandom random(5);
        SeedHierarchically(im, metric, g, s, goal, random, ws, cb);
        return Bytes(s.partition.faceRegion) + Bytes(s.partition.proxies) + Bytes(s.seeds) + Bytes(s.faceError);
    };
    const std::string quiet = seed(nullptr);
    std::string reported;
    {
        EveryTick everyTick(1);
        reported = seed(&Record);
    }
    EXPECT_TRUE(reported == quiet);
    EXPECT_TRUE(Monotonic(reports));
    EXPECT_GE(reports.size(), 30u);
    // Patches, rounds on them, then the faces: the positions pass through each part.
    std::map<int, int> positions;
    for (const Report &r : reports) ++positions[r.position];
    EXPECT_GE(positions.size(), 20u);
}

TEST(Progress, ApproximateShapeReportsSetupSeedingAndIterationsInOrder)
{
    TMesh in;
    Sphere(in);
    ShapeApproximationParam param;
    param.partition.proxyCount = 30;
    param.partition.maxIterations = 8;
    TMesh quietOut;
    const ShapeApproximationResult quiet = ApproximateShape(in, quietOut, param);
    ASSERT_TRUE(quiet.ok) << quiet.error;
    ShapeApproximationResult reported;
    TMesh out;
    {
        EveryTick everyTick(3);
        reported = ApproximateShape(in, out, param, &Record);
    }
    ASSERT_TRUE(reported.ok) << reported.error;
    EXPECT_TRUE(Fingerprint(reported.partition) == Fingerprint(quiet.partition));
    EXPECT_EQ(out.FN(), quietOut.FN());
    EXPECT_GT(reported.secondsSetup, 0);
    // Up to the end of the iterations (70%), the whole run's positions never go back.
    const char *order[] = {"VSA: setting up", "VSA: seeding proxies", "VSA: Lloyd iterations"};
    size_t stage = 0;
    int last = 0;
    for (const Report &r : reports) {
        if (std::find(std::begin(order), std::end(order), r.text) == std::end(order)) break;  // the meshable split
        while (stage < 3 && r.text != order[stage]) ++stage;
        ASSERT_LT(stage, 3u) << r.text << " after a later stage";
        EXPECT_GE(r.position, last);
        last = r.position;
    }
    EXPECT_EQ(stage, 2u);
    EXPECT_EQ(last, 70);
}

/// bull.off meets itself in 3 face pairs. At k = 1000 (hierarchical, seed 1, 30 iterations) the
/// meshable split's 1170 regions give an output that keeps them; the 1000 regions asked for give
/// a valid one, which is kept, and its meshing reports progress too. (If the split comes to give
/// bull a valid output, this test needs another case where it does not.) Here for the reports it
/// reads.
TEST(ApproximateShape, AnInvalidSplitKeepsTheRegionsAskedFor)
{
    TMesh bull, out;
    std::string error;
    ASSERT_TRUE(vsa_test::LoadMesh(bull, vsa_test::CgalMesh("bull.off"), &error)) << error;
    ShapeApproximationParam param;
    param.partition.proxyCount = 1000;
    param.partition.tolerance = 0;
    param.partition.randomSeed = 1;
    reports.clear();
    const ShapeApproximationResult r = ApproximateShape(bull, out, param, &Record);
    ASSERT_TRUE(r.ok) << r.error;
    ASSERT_TRUE(r.meshable.keptAsked) << r.meshable.Summary();
    EXPECT_GT(r.meshable.proxiesFinal, 1000);
    EXPECT_TRUE(r.meshing.validity.IsValid()) << r.meshing.validity.Summary();
    EXPECT_EQ(r.meshing.validity.selfIntersections, 0);
    EXPECT_EQ(int(r.partition.partition.proxies.size()), 1000);
    EXPECT_EQ(std::set<int>(r.meshing.faceRegion.begin(), r.meshing.faceRegion.end()).size(), 1000u);
    EXPECT_EQ(r.partition.energy, r.energyAsked);
    EXPECT_EQ(r.meshable.Summary().rfind("k kept at 1000", 0), 0u) << r.meshable.Summary();
    EXPECT_EQ(Reports("VSA meshing: done").size(), 2u);
}

/// The meshable split reports from within its trials, not only between rounds, and reporting
/// changes neither the splits nor the partition.
TEST(Progress, MeshableSplitReportsWithinItsTrials)
{
    const auto split = [](vcg::CallBackPos *cb, MeshablePartitionReport &report) {
        ApproximationParam param;
        param.proxyCount = 20;
        Approximation approximation(vsa_test::LoadCgalMesh("armadillo.off"), param);
        approximation.Initialize();
        approximation.Run(10);
        report = MakePartitionMeshable<vcg::Point3f>(approximation, MeshingParam(), MeshablePartitionParam(), cb);
        return Fingerprint(approximation.Result());
    };
    MeshablePartitionReport quietReport, report;
    const std::string quiet = split(nullptr, quietReport);
    std::string reported;
    {
        EveryTick everyTick(1);
        reported = split(&Record, report);
    }
    EXPECT_TRUE(reported == quiet);
    EXPECT_EQ(report.proxiesFinal, quietReport.proxiesFinal);
    ASSERT_GT(report.rounds, 0);
    EXPECT_TRUE(Monotonic(reports));
    // Each trial cuts, floods and triangulates every face: a report per 4096 faces at least.
    const size_t faces = vsa_test::LoadCgalMesh("armadillo.off").FaceCount();
    EXPECT_GE(reports.size(), size_t(report.rounds + 1) * (faces / kProgressItems));
    for (const Report &r : reports) EXPECT_EQ(r.text, "VSA: splitting regions that do not mesh as one polygon");
}

/// The final meshing reports from within its passes (the surface's set-up, the triangulation of
/// each cell), with texts of its own and positions that never go back, and reporting changes
/// neither the output nor the report.
TEST(Progress, MeshingReportsWithinItsPasses)
{
    ApproximationParam param;
    param.proxyCount = 40;
    Approximation approximation(vsa_test::LoadCgalMesh("armadillo.off"), param);
    approximation.Initialize();
    approximation.Run(10);
    const ApproximationResult partition = approximation.Result();
    TMesh quietOut, out;
    const MeshingReport quiet = BuildApproximatingMesh(approximation.Mesh(), partition.partition, MeshingParam(), quietOut);
    ASSERT_TRUE(quiet.ok) << quiet.error;
    MeshingReport report;
    {
        EveryTick everyTick(1);
        report = BuildApproximatingMesh(approximation.Mesh(), partition.partition, MeshingParam(), out, &Record);
    }
    ASSERT_TRUE(report.ok) << report.error;
    EXPECT_EQ(report.validity.Summary(), quiet.validity.Summary());
    EXPECT_EQ(report.faceRegion, quiet.faceRegion);
    ASSERT_EQ(out.VN(), quietOut.VN());
    for (int v = 0; v < out.VN(); ++v) EXPECT_EQ(out.vert[v].P(), quietOut.vert[v].P());
    EXPECT_TRUE(Monotonic(reports));
    for (const Report &r : reports) EXPECT_EQ(r.text.rfind("VSA meshing: ", 0), 0u) << r.text;
    // The set-up and the first pass each go over every face: a report per 4096 faces at least.
    const size_t faces = approximation.Mesh().FaceCount();
    EXPECT_GE(Reports("VSA meshing: cutting regions into discs").size(), faces / kProgressItems);
    EXPECT_GE(Reports("VSA meshing: anchors and triangulation").size(), faces / kProgressItems);
    EXPECT_EQ(reports.back().text, "VSA meshing: done");
}
