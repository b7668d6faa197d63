// The number of threads changes nothing: the partition, its energies and the output mesh are the
// same bits on 1, 2, 3 and 8 threads (vsa/parallel.h). Meshes of several chunks of faces, so that
// sums that followed the threads would round differently.
#include "partition_test_helpers.h"

#include <vsa/approximate_shape.h>
#include <vsa/mesh_validity.h>
#include <vsa/parallel.h>

#include <vcg/complex/algorithms/create/platonic.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace {

using namespace vcg::tri::vsa;
using vsa_test::TMesh;
using vsa_test::Bytes;
using vsa_test::Fingerprint;
using vsa_test::WithThreads;

const int kThreadCounts[] = {1, 2, 3, 8};

/// The output mesh's coordinates and triangles, as bytes.
std::string Fingerprint(const TMesh &m)
{
    std::vector<vcg::Point3f> coords;
    std::vector<int> triangles;
    for (const auto &v : m.vert)
        if (!v.IsD()) coords.push_back(v.cP());
    for (const auto &f : m.face)
        if (!f.IsD())
            for (int k = 0; k < 3; ++k) triangles.push_back(int(vcg::tri::Index(m, f.cV(k))));
    return Bytes(coords) + Bytes(triangles);
}

/// Fills `m` with "sphere" (an icosphere of 20480 faces) or one of CGAL's sample meshes.
/// (vcg meshes do not copy: TriMesh's copy constructor leaves the copy empty.)
void Load(const std::string &name, TMesh &m)
{
    if (name == "sphere") {
        vcg::tri::Sphere(m, 5);
        vcg::tri::UpdateBounding<TMesh>::Box(m);
        return;
    }
    std::string error;
    if (!vsa_test::LoadMesh(m, vsa_test::CgalMesh(name), &error)) ADD_FAILURE() << name << ": " << error;
}

IndexedMesh Indexed(const std::string &name)
{
    TMesh m;
    Load(name, m);
    return BuildIndexedMesh(m);
}

}  // namespace

TEST(ThreadCount, ParallelPassesSplitIntoSeveralChunks)
{
    // The meshes below must span several chunks, or the tests could not tell orders apart.
    EXPECT_GE(ChunkCount(Indexed("sphere").FaceCount()), 5);
    EXPECT_GE(ChunkCount(Indexed("fandisk.off").FaceCount()), 3);
}

TEST(ThreadCount, EveryGroupOnceOnAnyNumberOfThreads)
{
    // Groups of very different sizes, as cells are: each is visited once, whatever the threads.
    const int groups = 97;
    for (int threads : kThreadCounts) {
        const std::vector<int> visits = WithThreads(threads, [&] {
            std::vector<int> v(groups, 0);
            ForEachGroup(
                groups, size_t(groups) * 50, [](int g) { return g * g % 100; }, [&](int g) { v[g] += 1 + g; });
            return v;
        });
        for (int g = 0; g < groups; ++g) EXPECT_EQ(visits[g], 1 + g) << "group " << g << ", " << threads << " threads";
    }
}

TEST(ThreadCount, CompressedListsAreTheStableSortOnAnyNumberOfThreads)
{
    // Keys scattered over 3 chunks of items, some left out (-1), one key with no item.
    const size_t count = 3 * kChunkItems + 77;
    const int keys = 50;
    std::vector<int> key(count);
    for (size_t i = 0; i < count; ++i) {
        const int raw = int(i * 7919 % 53) - 3;  // -3 to 49: negatives are left out
        key[i] = raw == 17 ? 18 : raw;            // key 17 gets no item
    }
    std::vector<int> byKey;  // the items with a key, by key then item
    for (size_t i = 0; i < count; ++i)
        if (key[i] >= 0) byKey.push_back(int(i));
    std::stable_sort(byKey.begin(), byKey.end(), [&](int a, int b) { return key[a] < key[b]; });
    for (int threads : kThreadCounts) {
        std::vector<int> offset, list;
        WithThreads(threads, [&] {
            detail::BuildOffsets(key, keys, offset, list);
            return 0;
        });
        ASSERT_EQ(offset.size(), size_t(keys) + 1) << threads << " threads";
        EXPECT_EQ(offset[0], 0) << threads << " threads";
        EXPECT_TRUE(list == byKey) << threads << " threads";
        for (int k = 0; k < keys; ++k) {
            const auto items = std::count(key.begin(), key.end(), k);
            EXPECT_EQ(offset[k + 1] - offset[k], items) << "key " << k << ", " << threads << " threads";
        }
        EXPECT_EQ(offset[18], offset[17]) << threads << " threads";
    }
}

TEST(ThreadCount, ListsOfPairsKeepTheItemsOrderOnAnyNumberOfThreads)
{
    // Items over 3 chunks making 0 to 3 (key, value) pairs each, as faces make one per edge
    // between two patches; a key's values come by item, then in the order the item made them.
    const size_t count = 3 * kChunkItems + 77;
    const int keys = 40;
    const auto pairsOf = [](size_t item, auto &&emit) {
        for (int j = 0; j < int(item % 4); ++j) emit(int((item * 31 + size_t(j) * 7) % 40), int(item) * 4 + j);
    };
    std::vector<std::vector<int>> expected(keys);
    for (size_t i = 0; i < count; ++i) pairsOf(i, [&](int k, int value) { expected[size_t(k)].push_back(value); });
    for (int threads : kThreadCounts) {
        std::vector<int> offset, list;
        WithThreads(threads, [&] {
            detail::BuildLists(count, pairsOf, keys, offset, list);
            return 0;
        });
        ASSERT_EQ(offset.size(), size_t(keys) + 1) << threads << " threads";
        for (int k = 0; k < keys; ++k)
            EXPECT_TRUE(std::vector<int>(list.begin() + offset[k], list.begin() + offset[k + 1]) == expected[size_t(k)])
                << "key " << k << ", " << threads << " threads";
    }
}

TEST(ThreadCount, SelfIntersectionsAreTheSameOnAnyNumberOfThreads)
{
    // Two spheres that overlap: their faces cross along a circle, found chunk by chunk.
    IndexedMesh im = Indexed("sphere");
    const int faces = im.FaceCount(), vertices = int(im.positions.size());
    for (int v = 0; v < vertices; ++v) im.positions.push_back(im.positions[size_t(v)] + vcg::Point3d(0.5, 0.3, 0.1));
    for (int f = 0; f < faces; ++f) {
        const std::array<int, 3> t = im.faces[size_t(f)];
        im.faces.push_back({t[0] + vertices, t[1] + vertices, t[2] + vertices});
    }
    const std::vector<std::pair<int, int>> one = WithThreads(1, [&] { return detail::SelfIntersectingPairs(im); });
    ASSERT_GT(one.size(), 100u);
    for (const auto &[f, g] : one) EXPECT_TRUE(f < faces && g >= faces) << f << " " << g;  // each sphere is clean
    for (int threads : kThreadCounts)
        EXPECT_TRUE(WithThreads(threads, [&] { return detail::SelfIntersectingPairs(im); }) == one)
            << threads << " threads";
}

TEST(ThreadCount, ComponentsAndFansAreTheSameOnAnyNumberOfThreads)
{
    // Three spheres, the second touching the first at one vertex (two fans there), their faces
    // shuffled over 15 chunks: most links cross chunks, and each sphere's first face comes late.
    const IndexedMesh sphere = Indexed("sphere");
    const int faces = sphere.FaceCount(), vertices = sphere.VertexCount();
    IndexedMesh im;
    std::vector<std::array<int, 3>> ordered;
    for (int copy = 0; copy < 3; ++copy) {
        for (const vcg::Point3d &p : sphere.positions) im.positions.push_back(p + vcg::Point3d(3.0 * copy, 0, 0));
        for (std::array<int, 3> t : sphere.faces) {
            for (int &v : t) v = copy == 1 && v == 0 ? 0 : v + copy * vertices;  // copy 1's vertex 0: copy 0's
            ordered.push_back(t);
        }
    }
    const size_t count = ordered.size();
    const auto shuffled = [&](size_t i) { return (i * 7919 + 45000) % count; };  // 7919 is prime
    for (size_t i = 0; i < count; ++i) im.faces.push_back(ordered[shuffled(i)]);
    // What one depth-first pass in face order numbers: each component after its first face.
    std::vector<int> copyOfFace(count), expected(count);
    for (size_t i = 0; i < count; ++i) copyOfFace[i] = int(shuffled(i)) / faces;
    std::vector<int> numberOfCopy(3, -1);
    int numbered = 0;
    for (size_t i = 0; i < count; ++i) {
        int &number = numberOfCopy[size_t(copyOfFace[i])];
        if (number < 0) number = numbered++;
        expected[i] = number;
    }
    ASSERT_NE(numberOfCopy, (std::vector<int>{0, 1, 2}));  // the shuffle renumbers the spheres
    for (int threads : kThreadCounts) {
        IndexedMesh linked = im;
        MeshDiagnostics diag;
        WithThreads(threads, [&] {
            detail::LinkAndDiagnose(linked, diag);
            return 0;
        });
        EXPECT_EQ(diag.nonManifoldVertices, 1) << threads << " threads";
        EXPECT_EQ(diag.components, 3) << threads << " threads";
        EXPECT_TRUE(linked.component == expected) << threads << " threads";
    }
}

TEST(ThreadCount, SumsOfListedItemsAreTheSameBitsAsSumsOverAll)
{
    // Values of very different sizes, so that another order of the additions would round
    // differently; keys in runs, as regions are; every third item listed.
    const size_t count = 5 * kChunkItems + 123;
    std::vector<double> value(count);
    std::vector<int> key(count), listed;
    for (size_t i = 0; i < count; ++i) {
        value[i] = std::ldexp(1.0 + double(i % 97) / 97, int(i % 61) - 30);
        key[i] = int(i / 1000) % 7;
        if (i % 3 == 0) listed.push_back(int(i));
    }
    auto add = [&](double &sum, size_t i) { sum += value[i]; };
    auto merge = [](double &sum, double part) { sum += part; };
    const std::vector<double> listedSums = [&] {
        std::vector<double> sums(7, 0.25);
        SumByKeyOfListed(listed, sums, [&](size_t i) { return key[i]; }, add, merge);
        return sums;
    }();
    for (int threads : kThreadCounts) {
        const std::vector<double> all = WithThreads(threads, [&] {
            std::vector<double> sums(7, 0.25);
            SumByKey(count, sums, [&](size_t i) { return i % 3 == 0 ? key[i] : -1; }, add, merge);
            return sums;
        });
        EXPECT_TRUE(Bytes(all) == Bytes(listedSums)) << threads << " threads";
    }
    // Summed in another order, they would not be the same bits: the test can tell.
    std::vector<double> reversed(7, 0.25);
    for (auto i = listed.rbegin(); i != listed.rend(); ++i) reversed[key[*i]] += value[*i];
    EXPECT_FALSE(Bytes(reversed) == Bytes(listedSums));
}

TEST(ThreadCount, PartitionIsTheSameBitsOnAnyNumberOfThreads)
{
    const vsa_test::FloodInBlocks blocks(11, detail::kFloodExchangeWaves);  // floods on several threads
    struct Case
    {
        const char *mesh;
        int k;
        MetricKind metric;
        SeedingMethod init;
        bool teleports;  ///< the case that makes sure teleports (AdjacentRegionPairs) run on threads
    };
    for (const Case &c : {Case{"sphere", 50, MetricKind::L2, SeedingMethod::Hierarchical, false},
                          Case{"fandisk.off", 40, MetricKind::L21, SeedingMethod::Farthest, false},
                          Case{"armadillo.off", 100, MetricKind::L21, SeedingMethod::Random, true}}) {
        ApproximationParam param;
        param.proxyCount = c.k;
        param.metric = c.metric;
        param.init = c.init;
        param.randomSeed = 3;
        param.maxIterations = 15;
        const IndexedMesh im = Indexed(c.mesh);
        std::string reference;
        for (int threads : kThreadCounts) {
            const ApproximationResult r = WithThreads(threads, [&] { return Approximate(im, param); });
            ASSERT_TRUE(r.ok) << r.error;
            if (c.teleports) {
                bool teleported = false;
                for (const std::string &message : r.messages) teleported |= message.find("teleport") != std::string::npos;
                EXPECT_TRUE(teleported) << c.mesh << ", " << threads << " threads";
            }
            if (reference.empty()) reference = Fingerprint(r);
            EXPECT_TRUE(Fingerprint(r) == reference) << c.mesh << ", " << threads << " threads";
        }
    }
}

TEST(ThreadCount, MultilevelSeedingIsTheSameBitsOnAnyNumberOfThreads)
{
    const vsa_test::FloodInBlocks blocks(11, detail::kFloodExchangeWaves);  // floods on several threads
    const IndexedMesh im = Indexed("armadillo.off");
    const FaceGeometry g = ComputeFaceGeometry(im, true);
    const L2Metric metric(g);
    const SeedingGoal goal = vsa_test::PatchesGoal(100, 2);
    ASSERT_GT(detail::PatchFaces(im.FaceCount(), goal), 1);
    std::string reference;
    for (int threads : kThreadCounts) {
        const RegionState s = WithThreads(threads, [&] {
            RegionState state;
            PartitionWorkspace<L2Metric> ws;
            SeedRandom random(7);
            SeedHierarchically(im, metric, g, state, goal, random, ws);
            return state;
        });
        const std::string fingerprint = Bytes(s.partition.faceRegion) + Bytes(s.partition.proxies) +
                                        Bytes(s.seeds) + Bytes(s.faceError) + Bytes(s.regionEnergy);
        if (reference.empty()) reference = fingerprint;
        EXPECT_TRUE(fingerprint == reference) << threads << " threads";
    }
}

TEST(ThreadCount, ApproximateShapeIsTheSameBitsOnAnyNumberOfThreads)
{
    const vsa_test::FloodInBlocks blocks(11, detail::kFloodExchangeWaves);  // floods on several threads
    for (const char *name : {"sphere", "fandisk.off"}) {
        TMesh in;
        Load(name, in);
        ShapeApproximationParam param;
        param.partition.proxyCount = 60;
        param.partition.randomSeed = 1;
        std::string reference;
        for (int threads : kThreadCounts) {
            TMesh out;
            const ShapeApproximationResult r = WithThreads(threads, [&] { return ApproximateShape(in, out, param); });
            ASSERT_TRUE(r.ok) << r.error;
            const std::string fingerprint = Fingerprint(r.partition) + Fingerprint(out) + Bytes(r.inputFaceRegion);
            if (reference.empty()) reference = fingerprint;
            EXPECT_TRUE(fingerprint == reference) << name << ", " << threads << " threads";
        }
    }
}
