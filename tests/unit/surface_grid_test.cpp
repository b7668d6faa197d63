#include "meshing_test_util.h"
#include "test_meshes.h"

#include <vsa/surface_grid.h>
#include <vsa/indexed_mesh.h>

#include <gtest/gtest.h>

#include <random>

using namespace vcg::tri::vsa;
using vcg::Point3d;

namespace {

/// HasFaceWithin against a brute-force distance, on random points in and around the mesh's
/// box and radii from tiny to larger than the box; answers too close to call are skipped.
void ExpectMatchesBruteForce(const IndexedMesh &im, int queries)
{
    const SurfaceGrid grid(im.positions, im.faces);
    vcg::Box3d box;
    for (const Point3d &p : im.positions) box.Add(p);
    const double diagonal = box.Diag();
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0, 1);
    int near = 0, far = 0;
    for (int q = 0; q < queries; ++q) {
        Point3d p;
        for (int i = 0; i < 3; ++i)
            p[i] = box.min[i] - 0.25 * diagonal + unit(random) * (box.Dim()[i] + 0.5 * diagonal);
        const double radius = diagonal * std::pow(10.0, -4 + 4.3 * unit(random));
        const double distance = vsa_test::MaxDistanceToSurface({p}, im);
        if (std::abs(distance - radius) < 1e-9 * diagonal) continue;
        EXPECT_EQ(grid.HasFaceWithin(p, radius), distance <= radius) << "point " << p[0] << " " << p[1] << " " << p[2]
                                                                    << " radius " << radius << " distance " << distance;
        (distance <= radius ? near : far)++;
    }
    EXPECT_GT(near, queries / 10);  // both answers were exercised
    EXPECT_GT(far, queries / 10);
}

}  // namespace

TEST(SurfaceGrid, MatchesBruteForceOnATorus)
{
    vsa_test::TMesh torus;
    vsa_test::MakeTorus(torus, 1.f, 0.3f, 24, 12);
    ExpectMatchesBruteForce(BuildIndexedMesh(torus), 3000);
}

TEST(SurfaceGrid, MatchesBruteForceOnAFlatMesh)
{
    // Zero thickness in z: the grid's box must still hold the faces.
    vsa_test::TMesh square;
    vsa_test::MakeFlatSquare(square, 10);
    ExpectMatchesBruteForce(BuildIndexedMesh(square), 3000);
}

TEST(SurfaceGrid, MatchesBruteForceAmongBigSlantedFaces)
{
    // Big faces are bucketed only in the cells their plane crosses: none may be missed.
    ExpectMatchesBruteForce(vsa_test::RandomTriangleSoup(40, 400, 3), 3000);
}

TEST(SurfaceGrid, MatchesBruteForceAmongSlivers)
{
    // Long slivers are bucketed only in the cells they cross, which their boxes hold few of.
    ExpectMatchesBruteForce(vsa_test::RandomSlivers(300, 0.004, Point3d(0, 0, 0), 5), 3000);
    ExpectMatchesBruteForce(vsa_test::RandomSlivers(300, 0.004, Point3d(-3e5, 1e6, 2e5), 5), 3000);
}

TEST(SurfaceGrid, EmptyMeshHasNothingNear)
{
    const IndexedMesh empty;
    const SurfaceGrid grid(empty.positions, empty.faces);
    EXPECT_FALSE(grid.HasFaceWithin(Point3d(0, 0, 0), 1e9));
}

TEST(SurfaceGrid, FlatMeshFarFromTheOriginKeepsCellsOfPositiveSize)
{
    // Far from the origin a padding of the diagonal alone was lost to rounding: a unit square at
    // z = 1e12 kept a box of zero thickness, a cell size of 0, and cell indices of 0 / 0.
    for (double z : {1e12, 1e20, 3e38}) {
        const std::vector<Point3d> positions = {{0, 0, z}, {1, 0, z}, {1, 1, z}, {0, 1, z}};
        vcg::Box3d box;
        for (const Point3d &p : positions) box.Add(p);
        box.Offset(GridPadding(box));
        for (int i = 0; i < 3; ++i) EXPECT_GT(box.Dim()[i], 0) << "axis " << i << " at z = " << z;
        const std::vector<std::array<int, 3>> faces = {{0, 1, 2}, {0, 2, 3}};
        const SurfaceGrid grid(positions, faces);
        EXPECT_TRUE(grid.HasFaceWithin(Point3d(0.5, 0.25, z), 0)) << "z = " << z;
        EXPECT_FALSE(grid.HasFaceWithin(Point3d(2, 2, z), 0.5)) << "z = " << z;
    }
}

TEST(SurfaceGrid, PointsFarOutsideFallInTheCellsAtItsEdge)
{
    // Clamped before the conversion to int, which a quotient beyond its range would overflow.
    vsa_test::TMesh torus;
    vsa_test::MakeTorus(torus, 1.f, 0.3f, 24, 12);
    const IndexedMesh im = BuildIndexedMesh(torus);
    const SurfaceGrid grid(im.positions, im.faces);
    vcg::Box3d box;
    for (const Point3d &p : im.positions) box.Add(p);
    EXPECT_EQ(grid.CellOf(Point3d(1e300, 1e300, 1e300)), grid.CellOf(box.max));
    EXPECT_EQ(grid.CellOf(Point3d(-1e300, -1e300, -1e300)), grid.CellOf(box.min));
    EXPECT_EQ(grid.CellOf(box.min), vcg::Point3i(0, 0, 0));
}
