// The flood: its buckets hand candidates out by rank, and its labels are those of the flood that
// queues every candidate, on any number of threads. Relaxations stop at a fixed point only.
#include "partition_test_helpers.h"

#include <vsa/face_geometry.h>
#include <vsa/metrics.h>
#include <vsa/partition.h>
#include <vsa/seeding.h>

#include <gtest/gtest.h>

#include <cmath>
#include <queue>
#include <tuple>

using namespace vcg::tri::vsa;
using vcg::Point3d;

namespace {

using Key = std::tuple<FloodRanks::Rank, long, int, int>;  // (rank, wave, region, face)
using ReferenceQueue = std::priority_queue<Key, std::vector<Key>, std::greater<Key>>;

/// The flood with a std::priority_queue and no shortcut: every free neighbour is queued, keyed
/// by the rank of its error, then by its wave within that rank (the next wave's when it ranks
/// at or below the current rank); all candidates of the lowest key are popped together and a
/// free face goes to the lowest region among them.
template <class Metric>
std::vector<int> TextbookFlood(const IndexedMesh &mesh, const Metric &metric, const std::vector<Proxy> &proxies,
                               const std::vector<int> &seeds)
{
    FloodRanks ranks;
    ranks.Reset(metric.ErrorScale());
    std::vector<int> label(mesh.FaceCount(), -1);
    ReferenceQueue queue;
    const auto offer = [&](int face, int region, FloodRanks::Rank current, long wave) {
        if (face < 0 || label[face] >= 0) return;
        const FloodRanks::Rank rank = ranks.RankOf(metric.Error(face, proxies[region]));
        if (rank <= current) queue.emplace(current, wave + 1, region, face);
        else queue.emplace(rank, 0, region, face);
    };
    for (int r = 0; r < int(seeds.size()); ++r) label[seeds[r]] = r;
    for (int r = 0; r < int(seeds.size()); ++r)
        for (int g : mesh.neighbors[seeds[r]]) offer(g, r, 0, -1);
    while (!queue.empty()) {
        const FloodRanks::Rank rank = std::get<0>(queue.top());
        const long wave = std::get<1>(queue.top());
        std::vector<int> labelled;
        while (!queue.empty() && std::get<0>(queue.top()) == rank && std::get<1>(queue.top()) == wave) {
            const auto [r, t, region, face] = queue.top();  // by region: the lowest comes first
            queue.pop();
            if (label[face] >= 0) continue;
            label[face] = region;
            labelled.push_back(face);
        }
        for (int f : labelled)
            for (int g : mesh.neighbors[f]) offer(g, label[f], rank, wave);
    }
    return label;
}

/// A state with fitted proxies and seeds, as the Lloyd loop floods from.
template <class Metric>
RegionState SeededState(const IndexedMesh &mesh, const Metric &metric, const FaceGeometry &g, int k, uint64_t seed)
{
    RegionState s;
    PartitionWorkspace<Metric> ws;
    SeedRandom random(seed);
    SeedingGoal goal;
    goal.proxyCount = k;
    SeedRandomly(mesh, metric, g, s, goal, random, ws);
    LloydIteration(mesh, metric, s, ws);
    return s;
}

/// Calls check(metric, its geometry, whether it has second moments) with L2,1 and with L2 on `im`.
template <class Check>
void ForBothMetrics(const IndexedMesh &im, Check check)
{
    for (bool l2 : {false, true}) {
        const FaceGeometry g = ComputeFaceGeometry(im, l2);
        if (l2) check(L2Metric(g), g, l2);
        else check(L21Metric(g), g, l2);
    }
}

}  // namespace

TEST(PartitionFlood, RanksFollowTheErrorsToTwoPercent)
{
    FloodRanks queue;
    const double scale = 3.5;
    queue.Reset(scale);
    EXPECT_EQ(queue.RankOf(0.0), 0u);
    EXPECT_EQ(queue.RankOf(-0.0), 0u);
    EXPECT_EQ(queue.RankOf(1e-300), 0u);
    EXPECT_EQ(queue.RankOf(2 * scale), FloodRanks::kRanks - 1);
    EXPECT_EQ(queue.RankOf(1e300), FloodRanks::kRanks - 1);
    EXPECT_EQ(queue.RankOf(std::numeric_limits<double>::infinity()), FloodRanks::kRanks - 1);
    vsa_test::TestRandom random(5);
    for (int i = 0; i < 10000; ++i) {
        // Over the whole range the queue ranks: from the scale down 60 binades.
        const double error = scale * std::ldexp(1 + random.Uniform(), -1 - int(60 * random.Uniform()));
        const double larger = error * (1 + random.Uniform());
        ASSERT_LE(queue.RankOf(error), queue.RankOf(larger)) << error << " " << larger;
        ASSERT_GT(queue.RankOf(error), 0u) << error;
        ASSERT_LT(queue.RankOf(error), queue.RankOf(error * 1.02)) << error;  // 2% apart: never tied
    }
}

TEST(PartitionFlood, BucketsHandOutTheLowestRankInPushOrder)
{
    // Ranks pushed at random awave a level that moves, as floods push them; every MoveOut of the
    // lowest rank gives that rank's candidates in push order.
    vsa_test::TestRandom random(3);
    RankBuckets buckets;
    std::vector<std::vector<std::pair<int, int>>> reference(FloodRanks::kRanks);
    FloodRanks::Rank level = 0;
    int moves = 0;
    for (int step = 0; step < 20000; ++step) {
        if (random.Uniform() < 0.8) {
            const double u = random.Uniform();
            const FloodRanks::Rank rank =
                u < 0.1 ? 0 : std::min<FloodRanks::Rank>(FloodRanks::kRanks - 1, level + FloodRanks::Rank(200 * u));
            const int face = int(random.Uniform() * 50), region = int(random.Uniform() * 5);
            buckets.Push(rank, {face, region});
            reference[rank].emplace_back(face, region);
        } else if (!buckets.Empty()) {
            const FloodRanks::Rank lowest = buckets.Lowest();
            FloodRanks::Rank expected = 0;
            while (reference[expected].empty()) ++expected;
            ASSERT_EQ(lowest, expected);
            std::vector<FloodCandidate> out = {{-1, -1}};  // appended after what is there
            buckets.MoveOut(lowest, out);
            ASSERT_EQ(out.size(), reference[lowest].size() + 1);
            for (size_t i = 0; i < reference[lowest].size(); ++i)
                ASSERT_EQ(std::make_pair(out[i + 1].face, out[i + 1].region), reference[lowest][i]);
            reference[lowest].clear();
            level = lowest;
            ++moves;
        }
        bool empty = true;
        for (const auto &r : reference) empty = empty && r.empty();
        ASSERT_EQ(buckets.Empty(), empty);
    }
    EXPECT_GT(moves, 1000);
}

TEST(PartitionFlood, ClearForgetsCandidatesLeftBehind)
{
    // A flood that stopped early leaves candidates behind; the next flood must not see them.
    FloodRanks ranks;
    ranks.Reset(1.0);
    RankBuckets buckets;
    for (int i = 0; i < 100; ++i) buckets.Push(ranks.RankOf(0.01 * i), {i, 0});
    buckets.Clear();
    EXPECT_TRUE(buckets.Empty());
    EXPECT_EQ(buckets.Lowest(), FloodRanks::kNoRank);
    buckets.Push(ranks.RankOf(0.5), {7, 1});
    buckets.Push(ranks.RankOf(0.5), {8, 2});
    std::vector<FloodCandidate> out;
    buckets.MoveOut(ranks.RankOf(0.5), out);
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(std::make_pair(out[0].face, out[0].region), std::make_pair(7, 1));
    EXPECT_EQ(std::make_pair(out[1].face, out[1].region), std::make_pair(8, 2));
    EXPECT_TRUE(buckets.Empty());
}

/// FloodRegions' labels from the seeds and proxies of `s`, on `threads` threads; every face reached.
template <class Metric>
std::vector<int> FloodOnThreads(const IndexedMesh &im, const Metric &metric, const RegionState &s, int threads)
{
    std::vector<int> label(im.FaceCount(), -1);
    PartitionWorkspace<Metric> ws;
    const int unreached = vsa_test::WithThreads(
        threads, [&] { return FloodRegions(im, metric, s.partition.proxies, s.seeds, label, ws); });
    EXPECT_EQ(unreached, 0) << threads << " threads";
    return label;
}

TEST(PartitionFlood, LabelsAreTheTextbookFloodsOnARealMesh)
{
    // In one block (fandisk is smaller than one at kFloodBlockBits), and in 13 blocks of 1024
    // faces whose offers across borders are made before the next wave of the same rank; on 1,
    // 2 and 3 threads.
    const IndexedMesh im = vsa_test::LoadCgalMesh("fandisk.off");
    for (int blockBits : {detail::kFloodBlockBits, 10}) {
        const bool small = blockBits == 10;
        const vsa_test::FloodInBlocks blocks(blockBits, small ? 1 : detail::kFloodExchangeWaves,
                                             small ? 0 : detail::kFloodWindowCandidates);
        ForBothMetrics(im, [&](const auto &metric, const FaceGeometry &g, bool) {
            const RegionState s = SeededState(im, metric, g, 60, 11);
            const std::vector<int> textbook = TextbookFlood(im, metric, s.partition.proxies, s.seeds);
            EXPECT_EQ(vsa_test::CheckPartition(im, textbook, 60), "");
            for (int threads : {1, 2, 3})
                EXPECT_EQ(FloodOnThreads(im, metric, s, threads), textbook) << threads << " threads, " << blockBits;
        });
    }
}

TEST(PartitionFlood, BlocksFloodTheSameOnAnyNumberOfThreads)
{
    // With offers across blocks kept for kFloodExchangeWaves waves, and for windows of ranks,
    // the labels differ from the textbook flood near the blocks' borders, but not with the
    // threads, and the regions are still connected and cover the mesh.
    const IndexedMesh im = vsa_test::LoadCgalMesh("fandisk.off");
    const vsa_test::FloodInBlocks blocks(10, detail::kFloodExchangeWaves);
    ForBothMetrics(im, [&](const auto &metric, const FaceGeometry &g, bool) {
        const RegionState s = SeededState(im, metric, g, 60, 11);
        const std::vector<int> reference = FloodOnThreads(im, metric, s, 1);
        EXPECT_EQ(vsa_test::CheckPartition(im, reference, 60), "");
        for (int threads : {2, 3}) EXPECT_EQ(FloodOnThreads(im, metric, s, threads), reference) << threads << " threads";
        EXPECT_NE(reference, TextbookFlood(im, metric, s.partition.proxies, s.seeds));
        const vsa_test::FloodInBlocks rankByRank(10, detail::kFloodExchangeWaves, 0);
        EXPECT_NE(reference, FloodOnThreads(im, metric, s, 1)) << "the windows of ranks changed nothing";
    });
}

TEST(PartitionFlood, WavePolicyOutlastsOneSlowExchangeButNotALoadedMachine)
{
    // Timed at 40 ns a candidate alone and 20 ns on every thread, the blocks go to the threads.
    const size_t large = 16 * kParallelMinWave;
    WavePolicy policy;
    policy.Record(false, large, 1000, 40e-6);
    policy.Record(true, large, 1000, 20e-6);
    EXPECT_TRUE(policy.Choose(large));
    // One exchange that waited a millisecond for a thread the system put aside changes nothing...
    policy.Record(true, large, 1000, 1e-3);
    EXPECT_TRUE(policy.Choose(large));
    // ...but a few in a row, as on a loaded machine, send the blocks back to the calling thread.
    for (int slow = 0; slow < 8; ++slow) policy.Record(true, large, 1000, 1e-3);
    EXPECT_FALSE(policy.Choose(large));
}

TEST(PartitionFlood, WavePolicyJudgesSmallAndLargeExchangesApart)
{
    // Small exchanges where waking the threads costs more than it gains run alone, while large
    // ones, where the threads gain, still go to the threads.
    const size_t small = kParallelMinWave, large = 64 * kParallelMinWave;
    WavePolicy policy;
    policy.Record(false, large, 100000, 4e-3);
    policy.Record(true, large, 100000, 2e-3);
    for (int exchange = 0; exchange < 8; ++exchange) {
        policy.Record(false, small, 1000, 40e-6);
        policy.Record(true, small, 1000, 100e-6);
    }
    EXPECT_FALSE(policy.Choose(small));
    EXPECT_FALSE(policy.Choose(2 * small));  // the same size
    EXPECT_TRUE(policy.Choose(large));
    EXPECT_TRUE(policy.Choose(1000 * large));  // the largest size holds every larger exchange
}

TEST(PartitionFlood, TiesGrowBreadthFirstOnACube)
{
    // On a cube whole sides tie at exactly error 0: the order of the offers decides, so the
    // regions of one side grow breadth-first, as the textbook flood with the same key.
    vsa_test::TMesh m;
    vsa_test::MakeTessellatedCube(m, 6);
    const IndexedMesh im = BuildIndexedMesh(m);
    const FaceGeometry g = ComputeFaceGeometry(im, false);
    const L21Metric metric(g);
    const std::vector<int> seeds = {0, 100, 150, 400};
    std::vector<Proxy> proxies;
    for (int f : seeds) proxies.push_back(FitFace(metric, g, f));
    std::vector<int> label(im.FaceCount(), -1);
    PartitionWorkspace<L21Metric> ws;
    FloodRegions(im, metric, proxies, seeds, label, ws);
    EXPECT_EQ(label, TextbookFlood(im, metric, proxies, seeds));
}

TEST(PartitionFlood, SameProxiesComparesBitForBit)
{
    const std::vector<Proxy> a = {{Point3d(0, 1, 2), Point3d(0, 0, 1)}, {Point3d(3, 4, 5), Point3d(1, 0, 0)}};
    EXPECT_TRUE(SameProxies(a, a));
    EXPECT_TRUE(SameProxies({}, {}));
    std::vector<Proxy> b = a;
    b[1].point[2] = std::nextafter(5.0, 6.0);
    EXPECT_FALSE(SameProxies(a, b));
    b = a;
    b[0].point[0] = -0.0;  // equal as numbers, not as bits
    EXPECT_FALSE(SameProxies(a, b));
    b = a;
    b.pop_back();
    EXPECT_FALSE(SameProxies(a, b));
}

TEST(PartitionFlood, RelaxStopsAtAFixedPointOnlyAndEndsAsTheFullIterations)
{
    // Relax(n) must end exactly where n Lloyd iterations do, stopping early only when an
    // iteration changed nothing: on fandisk the 4th iteration still moves the proxies; on a cube
    // seeded on its six sides the first iteration reaches a fixed point, which the second finds.
    const auto expectAsFullIterations = [](const IndexedMesh &im, RegionState start, int iterations,
                                           int expectedRun, const char *what) {
        const FaceGeometry g = ComputeFaceGeometry(im, false);
        const L21Metric metric(g);
        PartitionWorkspace<L21Metric> ws;
        RegionState relaxed = start, full = start;
        EXPECT_EQ(detail::Relax(im, metric, relaxed, ws, iterations), expectedRun) << what;
        for (int i = 0; i < iterations; ++i) LloydIteration(im, metric, full, ws);
        EXPECT_EQ(relaxed.partition.faceRegion, full.partition.faceRegion) << what;
        EXPECT_EQ(relaxed.seeds, full.seeds) << what;
        EXPECT_TRUE(SameProxies(relaxed.partition.proxies, full.partition.proxies)) << what;
        EXPECT_EQ(relaxed.regionEnergy, full.regionEnergy) << what;
    };

    const IndexedMesh fandisk = vsa_test::LoadCgalMesh("fandisk.off");
    const FaceGeometry g = ComputeFaceGeometry(fandisk, false);
    const RegionState moving = SeededState(fandisk, L21Metric(g), g, 30, 3);
    {  // the last of the 4 iterations still changes the proxies: a stop before it would show
        RegionState s = moving;
        const L21Metric metric(g);
        PartitionWorkspace<L21Metric> ws;
        for (int i = 0; i < 3; ++i) LloydIteration(fandisk, metric, s, ws);
        const std::vector<Proxy> third = s.partition.proxies;
        LloydIteration(fandisk, metric, s, ws);
        ASSERT_FALSE(SameProxies(third, s.partition.proxies));
    }
    expectAsFullIterations(fandisk, moving, 4, 4, "fandisk");

    vsa_test::TMesh m;
    vsa_test::MakeTessellatedCube(m, 6);
    const IndexedMesh cube = BuildIndexedMesh(m);
    const FaceGeometry cubeGeometry = ComputeFaceGeometry(cube, false);
    const L21Metric cubeMetric(cubeGeometry);
    RegionState sides;
    std::vector<int> sideSeed(6, -1);
    for (int f = 0; f < cube.FaceCount(); ++f)
        if (sideSeed[vsa_test::CubeSide(cube, f)] < 0) sideSeed[vsa_test::CubeSide(cube, f)] = f;
    for (int f : sideSeed) {
        sides.seeds.push_back(f);
        sides.partition.proxies.push_back(FitFace(cubeMetric, cubeGeometry, f));
    }
    sides.partition.faceRegion.assign(cube.FaceCount(), -1);
    sides.faceError.assign(cube.FaceCount(), 0);
    sides.regionEnergy.assign(6, 0);
    expectAsFullIterations(cube, sides, 3, 2, "cube");
}

TEST(PartitionFlood, LabelledFacesAreWalls)
{
    // Re-flood only the faces of two regions: the others keep their labels and are not crossed.
    const IndexedMesh im = vsa_test::LoadCgalMesh("fandisk.off");
    const FaceGeometry g = ComputeFaceGeometry(im, false);
    const L21Metric metric(g);
    const RegionState s = SeededState(im, metric, g, 30, 5);
    std::vector<int> label = s.partition.faceRegion;
    std::vector<int> seeds(30, -1);
    for (int r : {3, 4}) seeds[r] = s.seeds[r];
    for (int &r : label)
        if (r == 3 || r == 4) r = -1;
    PartitionWorkspace<L21Metric> ws;
    const int unreached = FloodRegions(im, metric, s.partition.proxies, seeds, label, ws);
    int freed = 0;
    for (int f = 0; f < im.FaceCount(); ++f) {
        const int before = s.partition.faceRegion[f];
        if (before == 3 || before == 4) {
            ++freed;
            EXPECT_TRUE(label[f] == 3 || label[f] == 4 || label[f] == -1);
        } else {
            EXPECT_EQ(label[f], before);
        }
    }
    EXPECT_EQ(unreached, int(std::count(label.begin(), label.end(), -1)));
    EXPECT_GT(freed, 0);
}

TEST(PartitionFlood, GrowRegionStealsOnlyWhatItFitsBetterAndEmptiesNoRegion)
{
    const IndexedMesh im = vsa_test::LoadCgalMesh("fandisk.off");
    const FaceGeometry g = ComputeFaceGeometry(im, false);
    const L21Metric metric(g);
    RegionState s = SeededState(im, metric, g, 20, 9);
    const RegionState before = s;
    int worst = -1;
    for (int f = 0; f < im.FaceCount(); ++f)
        if (!s.IsSeed(f) && (worst < 0 || s.faceError[f] > s.faceError[worst])) worst = f;
    std::vector<int> size(20, 0);
    for (int r : s.partition.faceRegion) ++size[r];
    PartitionWorkspace<L21Metric> ws;
    const int added = GrowRegion(im, metric, g, s, worst, size, ws);
    EXPECT_EQ(added, 20);
    EXPECT_EQ(s.seeds[added], worst);
    EXPECT_EQ(ws.grown.front(), worst);
    ASSERT_EQ(ws.grown.size(), ws.grownFrom.size());
    std::vector<int> count(21, 0);
    for (int f = 0; f < im.FaceCount(); ++f) {
        ++count[s.partition.faceRegion[f]];
        if (s.partition.faceRegion[f] != added) {
            EXPECT_EQ(s.partition.faceRegion[f], before.partition.faceRegion[f]);
            continue;
        }
        if (f != worst) {
            EXPECT_LT(s.faceError[f], before.faceError[f]);
        }
        EXPECT_EQ(s.faceError[f], metric.Error(f, s.partition.proxies[added]));
    }
    EXPECT_EQ(count, size);  // kept up to date
    for (int c : count) EXPECT_GT(c, 0);
    // The energies follow the faces that moved, and the total can only fall.
    double total = 0;
    for (int f = 0; f < im.FaceCount(); ++f) total += s.faceError[f];
    EXPECT_NEAR(s.Energy(), total, 1e-12 * total);
    EXPECT_LT(s.Energy(), before.Energy());
}

TEST(PartitionFlood, FloodWithinAloneLabelsAsTheFloodWithWalls)
{
    // Three regions' faces freed, two of them seeded: on nodes and geometry of those faces alone,
    // the labels and the unreached faces are those of the flood on the whole mesh with every
    // other face a wall.
    const IndexedMesh im = vsa_test::LoadCgalMesh("fandisk.off");
    ForBothMetrics(im, [&](const auto &metric, const FaceGeometry &g, bool l2) {
        const RegionState s = SeededState(im, metric, g, 30, 5);
        std::vector<int> walls = s.partition.faceRegion, faces;
        std::vector<int> seeds(30, -1);
        for (int r : {3, 4}) seeds[r] = s.seeds[r];
        for (int f = 0; f < im.FaceCount(); ++f) {
            const int r = walls[f];
            if (r == 3 || r == 4 || r == 7) walls[f] = -1, faces.push_back(f);
        }
        using Metric = std::decay_t<decltype(metric)>;
        PartitionWorkspace<Metric> whole;
        const int unreached = FloodRegions(im, metric, s.partition.proxies, seeds, walls, whole);
        const FaceGeometry some = ComputeFaceGeometryOf(im, faces, l2, g.maxArea, g.diagonal);
        std::vector<int> entry(im.FaceCount(), -1);
        for (size_t i = 0; i < faces.size(); ++i) entry[faces[i]] = int(i);
        PartitionWorkspace<ListedFacesMetric<Metric>> alone;
        std::vector<int> label = s.partition.faceRegion;
        EXPECT_EQ(FloodWithinAlone(im, ListedFacesMetric<Metric>(some, faces, entry), s.partition.proxies,
                                   {{3, seeds[3]}, {4, seeds[4]}}, faces, label, alone),
                  unreached);
        EXPECT_EQ(label, walls);
        EXPECT_EQ(alone.nodes.size(), faces.size());

        // The same when the map also holds the entries of the other faces, in lists of their own
        // (as when SplitEach splits neighbouring regions at once): they stay walls.
        std::vector<int> others;
        for (int f = 0; f < im.FaceCount(); ++f)
            if (entry[f] < 0) entry[f] = int(others.size()), others.push_back(f);
        label = s.partition.faceRegion;
        EXPECT_EQ(FloodWithinAlone(im, ListedFacesMetric<Metric>(some, faces, entry), s.partition.proxies,
                                   {{3, seeds[3]}, {4, seeds[4]}}, faces, label, alone),
                  unreached);
        EXPECT_EQ(label, walls);
    });
}
