// ApproximateShape, the whole pipeline in one call: what it gives, and how it refuses.
#include "test_meshes.h"

#include <vsa/approximate_shape.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace {

using namespace vcg::tri::vsa;
using vsa_test::TMesh;

int progressCalls = 0;
bool CountProgress(int, const char *)
{
    ++progressCalls;
    return true;
}

/// Runs ApproximateShape with k proxies, counting progress calls in progressCalls.
ShapeApproximationResult ApproximateCounted(const TMesh &in, TMesh &out, int k)
{
    ShapeApproximationParam param;
    param.partition.proxyCount = k;
    progressCalls = 0;
    return ApproximateShape(in, out, param, &CountProgress);
}

TEST(ApproximateShape, CubeBecomesItsSixSides)
{
    TMesh cube, out;
    vsa_test::MakeTessellatedCube(cube, 4);
    const ShapeApproximationResult r = ApproximateCounted(cube, out, 6);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(out.VN(), 8);
    EXPECT_EQ(out.FN(), 12);
    EXPECT_EQ(r.meshing.regions, 6);
    EXPECT_GT(progressCalls, 0);
    ASSERT_EQ(r.inputFaceRegion.size(), cube.face.size());
    for (size_t f = 0; f < cube.face.size(); ++f) EXPECT_GE(r.inputFaceRegion[f], 0);
}

/// Large meshes are approximated with their faces in space order; every input face must still
/// get the region of its own side.
TEST(ApproximateShape, FacesInSpaceOrderKeepTheirOwnRegions)
{
    TMesh cube, out;
    vsa_test::MakeTessellatedCube(cube, 6);
    vsa_test::ShuffleFaces(cube, 11);
    const vsa_test::SpatialOrderFrom always(0);
    const ShapeApproximationResult r = ApproximateCounted(cube, out, 6);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(out.FN(), 12);
    ASSERT_EQ(r.inputFaceRegion.size(), cube.face.size());
    std::vector<int> sideRegion(6, -1);
    for (size_t f = 0; f < cube.face.size(); ++f) {
        const vcg::Point3f n = cube.face[f].cN();
        int side = -1;
        for (int axis = 0; axis < 3; ++axis)
            if (std::abs(n[axis]) > 0.5f) side = 2 * axis + (n[axis] > 0);
        ASSERT_GE(side, 0);
        if (sideRegion[side] < 0) sideRegion[side] = r.inputFaceRegion[f];
        ASSERT_EQ(r.inputFaceRegion[f], sideRegion[side]) << "face " << f;
    }
    std::sort(sideRegion.begin(), sideRegion.end());
    EXPECT_EQ(std::unique(sideRegion.begin(), sideRegion.end()) - sideRegion.begin(), 6);
    EXPECT_GE(sideRegion[0], 0);
}

/// A mesh the meshing cannot take is refused with the meshing's reason before any partitioning
/// (no progress reported), when its own edge counts are the meshing's.
TEST(ApproximateShape, RefusesWhatItCannotMeshBeforePartitioning)
{
    auto expectRefusedUpFront = [](const TMesh &m, const std::string &words) {
        TMesh out;
        const ShapeApproximationResult r = ApproximateCounted(m, out, 1);
        EXPECT_FALSE(r.ok);
        EXPECT_NE(r.error.find(words), std::string::npos) << r.error;
        EXPECT_EQ(progressCalls, 0) << r.error;
        EXPECT_EQ(out.FN(), 0);
    };
    TMesh book;  // three faces on one edge
    vsa_test::BuildFromLists(book, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}},
                             {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
    expectRefusedUpFront(book, "non-manifold edges");

    TMesh cube;  // one face turned over: three edges walked the same way twice
    vsa_test::MakeTessellatedCube(cube, 3);
    std::swap(cube.face[5].V(1), cube.face[5].V(2));
    expectRefusedUpFront(cube, "not consistently oriented (3 edges");
}

/// With a face that repeats a vertex (which the meshing leaves out, so that the input's edge
/// counts are not its own) the meshing still refuses an unoriented mesh, for the same reason.
TEST(ApproximateShape, RefusesAnUnorientedMeshWithARepeatedVertexFaceToo)
{
    TMesh cube, out;
    vsa_test::MakeTessellatedCube(cube, 3);
    std::swap(cube.face[5].V(1), cube.face[5].V(2));
    vcg::tri::Allocator<TMesh>::AddFace(cube, &cube.vert[0], &cube.vert[0], &cube.vert[1]);
    const ShapeApproximationResult r = ApproximateCounted(cube, out, 6);
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("not consistently oriented (3 edges"), std::string::npos) << r.error;
    EXPECT_EQ(out.FN(), 0);
}

/// Every output coordinate finite, and the report saying so.
void ExpectFiniteOutput(const TMesh &out, const ShapeApproximationResult &r)
{
    for (const auto &v : out.vert)
        EXPECT_TRUE(vcg::tri::vsa::IsFinite(vcg::Point3d::Construct(v.cP()))) << "vertex " << (&v - &out.vert[0]);
    EXPECT_EQ(r.meshing.validity.nonFiniteVertices, 0);
}

/// An open triangular prism around 1e37 with a corner at z = FLT_MAX (k=3, L2, random seeding,
/// anchors projected): projecting that corner on the planes took it beyond FLT_MAX, and the
/// float output got an infinite coordinate while the report said valid.
TEST(ApproximateShape, ProjectedAnchorsStayWithinTheFloatRange)
{
    const float s = std::ldexp(1.f, 121), top = std::numeric_limits<float>::max();
    TMesh prism, out;
    vsa_test::BuildFromLists(prism,
                             {{0, -3 * s, s}, {0, 2 * s, 3 * s}, {0, 3 * s, -s},
                              {3 * s, -3 * s, top}, {3 * s, 2 * s, 3 * s}, {3 * s, 3 * s, -s}},
                             {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}, {2, 0, 3}, {2, 3, 5}});
    ShapeApproximationParam param;
    param.partition.proxyCount = 3;
    param.partition.metric = MetricKind::L2;
    param.partition.init = SeedingMethod::Random;
    param.partition.randomSeed = 46;
    const ShapeApproximationResult r = ApproximateShape(prism, out, param);
    ASSERT_TRUE(r.ok) << r.error;
    ExpectFiniteOutput(out, r);
    EXPECT_TRUE(r.meshing.validity.IsValid()) << r.meshing.validity.Summary();
}

/// In `tetrahedron`, the unit one's corners times `scale`, except vertex 1 at x = `x1`.
void MakeScaledTetrahedron(vsa_test::BareMesh &tetrahedron, double scale, double x1)
{
    const std::vector<vcg::Point3d> coords = {{0, 0, 0}, {x1, 0, 0}, {0, scale, 0}, {0, 0, scale}};
    vcg::tri::BuildMeshFromCoordVectorIndexVector(
        tetrahedron, coords, std::vector<vcg::Point3i>{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}});
}

/// Coordinates beyond the float range (a double mesh, pymeshlab's) are refused: areas and moments
/// could overflow, and a float output could not hold them. So is a double mesh smaller than the
/// smallest normal float: at 1e-90 its moments underflowed, and the output of a cube had 22
/// degenerate faces; at 1e-200 even the squares of its diagonal do. At 1e-30 (above that bound)
/// it is approximated.
TEST(ApproximateShape, RefusesMeshesBeyondTheFloatRange)
{
    ShapeApproximationParam param;
    param.partition.proxyCount = 4;
    struct Case
    {
        double scale, x1;
        const char *message;
    };
    for (const Case &c : {Case{1, 1e39, "(the float range)"}, Case{1e-90, 1e-90, "(the smallest normal float)"},
                          Case{1e-200, 1e-200, "(the smallest normal float)"},
                          Case{1e-39, 1e-39, "(the smallest normal float)"}, Case{1e-30, 1e-30, nullptr}}) {
        vsa_test::BareMesh tetrahedron;
        MakeScaledTetrahedron(tetrahedron, c.scale, c.x1);
        TMesh out;
        const ShapeApproximationResult r = ApproximateShape(tetrahedron, out, param);
        if (!c.message) {
            EXPECT_TRUE(r.ok) << r.error;
            EXPECT_EQ(out.FN(), 4);
            continue;
        }
        EXPECT_FALSE(r.ok) << c.scale;
        EXPECT_NE(r.error.find(c.message), std::string::npos) << r.error;
        EXPECT_EQ(out.FN(), 0);
    }
}

/// A unit square flat in the plane z = 1e12 (or 1e20), k=1: the grids' boxes kept no thickness
/// there, and cell indices came out of 0 / 0 (undefined behaviour, caught under UBSan).
TEST(ApproximateShape, FlatSquareFarFromTheOrigin)
{
    for (float z : {1e12f, 1e20f}) {
        TMesh square, out;
        vsa_test::BuildFromLists(square, {{0, 0, z}, {1, 0, z}, {1, 1, z}, {0, 1, z}}, {{0, 1, 2}, {0, 2, 3}});
        const ShapeApproximationResult r = ApproximateCounted(square, out, 1);
        ASSERT_TRUE(r.ok) << r.error;
        EXPECT_EQ(out.FN(), 2);
        EXPECT_EQ(out.VN(), 4);
        ExpectFiniteOutput(out, r);
        EXPECT_TRUE(r.meshing.validity.IsValid()) << r.meshing.validity.Summary();
    }
}

/// Deleted faces and vertices, as MeshLab leaves them before compacting, are left out: the
/// output is the compact mesh's, and deleted faces have no region.
TEST(ApproximateShape, DeletedElementsAreLeftOut)
{
    TMesh compact, withDeleted, out, outOfCompact;
    vsa_test::MakeTessellatedCube(compact, 3);
    vsa_test::MakeTessellatedCube(withDeleted, 3);
    auto extra = vcg::tri::Allocator<TMesh>::AddVertices(withDeleted, 2);
    extra[0].P() = vcg::Point3f(5, 5, 5);
    extra[1].P() = vcg::Point3f(std::numeric_limits<float>::quiet_NaN(), 0, 0);
    vcg::tri::Allocator<TMesh>::AddFace(withDeleted, &withDeleted.vert[0], &withDeleted.vert[1],
                                         &withDeleted.vert[withDeleted.vert.size() - 2]);
    vcg::tri::Allocator<TMesh>::DeleteFace(withDeleted, withDeleted.face.back());
    vcg::tri::Allocator<TMesh>::DeleteFace(withDeleted, withDeleted.face[7]);
    vcg::tri::Allocator<TMesh>::DeleteVertex(withDeleted, withDeleted.vert.back());
    vcg::tri::Allocator<TMesh>::DeleteVertex(withDeleted, withDeleted.vert[withDeleted.vert.size() - 2]);
    vcg::tri::Allocator<TMesh>::DeleteFace(compact, compact.face[7]);
    vcg::tri::Allocator<TMesh>::CompactEveryVector(compact);

    const ShapeApproximationResult r = ApproximateCounted(withDeleted, out, 6);
    const ShapeApproximationResult rc = ApproximateCounted(compact, outOfCompact, 6);
    ASSERT_TRUE(r.ok) << r.error;
    ASSERT_TRUE(rc.ok) << rc.error;
    EXPECT_EQ(r.input.faces, compact.FN());
    ASSERT_EQ(out.VN(), outOfCompact.VN());
    ASSERT_EQ(out.FN(), outOfCompact.FN());
    for (int v = 0; v < out.VN(); ++v) EXPECT_EQ(out.vert[v].cP(), outOfCompact.vert[v].cP());
    ASSERT_EQ(r.inputFaceRegion.size(), withDeleted.face.size());
    for (size_t f = 0; f < withDeleted.face.size(); ++f)
        EXPECT_EQ(r.inputFaceRegion[f] < 0, withDeleted.face[f].IsD()) << "face " << f;
}

}  // namespace
