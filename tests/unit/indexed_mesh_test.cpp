#include "test_meshes.h"

#include <vsa/indexed_mesh.h>

#include <gtest/gtest.h>

#include <limits>

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
