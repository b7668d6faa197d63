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

TEST(SurfaceGrid, EmptyMeshHasNothingNear)
{
    const IndexedMesh empty;
    const SurfaceGrid grid(empty.positions, empty.faces);
    EXPECT_FALSE(grid.HasFaceWithin(Point3d(0, 0, 0), 1e9));
}
