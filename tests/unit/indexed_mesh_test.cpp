#include "test_meshes.h"

#include <vsa/indexed_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <vector>

using namespace vcg::tri::vsa;
using vsa_test::TMesh;

TEST(IndexedMesh, TessellatedCubeIsClosedOrientedManifold)
{
    TMesh m;
    vsa_test::MakeTessellatedCube(m, 3);
    MeshDiagnostics diag;
    const IndexedMesh im = BuildIndexedMesh(m, &diag);
    EXPECT_EQ(im.FaceCount(), 6 * 2 * 9);
    EXPECT_EQ(im.VertexCount(), 6 * 3 * 3 + 2);  // Euler: V = F/2 + 2
    EXPECT_EQ(diag.borderEdges, 0);
    EXPECT_EQ(diag.nonManifoldEdges, 0);
    EXPECT_EQ(diag.nonManifoldVertices, 0);
    EXPECT_EQ(diag.inconsistentEdges, 0);
    EXPECT_EQ(diag.degenerateFaces, 0);
    EXPECT_EQ(im.componentCount, 1);
    for (int f = 0; f < im.FaceCount(); ++f)
        for (int i = 0; i < 3; ++i) {
            const int g = im.neighbors[f][i];
            ASSERT_GE(g, 0);
            // The neighbour walks the shared edge the other way.
            const int a = im.faces[f][i], b = im.faces[f][(i + 1) % 3];
            bool found = false;
            for (int j = 0; j < 3; ++j)
                found |= im.faces[g][j] == b && im.faces[g][(j + 1) % 3] == a;
            EXPECT_TRUE(found);
        }
}

TEST(IndexedMesh, ReportsBorderNonManifoldEdgeAndDegenerateFace)
{
    // Three triangles around edge 0-1 (a "book"), plus a zero-area triangle far away.
    TMesh m;
    vsa_test::BuildFromLists(m,
                             {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {5, 5, 5}, {6, 6, 6}, {7, 7, 7}},
                             {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {5, 6, 7}});
    MeshDiagnostics diag;
    const IndexedMesh im = BuildIndexedMesh(m, &diag);
    EXPECT_EQ(diag.nonManifoldEdges, 1);
    EXPECT_EQ(diag.borderEdges, 6 + 3);
    EXPECT_EQ(diag.degenerateFaces, 1);
    EXPECT_FALSE(diag.IsEdgeManifold());
    // The non-manifold edge joins nothing: every face is its own component.
    EXPECT_EQ(im.componentCount, 4);
    EXPECT_EQ(im.neighbors[0][0], -1);
}

TEST(IndexedMesh, ReportsNonManifoldVertexAndOrientation)
{
    // Two triangles touching at vertex 0 only; then a pair whose shared edge runs the same way.
    TMesh bowtie;
    vsa_test::BuildFromLists(bowtie, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}},
                             {{0, 1, 2}, {0, 3, 4}});
    MeshDiagnostics diag;
    BuildIndexedMesh(bowtie, &diag);
    EXPECT_EQ(diag.nonManifoldVertices, 1);
    EXPECT_EQ(diag.components, 2);

    TMesh flipped;
    vsa_test::BuildFromLists(flipped, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {{0, 1, 2}, {1, 2, 3}});
    BuildIndexedMesh(flipped, &diag);
    EXPECT_EQ(diag.inconsistentEdges, 1);
    EXPECT_FALSE(diag.IsOriented());
    EXPECT_EQ(diag.components, 1);
}

TEST(IndexedMesh, SkipsDeletedAndUnreferencedAndFlagsNaN)
{
    TMesh m;
    vsa_test::BuildFromLists(m, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {9, 9, 9}}, {{0, 1, 2}, {2, 1, 3}});
    vcg::tri::Allocator<TMesh>::DeleteFace(m, m.face[0]);
    m.vert[3].P()[0] = std::numeric_limits<float>::quiet_NaN();
    MeshDiagnostics diag;
    const IndexedMesh im = BuildIndexedMesh(m, &diag);
    EXPECT_EQ(im.FaceCount(), 1);
    EXPECT_EQ(im.sourceFace[0], 1);
    EXPECT_EQ(im.VertexCount(), 3);
    EXPECT_EQ(diag.unreferencedVertices, 2);  // vertex 0 (only in the deleted face) and 4
    EXPECT_EQ(diag.nonFiniteVertices, 1);
}

namespace {

/// Mean distance in the face arrays between two faces that share an edge: what the spatial
/// order is there to shrink.
double MeanNeighbourGap(const IndexedMesh &im)
{
    double sum = 0;
    int pairs = 0;
    for (int f = 0; f < im.FaceCount(); ++f)
        for (int g : im.neighbors[f])
            if (g > f) sum += g - f, ++pairs;
    return sum / pairs;
}

}  // namespace

TEST(IndexedMesh, SpatialOrderKeepsEveryFaceWithItsCornersAndBringsNeighboursClose)
{
    TMesh m;
    vsa_test::MakeTessellatedCube(m, 16);
    vsa_test::ShuffleFaces(m, 7);
    MeshDiagnostics asRead, inSpace;
    const IndexedMesh input = BuildIndexedMesh(m, &asRead);
    const vsa_test::SpatialOrderFrom always(0);
    const IndexedMesh im = BuildIndexedMesh(m, &inSpace, FaceOrder::kSpatialWhenLarge);

    ASSERT_EQ(im.FaceCount(), input.FaceCount());
    ASSERT_EQ(im.VertexCount(), input.VertexCount());
    std::vector<int> faces = im.sourceFace, vertices = im.sourceVertex, all(size_t(im.FaceCount()));
    std::sort(faces.begin(), faces.end());
    std::iota(all.begin(), all.end(), 0);
    EXPECT_EQ(faces, all);  // every face once
    std::sort(vertices.begin(), vertices.end());
    all.resize(size_t(im.VertexCount()));
    std::iota(all.begin(), all.end(), 0);
    EXPECT_EQ(vertices, all);
    for (int v = 0; v < im.VertexCount(); ++v)
        ASSERT_EQ(im.positions[v], vcg::Point3d::Construct(m.vert[im.sourceVertex[v]].cP()));
    for (int f = 0; f < im.FaceCount(); ++f)
        for (int k = 0; k < 3; ++k)  // the same corners in the same turn: orientation kept
            ASSERT_EQ(im.sourceVertex[im.faces[f][k]], int(m.face[im.sourceFace[f]].cV(k) - &m.vert[0]));

    // The same mesh as far as every check can tell.
    EXPECT_EQ(inSpace.Summary(), asRead.Summary());
    EXPECT_TRUE(inSpace.IsClosed() && inSpace.IsTwoManifold() && inSpace.IsOriented());

    // Along the curve: codes never decrease, and faces that share an edge are close in memory.
    const std::vector<uint32_t> code = detail::FaceSpaceCodes(im, FiniteBox(im.positions));
    EXPECT_TRUE(std::is_sorted(code.begin(), code.end()));
    EXPECT_GT(MeanNeighbourGap(input), 500);  // shuffled: about a third of the 3,072 faces
    EXPECT_LT(MeanNeighbourGap(im), 50);
}

TEST(IndexedMesh, SpatialOrderOnlyForLargeMeshesAndWhenAsked)
{
    TMesh m;
    vsa_test::MakeTessellatedCube(m, 4);
    vsa_test::ShuffleFaces(m, 3);
    for (const IndexedMesh &im : {BuildIndexedMesh(m, nullptr, FaceOrder::kSpatialWhenLarge), BuildIndexedMesh(m)})
        for (int f = 0; f < im.FaceCount(); ++f) ASSERT_EQ(im.sourceFace[f], f);
    const vsa_test::SpatialOrderFrom always(0);
    const IndexedMesh asRead = BuildIndexedMesh(m);
    for (int f = 0; f < asRead.FaceCount(); ++f) ASSERT_EQ(asRead.sourceFace[f], f);
    const IndexedMesh inSpace = BuildIndexedMesh(m, nullptr, FaceOrder::kSpatialWhenLarge);
    int moved = 0;
    for (int f = 0; f < inSpace.FaceCount(); ++f) moved += inSpace.sourceFace[f] != f;
    EXPECT_GT(moved, inSpace.FaceCount() / 2);
}
