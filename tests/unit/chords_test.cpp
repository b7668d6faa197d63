// Tests of vsa/chords.h.
#include "meshing_fixtures.h"
#include "meshing_test_util.h"
#include "partition_test_helpers.h"
#include "test_meshes.h"

#include <vsa/chords.h>
#include <vsa/meshing.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <set>
#include <string>
#include <vector>

using namespace vcg::tri::vsa;
using namespace vsa_test;
using vcg::Point3d;

TEST(Chords, ChordThresholdOnAFlatDisc)
{
    TMesh disc;
    vsa_test::MakeHemisphere(disc, 4, 24, /*flat=*/true);
    const IndexedMesh im = BuildIndexedMesh(disc);
    const Partition one = vsa_test::PartitionByRule(im, 1, [](int) { return 0; });

    // The disc is exactly planar, so by default its outline is kept exactly, whatever the
    // threshold: a chord may not stray farther than the plane does (see chordErrorFactor).
    for (double threshold : {0.0, 0.2, 1e9}) {
        MeshingParam exact;
        exact.chordThreshold = threshold;
        MeshingRun run;
        Mesh(disc, one, exact, run);
        ExpectValidWithInputTopology(run);
        EXPECT_EQ(run.report.anchors, 24) << threshold;
    }

    // The paper's criterion alone. Threshold 0 keeps every bend of the border: each border
    // vertex becomes an anchor.
    MeshingParam param;
    param.chordErrorFactor = 0;
    param.chordThreshold = 0;
    MeshingRun fine;
    Mesh(disc, one, param, fine);
    ExpectValidWithInputTopology(fine);
    EXPECT_EQ(fine.report.anchors, 24);
    EXPECT_EQ(fine.out.FN(), 22);
    EXPECT_EQ(vsa_test::BorderLoopCount(fine.output), 1);
    EXPECT_EQ(fine.report.validity.selfIntersections, 0);
    EXPECT_NEAR(vsa_test::SurfaceArea(fine.output), vsa_test::SurfaceArea(im), 1e-6);

    // A huge threshold keeps the least a loop needs: one seed, the farthest point from it
    // (a closed chain is always split), and the farthest point from their chord.
    param.chordThreshold = 1e9;
    MeshingRun coarse;
    Mesh(disc, one, param, coarse);
    ExpectValidWithInputTopology(coarse);
    EXPECT_EQ(coarse.report.anchors, 3);
    EXPECT_EQ(coarse.report.loopSeedAnchors, 1);
    EXPECT_EQ(coarse.report.chordAnchors, 1);
    EXPECT_EQ(coarse.report.loopAnchors, 1);
    EXPECT_EQ(coarse.out.FN(), 1);

    // In between, the paper's criterion: fewer anchors for a larger threshold.
    int previous = std::numeric_limits<int>::max();
    for (double threshold : {0.01, 0.05, 0.1, 0.3}) {
        param.chordThreshold = threshold;
        MeshingRun run;
        Mesh(disc, one, param, run);
        ExpectValidWithInputTopology(run);
        EXPECT_LE(run.report.anchors, previous);
        previous = run.report.anchors;
    }
    EXPECT_LT(previous, 24);
    EXPECT_GT(previous, 3);
}

// A 10 x 1 strip, one region. Three of its corners are anchors (the loop's seed, then the
// farthest vertices); the chain around the fourth strays 10 / sqrt(101) = 0.995 from its chord
// of length sqrt(101), a ratio of 0.099: the paper's criterion cuts that corner off, and half
// the strip with it. The bound by the partition's own error keeps it. The strip is bent into
// z = A (2x/10 - 1)^2, whose plane error is 2A/3 (the proxy point sits at z = A/3), so the
// bound's scale shows: the long sides' chains stray A from their chords, more than 2A/3.
TEST(Chords, ChordErrorBoundKeepsTheCornersTheRegionsFit)
{
    const double bend = 0.01;
    TMesh strip;
    vsa_test::MakeQuadGrid(strip, 20, 2, [&](int i, int j) {
        const double t = 2 * (i / 20.0) - 1;
        return vcg::Point3f(0.5f * i, 0.5f * j, float(bend * t * t));
    });
    const IndexedMesh im = BuildIndexedMesh(strip);
    const Partition one = vsa_test::PartitionByRule(im, 1, [](int) { return 0; });
    ASSERT_NEAR(one.proxies[0].point[2], bend / 3, 1e-4);
    auto run = [&](double factor, MeshingRun &r) {
        MeshingParam param;
        param.chordErrorFactor = factor;
        Mesh(strip, one, param, r);
        ExpectValidWithInputTopology(r);
    };

    MeshingRun paperOnly, loose, corners, tight;
    run(0, paperOnly);
    EXPECT_EQ(paperOnly.report.anchors, 3);
    EXPECT_NEAR(vsa_test::SurfaceArea(paperOnly.output), 5, 0.01);
    // Bounds of 50 * 2A/3 = 0.33 and of 1000 * 2A/3 = 6.7, on either side of 0.995.
    run(1000, loose);
    EXPECT_EQ(loose.report.anchors, 3);
    run(50, corners);
    EXPECT_EQ(corners.report.anchors, 4);
    EXPECT_EQ(corners.out.FN(), 2);
    EXPECT_NEAR(vsa_test::SurfaceArea(corners.output), 10, 0.01);
    // The default bound, 2A/3: the long sides are also split at their middle, once.
    run(MeshingParam().chordErrorFactor, tight);
    ASSERT_EQ(tight.report.anchors, 6);
    std::set<std::pair<double, double>> corners2d;  // (x, y): z moves with the projection
    for (const Point3d &p : tight.output.positions) corners2d.insert({p[0], p[1]});
    EXPECT_EQ(corners2d, (std::set<std::pair<double, double>>{{0, 0}, {5, 0}, {10, 0}, {0, 1}, {5, 1}, {10, 1}}));
}

namespace {

/// A flat "C" in `c` (and `im`), its inner and outer halves as two regions.
Partition FlatCHalves(TMesh &c, IndexedMesh &im)
{
    vsa_test::MakeFlatC(c, 8, 60, M_PI / 3);
    im = BuildIndexedMesh(c);
    return vsa_test::PartitionByRule(im, 2, [&](int f) { return vsa_test::FaceCentroid(im, f).Norm() < 1.5 ? 0 : 1; });
}

}  // namespace

// Two coplanar regions, the inner and outer halves of a flat "C": the paper's criterion
// (sin 0 = 0) never splits the chain between them, whose chord then runs straight across the
// C's opening. The gap test must split it until the output stays on the surface. Repair
// rounds are off: they would catch this case's fold for other reasons, not every such case's.
TEST(Chords, ChordAcrossAGapIsSplit)
{
    TMesh c;
    IndexedMesh im;
    const Partition halves = FlatCHalves(c, im);
    auto farthestFromInput = [&](const MeshingRun &run) {
        std::vector<Point3d> samples;  // the output's vertices and face centroids
        for (const auto &t : run.output.faces) {
            for (int v : t) samples.push_back(run.output.positions[v]);
            const auto &P = run.output.positions;
            samples.push_back((P[t[0]] + P[t[1]] + P[t[2]]) / 3);
        }
        return vsa_test::MaxDistanceToSurface(samples, im);
    };

    MeshingParam param;
    param.repairRounds = 0;
    param.chordGapThreshold = 0;
    MeshingRun without;
    Mesh(c, halves, param, without);
    ASSERT_TRUE(without.report.ok);
    EXPECT_GT(farthestFromInput(without), 0.3);

    param.chordGapThreshold = MeshingParam().chordGapThreshold;
    MeshingRun with;
    Mesh(c, halves, param, with);
    ExpectValidWithInputTopology(with);
    EXPECT_GT(with.report.chordAnchors, without.report.chordAnchors);
    // Chords of the outer arc still bulge into the band by their sagitta; none crosses a gap.
    EXPECT_LT(farthestFromInput(with), 0.15);
    EXPECT_EQ(with.report.validity.selfIntersections, 0);
}

// The chains are subdivided on the threads, and those that need the gap test's grid wait for
// it to be built: the flat C's output must be the same on any number of threads.
TEST(Chords, ChordAcrossAGapIsSplitAlikeOnAnyNumberOfThreads)
{
    TMesh c;
    IndexedMesh im;
    const Partition halves = FlatCHalves(c, im);
    MeshingParam param;
    param.repairRounds = 0;
    const auto meshOn = [&](int threads, MeshingRun &run) {
        WithThreads(threads, [&] { return Mesh(c, halves, param, run), 0; });
    };
    MeshingRun one, without;
    meshOn(1, one);
    ExpectValidWithInputTopology(one);
    param.chordGapThreshold = 0;
    meshOn(1, without);
    param.chordGapThreshold = MeshingParam().chordGapThreshold;
    EXPECT_GT(one.report.chordAnchors, without.report.chordAnchors);  // the gap test split chains
    for (int threads : {2, 3}) {
        MeshingRun several;
        meshOn(threads, several);
        EXPECT_EQ(several.report.chordAnchors, one.report.chordAnchors) << threads;
        EXPECT_EQ(several.output.positions, one.output.positions) << threads;
        EXPECT_EQ(several.output.faces, one.output.faces) << threads;
    }
}

// Repair passes reuse the chord subdivision of the chains they did not change: the anchors
// must be those of a subdivision from scratch.
TEST(Chords, RememberedChordSubdivisionEqualsAFreshOne)
{
    RepairSequence r;
    MakeHemisphereRepairSequence(20, r);
    const MeshingSurface &s = r.surface;
    detail::ChainSubdivision remembered(s, r.partition.proxies, 0.2);
    const AnchorSet coarse = FreshAnchors(s, r.partition.proxies, 0.2);
    for (const std::vector<char> &required : r.required) {
        const AnchorSet expected = FreshAnchors(s, r.partition.proxies, 0.2, required);
        const AnchorSet anchors = SelectAnchors(s, remembered, required);
        EXPECT_GT(expected.Count(), required.empty() ? 0 : coarse.Count());
        EXPECT_GT(expected.chordSplits, 0);
        EXPECT_EQ(anchors.vertexOfAnchor, expected.vertexOfAnchor);
        EXPECT_EQ(anchors.chordSplits, expected.chordSplits);
    }
}
