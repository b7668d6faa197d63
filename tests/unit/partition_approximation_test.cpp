// The Approximation class and the one-shot function: exact answers on shapes with known
// partitions, reproducibility, the Lloyd loop's guarantees, odd inputs, region operations.
#include "partition_test_helpers.h"

#include <vsa/approximation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <set>
#include <tuple>

using namespace vcg::tri::vsa;
using vcg::Point3d;
using vsa_test::TMesh;

namespace {

ApproximationParam Params(int k, MetricKind metric, SeedingMethod init, uint64_t seed)
{
    ApproximationParam p;
    p.proxyCount = k;
    p.metric = metric;
    p.init = init;
    p.randomSeed = seed;
    return p;
}

/// Each of the six regions is exactly one side of the cube.
void ExpectOneRegionPerSide(const IndexedMesh &im, const ApproximationResult &r)
{
    ASSERT_TRUE(r.ok) << r.error;
    ASSERT_EQ(r.proxyCount, 6);
    std::vector<int> sideOfRegion(6, -1);
    for (int f = 0; f < im.FaceCount(); ++f) {
        const int side = vsa_test::CubeSide(im, f), region = r.partition.faceRegion[f];
        if (sideOfRegion[region] < 0) sideOfRegion[region] = side;
        ASSERT_EQ(sideOfRegion[region], side) << "region " << region << " spans two sides";
    }
    EXPECT_EQ(std::set<int>(sideOfRegion.begin(), sideOfRegion.end()).size(), 6u);
    EXPECT_LT(r.energy, 1e-12);
}

}  // namespace

TEST(PartitionApproximation, CubeGetsOneRegionPerSideFromEverySeedingUnderBothMetrics)
{
    TMesh m;
    vsa_test::MakeTessellatedCube(m, 5);
    const IndexedMesh im = BuildIndexedMesh(m);
    for (MetricKind metric : {MetricKind::L21, MetricKind::L2})
        for (SeedingMethod init : {SeedingMethod::Farthest, SeedingMethod::Hierarchical, SeedingMethod::Random})
            for (uint64_t seed : {1u, 2u, 3u, 42u, 1234u}) {
                SCOPED_TRACE(testing::Message()
                             << "metric " << int(metric) << " init " << int(init) << " seed " << seed);
                ApproximationParam p = Params(6, metric, init, seed);
                // Random seeds can put two proxies on one side and none on another; only
                // teleporting a proxy gets Lloyd out of that minimum.
                p.teleport = init == SeedingMethod::Random;
                ExpectOneRegionPerSide(im, Approximate(im, p));
            }
}

TEST(PartitionApproximation, FoldedSheetUnderL2GetsOneRegionPerPlane)
{
    TMesh m;
    vsa_test::MakeFoldedSheet(m, 6);
    const IndexedMesh im = BuildIndexedMesh(m);
    for (SeedingMethod init : {SeedingMethod::Farthest, SeedingMethod::Hierarchical})
        for (uint64_t seed : {1u, 2u, 3u, 42u, 1234u}) {
            SCOPED_TRACE(testing::Message() << "init " << int(init) << " seed " << seed);
            const ApproximationResult r = Approximate(im, Params(2, MetricKind::L2, init, seed));
            ASSERT_TRUE(r.ok) << r.error;
            for (int f = 0; f < im.FaceCount(); ++f) {
                const bool onFloor = im.positions[im.faces[f][0]][2] == 0 && im.positions[im.faces[f][1]][2] == 0 &&
                                     im.positions[im.faces[f][2]][2] == 0;
                ASSERT_EQ(r.partition.faceRegion[f], r.partition.faceRegion[onFloor ? 0 : im.FaceCount() - 1]);
                ASSERT_NE(r.partition.faceRegion[0], r.partition.faceRegion[im.FaceCount() - 1]);
            }
            EXPECT_LT(r.energy, 1e-20);
        }
}

TEST(PartitionApproximation, SeedingFindsTheFlatPiecesOfACadModel)
{
    // blade.off is mostly planar pieces: 100 proxies fit it almost exactly when the seeding
    // puts them where the error is (CGAL 5.5: incremental 4.6e-5, hierarchical 0.36, random 1.8).
    const IndexedMesh im = vsa_test::LoadCgalMesh("blade.off");
    for (SeedingMethod init : {SeedingMethod::Farthest, SeedingMethod::Hierarchical}) {
        const ApproximationResult r = Approximate(im, Params(100, MetricKind::L21, init, 1));
        ASSERT_TRUE(r.ok) << r.error;
        EXPECT_LT(r.energy, 1e-4) << "init " << int(init);
        EXPECT_EQ(vsa_test::CheckPartition(im, r.partition.faceRegion, 100), "");
    }
}

TEST(PartitionApproximation, HierarchicalSeedingEndsNoHigherThanRandom)
{
    // The seeding's energy after 30 plain Lloyd iterations (no teleports), summed over seeds 1-4:
    // hierarchical against random. On the CAD model random seeds leave regions across creases
    // that Lloyd cannot move (measured: 0.06 of random's); on the smooth armadillo the two end
    // close (0.98), and hierarchical must not end above.
    for (const auto &c : {std::make_tuple("fandisk.off", 50, 0.25), std::make_tuple("armadillo.off", 100, 1.0)}) {
        const IndexedMesh im = vsa_test::LoadCgalMesh(std::get<0>(c));
        double hierarchical = 0, random = 0;
        for (uint64_t seed : {1u, 2u, 3u, 4u}) {
            for (SeedingMethod init : {SeedingMethod::Hierarchical, SeedingMethod::Random}) {
                ApproximationParam p = Params(std::get<1>(c), MetricKind::L21, init, seed);
                p.maxIterations = 30;
                p.tolerance = 0;
                p.teleport = false;
                const ApproximationResult r = Approximate(im, p);
                ASSERT_TRUE(r.ok) << r.error;
                (init == SeedingMethod::Hierarchical ? hierarchical : random) += r.energy;
            }
        }
        EXPECT_LE(hierarchical, std::get<2>(c) * random) << std::get<0>(c);
    }
}

TEST(PartitionApproximation, EveryFaceLabelledAndEveryRegionConnected)
{
    const IndexedMesh im = vsa_test::LoadCgalMesh("fandisk.off");
    for (SeedingMethod init : {SeedingMethod::Random, SeedingMethod::Farthest, SeedingMethod::Hierarchical})
        for (MetricKind metric : {MetricKind::L21, MetricKind::L2}) {
            const ApproximationResult r = Approximate(im, Params(80, metric, init, 5));
            ASSERT_TRUE(r.ok) << r.error;
            EXPECT_EQ(r.proxyCount, 80);
            EXPECT_EQ(r.partition.proxies.size(), 80u);
            EXPECT_EQ(vsa_test::CheckPartition(im, r.partition.faceRegion, 80), "");
            for (const Proxy &p : r.partition.proxies) EXPECT_NEAR(p.normal.Norm(), 1.0, 1e-12);
        }
}

TEST(PartitionApproximation, SameSeedIsBitIdenticalAndAnotherSeedDiffers)
{
    const IndexedMesh im = vsa_test::LoadCgalMesh("fandisk.off");
    for (SeedingMethod init : {SeedingMethod::Random, SeedingMethod::Farthest, SeedingMethod::Hierarchical}) {
        const ApproximationResult a = Approximate(im, Params(50, MetricKind::L21, init, 7));
        const ApproximationResult b = Approximate(im, Params(50, MetricKind::L21, init, 7));
        const ApproximationResult c = Approximate(im, Params(50, MetricKind::L21, init, 8));
        ASSERT_TRUE(a.ok && b.ok && c.ok);
        EXPECT_EQ(a.partition.faceRegion, b.partition.faceRegion);
        ASSERT_EQ(a.partition.proxies.size(), b.partition.proxies.size());
        for (size_t r = 0; r < a.partition.proxies.size(); ++r) {
            EXPECT_EQ(a.partition.proxies[r].point, b.partition.proxies[r].point);
            EXPECT_EQ(a.partition.proxies[r].normal, b.partition.proxies[r].normal);
        }
        EXPECT_EQ(a.regionEnergy, b.regionEnergy);
        EXPECT_EQ(a.energyPerIteration, b.energyPerIteration);
        EXPECT_NE(a.partition.faceRegion, c.partition.faceRegion);
    }
}

TEST(PartitionApproximation, ResultIsNeverWorseThanAnyIteration)
{
    const IndexedMesh im = vsa_test::LoadCgalMesh("fandisk.off");
    for (MetricKind metric : {MetricKind::L21, MetricKind::L2}) {
        ApproximationParam p = Params(40, metric, SeedingMethod::Random, 3);
        p.tolerance = 0;  // run them all, unless the partition cycles
        const ApproximationResult r = Approximate(im, p);
        ASSERT_TRUE(r.ok);
        ASSERT_FALSE(r.energyPerIteration.empty());
        EXPECT_EQ(int(r.energyPerIteration.size()), r.iterations);
        for (double e : r.energyPerIteration) EXPECT_LE(r.energy, e);
        // The energy reported is the sum of the face errors against the returned proxies.
        const FaceGeometry g = ComputeFaceGeometry(im, metric == MetricKind::L2);
        double sum = 0;
        for (int f = 0; f < im.FaceCount(); ++f) {
            const Proxy &proxy = r.partition.proxies[r.partition.faceRegion[f]];
            sum += metric == MetricKind::L2 ? L2Metric(g).Error(f, proxy) : L21Metric(g).Error(f, proxy);
        }
        EXPECT_NEAR(r.energy, sum, 1e-12 * sum);
    }
}

TEST(PartitionApproximation, LloydStopsOnTolerance)
{
    const IndexedMesh im = vsa_test::LoadCgalMesh("fandisk.off");
    ApproximationParam p = Params(30, MetricKind::L21, SeedingMethod::Random, 1);
    p.tolerance = 0.05;
    p.maxIterations = 100;
    p.teleport = false;  // it would go on after converging
    p.relaxations = 0;   // straight from random seeds: several iterations before 5%
    const ApproximationResult r = Approximate(im, p);
    ASSERT_TRUE(r.ok);
    ASSERT_GE(r.iterations, 2);
    EXPECT_LT(r.iterations, 100);
    const double previous = r.energyPerIteration[r.iterations - 2], last = r.energyPerIteration.back();
    EXPECT_LE(std::abs(previous - last), 0.05 * previous);
}

TEST(PartitionApproximation, OpenPatchWithBorder)
{
    // A planar grid: one proxy fits exactly; with more, every region is still exact.
    TMesh m;
    vsa_test::MakePlanarGrid(m, 8, vcg::Point3f(0, 0, 0), vcg::Point3f(1, 0, 0), vcg::Point3f(0, 1, 0));
    const IndexedMesh im = BuildIndexedMesh(m);
    for (int k : {1, 5}) {
        const ApproximationResult r = Approximate(im, Params(k, MetricKind::L2, SeedingMethod::Hierarchical, 1));
        ASSERT_TRUE(r.ok) << r.error;
        EXPECT_EQ(r.proxyCount, k);
        EXPECT_EQ(vsa_test::CheckPartition(im, r.partition.faceRegion, k), "");
        EXPECT_LT(r.energy, 1e-20);
        for (const Proxy &p : r.partition.proxies) EXPECT_NEAR(p.normal * Point3d(0, 0, 1), 1.0, 1e-12);
    }
}

TEST(PartitionApproximation, SeveralComponentsRaiseTheProxyCount)
{
    TMesh m;
    vsa_test::MakeCubeRow(m, 3, 2);
    const IndexedMesh im = BuildIndexedMesh(m);
    ASSERT_EQ(im.componentCount, 3);
    for (SeedingMethod init : {SeedingMethod::Random, SeedingMethod::Farthest, SeedingMethod::Hierarchical}) {
        const ApproximationResult raised = Approximate(im, Params(1, MetricKind::L21, init, 4));
        ASSERT_TRUE(raised.ok) << raised.error;
        EXPECT_EQ(raised.proxyCount, 3);
        ASSERT_FALSE(raised.messages.empty());
        EXPECT_NE(raised.messages.front().find("raised from 1 to 3"), std::string::npos) << raised.messages.front();
        for (int f = 0; f < im.FaceCount(); ++f) EXPECT_EQ(raised.partition.faceRegion[f], im.component[f]);

        // 18 = six sides on each of the three cubes, whatever the seeding.
        ApproximationParam p = Params(18, MetricKind::L21, init, 4);
        p.teleport = true;
        const ApproximationResult sides = Approximate(im, p);
        ASSERT_TRUE(sides.ok);
        EXPECT_EQ(vsa_test::CheckPartition(im, sides.partition.faceRegion, 18), "");
        EXPECT_LT(sides.energy, 1e-12);
    }
}

TEST(PartitionApproximation, SingleTriangleAndOneProxyPerFace)
{
    TMesh triangle;
    vsa_test::BuildFromLists(triangle, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
    for (SeedingMethod init : {SeedingMethod::Random, SeedingMethod::Farthest, SeedingMethod::Hierarchical}) {
        const ApproximationResult r = Approximate(triangle, Params(1, MetricKind::L2, init, 0));
        ASSERT_TRUE(r.ok) << r.error;
        EXPECT_EQ(r.partition.faceRegion, std::vector<int>{0});
        EXPECT_EQ(r.energy, 0);
        EXPECT_NEAR(r.partition.proxies[0].normal * Point3d(0, 0, 1), 1.0, 1e-15);
    }

    TMesh cube;
    vsa_test::MakeTessellatedCube(cube, 2);
    const IndexedMesh im = BuildIndexedMesh(cube);
    for (SeedingMethod init : {SeedingMethod::Random, SeedingMethod::Farthest, SeedingMethod::Hierarchical}) {
        const ApproximationResult r = Approximate(im, Params(im.FaceCount(), MetricKind::L21, init, 2));
        ASSERT_TRUE(r.ok) << r.error;
        EXPECT_EQ(std::set<int>(r.partition.faceRegion.begin(), r.partition.faceRegion.end()).size(),
                  size_t(im.FaceCount()));
        EXPECT_EQ(r.energy, 0);
    }
}

TEST(PartitionApproximation, BadInputGetsAClearError)
{
    TMesh cube;
    vsa_test::MakeTessellatedCube(cube, 1);  // 12 faces
    ApproximationResult r = Approximate(cube, Params(13, MetricKind::L21, SeedingMethod::Farthest, 0));
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("exceeds the number of faces (12)"), std::string::npos) << r.error;
    r = Approximate(cube, Params(0, MetricKind::L21, SeedingMethod::Farthest, 0));
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("at least 1"), std::string::npos) << r.error;

    TMesh empty;
    r = Approximate(empty, Params(1, MetricKind::L21, SeedingMethod::Random, 0));
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("no faces"), std::string::npos) << r.error;

    cube.vert[0].P()[1] = std::numeric_limits<float>::quiet_NaN();
    r = Approximate(cube, Params(2, MetricKind::L21, SeedingMethod::Random, 0));
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("NaN"), std::string::npos) << r.error;

    // The stepwise class throws the same messages, and refuses calls out of order.
    TMesh good;
    vsa_test::MakeTessellatedCube(good, 1);
    EXPECT_THROW(Approximation(good, Params(13, MetricKind::L2, SeedingMethod::Random, 0)), std::invalid_argument);
    Approximation a(good, Params(2, MetricKind::L2, SeedingMethod::Random, 0));
    EXPECT_THROW(a.Run(3), std::logic_error);
    a.Initialize();
    EXPECT_THROW(a.Merge(0, 0), std::invalid_argument);
    EXPECT_THROW(a.Split(5), std::invalid_argument);
}

TEST(PartitionApproximation, DegenerateAndNonManifoldInputStillPartitions)
{
    // A "book" of three triangles on one edge (cut there into three components), and a
    // zero-area triangle: k is raised to 4 components, nothing is NaN.
    TMesh m;
    vsa_test::BuildFromLists(m,
                             {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {5, 5, 5}, {6, 6, 6}, {7, 7, 7}},
                             {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {5, 6, 7}});
    for (MetricKind metric : {MetricKind::L21, MetricKind::L2}) {
        const ApproximationResult r = Approximate(m, Params(2, metric, SeedingMethod::Farthest, 0));
        ASSERT_TRUE(r.ok) << r.error;
        EXPECT_EQ(r.proxyCount, 4);
        EXPECT_EQ(r.energy, r.energy);
        for (const Proxy &p : r.partition.proxies) EXPECT_NEAR(p.normal.Norm(), 1.0, 1e-12);
    }
}

TEST(PartitionApproximation, TargetErrorAddsProxiesUntilReached)
{
    const IndexedMesh im = vsa_test::LoadCgalMesh("fandisk.off");
    for (SeedingMethod init : {SeedingMethod::Random, SeedingMethod::Farthest, SeedingMethod::Hierarchical}) {
        ApproximationParam p = Params(0, MetricKind::L21, init, 1);  // proxyCount unused
        p.targetError = 0.01;
        const ApproximationResult r = Approximate(im, p);
        ASSERT_TRUE(r.ok) << r.error;
        EXPECT_LE(r.energy, 0.01 * r.referenceEnergy);
        EXPECT_GT(r.proxyCount, 1);
        EXPECT_EQ(vsa_test::CheckPartition(im, r.partition.faceRegion, r.proxyCount), "");
    }
    // Farthest adds one proxy at a time: one fewer would miss the target (before iterating).
    ApproximationParam p = Params(0, MetricKind::L21, SeedingMethod::Farthest, 1);
    p.targetError = 0.02;
    Approximation a(im, p);
    a.Initialize();
    EXPECT_LE(a.Energy(), 0.02 * a.ReferenceEnergy());
    EXPECT_GT(a.ProxyCount(), 2);
}

TEST(PartitionApproximation, RegionOperations)
{
    const IndexedMesh im = vsa_test::LoadCgalMesh("fandisk.off");
    Approximation a(im, Params(20, MetricKind::L21, SeedingMethod::Hierarchical, 1));
    a.Initialize();
    a.Run(10);
    const double converged = a.Energy();

    // AddProxy: at the worst face, energy down.
    const int added = a.AddProxy();
    EXPECT_EQ(added, 20);
    EXPECT_EQ(a.ProxyCount(), 21);
    EXPECT_LT(a.Energy(), converged);
    a.Run(10);
    EXPECT_EQ(vsa_test::CheckPartition(im, a.CurrentPartition().faceRegion, 21), "");

    // Merge: two adjacent regions into the lower index; energy up by what is returned.
    int ra = -1, rb = -1;
    for (int f = 0; f < im.FaceCount() && ra < 0; ++f)
        for (int g : im.neighbors[f])
            if (g >= 0 && a.CurrentPartition().faceRegion[g] != a.CurrentPartition().faceRegion[f]) {
                ra = a.CurrentPartition().faceRegion[f];
                rb = a.CurrentPartition().faceRegion[g];
                break;
            }
    const double beforeMerge = a.Energy();
    const double increase = a.Merge(ra, rb);
    EXPECT_EQ(a.ProxyCount(), 20);
    EXPECT_GE(increase, -1e-12);
    EXPECT_NEAR(a.Energy(), beforeMerge + increase, 1e-12);
    EXPECT_EQ(vsa_test::CheckPartition(im, a.CurrentPartition().faceRegion, 20), "");

    // Split: the worst region in two, both connected, energy down.
    const auto &energies = a.RegionEnergies();
    const int worst = int(std::max_element(energies.begin(), energies.end()) - energies.begin());
    const double beforeSplit = a.Energy();
    EXPECT_EQ(a.Split(worst), 20);
    EXPECT_LT(a.Energy(), beforeSplit);
    EXPECT_EQ(vsa_test::CheckPartition(im, a.CurrentPartition().faceRegion, 21), "");

    // Non-adjacent regions do not merge.
    std::vector<std::set<int>> adjacent(a.ProxyCount());
    for (int f = 0; f < im.FaceCount(); ++f)
        for (int g : im.neighbors[f])
            if (g >= 0) adjacent[a.CurrentPartition().faceRegion[f]].insert(a.CurrentPartition().faceRegion[g]);
    for (int r = 1; r < a.ProxyCount(); ++r)
        if (!adjacent[0].count(r)) {
            EXPECT_THROW(a.Merge(0, r), std::invalid_argument);
            break;
        }
}

/// A flat square frame (a ring: the 12 x 12 grid of [-1,1]^2 without its middle 6 x 6 quads)
/// with one corner vertex raised, so that the frame's proxy is tilted a little off the flat
/// faces' plane, as a ring region of a CAD part is (the gear's faces beside their bore).
TEST(PartitionApproximation, SplitByDistanceCutsAFlatRingInHalves)
{
    std::vector<vcg::Point3f> coords;
    std::vector<vcg::Point3i> tris;
    const int n = 12;
    auto at = [&](int i, int j) { return j * (n + 1) + i; };
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            coords.emplace_back(-1.f + 2.f * i / n, -1.f + 2.f * j / n, i == 0 && j == 0 ? 0.2f : 0.f);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            if (i < 3 || i >= 9 || j < 3 || j >= 9) {
                tris.emplace_back(at(i, j), at(i + 1, j), at(i + 1, j + 1));
                tris.emplace_back(at(i, j), at(i + 1, j + 1), at(i, j + 1));
            }
    TMesh m;
    vsa_test::BuildFromLists(m, coords, tris);
    const IndexedMesh im = BuildIndexedMesh(m);
    ASSERT_EQ(im.FaceCount(), 216);
    const auto centroid = [&](int f) {
        return (im.positions[im.faces[f][0]] + im.positions[im.faces[f][1]] + im.positions[im.faces[f][2]]) / 3.0;
    };
    for (SplitKind kind : {SplitKind::ByFit, SplitKind::ByDistance}) {
        Approximation a(im, Params(1, MetricKind::L21, SeedingMethod::Hierarchical, 1));
        a.Initialize();
        const int seed = a.SeedFaces()[0];
        int far = -1;  // the face farthest from the seed, across the ring
        for (int f = 0; f < im.FaceCount(); ++f)
            if (far < 0 || (centroid(f) - centroid(seed)).Norm() > (centroid(far) - centroid(seed)).Norm()) far = f;
        ASSERT_EQ(a.Split(0, far, kind), 1);
        const std::vector<int> &label = a.CurrentPartition().faceRegion;
        EXPECT_EQ(vsa_test::CheckPartition(im, label, 2), "");
        const int added = int(std::count(label.begin(), label.end(), 1));
        if (kind == SplitKind::ByFit) {
            // The new proxy, the plane of a flat face, fits every flat face exactly and wins them.
            EXPECT_TRUE(added < 10 || added > 206) << added;
            continue;
        }
        // Each face to the nearer seed: two halves of the ring, each a C of about 108 faces.
        EXPECT_EQ(label[seed], 0);
        EXPECT_EQ(label[far], 1);
        EXPECT_GE(added, 90);
        EXPECT_LE(added, 126);
    }
}

TEST(PartitionApproximation, SplitEachIsSplitAfterSplit)
{
    // Several regions split at once, with one pass over the faces and on any number of threads,
    // end as split one at a time: regions, proxies, errors and energies to the bit (sums over a
    // region's faces keep the chunks of a sum over every face, see SumByKeyOfListed). Region 3
    // and the regions around it: neighbours split side by side on two threads, each flood
    // walled off from the other's faces.
    const IndexedMesh im = vsa_test::LoadCgalMesh("armadillo.off");
    auto converged = [&] {
        Approximation a(im, Params(30, MetricKind::L21, SeedingMethod::Hierarchical, 2));
        a.Initialize();
        a.Run(5);
        return a;
    };
    Approximation oneByOne = converged();
    const std::vector<int> &label = oneByOne.CurrentPartition().faceRegion;
    std::vector<int> regions = {3};
    for (int f = 0; f < im.FaceCount(); ++f)
        for (int g : im.neighbors[f])
            if (label[f] == 3 && g >= 0 && label[g] != 3 &&
                std::find(regions.begin(), regions.end(), label[g]) == regions.end())
                regions.push_back(label[g]);
    ASSERT_GE(regions.size(), 3u);
    std::vector<int> faces(regions.size(), -1);  // the second region at its worst face
    for (size_t i = 0; i < regions.size(); ++i)
        if (i != 1)
            for (int f = im.FaceCount() - 1; f >= 0 && faces[i] < 0; --f)
                if (label[f] == regions[i] && f != oneByOne.SeedFaces()[regions[i]]) faces[i] = f;
    const int count = 30 + int(regions.size());
    for (size_t i = 0; i < regions.size(); ++i) EXPECT_EQ(oneByOne.Split(regions[i], faces[i]), 30 + int(i));
    const ApproximationResult b = oneByOne.Result();
    for (int threads : {1, 2, 3}) {
        Approximation each = converged();
        vsa_test::WithThreads(threads, [&] {
            each.SplitEach(regions, faces);
            return 0;
        });
        const ApproximationResult a = each.Result();
        ASSERT_EQ(a.proxyCount, count) << threads << " threads";
        EXPECT_TRUE(a.partition.faceRegion == b.partition.faceRegion) << threads << " threads";
        EXPECT_EQ(std::memcmp(a.partition.proxies.data(), b.partition.proxies.data(), sizeof(Proxy) * count), 0);
        EXPECT_TRUE(a.regionEnergy == b.regionEnergy);
        EXPECT_TRUE(each.FaceErrors() == oneByOne.FaceErrors());
        EXPECT_TRUE(each.SeedFaces() == oneByOne.SeedFaces());
        EXPECT_EQ(vsa_test::CheckPartition(im, a.partition.faceRegion, count), "");
    }

    Approximation each = converged();
    // Bad arguments change nothing.
    EXPECT_THROW(each.SplitEach({1, 2}, {-1}), std::invalid_argument);
    EXPECT_THROW(each.SplitEach({1, 2, 1}, {-1, -1, -1}), std::invalid_argument);
    EXPECT_THROW(each.SplitEach({1, 30}, {-1, -1}), std::invalid_argument);
    EXPECT_EQ(each.ProxyCount(), 30);
    EXPECT_TRUE(each.CurrentPartition().faceRegion == converged().CurrentPartition().faceRegion);
}

TEST(PartitionApproximation, TeleportLeavesAStuckMinimum)
{
    // Two proxies on one side of a cube, four on others: one side is shared with a neighbour.
    // Lloyd alone stays there; a teleport moves a redundant proxy and reaches energy 0.
    TMesh m;
    vsa_test::MakeTessellatedCube(m, 4);
    const IndexedMesh im = BuildIndexedMesh(m);
    ApproximationParam p = Params(6, MetricKind::L21, SeedingMethod::Random, 0);
    for (uint64_t seed = 0; seed < 50; ++seed) {
        p.randomSeed = seed;
        p.teleport = false;
        const ApproximationResult stuck = Approximate(im, p);
        if (stuck.energy < 1e-12) continue;
        p.teleport = true;
        const ApproximationResult freed = Approximate(im, p);
        ExpectOneRegionPerSide(im, freed);
        bool teleported = false;
        for (const std::string &message : freed.messages) teleported |= message.find("teleport") != std::string::npos;
        EXPECT_TRUE(teleported);
        return;
    }
    FAIL() << "no random seeding got stuck: this test needs another seed range";
}

namespace {

/// The same run from random seeds with a zero tolerance (so only stalls can trigger a
/// teleport), without and with teleports.
std::pair<ApproximationResult, ApproximationResult> WithoutAndWithTeleports(const char *mesh, int k, uint64_t seed)
{
    const IndexedMesh im = vsa_test::LoadCgalMesh(mesh);
    ApproximationParam p = Params(k, MetricKind::L21, SeedingMethod::Random, seed);
    p.tolerance = 0;
    p.teleport = false;
    ApproximationResult lloyd = Approximate(im, p);
    p.teleport = true;
    return {std::move(lloyd), Approximate(im, p)};
}

}  // namespace

TEST(PartitionApproximation, TeleportAlsoWhenLloydOnlyCreeps)
{
    // Random seeds on a CAD shape: Lloyd keeps improving by a hair per iteration and never
    // meets a zero tolerance, yet teleporting proxies out of crowded flat sides pays off.
    const auto [lloyd, teleported] = WithoutAndWithTeleports("fandisk.off", 100, 1);
    ASSERT_TRUE(lloyd.ok && teleported.ok);
    bool said = false;
    for (const std::string &message : teleported.messages) said |= message.find("teleport") != std::string::npos;
    EXPECT_TRUE(said);
    EXPECT_LT(teleported.energy, 0.5 * lloyd.energy);  // 0.0070 against 0.0223 when written
}

TEST(PartitionApproximation, TeleportWhenLloydOscillates)
{
    // Random seeds on blade at k=500: Lloyd swings between two partitions worse than its
    // seeding, each step over 0.1%, never repeating exactly; teleports find the exact fit.
    const auto [lloyd, teleported] = WithoutAndWithTeleports("blade.off", 500, 3);
    ASSERT_TRUE(lloyd.ok && teleported.ok);
    EXPECT_GT(lloyd.energy, 1e-6 * lloyd.referenceEnergy);  // 0.057 of 5106 when written
    EXPECT_LT(teleported.energy, 1e-12 * lloyd.referenceEnergy);
}
