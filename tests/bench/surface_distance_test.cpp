// The benchmark's surface measurement (bench/surface_distance.h) on meshes with known answers.
#include "test_meshes.h"

#include <surface_distance.h>

#include <gtest/gtest.h>

#include <utility>

namespace {

using vsa_test::TMesh;

/// Turns faces [first, last) of `m` over.
void FlipFaces(TMesh &m, size_t first, size_t last)
{
    for (size_t f = first; f < last; ++f) std::swap(m.face[f].V(1), m.face[f].V(2));
}

TEST(SurfaceDistance, SameCubeIsAtZeroAndFacesTheSameWay)
{
    TMesh cube, copy;
    vsa_test::MakeTessellatedCube(cube, 2);
    vsa_test::MakeTessellatedCube(copy, 2);
    const vsa_bench::SurfaceDistance d = vsa_bench::MeasureSurfaceDistance(cube, copy);
    ASSERT_TRUE(d.valid);
    EXPECT_NEAR(d.max, 0, 1e-6);
    EXPECT_EQ(d.facingAway, 0);
    EXPECT_NEAR(d.normalDeviationDeg, 0, 1e-3);
}

TEST(SurfaceDistance, FacingAwayIsTheAreaShareOfFlippedFaces)
{
    TMesh cube, turned;
    vsa_test::MakeTessellatedCube(cube, 2);  // 6 sides of 8 triangles, all of one area
    vsa_test::MakeTessellatedCube(turned, 2);
    FlipFaces(turned, 0, 8);  // one side
    const vsa_bench::SurfaceDistance d = vsa_bench::MeasureSurfaceDistance(cube, turned);
    ASSERT_TRUE(d.valid);
    EXPECT_NEAR(d.max, 0, 1e-6);  // the same surface: only the orientation differs
    EXPECT_NEAR(d.facingAway, 1.0 / 6, 1e-3);
    EXPECT_NEAR(d.normalDeviationDeg, 180.0 / 6, 0.2);  // a sixth of the area turned by 180 degrees

    FlipFaces(turned, 8, turned.face.size());
    const vsa_bench::SurfaceDistance all = vsa_bench::MeasureSurfaceDistance(cube, turned);
    EXPECT_EQ(all.facingAway, 1.0);
    EXPECT_NEAR(all.normalDeviationDeg, 180, 0.2);
}

}  // namespace
