// Tests of vsa/meshing_surface.h.
#include "meshing_fixtures.h"
#include "meshing_test_util.h"
#include "partition_test_helpers.h"
#include "test_meshes.h"

#include <vsa/meshing_surface.h>
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

TEST(MeshingSurface, IslandAndRingRegionsOnAFlatSquare)
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

TEST(MeshingSurface, ClosedRegionsWithoutBoundary)
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

TEST(MeshingSurface, NonManifoldVertexIsSplitPerFan)
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

TEST(MeshingSurface, WeldedVerticesAreSplitPerFanAfterTheOthers)
{
    // Two spheres welded at many vertices that share no edge: each welded vertex has two fans,
    // one per sphere, and splitting gives the second sphere's fan a vertex of its own, numbered
    // after the vertices used, which keep their order (the welded vertices' copies are unused).
    TMesh sphere;
    vcg::tri::Sphere(sphere, 3);
    IndexedMesh im = BuildIndexedMesh(sphere);
    const int vertices = im.VertexCount(), faces = im.FaceCount();
    std::vector<char> welded(vertices, 0), blocked(vertices, 0);
    int weldCount = 0;
    for (int f = 0; f < faces; f += 7) {
        const int v = im.faces[f][0];
        if (blocked[v]) continue;
        welded[v] = 1;
        ++weldCount;
        for (const auto &t : im.faces)  // its neighbours may not be welded too: no edge is shared
            if (t[0] == v || t[1] == v || t[2] == v)
                for (int w : t) blocked[w] = 1;
    }
    ASSERT_GT(weldCount, 20);
    for (int v = 0; v < vertices; ++v) im.positions.push_back(im.positions[v] + Point3d(0, 0, 3));
    for (int f = 0; f < faces; ++f) {
        std::array<int, 3> t = im.faces[f];
        for (int &v : t) v = welded[v] ? v : v + vertices;
        im.faces.push_back(t);
    }
    im.diagnostics.reset();  // its faces changed: the links are made again below
    MeshDiagnostics diag;
    detail::LinkFaces(im, diag);
    ASSERT_EQ(diag.nonManifoldEdges, 0);
    EXPECT_EQ(detail::CountNonManifoldVertices(im), weldCount);

    IndexedMesh split = im;
    std::vector<int> sourceVertex;
    EXPECT_EQ(detail::SplitVerticesPerFan(split, sourceVertex), weldCount);
    ASSERT_EQ(split.VertexCount(), 2 * vertices);
    const int used = split.VertexCount() - weldCount;
    for (int v = 1; v < used; ++v) ASSERT_LT(sourceVertex[v - 1], sourceVertex[v]);
    int seen = used;  // the extra fans' vertices, as the corners first use them
    for (const auto &t : split.faces)
        for (int v : t)
            if (v >= used) {
                ASSERT_LE(v, seen);
                seen += v == seen;
            }
    EXPECT_EQ(seen, split.VertexCount());
    for (int v = 0; v < split.VertexCount(); ++v) EXPECT_EQ(split.positions[v], im.positions[sourceVertex[v]]);
    for (int f = 0; f < faces; ++f)
        for (int i = 0; i < 3; ++i) {
            EXPECT_LT(split.faces[f][i], used);  // the first sphere's fans come first
            EXPECT_EQ(sourceVertex[split.faces[f][i]], im.faces[f][i]);
            EXPECT_EQ(sourceVertex[split.faces[f + faces][i]], im.faces[f + faces][i]);
            EXPECT_NE(split.faces[f][i], split.faces[f + faces][i]);
        }
}

namespace {

/// Checks that the surface of `im` built with the snapshot's links is the one built linking its
/// faces again (no diagnostics kept), array by array; returns the first.
MeshingSurface ExpectSameSurfaceAsRelinked(const IndexedMesh &im)
{
    IndexedMesh unlinked = im;
    unlinked.diagnostics.reset();
    MeshingSurface reused, relinked;
    std::string error;
    EXPECT_TRUE(BuildSurfaceTopology(im, reused, error)) << error;
    EXPECT_TRUE(BuildSurfaceTopology(unlinked, relinked, error)) << error;
    const auto same = [](const auto &a, const auto &b) {
        return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin());
    };
    EXPECT_TRUE(same(reused.positions, relinked.positions));
    EXPECT_TRUE(same(reused.sourceVertex, relinked.sourceVertex));
    EXPECT_TRUE(same(reused.faces, relinked.faces));
    EXPECT_TRUE(same(reused.neighbors, relinked.neighbors));
    EXPECT_TRUE(same(reused.sourceFace, relinked.sourceFace));
    EXPECT_TRUE(same(reused.vertexFaceOffset, relinked.vertexFaceOffset));
    EXPECT_TRUE(same(reused.vertexFaces, relinked.vertexFaces));
    EXPECT_EQ(reused.splitVertices, relinked.splitVertices);
    EXPECT_EQ(reused.ignoredFaces, relinked.ignoredFaces);
    return reused;
}

}  // namespace

TEST(MeshingSurface, ReusesTheSnapshotsLinksAsIfLinkedAgain)
{
    TMesh torus;
    MakeTorus(torus, 2, 0.5f, 40, 20);
    {
        // In space order, the corners first use the vertices out of their order: the surface
        // keeps the snapshot's numbers, with the links reused or not.
        const SpatialOrderFrom everyMesh(1);
        const IndexedMesh im = BuildIndexedMesh(torus, nullptr, FaceOrder::kSpatialWhenLarge);
        ASSERT_TRUE(im.diagnostics.has_value());
        const MeshingSurface s = ExpectSameSurfaceAsRelinked(im);
        std::vector<int> identity(s.sourceVertex.size());
        std::iota(identity.begin(), identity.end(), 0);
        EXPECT_EQ(static_cast<const std::vector<int> &>(s.sourceVertex), identity);
        EXPECT_EQ(s.splitVertices, 0);
    }
    {
        // Two tetrahedra sharing a vertex: linked, but with a vertex to split per fan.
        TMesh m;
        vsa_test::BuildFromLists(m, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}},
                                 {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 5, 4}, {0, 4, 6}, {0, 6, 5}, {4, 5, 6}});
        EXPECT_EQ(ExpectSameSurfaceAsRelinked(BuildIndexedMesh(m)).splitVertices, 1);
    }
    {
        // A face that repeats a vertex is left out: the surface's faces are not the snapshot's.
        TMesh m;
        vsa_test::BuildFromLists(m, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}},
                                 {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {4, 4, 1}});
        const MeshingSurface s = ExpectSameSurfaceAsRelinked(BuildIndexedMesh(m));
        EXPECT_EQ(s.ignoredFaces, 1);
        EXPECT_EQ(s.VertexCount(), 4);  // the vertex only that face used is dropped
    }
}

namespace {

/// A surface's cells and what is derived from them, as one string to compare.
std::string CellFingerprint(const MeshingSurface &s)
{
    std::string print;
    const auto add = [&print](const std::vector<int> &v) {
        for (int x : v) print += std::to_string(x) + ',';
        print += ';';
    };
    add(s.faceCell);
    add(s.cellRegion);
    add(s.cellComponentFace);
    add(s.cellFaces);
    for (const std::vector<int> &loop : s.cellLoop) add(loop);
    for (const std::vector<int> &other : s.cellLoopOther) add(other);
    add(std::vector<int>(s.junction.begin(), s.junction.end()));
    return print;
}

}  // namespace

TEST(MeshingSurface, CellsAreTheSameOnAnyNumberOfThreads)
{
    // Bands around the tube of a torus are rings, cut into two discs or more; every other band
    // is cut across into patches, which are discs, and opposite bands' patches share regions,
    // of two components each. Each region's cells are grown on a thread of their own and
    // numbered afterwards; relabelling (a band split in two, a band merged into a ring) grows
    // the changed regions again.
    TMesh torus;
    MakeTorus(torus, 2, 0.5f, 48, 24);
    const IndexedMesh im = BuildIndexedMesh(torus);
    const auto angle = [](double y, double x) { return std::atan2(y, x) + M_PI; };  // in [0, 2 pi]
    const auto labels = [&](int variant) {
        std::vector<int> label(im.FaceCount());
        for (int f = 0; f < im.FaceCount(); ++f) {
            const Point3d c = vsa_test::FaceCentroid(im, f);
            const int band = std::min(7, int(angle(c[1], c[0]) / (2 * M_PI) * 8));
            const Point3d axis(c[0], c[1], 0);
            const int patch = std::min(3, int(angle(c[2], axis.Norm() - 2) / (2 * M_PI) * 4));
            label[f] = band % 2 ? 8 + 4 * (band / 2 % 2) + patch : band;
            if (variant == 1 && band == 0 && patch < 2) label[f] = 24;  // a ring split in two
            if (variant == 1 && band == 3) label[f] = 2;                 // patches merged into a ring
        }
        return label;
    };
    std::string reference;
    for (int threads : {1, 2, 3, 8}) {
        const std::string print = WithThreads(threads, [&] {
            std::string error, print;
            MeshingSurface s, fresh;
            EXPECT_TRUE(BuildMeshingSurface(im, labels(0), 24, s, error)) << error;
            EXPECT_GT(s.CellCount(), 20);  // the rings are cut, the shared regions in two
            print = CellFingerprint(s);
            EXPECT_TRUE(AssignRegions(s, labels(1), 25, error)) << error;
            EXPECT_TRUE(BuildMeshingSurface(im, labels(1), 25, fresh, error)) << error;
            EXPECT_EQ(CellFingerprint(s), CellFingerprint(fresh)) << threads << " threads";
            return print + CellFingerprint(s);
        });
        if (reference.empty()) reference = print;
        EXPECT_TRUE(print == reference) << threads << " threads";
    }
}
