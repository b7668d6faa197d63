#include "meshing_test_util.h"
#include "test_meshes.h"

#include <vsa/mesh_validity.h>

#include <vcg/complex/algorithms/create/platonic.h>

#include <gtest/gtest.h>

using namespace vcg::tri::vsa;
using vsa_test::BareMesh;
using vsa_test::TMesh;
using vcg::Point3d;

namespace {

MeshValidity Check(const std::vector<vcg::Point3f> &coords, const std::vector<vcg::Point3i> &tris)
{
    TMesh m;
    vsa_test::BuildFromLists(m, coords, tris);
    return CheckMeshValidity(m);
}

}  // namespace

TEST(MeshValidity, CubeIsClosedOrientedManifoldWithEulerTwo)
{
    TMesh m;
    vsa_test::MakeTessellatedCube(m, 1);
    const MeshValidity v = CheckMeshValidity(m);
    EXPECT_EQ(v.vertices, 8);
    EXPECT_EQ(v.faces, 12);
    EXPECT_EQ(v.edges, 18);
    EXPECT_EQ(v.eulerCharacteristic, 2);
    EXPECT_EQ(v.components, 1);
    EXPECT_EQ(v.borderEdges, 0);
    EXPECT_EQ(v.nonManifoldEdges, 0);
    EXPECT_EQ(v.nonManifoldVertices, 0);
    EXPECT_EQ(v.inconsistentEdges, 0);
    EXPECT_EQ(v.degenerateFaces, 0);
    EXPECT_EQ(v.duplicateFaces, 0);
    EXPECT_EQ(v.selfIntersections, 0);
    EXPECT_TRUE(v.IsTwoManifold());
    EXPECT_TRUE(v.IsClosed());
    EXPECT_TRUE(v.IsOriented());
    EXPECT_TRUE(v.IsValid());
}

TEST(MeshValidity, FinerClosedMeshesHaveNoFalseIntersections)
{
    TMesh cube;
    vsa_test::MakeTessellatedCube(cube, 7);  // many coplanar neighbours sharing edges and vertices
    MeshValidity v = CheckMeshValidity(cube);
    EXPECT_EQ(v.selfIntersections, 0);
    EXPECT_EQ(v.eulerCharacteristic, 2);

    TMesh sphere;
    vcg::tri::Sphere(sphere, 3);
    v = CheckMeshValidity(sphere);
    EXPECT_EQ(v.faces, 20 * 64);
    EXPECT_EQ(v.selfIntersections, 0);
    EXPECT_EQ(v.eulerCharacteristic, 2);
    EXPECT_TRUE(v.IsClosed());
    EXPECT_TRUE(v.IsValid());
}

TEST(MeshValidity, OpenSquareHasFourBorderEdges)
{
    const MeshValidity v = Check({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
    EXPECT_EQ(v.vertices, 4);
    EXPECT_EQ(v.edges, 5);
    EXPECT_EQ(v.borderEdges, 4);
    EXPECT_EQ(v.eulerCharacteristic, 1);  // a disc
    EXPECT_FALSE(v.IsClosed());
    EXPECT_TRUE(v.IsTwoManifold());
    EXPECT_TRUE(v.IsOriented());
    EXPECT_EQ(v.selfIntersections, 0);  // the two faces are coplanar and share an edge
    EXPECT_TRUE(v.IsValid());
}

TEST(MeshValidity, NonManifoldEdgeAndVertex)
{
    // Three triangles on edge 0-1.
    MeshValidity v = Check({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
    EXPECT_EQ(v.nonManifoldEdges, 1);
    EXPECT_EQ(v.edges, 7);
    EXPECT_FALSE(v.IsTwoManifold());
    EXPECT_EQ(v.selfIntersections, 0);

    // Two tetrahedra sharing only vertex 0: closed, edge-manifold, one non-manifold vertex.
    v = Check({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}},
              {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 5, 4}, {0, 4, 6}, {0, 6, 5}, {4, 5, 6}});
    EXPECT_EQ(v.nonManifoldEdges, 0);
    EXPECT_EQ(v.nonManifoldVertices, 1);
    EXPECT_TRUE(v.IsClosed());
    EXPECT_TRUE(v.IsOriented());
    EXPECT_FALSE(v.IsTwoManifold());
    EXPECT_EQ(v.eulerCharacteristic, 7 - 12 + 8);
    EXPECT_EQ(v.selfIntersections, 0);
}

TEST(MeshValidity, TwoCrossingTrianglesIntersectOnce)
{
    const MeshValidity v = Check({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5f, 0.5f, -1}, {0.5f, 0.5f, 1}, {3, 3, 0}},
                                 {{0, 1, 2}, {3, 4, 5}});
    EXPECT_EQ(v.selfIntersections, 1);
    EXPECT_EQ(v.components, 2);
    EXPECT_FALSE(v.IsValid());

    // The same two, moved apart.
    const MeshValidity apart = Check({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {5.5f, 0.5f, -1}, {5.5f, 0.5f, 1}, {8, 3, 0}},
                                     {{0, 1, 2}, {3, 4, 5}});
    EXPECT_EQ(apart.selfIntersections, 0);
}

TEST(MeshValidity, IntersectionsThroughSharedVerticesAndFolds)
{
    // Sharing vertex 0, the second triangle pierces the first.
    MeshValidity v = Check({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, -1}, {1, 1, 1}}, {{0, 1, 2}, {0, 3, 4}});
    EXPECT_EQ(v.selfIntersections, 1);
    // Sharing vertex 0, leaning away: no intersection.
    v = Check({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {-1, -1, 1}, {-1, -2, 1}}, {{0, 1, 2}, {0, 3, 4}});
    EXPECT_EQ(v.selfIntersections, 0);
    // Coplanar, sharing edge 0-1, folded onto each other (third vertices on the same side).
    v = Check({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, 0}}, {{0, 1, 2}, {1, 0, 3}});
    EXPECT_EQ(v.selfIntersections, 1);
    // Coplanar fan triangles sharing vertex 0 whose sectors overlap.
    v = Check({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {2, 1, 0}, {1, 2, 0}}, {{0, 1, 2}, {0, 3, 4}});
    EXPECT_EQ(v.selfIntersections, 1);
    // Coplanar triangles sharing vertex 0 side by side: no overlap.
    v = Check({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {-2, 2, 0}}, {{0, 1, 2}, {0, 3, 4}});
    EXPECT_EQ(v.selfIntersections, 0);
    // Coplanar, disjoint vertices, one inside the other.
    v = Check({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0.5f, 0.5f, 0}, {1, 0.5f, 0}, {0.5f, 1, 0}}, {{0, 1, 2}, {3, 4, 5}});
    EXPECT_EQ(v.selfIntersections, 1);
}

TEST(MeshValidity, SliversSeenEdgeOnMeetOnlyWhereTheyAre)
{
    // A triangle without area in the plane contains the points of its edges, not its whole line.
    const std::array<vcg::Point2d, 3> edgeOn = {vcg::Point2d(0, 0), vcg::Point2d(0, 0), vcg::Point2d(2, 2)};
    EXPECT_TRUE(detail::PointInTriangle2d({1, 1}, edgeOn));
    EXPECT_TRUE(detail::PointInTriangle2d({2, 2}, edgeOn));
    EXPECT_FALSE(detail::PointInTriangle2d({3, 3}, edgeOn));
    EXPECT_FALSE(detail::PointInTriangle2d({-1, -1}, edgeOn));
    EXPECT_FALSE(detail::PointInTriangle2d({1, 0}, edgeOn));

    // Two slivers 1e12 long, 40 apart, each within 1 of the other's plane (kOnPlane times the
    // longest edge): tested as coplanar, the first seen edge-on from the second, on the line
    // through the second's far corner. A fuzz input's output had them, and the pass reported
    // them as meeting while the check of the written mesh, whose grid keeps them apart, did not.
    IndexedMesh slivers;
    slivers.positions = {{0, 1, 0},           {0, 0, 0},
                         {-40, -39.666667938232422, 333333331968},
                         {-120, -120, 999999995904},
                         {-120, -111, 0},     {-80, -77, 333333331968}};
    slivers.faces = {{0, 1, 2}, {3, 4, 5}};
    EXPECT_FALSE(detail::FacesIntersect(slivers, 0, 1));
    EXPECT_FALSE(detail::FacesIntersect(slivers, 1, 0));

    // The same, moved by 1e-15: the first, seen from the second, keeps a sliver of area, and the
    // rounding of the 2D test put the far corner inside it. Faces farther apart than the
    // tolerances do not meet, whatever the tests say.
    slivers.positions[0] = {9.6817835222768895e-16, 1, 7.7800048997201391e-17};
    slivers.positions[4] = {-120, -111, 1.0038767675479583e-15};
    EXPECT_FALSE(detail::FacesIntersect(slivers, 0, 1));
    EXPECT_FALSE(detail::FacesIntersect(slivers, 1, 0));
}

TEST(MeshValidity, CoincidentCornersCountAsShared)
{
    // An unmerged square (each triangle with its own vertices) and two triangles meeting at
    // one point from two copies of it: touching, not intersecting.
    MeshValidity v = Check({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {3, 4, 5}});
    EXPECT_EQ(v.selfIntersections, 0);
    EXPECT_EQ(v.borderEdges, 6);
    v = Check({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {-1, 0, 1}, {0, -1, 1}}, {{0, 1, 2}, {3, 4, 5}});
    EXPECT_EQ(v.selfIntersections, 0);
    // But an unmerged copy folded onto its neighbour does intersect.
    v = Check({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {2, 0, 0}, {0, 0, 0}, {1, 1, 0}}, {{0, 1, 2}, {4, 3, 5}});
    EXPECT_EQ(v.selfIntersections, 1);
}

TEST(MeshValidity, DuplicateDegenerateAndFlippedFaces)
{
    MeshValidity v = Check({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 2, 2}, {3, 3, 3}, {4, 4, 4}},
                           {{0, 1, 2}, {0, 1, 2}, {2, 1, 0}, {3, 4, 5}});
    EXPECT_EQ(v.duplicateFaces, 2);
    EXPECT_EQ(v.degenerateFaces, 1);
    EXPECT_EQ(v.selfIntersections, 0);  // duplicates and degenerate faces are counted as such only
    EXPECT_FALSE(v.IsValid());

    v = Check({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {{0, 1, 2}, {1, 2, 3}});
    EXPECT_EQ(v.inconsistentEdges, 1);
    EXPECT_FALSE(v.IsOriented());
}

TEST(MeshValidity, WorksOnABareDoubleMeshAndCanSkipIntersections)
{
    BareMesh m;
    vcg::tri::Hexahedron(m);  // quads split: 8 vertices, 12 faces
    MeshValidity v = CheckMeshValidity(m);
    EXPECT_EQ(v.faces, 12);
    EXPECT_EQ(v.eulerCharacteristic, 2);
    EXPECT_EQ(v.selfIntersections, 0);
    EXPECT_TRUE(v.IsValid());
    v = CheckMeshValidity(m, false);
    EXPECT_EQ(v.selfIntersections, -1);
    EXPECT_NE(v.Summary().find("not checked"), std::string::npos);

    BareMesh empty;
    v = CheckMeshValidity(empty);
    EXPECT_EQ(v.faces, 0);
    EXPECT_EQ(v.selfIntersections, 0);
}

TEST(MeshValidity, GridFindsTheSamePairsAsTestingEveryPair)
{
    // Big slanted faces among small ones: the grid must offer every pair that meets, and
    // with a fresh mask every such pair with a fresh face, each once.
    const IndexedMesh soup = vsa_test::RandomTriangleSoup(60, 600, 5);
    const std::vector<char> degenerate = detail::DegenerateFaceMask(soup);
    std::vector<char> fresh(soup.FaceCount(), 0);
    for (int f = 0; f < soup.FaceCount(); f += 3) fresh[f] = 1;
    std::vector<std::pair<int, int>> all, withFresh;
    for (int f = 0; f < soup.FaceCount(); ++f)
        for (int g = f + 1; g < soup.FaceCount(); ++g)
            if (!degenerate[f] && !degenerate[g] && detail::FacesIntersect(soup, f, g)) {
                all.emplace_back(f, g);
                if (fresh[f] || fresh[g]) withFresh.emplace_back(f, g);
            }
    ASSERT_GT(withFresh.size(), 100u);
    EXPECT_EQ(detail::SelfIntersectingPairs(soup, degenerate, {}), all);
    EXPECT_EQ(detail::SelfIntersectingPairs(soup, degenerate, fresh), withFresh);
}

namespace {

/// Pairs of `faces` on `positions` that intersect, or come within `clearance` of each other.
std::vector<std::pair<int, int>> PairsWithin(const std::vector<Point3d> &positions,
                                             const std::vector<std::array<int, 3>> &faces, double clearance)
{
    IndexedMesh im;
    im.positions = positions;
    im.faces = faces;
    return detail::SelfIntersectingPairs(im, detail::DegenerateFaceMask(im), {}, clearance);
}

}  // namespace

// A quad folded by `lift` along its diagonal B-D, and a fin on its other diagonal A-C: the fin's
// edge runs `lift` above the quad, so the faces meet only once their corners move by about that
// (as cheese's output at k=20 did once saved as text and read back in double).
TEST(MeshValidity, ClearanceCountsFacesNearlyMeetingAsIntersecting)
{
    auto finOverQuad = [](double lift) {
        return std::vector<Point3d>{{0, 0, lift}, {1, 0, 0}, {1, 1, lift}, {0, 1, 0}, {0.5, 0.5, 1}};
    };
    const std::vector<std::array<int, 3>> faces = {{0, 1, 3}, {1, 2, 3}, {0, 2, 4}};
    const std::vector<std::pair<int, int>> both = {{0, 2}, {1, 2}};
    EXPECT_TRUE(PairsWithin(finOverQuad(1e-9), faces, 0).empty());
    EXPECT_EQ(PairsWithin(finOverQuad(1e-9), faces, 1e-6), both);
    EXPECT_TRUE(PairsWithin(finOverQuad(1e-4), faces, 1e-6).empty());
    EXPECT_EQ(PairsWithin(finOverQuad(0), faces, 0), both);  // flat: the fin's edge lies on the quad

    // Sharing edge 0-1, the other corners within the clearance of one half-plane (folded flat,
    // at an angle of 5e-4 rad the exact test does not see), then clearly apart.
    auto folded = [](double height) {
        return std::vector<Point3d>{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1e-3, height}};
    };
    const std::vector<std::array<int, 3>> hinge = {{0, 1, 2}, {1, 0, 3}};
    EXPECT_TRUE(PairsWithin(folded(5e-7), hinge, 0).empty());
    EXPECT_EQ(PairsWithin(folded(5e-7), hinge, 1e-6), (std::vector<std::pair<int, int>>{{0, 1}}));
    EXPECT_TRUE(PairsWithin(folded(5e-5), hinge, 1e-6).empty());

    // Disjoint faces: parallel, 5e-7 apart, then crossing planes with a 5e-7 gap between edges.
    EXPECT_EQ(PairsWithin({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.1, 0.1, 5e-7}, {1, 0.1, 5e-7}, {0.1, 1, 5e-7}},
                          {{0, 1, 2}, {3, 4, 5}}, 1e-6)
                  .size(),
              1u);
    EXPECT_EQ(PairsWithin({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0.5 + 5e-7, -1}, {0.5, 0.5 + 5e-7, 1}, {2, 2, 0}},
                          {{0, 1, 2}, {3, 4, 5}}, 1e-6)
                  .size(),
              1u);
    EXPECT_TRUE(PairsWithin({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0.5 + 1e-3, -1}, {0.5, 0.5 + 1e-3, 1}, {2, 2, 0}},
                            {{0, 1, 2}, {3, 4, 5}}, 1e-6)
                    .empty());
}

// Neighbouring faces of clean meshes touch at their shared corners only: a clearance finds
// nothing there, on fans of coplanar faces, around the vertices of a sphere or a torus, and on
// a real CAD mesh.
TEST(MeshValidity, ClearanceFindsNothingBetweenNeighboursOfCleanMeshes)
{
    std::vector<TMesh> meshes(4);
    vsa_test::MakeTessellatedCube(meshes[0], 7);
    vcg::tri::Sphere(meshes[1], 4);
    vsa_test::MakeTorus(meshes[2], 1, 0.3f, 64, 24);
    ASSERT_TRUE(vsa_test::LoadMesh(meshes[3], vsa_test::CgalMesh("fandisk.off")));
    for (const TMesh &m : meshes) {
        const IndexedMesh im = BuildIndexedMesh(m);
        const double clearance = detail::SavedCoordinateClearance<float>(im.positions);
        EXPECT_GT(clearance, 0);
        EXPECT_TRUE(detail::SelfIntersectingPairs(im, detail::DegenerateFaceMask(im), {}, clearance).empty());
    }
}

TEST(MeshValidity, GridFindsTheSamePairsAsTestingEveryPairWithAClearance)
{
    const IndexedMesh soup = vsa_test::RandomTriangleSoup(60, 600, 5);
    const std::vector<char> degenerate = detail::DegenerateFaceMask(soup);
    const double clearance = 0.005;
    std::vector<std::pair<int, int>> exact, within;
    for (int f = 0; f < soup.FaceCount(); ++f)
        for (int g = f + 1; g < soup.FaceCount(); ++g) {
            if (degenerate[f] || degenerate[g]) continue;
            if (detail::FacesIntersect(soup, f, g)) exact.emplace_back(f, g);
            if (detail::FacesIntersect(soup, f, g, clearance)) within.emplace_back(f, g);
        }
    ASSERT_GT(within.size(), exact.size() + 20);
    EXPECT_TRUE(std::includes(within.begin(), within.end(), exact.begin(), exact.end()));
    EXPECT_EQ(detail::SelfIntersectingPairs(soup, degenerate, {}, clearance), within);
}

// Long slivers cross few of the cells their boxes hold, and the grid keeps each in those alone
// (SurfaceGrid::CellsCrossedBy): no pair within the clearance may be missed, near the origin or
// far from it, where plain coordinates lose the small differences the cells are tested by.
TEST(MeshValidity, GridFindsTheSamePairsAsTestingEveryPairAmongSlivers)
{
    for (const Point3d &offset : {Point3d(0, 0, 0), Point3d(-3e5, 1e6, 2e5)})
        for (const double clearance : {0.0, 0.002}) {
            const IndexedMesh soup = vsa_test::RandomSlivers(500, 0.004, offset, 11);
            const std::vector<char> degenerate = detail::DegenerateFaceMask(soup);
            std::vector<std::pair<int, int>> within;
            for (int f = 0; f < soup.FaceCount(); ++f)
                for (int g = f + 1; g < soup.FaceCount(); ++g)
                    if (!degenerate[f] && !degenerate[g] && detail::FacesIntersect(soup, f, g, clearance))
                        within.emplace_back(f, g);
            ASSERT_GT(within.size(), 50u) << "clearance " << clearance;
            EXPECT_EQ(detail::SelfIntersectingPairs(soup, degenerate, {}, clearance), within)
                << "offset " << offset[1] << ", clearance " << clearance;
        }
}

// A face grown by the margin stands for the points within the margin of it, beyond its edges
// too: a small face beside a long sliver, closer than the clearance but in cells of its own
// (made small by a fine square below), is found with it.
TEST(MeshValidity, GridFindsAFaceBesideASliverWithinTheClearance)
{
    vsa_test::TMesh square;
    vsa_test::MakeFlatSquare(square, 150);
    IndexedMesh im = BuildIndexedMesh(square);
    for (Point3d &p : im.positions) p[2] = -0.5;
    const int n = int(im.positions.size());
    for (const Point3d &p : {Point3d(-0.9, 0, 0), Point3d(0.9, 0.01, 0), Point3d(0, -0.01, 0),  // the sliver
                             Point3d(0, 0.04, 0), Point3d(0.01, 0.05, 0), Point3d(0, 0.05, 0)})   // beside it
        im.positions.push_back(p);
    im.faces.push_back({n, n + 1, n + 2});
    im.faces.push_back({n + 3, n + 4, n + 5});
    const int sliver = im.FaceCount() - 2, beside = im.FaceCount() - 1;
    const std::vector<char> degenerate = detail::DegenerateFaceMask(im);
    ASSERT_FALSE(detail::FacesIntersect(im, sliver, beside, 0.02));
    ASSERT_TRUE(detail::FacesIntersect(im, sliver, beside, 0.04));
    std::vector<std::pair<int, int>> pairs;  // the square's own faces are within the clearance of each other
    for (const auto &pair : detail::SelfIntersectingPairs(im, degenerate, {}, 0.04))
        if (pair.second >= sliver) pairs.push_back(pair);
    EXPECT_EQ(pairs, (std::vector<std::pair<int, int>>{{sliver, beside}}));
}
