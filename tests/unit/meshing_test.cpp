// Tests of vsa/meshing.h.
#include "meshing_fixtures.h"
#include "meshing_test_util.h"
#include "test_meshes.h"

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

TEST(Meshing, CubeSixRegionsGivesTheEightCorners)
{
    TMesh cube;
    vsa_test::MakeTessellatedCube(cube, 4);
    for (bool project : {true, false}) {
        SCOPED_TRACE(project ? "projected anchors" : "anchors at input vertices");
        MeshingParam param;
        param.projectAnchors = project;
        MeshingRun run;
        const Partition partition = vsa_test::DominantAxisPartition(BuildIndexedMesh(cube));
        Mesh(cube, partition, param, run);
        ExpectValidWithInputTopology(run);
        EXPECT_EQ(run.report.anchors, 8);
        EXPECT_EQ(run.report.junctionAnchors, 8);
        EXPECT_EQ(run.report.steinerVertices, 0);
        EXPECT_EQ(run.report.regionsCut, 0);
        EXPECT_EQ(run.out.VN(), 8);
        EXPECT_EQ(run.out.FN(), 12);
        EXPECT_EQ(run.report.validity.selfIntersections, 0);
        EXPECT_EQ(run.report.passes, 1);  // nothing to repair
        EXPECT_EQ(run.report.outputRepairRound, 0);
        for (const Point3d &p : run.output.positions)
            for (int i = 0; i < 3; ++i) EXPECT_NEAR(std::abs(p[i]), 1.0, 1e-7);
        // Hausdorff distance 0: the output's corners are the cube's, and every input vertex
        // lies on the output surface.
        EXPECT_LT(vsa_test::MaxDistanceToSurface(Positions(run.input), run.output), 1e-6);
        std::vector<int> perRegion(6, 0);
        for (int r : run.report.faceRegion) ++perRegion[r];
        EXPECT_EQ(perRegion, std::vector<int>(6, 2));
        // Each side's two triangles lie in its plane, oriented outward like the input.
        for (int f = 0; f < run.output.FaceCount(); ++f) {
            const Point3d n = vsa_test::FaceNormal(run.output, f);
            EXPECT_EQ(vsa_test::DominantAxisLabel(n), run.report.faceRegion[f]);
            EXPECT_NEAR(std::abs(n[run.report.faceRegion[f] / 2]), 1.0, 1e-7);
        }
    }
}

TEST(Meshing, PolygonalCubeFlagsOneDiagonalPerSide)
{
    TMesh cube;
    vsa_test::MakeTessellatedCube(cube, 3);
    MeshingParam param;
    param.polygonal = true;
    MeshingRun run;
    Mesh(cube, vsa_test::DominantAxisPartition(BuildIndexedMesh(cube)), param, run);
    ExpectValidWithInputTopology(run);
    std::set<std::pair<int, int>> fauxEdges, outlineEdges;
    for (const auto &f : run.out.face) {
        int faux = 0;
        for (int i = 0; i < 3; ++i) {
            const int a = int(vcg::tri::Index(run.out, f.cV(i))), b = int(vcg::tri::Index(run.out, f.cV((i + 1) % 3)));
            const std::pair<int, int> edge(std::min(a, b), std::max(a, b));
            if (f.IsF(i)) {
                ++faux;
                fauxEdges.insert(edge);
                // A diagonal of a side: its ends differ in two coordinates.
                const Point3d d = Point3d::Construct(f.cP(i) - f.cP((i + 1) % 3));
                EXPECT_EQ((std::abs(d[0]) > 1) + (std::abs(d[1]) > 1) + (std::abs(d[2]) > 1), 2);
            } else {
                outlineEdges.insert(edge);
            }
        }
        EXPECT_EQ(faux, 1);
    }
    EXPECT_EQ(fauxEdges.size(), 6u);
    EXPECT_EQ(outlineEdges.size(), 12u);  // the cube's edges
}

TEST(Meshing, TorusKeepsItsGenusWhateverTheRegions)
{
    TMesh torus;
    vsa_test::MakeTorus(torus, 2.f, 0.7f, 32, 16);
    const IndexedMesh im = BuildIndexedMesh(torus);
    auto sector = [&](int f, int count) {
        const Point3d c = vsa_test::FaceCentroid(im, f);
        const double angle = std::atan2(c[1], c[0]) + M_PI;
        return std::min(count - 1, int(angle / (2 * M_PI) * count));
    };
    // Eight bands around the tube: every region is a ring.
    const Partition bands = vsa_test::PartitionByRule(im, 8, [&](int f) { return sector(f, 8); });
    // Eight sectors, each split into the outer and inner half of the tube: discs.
    const Partition discs = vsa_test::PartitionByRule(im, 16, [&](int f) {
        const Point3d c = vsa_test::FaceCentroid(im, f);
        return 2 * sector(f, 8) + (std::hypot(c[0], c[1]) > 2.0 ? 1 : 0);
    });
    // The whole torus as one region.
    const Partition whole = vsa_test::PartitionByRule(im, 1, [](int) { return 0; });
    struct Case
    {
        const char *name;
        const Partition &partition;
        int cut;
    };
    for (const Case &c : {Case{"bands", bands, 8}, Case{"discs", discs, 0}, Case{"whole", whole, 1}}) {
        SCOPED_TRACE(c.name);
        MeshingRun run;
        Mesh(torus, c.partition, MeshingParam(), run);
        ExpectValidWithInputTopology(run);
        ExpectNoRegionDropped(run, c.partition);
        EXPECT_EQ(run.report.validity.eulerCharacteristic, 0);
        EXPECT_TRUE(run.report.validity.IsClosed());
        EXPECT_EQ(run.report.regionsCut, c.cut);
    }
}

TEST(Meshing, BoxWithCylindricalHoleKeepsItsGenus)
{
    TMesh box;
    vsa_test::MakeBoxWithHole(box, 32);
    const IndexedMesh im = BuildIndexedMesh(box);
    // Six regions by the normal's dominant axis: the top and bottom are rings, and each side
    // region also holds the arc of the hole's wall that faces the same way (two pieces).
    const Partition axes = vsa_test::DominantAxisPartition(im);
    // Ten regions: top, bottom, four outer sides, four quarters of the hole.
    const Partition ten = vsa_test::PartitionByRule(im, 10, [&](int f) {
        const Point3d c = vsa_test::FaceCentroid(im, f), n = vsa_test::FaceNormal(im, f);
        if (std::abs(n[2]) > 0.5) return n[2] > 0 ? 0 : 1;
        if (std::hypot(c[0], c[1]) > 0.9) return 2 + vsa_test::DominantAxisLabel(n);  // 2..5
        return 6 + std::min(3, int((std::atan2(c[1], c[0]) + M_PI) / (0.5 * M_PI)));
    });
    for (const Partition *partition : {&axes, &ten}) {
        SCOPED_TRACE(partition == &axes ? "six regions" : "ten regions");
        MeshingRun run;
        Mesh(box, *partition, MeshingParam(), run);
        ExpectValidWithInputTopology(run);
        ExpectNoRegionDropped(run, *partition);
        EXPECT_EQ(run.report.validity.eulerCharacteristic, 0);
        EXPECT_TRUE(run.report.validity.IsClosed());
        EXPECT_GE(run.report.regionsCut, 2);  // the two rings at least
    }
}

TEST(Meshing, OpenHemisphereKeepsItsBorder)
{
    TMesh dome;
    vsa_test::MakeHemisphere(dome, 8, 32);
    const IndexedMesh im = BuildIndexedMesh(dome);
    const std::set<int> inputBorder = vsa_test::BorderVertices(im);
    // A polar cap and four sectors around it, every sector meeting the border.
    const Partition five = vsa_test::PartitionByRule(im, 5, [&](int f) {
        const Point3d c = vsa_test::FaceCentroid(im, f);
        if (c[2] > 0.8) return 4;
        return std::min(3, int((std::atan2(c[1], c[0]) + M_PI) / (0.5 * M_PI)));
    });
    const Partition one = vsa_test::PartitionByRule(im, 1, [](int) { return 0; });
    for (const Partition *partition : {&five, &one})
        for (bool project : {false, true}) {
            SCOPED_TRACE(std::string(partition == &five ? "five regions" : "one region") +
                         (project ? ", projected" : ", not projected"));
            MeshingParam param;
            param.projectAnchors = project;
            MeshingRun run;
            Mesh(dome, *partition, param, run);
            ExpectValidWithInputTopology(run);
            ExpectNoRegionDropped(run, *partition);
            EXPECT_EQ(run.report.validity.eulerCharacteristic, 1);
            EXPECT_EQ(vsa_test::BorderLoopCount(run.output), 1);
            // The output's border vertices are input border vertices (or their projections).
            auto sourceOf = [&](int v) { return run.report.vertexSource[run.output.sourceVertex[v]]; };
            const std::set<int> border = vsa_test::BorderVertices(run.output);
            EXPECT_GE(border.size(), 3u);
            for (int v : border) {
                ASSERT_TRUE(inputBorder.count(sourceOf(v))) << "output border vertex " << v;
                const double moved = (run.output.positions[v] - im.positions[sourceOf(v)]).Norm();
                if (!project) EXPECT_EQ(moved, 0.0);
                else EXPECT_LE(moved, param.maxAnchorMove * 2.0 + 1e-6);  // chords are at most a diameter
            }
            // Inner output vertices come from inner input vertices: the border is not crossed.
            for (int v = 0; v < run.output.VertexCount(); ++v)
                if (!border.count(v)) {
                    EXPECT_FALSE(inputBorder.count(sourceOf(v)));
                }
        }
}

TEST(Meshing, FragmentedAndPinchedRegionsStillGiveAValidMesh)
{
    // Labels that scatter each region over many pieces, touching at vertices: the worst a
    // partition can do. Geometry is nonsense, but the topology must hold.
    TMesh cube;
    vsa_test::MakeTessellatedCube(cube, 6);
    const IndexedMesh im = BuildIndexedMesh(cube);
    for (int k : {2, 3, 5}) {
        SCOPED_TRACE(k);
        const Partition scattered = vsa_test::PartitionByRule(im, k, [&](int f) { return int((f * 7919u) % k); });
        MeshingRun run;
        Mesh(cube, scattered, MeshingParam(), run);
        ExpectValidWithInputTopology(run);
        ExpectNoRegionDropped(run, scattered);
        EXPECT_EQ(run.report.validity.eulerCharacteristic, 2);
    }
    TMesh torus;
    vsa_test::MakeTorus(torus, 2.f, 0.7f, 24, 12);
    const IndexedMesh tim = BuildIndexedMesh(torus);
    const Partition scattered = vsa_test::PartitionByRule(tim, 4, [&](int f) { return int((f * 104729u) % 4); });
    MeshingRun run;
    Mesh(torus, scattered, MeshingParam(), run);
    ExpectValidWithInputTopology(run);
    EXPECT_EQ(run.report.validity.eulerCharacteristic, 0);
}

TEST(Meshing, RejectsWhatItCannotMeshWithAClearError)
{
    auto expectError = [](const TMesh &m, const Partition &p, const std::string &words) {
        TMesh out;
        const MeshingReport r = BuildApproximatingMesh(BuildIndexedMesh(m), p, MeshingParam(), out);
        EXPECT_FALSE(r.ok);
        EXPECT_NE(r.error.find(words), std::string::npos) << r.error;
        EXPECT_EQ(out.VN(), 0);
        EXPECT_EQ(out.FN(), 0);
        EXPECT_NE(r.Summary().find(words), std::string::npos);
    };
    TMesh book;  // three faces on one edge
    vsa_test::BuildFromLists(book, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}},
                             {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
    expectError(book, vsa_test::PartitionByRule(BuildIndexedMesh(book), 1, [](int) { return 0; }), "non-manifold");

    TMesh flipped;
    vsa_test::BuildFromLists(flipped, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {{0, 1, 2}, {1, 2, 3}});
    expectError(flipped, vsa_test::PartitionByRule(BuildIndexedMesh(flipped), 1, [](int) { return 0; }), "oriented");

    TMesh cube;
    vsa_test::MakeTessellatedCube(cube, 1);
    Partition p = vsa_test::DominantAxisPartition(BuildIndexedMesh(cube));
    Partition shortLabels = p;
    shortLabels.faceRegion.pop_back();
    expectError(cube, shortLabels, "partition labels 11 faces");
    Partition outOfRange = p;
    outOfRange.faceRegion[3] = 6;
    expectError(cube, outOfRange, "region 6");
    TMesh nan;
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(nan, cube);
    nan.vert[0].P()[1] = std::numeric_limits<float>::quiet_NaN();
    expectError(nan, p, "NaN");

    for (double MeshingParam::*field : {&MeshingParam::chordThreshold, &MeshingParam::chordGapThreshold,
                                         &MeshingParam::chordErrorFactor, &MeshingParam::maxAnchorMove}) {
        MeshingParam negative;
        negative.*field = -1;
        TMesh out;
        const MeshingReport r = BuildApproximatingMesh(BuildIndexedMesh(cube), p, negative, out);
        EXPECT_FALSE(r.ok);
        EXPECT_NE(r.error.find("non-negative"), std::string::npos) << r.error;
    }
}

TEST(Meshing, IgnoresFacesWithARepeatedVertexAndBadProxies)
{
    TMesh cube;
    vsa_test::MakeTessellatedCube(cube, 2);
    vcg::tri::Allocator<TMesh>::AddFace(cube, &cube.vert[0], &cube.vert[0], &cube.vert[1]);
    const IndexedMesh im = BuildIndexedMesh(cube);
    Partition p = vsa_test::DominantAxisPartition(im);
    p.faceRegion.back() = 0;
    p.proxies[1].normal = Point3d(0, 0, 0);  // unusable: replaced by the region's own plane
    p.proxies[2].point[0] = std::numeric_limits<double>::infinity();
    TMesh out;
    const MeshingReport r = BuildApproximatingMesh(im, p, MeshingParam(), out);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.ignoredFaces, 1);
    EXPECT_EQ(out.VN(), 8);
    EXPECT_EQ(out.FN(), 12);
    EXPECT_TRUE(r.validity.IsValid()) << r.validity.Summary();
    for (const auto &v : out.vert)
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(std::abs(v.cP()[i]), 1.0, 1e-6);
}

TEST(Meshing, WritesIntoABareMeshTypeAndIsDeterministic)
{
    TMesh torus;
    vsa_test::MakeTorus(torus, 2.f, 0.5f, 40, 20);
    const IndexedMesh im = BuildIndexedMesh(torus);
    const Partition p = vsa_test::PartitionByRule(im, 12, [&](int f) {
        const Point3d c = vsa_test::FaceCentroid(im, f);
        const int around = std::min(5, int((std::atan2(c[1], c[0]) + M_PI) / (M_PI / 3)));
        return 2 * around + (c[2] > 0 ? 1 : 0);
    });
    MeshingParam param;
    param.polygonal = true;
    BareMesh first, second;
    const MeshingReport a = BuildApproximatingMesh(im, p, param, first);
    const MeshingReport b = BuildApproximatingMesh(im, p, param, second);
    ASSERT_TRUE(a.ok) << a.error;
    EXPECT_TRUE(a.validity.IsValid()) << a.validity.Summary();
    EXPECT_EQ(a.validity.eulerCharacteristic, 0);
    ASSERT_EQ(first.VN(), second.VN());
    ASSERT_EQ(first.FN(), second.FN());
    for (int v = 0; v < first.VN(); ++v) EXPECT_EQ(first.vert[v].cP(), second.vert[v].cP());
    for (int f = 0; f < first.FN(); ++f)
        for (int i = 0; i < 3; ++i) {
            EXPECT_EQ(vcg::tri::Index(first, first.face[f].cV(i)), vcg::tri::Index(second, second.face[f].cV(i)));
            EXPECT_EQ(first.face[f].IsF(i), second.face[f].IsF(i));
        }
    EXPECT_EQ(a.faceRegion, b.faceRegion);
}

// Triangles are judged on the coordinates the output will store; a loop of plain double ->
// float -> double round trips is compiled away by GCC 12.2 at -O2/-O3 for some of them.
TEST(Meshing, PositionsAreRoundedAsTheOutputStoresThem)
{
    std::vector<Point3d> points;
    for (int i = 0; i < 101; ++i) points.emplace_back(0.1 * i + 1e-9, 1.0 / 3 + i, 2.0 / 7 - i);
    std::vector<vcg::Point3f> stored;
    for (const Point3d &p : points) stored.push_back(vcg::Point3f::Construct(p));
    for (Point3d &p : points) p = detail::AsWritten<vcg::Point3f>(p);
    for (size_t i = 0; i < points.size(); ++i)
        for (int k = 0; k < 3; ++k) EXPECT_EQ(points[i][k], double(stored[i][k])) << "point " << i << " axis " << k;
    const Point3d exact(1.0 / 3, 0.1, 1e300);
    EXPECT_EQ(detail::AsWritten<vcg::Point3d>(exact), exact);
}
