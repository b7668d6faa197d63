#include "meshing_test_util.h"
#include "test_meshes.h"

#include <vsa/meshing.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numeric>
#include <limits>
#include <set>

using namespace vcg::tri::vsa;
using vcg::Point3d;
using vsa_test::BareMesh;
using vsa_test::TMesh;

namespace {


struct MeshingRun
{
    IndexedMesh input;
    MeshValidity inputValidity;
    TMesh out;
    IndexedMesh output;
    MeshingReport report;
};

/// Meshes `m` with `partition` and snapshots the output.
void Mesh(const TMesh &m, const Partition &partition, const MeshingParam &param, MeshingRun &run)
{
    MeshDiagnostics diag;
    run.input = BuildIndexedMesh(m, &diag);
    run.inputValidity = CheckMeshValidity(run.input, diag, false);
    run.report = BuildApproximatingMesh(run.input, partition, param, run.out);
    run.output = BuildIndexedMesh(run.out);
}

/// What every output must be: a valid mesh with the input's topology.
void ExpectValidWithInputTopology(const MeshingRun &run)
{
    ASSERT_TRUE(run.report.ok) << run.report.error;
    const MeshValidity &v = run.report.validity;
    EXPECT_TRUE(v.IsTwoManifold()) << v.Summary();
    EXPECT_TRUE(v.IsOriented()) << v.Summary();
    EXPECT_EQ(v.degenerateFaces, 0) << v.Summary();
    EXPECT_EQ(v.duplicateFaces, 0) << v.Summary();
    EXPECT_EQ(v.IsClosed(), run.inputValidity.IsClosed()) << v.Summary();
    EXPECT_EQ(v.components, run.inputValidity.components) << v.Summary();
    EXPECT_EQ(v.eulerCharacteristic, run.inputValidity.eulerCharacteristic) << v.Summary();
    EXPECT_EQ(int(run.report.faceRegion.size()), v.faces);
    EXPECT_EQ(int(run.report.vertexSource.size()), v.vertices);
    EXPECT_EQ(run.report.regionsByFlooding + run.report.regionsByEarClipping + run.report.regionsWithSteinerVertex +
                  run.report.regionsKeptAsInput,
              run.report.regions);
}

/// Every region with faces in the partition has faces in the output.
void ExpectNoRegionDropped(const MeshingRun &run, const Partition &partition)
{
    std::set<int> in(partition.faceRegion.begin(), partition.faceRegion.end());
    std::set<int> out(run.report.faceRegion.begin(), run.report.faceRegion.end());
    EXPECT_EQ(in, out);
    EXPECT_EQ(run.report.regions, int(in.size()));
}

std::vector<Point3d> Positions(const IndexedMesh &m) { return m.positions; }

/// The flat square [-1,1]^2 as a 16 x 16 grid, indexed into `im`, in 3 regions: label(f, r) for
/// face f whose centroid is at distance r from the centre.
Partition PartitionFlatSquare(TMesh &square, IndexedMesh &im, const std::function<int(int, double)> &label)
{
    vsa_test::MakeFlatSquare(square, 16);
    im = BuildIndexedMesh(square);
    return vsa_test::PartitionByRule(im, 3, [&](int f) {
        const Point3d c = vsa_test::FaceCentroid(im, f);
        return label(f, std::hypot(c[0], c[1]));
    });
}

/// The flat square partitioned by a label (see PartitionFlatSquare), and its meshing surface.
struct FlatSquareSurface
{
    TMesh square;
    IndexedMesh im;
    Partition partition;
    MeshingSurface s;

    explicit FlatSquareSurface(const std::function<int(int, double)> &label)
    {
        partition = PartitionFlatSquare(square, im, label);
        std::string error;
        EXPECT_TRUE(BuildMeshingSurface(im, partition.faceRegion, 3, s, error)) << error;
    }
};

/// A disc region in the middle of the flat square, a one-face region, and the rest around them.
int DiscOneFaceAndRest(int f, double r) { return f == 0 ? 2 : (r < 0.5 ? 0 : 1); }

/// The faces of cell c of `s`, in the surface's order.
std::vector<int> FacesOfCell(const MeshingSurface &s, int c)
{
    return std::vector<int>(s.cellFaces.begin() + s.cellFaceOffset[c], s.cellFaces.begin() + s.cellFaceOffset[c + 1]);
}

}  // namespace

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

TEST(Meshing, ChordThresholdOnAFlatDisc)
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
TEST(Meshing, ChordErrorBoundKeepsTheCornersTheRegionsFit)
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

// Two coplanar regions, the inner and outer halves of a flat "C": the paper's criterion
// (sin 0 = 0) never splits the chain between them, whose chord then runs straight across the
// C's opening. The gap test must split it until the output stays on the surface. Repair
// rounds are off: they would catch this case's fold for other reasons, not every such case's.
TEST(Meshing, ChordAcrossAGapIsSplit)
{
    TMesh c;
    vsa_test::MakeFlatC(c, 8, 60, M_PI / 3);
    const IndexedMesh im = BuildIndexedMesh(c);
    const Partition halves = vsa_test::PartitionByRule(
        im, 2, [&](int f) { return vsa_test::FaceCentroid(im, f).Norm() < 1.5 ? 0 : 1; });
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

TEST(Meshing, IslandAndRingRegionsOnAFlatSquare)
{
    TMesh square;
    IndexedMesh im;
    const Partition rings = PartitionFlatSquare(square, im, [](int, double r) {
        return r < 0.3 ? 0 : (r < 0.65 ? 1 : 2);  // island, ring around it, the rest
    });
    for (bool polygonal : {false, true}) {
        MeshingParam param;
        param.polygonal = polygonal;
        param.chordThreshold = 0.01;  // keeps the square's corners, which cut off 6% of a chord
        MeshingRun run;
        Mesh(square, rings, param, run);
        ExpectValidWithInputTopology(run);
        ExpectNoRegionDropped(run, rings);
        EXPECT_EQ(vsa_test::BorderLoopCount(run.output), 1);
        EXPECT_EQ(run.report.regionsCut, 2);       // the ring and the square around it
        EXPECT_EQ(run.report.validity.selfIntersections, 0);
        for (const Point3d &p : run.output.positions) EXPECT_EQ(p[2], 0.0);
        // Flat in, flat out: the output tiles the same square, without overlap or gap.
        EXPECT_NEAR(vsa_test::SurfaceArea(run.output), 4.0, 1e-5);
        if (polygonal) {
            // A faux edge never separates two regions, and the faux edges group the faces into
            // exactly one polygon per disc (a cut ring is two or more polygons, never lost).
            std::vector<int> group(run.out.face.size());
            std::iota(group.begin(), group.end(), 0);
            std::function<int(int)> root = [&](int x) { return group[x] == x ? x : group[x] = root(group[x]); };
            for (const auto &f : run.out.face)
                for (int i = 0; i < 3; ++i) {
                    if (!f.IsF(i)) continue;
                    for (const auto &h : run.out.face)
                        for (int j = 0; j < 3; ++j)
                            if (&h != &f && h.cV(j) == f.cV((i + 1) % 3) && h.cV((j + 1) % 3) == f.cV(i)) {
                                const int a = int(vcg::tri::Index(run.out, f)), b = int(vcg::tri::Index(run.out, h));
                                EXPECT_EQ(run.report.faceRegion[a], run.report.faceRegion[b]);
                                EXPECT_TRUE(h.IsF(j));
                                group[root(a)] = root(b);
                            }
                }
            std::set<int> polygons;
            for (int f = 0; f < int(run.out.face.size()); ++f) polygons.insert(root(f));
            EXPECT_EQ(int(polygons.size()), run.report.cells);
        }
    }
}

TEST(Meshing, HalvingACellGivesTwoDiscsOfItsRegionAndLeavesTheOthers)
{
    FlatSquareSurface flat(DiscOneFaceAndRest);
    MeshingSurface &s = flat.s;
    std::string error;
    auto facesOfCells = [](const MeshingSurface &m) {
        std::set<std::set<int>> cells;
        for (int c = 0; c < m.CellCount(); ++c) {
            const std::vector<int> faces = FacesOfCell(m, c);
            cells.insert(std::set<int>(faces.begin(), faces.end()));
        }
        return cells;
    };
    const std::set<std::set<int>> before = facesOfCells(s);
    int disc = -1, single = -1;
    for (int c = 0; c < s.CellCount(); ++c) {
        if (s.cellRegion[c] == 0) disc = c;
        if (s.cellRegion[c] == 2) single = c;
    }
    ASSERT_GE(disc, 0);
    ASSERT_GE(single, 0);
    const std::vector<int> discList = FacesOfCell(s, disc);
    const std::set<int> discFaces(discList.begin(), discList.end());
    ASSERT_GT(discFaces.size(), 20u);

    std::vector<char> flagged(s.CellCount(), 0);
    flagged[disc] = flagged[single] = 1;
    EXPECT_EQ(HalveCells(s, flagged), 1);  // a cell of one face cannot be halved
    ASSERT_TRUE(detail::BuildCellsAndLoops(s, error)) << error;
    const std::set<std::set<int>> after = facesOfCells(s);
    EXPECT_EQ(after.size(), before.size() + 1);
    // Every other cell is as it was; the disc's faces are now two cells of region 0, each a
    // disc (one boundary loop, traced above) with a fair share of the faces.
    std::set<int> halves;
    for (int c = 0; c < s.CellCount(); ++c) {
        const std::vector<int> list = FacesOfCell(s, c);
        const std::set<int> faces(list.begin(), list.end());
        if (s.cellRegion[c] != 0) {
            EXPECT_TRUE(before.count(faces)) << "cell " << c;
            continue;
        }
        EXPECT_GT(faces.size(), discFaces.size() / 4) << "cell " << c;
        halves.insert(faces.begin(), faces.end());
        EXPECT_EQ(s.cellLoop[c].size(), s.cellLoopOther[c].size());
    }
    EXPECT_EQ(halves, discFaces);
    EXPECT_EQ(std::count(s.cellRegion.begin(), s.cellRegion.end(), 0), 2);

    // The meshing halves nothing where nothing intersects.
    MeshingRun run;
    Mesh(flat.square, flat.partition, MeshingParam(), run);
    ExpectValidWithInputTopology(run);
    EXPECT_EQ(run.report.validity.selfIntersections, 0);
    EXPECT_EQ(run.report.outputHalvingRound, 0);
    EXPECT_EQ(run.report.cells, int(before.size()));
}

TEST(Meshing, CarvingCutsAShareOfTheCellAroundItsSeedAndLeavesTheOthers)
{
    // The flat square's middle disc, carved around its central face: the faces nearest to that
    // face (a quarter of the disc) make a cell, and the ring left around them is cut into discs.
    // A seed in a piece already cut adds none, and a cell of one face cannot be carved.
    FlatSquareSurface flat(DiscOneFaceAndRest);
    MeshingSurface &s = flat.s;
    const IndexedMesh &im = flat.im;
    ASSERT_EQ(s.FaceCount(), im.FaceCount());
    std::vector<std::vector<int>> before(s.CellCount());
    for (int c = 0; c < s.CellCount(); ++c) before[c] = FacesOfCell(s, c);
    int center = -1;
    for (int f = 0; f < s.FaceCount(); ++f)
        if (s.faceRegion[f] == 0 && (center < 0 || vsa_test::FaceCentroid(im, f).Norm() <
                                                       vsa_test::FaceCentroid(im, center).Norm()))
            center = f;
    ASSERT_GE(center, 0);
    const int disc = s.faceCell[center];
    const int discFaces = int(before[disc].size());
    ASSERT_GT(discFaces, 40);
    int beside = -1;  // a neighbour of the central face in the disc
    for (int g : s.neighbors[center])
        if (g >= 0 && s.faceCell[g] == disc) beside = g;
    ASSERT_GE(beside, 0);
    std::vector<int> hop(s.FaceCount(), -1);  // from the central face, within the disc
    std::vector<int> order = {center};
    hop[center] = 0;
    for (size_t head = 0; head < order.size(); ++head)
        for (int g : s.neighbors[order[head]])
            if (g >= 0 && s.faceCell[g] == disc && hop[g] < 0) {
                hop[g] = hop[order[head]] + 1;
                order.push_back(g);
            }
    ASSERT_EQ(int(order.size()), discFaces);

    EXPECT_EQ(CarveCells(s, {center, beside, 0}), 1);
    std::string error;
    ASSERT_TRUE(detail::BuildCellsAndLoops(s, error)) << error;
    // The other cells are as they were.
    for (int c = 0; c < s.CellCount(); ++c) {
        if (s.cellRegion[c] == 0) continue;
        EXPECT_NE(std::find(before.begin(), before.end(), FacesOfCell(s, c)), before.end()) << "cell " << c;
    }
    // The piece: the central face and the faces nearest to it, no farther than any other.
    const int piece = s.faceCell[center];
    EXPECT_EQ(s.faceCell[beside], piece);
    EXPECT_EQ(s.cellFaceOffset[piece + 1] - s.cellFaceOffset[piece], discFaces / detail::kCarvedShare);
    int farthestIn = 0, nearestOut = s.FaceCount();
    for (int f : before[disc]) {
        if (s.faceCell[f] == piece)
            farthestIn = std::max(farthestIn, hop[f]);
        else
            nearestOut = std::min(nearestOut, hop[f]);
    }
    EXPECT_LE(farthestIn, nearestOut);
    // The ring around it: discs of region 0 (each traced with one loop above), with the piece
    // covering the disc's faces.
    EXPECT_GE(std::count(s.cellRegion.begin(), s.cellRegion.end(), 0), 3);
    int regionFaces = 0;
    for (int c = 0; c < s.CellCount(); ++c)
        if (s.cellRegion[c] == 0) regionFaces += s.cellFaceOffset[c + 1] - s.cellFaceOffset[c];
    EXPECT_EQ(regionFaces, discFaces);
}

TEST(Meshing, CarvingSeedsAreWhereTheCellPassesNearestToTheFaceItMeets)
{
    // Two output faces of the flat square said to intersect: one of the middle disc's cell, one
    // just above an input face of the ring (cut into two cells). The disc's seed is its input face
    // nearest to the second; excluded cells, and cells kept as input faces, get no seed.
    const FlatSquareSurface flat([](int, double r) { return r < 0.5 ? 0 : 1; });
    const MeshingSurface &s = flat.s;
    const IndexedMesh &im = flat.im;
    int disc = -1;
    for (int c = 0; c < s.CellCount(); ++c)
        if (s.cellRegion[c] == 0) disc = c;
    ASSERT_GE(disc, 0);
    int nearestInDisc = -1, above = -1;  // the disc's face nearest to the ring face at (0.6, 0)
    const Point3d target(0.6, 0, 0);
    for (int f = 0; f < s.FaceCount(); ++f) {
        const double distance = (vsa_test::FaceCentroid(im, f) - target).Norm();
        auto nearer = [&](int g) { return g < 0 || distance < (vsa_test::FaceCentroid(im, g) - target).Norm(); };
        if (s.faceCell[f] == disc && nearer(nearestInDisc)) nearestInDisc = f;
        if (s.faceCell[f] != disc && nearer(above)) above = f;
    }
    const int ring = s.faceCell[above];
    detail::MeshingPass pass;
    const Point3d lifted = vsa_test::FaceCentroid(im, above) + Point3d(0, 0, 0.01);
    pass.positions = {Point3d(-0.4, -0.3, 0),           Point3d(0.4, -0.3, 0),
                      Point3d(0, 0.4, 0),               lifted + Point3d(-0.01, -0.01, 0),
                      lifted + Point3d(0.01, -0.01, 0), lifted + Point3d(0, 0.01, 0)};
    pass.triangles = {{0, 1, 2}, {3, 4, 5}};
    pass.triangleCell = {disc, ring};
    pass.cellMethod.assign(s.CellCount(), CellMethod::Flooding);
    detail::PassDefects defects;
    defects.intersections = {{0, 1}};
    std::vector<char> excluded(s.CellCount(), 0);
    excluded[ring] = 1;
    EXPECT_EQ(detail::CarvingSeeds(s, pass, defects, excluded), std::vector<int>{nearestInDisc});
    pass.cellMethod[disc] = CellMethod::InputFaces;
    excluded[ring] = 0;
    const std::vector<int> ringOnly = detail::CarvingSeeds(s, pass, defects, excluded);
    ASSERT_EQ(ringOnly.size(), 1u);
    EXPECT_EQ(s.faceCell[ringOnly[0]], ring);
}

TEST(Meshing, ClosedRegionsWithoutBoundary)
{
    TMesh sphere;
    vcg::tri::Sphere(sphere, 3);
    const IndexedMesh im = BuildIndexedMesh(sphere);
    const Partition one = vsa_test::PartitionByRule(im, 1, [](int) { return 0; });
    const Partition halves =
        vsa_test::PartitionByRule(im, 2, [&](int f) { return vsa_test::FaceCentroid(im, f)[2] > 0 ? 1 : 0; });
    for (const Partition *partition : {&one, &halves}) {
        MeshingRun run;
        Mesh(sphere, *partition, MeshingParam(), run);
        ExpectValidWithInputTopology(run);
        ExpectNoRegionDropped(run, *partition);
        EXPECT_EQ(run.report.validity.eulerCharacteristic, 2);
        EXPECT_GE(run.out.FN(), 4);
        // One region: its two halves meet along a cut whose anchors stay on the sphere, so
        // the output has volume. Two opposite planes, by contrast, make the faithful output
        // a flat double-sided polygon, whose two sides overlap: not checked.
        if (partition == &one) {
            EXPECT_EQ(run.report.validity.selfIntersections, 0);
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

TEST(Meshing, NonManifoldVertexIsSplitPerFan)
{
    // Two tetrahedra sharing only vertex 0.
    TMesh m;
    vsa_test::BuildFromLists(m, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}},
                             {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 5, 4}, {0, 4, 6}, {0, 6, 5}, {4, 5, 6}});
    const IndexedMesh im = BuildIndexedMesh(m);
    const Partition perFace = vsa_test::PartitionByRule(im, 8, [](int f) { return f; });
    MeshingRun run;
    Mesh(m, perFace, MeshingParam(), run);
    ASSERT_TRUE(run.report.ok) << run.report.error;
    EXPECT_EQ(run.report.splitVertices, 1);
    EXPECT_TRUE(run.report.validity.IsValid()) << run.report.validity.Summary();
    EXPECT_EQ(run.report.validity.nonManifoldVertices, 0);
    EXPECT_EQ(run.report.validity.components, 2);
    EXPECT_EQ(run.report.validity.eulerCharacteristic, 4);
    EXPECT_EQ(run.out.VN(), 8);  // each tetrahedron keeps its four corners
    EXPECT_EQ(run.out.FN(), 8);
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

TEST(Meshing, AnchorProjectionAveragesThePlanesAndIsCapped)
{
    // A cube whose corner (1,1,1) is off the three planes; proxies are the exact planes.
    TMesh cube;
    vsa_test::MakeTessellatedCube(cube, 2);
    for (auto &v : cube.vert)
        if (v.P() == vcg::Point3f(1, 1, 1)) v.P() = vcg::Point3f(1.03f, 1.01f, 0.98f);
    const IndexedMesh im = BuildIndexedMesh(cube);
    Partition p = vsa_test::DominantAxisPartition(im);
    for (int r = 0; r < 6; ++r) {
        Point3d n(0, 0, 0);
        n[r / 2] = r % 2 ? 1 : -1;
        p.proxies[r].normal = n;
        p.proxies[r].point = n;
    }
    const Point3d original = Point3d::Construct(vcg::Point3f(1.03f, 1.01f, 0.98f));
    // Average of the projections on x = 1, y = 1, z = 1.
    const Point3d expected = (Point3d(1, original[1], original[2]) + Point3d(original[0], 1, original[2]) +
                              Point3d(original[0], original[1], 1)) / 3.0;
    auto cornerOf = [](const TMesh &out, const MeshingReport &r, const IndexedMesh &in, const Point3d &source) {
        for (int v = 0; v < out.VN(); ++v)
            if (in.positions[r.vertexSource[v]] == source) return Point3d::Construct(out.vert[v].cP());
        return Point3d(0, 0, 0);
    };
    MeshingParam param;
    TMesh out;
    MeshingReport r = BuildApproximatingMesh(im, p, param, out);
    ASSERT_TRUE(r.ok);
    EXPECT_LT((cornerOf(out, r, im, original) - expected).Norm(), 1e-6);
    // Other corners were on their planes already.
    EXPECT_LT((cornerOf(out, r, im, Point3d(-1, -1, -1)) - Point3d(-1, -1, -1)).Norm(), 1e-7);

    param.projectAnchors = false;
    r = BuildApproximatingMesh(im, p, param, out);
    EXPECT_EQ(cornerOf(out, r, im, original), original);

    // Capped at maxAnchorMove times the shortest chord at the anchor (about 2).
    param.projectAnchors = true;
    param.maxAnchorMove = 0.002;
    r = BuildApproximatingMesh(im, p, param, out);
    const double moved = (cornerOf(out, r, im, original) - original).Norm();
    const double shortestChord = (original - Point3d(1, 1, -1)).Norm();
    EXPECT_NEAR(moved, 0.002 * shortestChord, 1e-6);
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

namespace {

/// A mesh cut into three regions, and what successive repair passes could require on its
/// cells' loops: loop vertices picked by a fixed pseudo-random sequence, so that anchors are
/// added and dropped in turn.
struct RepairSequence
{
    IndexedMesh mesh;
    Partition partition;
    MeshingSurface surface;
    std::vector<std::vector<char>> required;
};

void MakeRepairSequence(const TMesh &m, int steps, RepairSequence &r)
{
    r.mesh = BuildIndexedMesh(m);
    r.partition = vsa_test::PartitionByRule(r.mesh, 3, [&](int f) {
        const Point3d c = vsa_test::FaceCentroid(r.mesh, f);
        return c[0] < -0.3 ? 0 : (c[1] < 0.2 ? 1 : 2);
    });
    std::string error;
    ASSERT_TRUE(BuildMeshingSurface(r.mesh, r.partition.faceRegion, 3, r.surface, error)) << error;
    r.required.assign(1, {});
    unsigned state = 12345;
    for (int step = 0; step < steps; ++step) {
        std::vector<char> required(r.surface.VertexCount(), 0);
        for (const std::vector<int> &loop : r.surface.cellLoop)
            for (int v : loop) {
                state = state * 1103515245u + 12345u;
                required[v] = (state >> 16) % 7 == 0;
            }
        r.required.push_back(required);
    }
}

/// MakeRepairSequence on a hemisphere of 12 rings and 32 sectors.
void MakeHemisphereRepairSequence(int steps, RepairSequence &r)
{
    TMesh hemisphere;
    vsa_test::MakeHemisphere(hemisphere, 12, 32);
    MakeRepairSequence(hemisphere, steps, r);
}

/// Anchors by a chord subdivision made for this call alone.
AnchorSet FreshAnchors(const MeshingSurface &s, const std::vector<Proxy> &proxies, double chordThreshold,
                       const std::vector<char> &required = {})
{
    detail::ChainSubdivision subdivision(s, proxies, chordThreshold);
    return SelectAnchors(s, subdivision, required);
}

/// Floods every cell of `s` with `flooding`, and expects the colours of a flooding from scratch.
void ExpectFloodingFromScratch(const MeshingSurface &s, const AnchorSet &anchors, CellFlooding &flooding)
{
    for (int c = 0; c < s.CellCount(); ++c) {
        CellFlooding fresh(s);
        const std::vector<std::array<int, 3>> expected = fresh.Triples(c, anchors);
        EXPECT_GT(expected.size(), 0u);
        EXPECT_EQ(flooding.Triples(c, anchors), expected) << "cell " << c;
        EXPECT_EQ(flooding.VerticesDeepestFirst(c), fresh.VerticesDeepestFirst(c)) << "cell " << c;
    }
}

}  // namespace

// Repair passes update each cell's flooding instead of redoing it; the colours must be those
// of a flooding from scratch, anchors added or removed, ties between equal distances (the
// flat grid is full of them) included.
TEST(Meshing, UpdatedFloodingEqualsAFreshOne)
{
    TMesh square, hemisphere;
    vsa_test::MakeFlatSquare(square, 24);
    vsa_test::MakeHemisphere(hemisphere, 12, 32);
    for (const TMesh *m : {&square, &hemisphere}) {
        SCOPED_TRACE(m == &square ? "flat square" : "hemisphere");
        RepairSequence r;
        MakeRepairSequence(*m, 150, r);
        const MeshingSurface &s = r.surface;
        CellFlooding updated(s);
        for (const std::vector<char> &required : r.required)
            ExpectFloodingFromScratch(s, FreshAnchors(s, r.partition.proxies, 0.5, required), updated);
    }
}

// A halving round carries the floodings of the cells it did not halve over to the new surface
// (renumbered cells, new anchors where the cuts meet their loops): they must still update to
// the colours of a flooding from scratch, in every cell, halved or not.
TEST(Meshing, FloodingCarriedOverToHalvedCellsEqualsAFreshOne)
{
    RepairSequence r;
    MakeHemisphereRepairSequence(3, r);
    const MeshingSurface &s = r.surface;
    CellFlooding earlier(s);
    for (const std::vector<char> &required : r.required) {
        const AnchorSet anchors = FreshAnchors(s, r.partition.proxies, 0.5, required);
        for (int c = 0; c < s.CellCount(); ++c) earlier.Triples(c, anchors);
    }
    MeshingSurface halved = s;
    std::vector<char> flagged(s.CellCount(), 0);
    flagged[0] = 1;
    ASSERT_EQ(HalveCells(halved, flagged), 1);
    std::string error;
    ASSERT_TRUE(detail::BuildCellsAndLoops(halved, error)) << error;
    ASSERT_EQ(halved.CellCount(), s.CellCount() + 1);

    CellFlooding carried(halved, earlier);
    for (const std::vector<char> &required : {std::vector<char>(), r.required.back()})
        ExpectFloodingFromScratch(halved, FreshAnchors(halved, r.partition.proxies, 0.5, required), carried);
}

// Repair passes reuse the chord subdivision of the chains they did not change: the anchors
// must be those of a subdivision from scratch.
TEST(Meshing, RememberedChordSubdivisionEqualsAFreshOne)
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

// Keeping a cell's input faces cannot undo an intersection that is in the input: two
// overlapping cubes, one region per side, keep their 12 sides as meshed polygons, their
// intersections reported.
TEST(Meshing, IntersectionsOfTheInputItselfAreNotRepairedWithInputFaces)
{
    TMesh cube;
    vsa_test::MakeTessellatedCube(cube, 1);
    std::vector<vcg::Point3f> coords;
    std::vector<vcg::Point3i> tris;
    for (const vcg::Point3f &shift : {vcg::Point3f(0, 0, 0), vcg::Point3f(1, 1, 1)}) {
        const int first = int(coords.size());
        for (const auto &v : cube.vert) coords.push_back(v.cP() + shift);
        for (const auto &f : cube.face)
            tris.emplace_back(first + vcg::tri::Index(cube, f.cV(0)), first + vcg::tri::Index(cube, f.cV(1)),
                              first + vcg::tri::Index(cube, f.cV(2)));
    }
    TMesh cubes;
    vsa_test::BuildFromLists(cubes, coords, tris);
    const IndexedMesh im = BuildIndexedMesh(cubes);
    ASSERT_GT(detail::SelfIntersectingPairs(im).size(), 0u);
    const Partition partition = vsa_test::PartitionByRule(im, 12, [&](int f) {
        return vsa_test::DominantAxisLabel(vsa_test::FaceNormal(im, f)) + (f < cube.FN() ? 0 : 6);
    });
    MeshingRun run;
    Mesh(cubes, partition, MeshingParam(), run);
    ExpectValidWithInputTopology(run);
    EXPECT_EQ(run.out.FN(), 24);
    EXPECT_GT(run.report.validity.selfIntersections, 0);
    EXPECT_EQ(run.report.regionsKeptAsInput, 0);
    // The first pass and a repair round that pins the anchors; no pass keeping input faces, no
    // halving of cells.
    EXPECT_EQ(run.report.passes, 2);
    EXPECT_EQ(run.report.outputHalvingRound, 0);
}

TEST(Meshing, CrossingPolygonEdgesAreThoseOfTestingEveryPair)
{
    // Random polygons on a slanted plane, many of them self-crossing, on a coarse lattice so
    // that edges share x ranges, touch and overlap exactly: the sweep must report what
    // testing every pair of non-neighbouring edges does, in the same order.
    std::mt19937 random(11);
    const Point3d normal = Point3d(1, 2, 3).Normalize();
    const Point3d u = (Point3d(1, 0, 0) - normal * normal[0]).Normalize(), v = normal ^ u;
    size_t crossingsSeen = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const int n = 3 + int(random() % 40);
        std::vector<Point3d> positions;
        std::vector<int> polygon;
        for (int i = 0; i < n; ++i) {
            positions.push_back(u * double(random() % 8) + v * double(random() % 8));
            polygon.push_back(i);
        }
        const std::vector<vcg::Point2d> plane = detail::PolygonOnPlane(polygon, positions, normal);
        std::vector<std::pair<int, int>> expected;
        for (int i = 0; i < n; ++i)
            for (int j = i + 2; j < n; ++j)
                if (!(i == 0 && j == n - 1) &&
                    detail::SegmentsMeet2d(plane[i], plane[i + 1], plane[j], plane[(j + 1) % n]))
                    expected.emplace_back(i, j);
        EXPECT_EQ(detail::CrossingPolygonEdges(polygon, positions, normal), expected) << "polygon of " << n;
        crossingsSeen += expected.size();
    }
    EXPECT_GT(crossingsSeen, 1000u);
}

TEST(Meshing, OutputRegistryKnowsEveryEdgeAndFaceItWasGiven)
{
    // Thousands of faces (its tables grow many times), on small indices and on indices past
    // what fits three to a key; a face is known in any corner order, its edges both ways.
    OutputRegistry registry;
    std::set<std::array<int, 3>> faces;
    std::set<std::pair<int, int>> edges;
    unsigned state = 7;
    auto next = [&](int range) {
        state = state * 1103515245u + 12345u;
        return int((state >> 8) % unsigned(range));
    };
    for (int i = 0; i < 5000; ++i) {
        const int range = i % 3 == 0 ? 1 << 30 : 3000;
        std::array<int, 3> t = {next(range), next(range), next(range)};
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;
        registry.AddFace(t);
        faces.insert(OutputRegistry::Sorted(t));
        for (int k = 0; k < 3; ++k) edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
    }
    ASSERT_GT(faces.size(), 4000u);
    for (const auto &t : faces) {
        EXPECT_TRUE(registry.HasFace({t[2], t[0], t[1]}));
        EXPECT_TRUE(registry.HasEdge(t[1], t[0]));
    }
    // Near misses: corners of known faces, recombined.
    const std::vector<std::array<int, 3>> known(faces.begin(), faces.end());
    int unknownFaces = 0, unknownEdges = 0;
    for (int i = 0; i < 20000; ++i) {
        const int n = int(known.size());
        const std::array<int, 3> t = {known[next(n)][next(3)], known[next(n)][next(3)], known[next(n)][next(3)]};
        EXPECT_EQ(registry.HasFace(t), faces.count(OutputRegistry::Sorted(t)) != 0);
        EXPECT_EQ(registry.HasEdge(t[0], t[1]), edges.count(std::minmax(t[0], t[1])) != 0);
        unknownFaces += !registry.HasFace(t);
        unknownEdges += !registry.HasEdge(t[0], t[1]);
    }
    EXPECT_GT(unknownFaces, 10000);
    EXPECT_GT(unknownEdges, 10000);
}

TEST(Meshing, PolygonCrossingsAreCarriedOverOnlyForUnchangedPolygons)
{
    // One cell, a quadrilateral on z = 0: a square, then a bow tie (the same anchors, two of
    // them moved), then the same bow tie again. Its crossings are reused only while its
    // corners stay where they were.
    auto passWith = [](const std::vector<Point3d> &positions) {
        detail::MeshingPass pass;
        pass.anchors.vertexOfAnchor = {0, 1, 2, 3};
        pass.anchors.anchorOfVertex = {0, 1, 2, 3};
        pass.polygons = {{0, 1, 2, 3}};
        pass.positions = positions;
        pass.vertexSource = {0, 1, 2, 3};
        pass.cellMethod = {CellMethod::Flooding};
        pass.cellNormal = {Point3d(0, 0, 1)};
        pass.cellTriangles = {{0, 0}};
        return pass;
    };
    const detail::MeshingPass square = passWith({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    const detail::MeshingPass bowTie = passWith({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}});
    const detail::PassDefects squareDefects = detail::FindDefects(square, 0);
    EXPECT_TRUE(squareDefects.crossings.empty());
    const detail::PassDefects bowTieDefects = detail::FindDefects(bowTie, 0, &square, &squareDefects);
    ASSERT_EQ(bowTieDefects.crossings.size(), 1u);
    EXPECT_EQ(bowTieDefects.crossings[0].edge, 1);  // (1, 0)-(0, 1) across (1, 1)-(0, 0)
    EXPECT_EQ(bowTieDefects.crossings[0].otherEdge, 3);
    EXPECT_EQ(detail::FindDefects(bowTie, 0, &bowTie, &bowTieDefects).crossings.size(), 1u);
    EXPECT_TRUE(detail::FindDefects(square, 0, &bowTie, &bowTieDefects).crossings.empty());
}
