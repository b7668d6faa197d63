// Tests of vsa/anchors.h.
#include "meshing_fixtures.h"
#include "meshing_test_util.h"
#include "output_quality.h"  // bench/: the benchmarks' polygons of an output
#include "test_meshes.h"

#include <vsa/anchors.h>
#include <vsa/approximate_shape.h>
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

TEST(Anchors, AnchorProjectionAveragesThePlanesAndIsCapped)
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
    param.planarPolygons = false;  // the three sides around the corner would then move it on to flatten them
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

/// A dome on a flat disc: the anchors around the disc are shared with the dome's regions,
/// whose planes tilt. The disc is flat, so they go onto its plane, not to the average of the
/// planes (which would lift them and bend the disc's polygon).
TEST(Anchors, FlatRegionKeepsItsAnchorsOnItsPlane)
{
    TMesh dome, out;
    vsa_test::MakeHemisphere(dome, 8, 32, /*flat=*/false, /*base=*/true);
    ShapeApproximationParam param;
    param.partition.proxyCount = 12;
    const ShapeApproximationResult r = ApproximateShape(dome, out, param);
    ASSERT_TRUE(r.ok) << r.error;
    int onRim = 0;
    for (int v = 0; v < out.VN(); ++v) {
        const int source = r.meshing.vertexSource[v];
        if (source < 0 || std::abs(dome.vert[source].cP()[2]) > 1e-6f) continue;
        ++onRim;
        EXPECT_NEAR(out.vert[v].cP()[2], 0.0, 1e-6) << "output vertex " << v;
    }
    EXPECT_GE(onRim, 3);
    // And the disc's triangles all face straight down.
    int down = 0;
    for (const auto &f : out.face) {
        const vcg::Point3f n = vcg::TriangleNormal(f).Normalize();
        if (n[2] < -0.9f) {
            ++down;
            EXPECT_NEAR(n[2], -1.0f, 1e-6f);
        }
    }
    EXPECT_GE(down, 1);
}

namespace {

/// The largest angle, in degrees, between an output triangle and the area-weighted normal of
/// its polygon (faces joined across faux edges): 0 when every polygon is planar.
double LargestPolygonBend(const TMesh &out)
{
    const std::vector<int> polygon = vsa_bench::LabelPolygons(out).faceLabel;
    std::vector<Point3d> areaNormal(out.FN(), Point3d(0, 0, 0));
    for (int f = 0; f < out.FN(); ++f) areaNormal[polygon[f]] += Point3d::Construct(vcg::TriangleNormal(out.face[f]));
    double largest = 0;
    for (int f = 0; f < out.FN(); ++f) {
        const Point3d n = Point3d::Construct(vcg::TriangleNormal(out.face[f])).Normalize();
        const Point3d m = Point3d(areaNormal[polygon[f]]).Normalize();
        largest = std::max(largest, vcg::math::ToDeg(vcg::Angle(n, m)));
    }
    return largest;
}

}  // namespace

/// A box with a round hole at k = 24: the wall of the hole is cut into strips, and the paper's
/// average lifts the anchors they share with the top and the bottom off the strips' planes,
/// bending their polygons by a few degrees. Planarizing makes every polygon planar, keeps the
/// top's and the bottom's anchors on their planes, and changes nothing else.
TEST(Anchors, PlanarizingMakesEveryPolygonPlanar)
{
    TMesh box, bent, planar;
    vsa_test::MakeBoxWithHole(box, 64);
    ShapeApproximationParam param;
    param.partition.proxyCount = 24;
    param.meshing.polygonal = true;
    param.meshing.planarPolygons = false;
    const ShapeApproximationResult before = ApproximateShape(box, bent, param);
    ASSERT_TRUE(before.ok) << before.error;
    EXPECT_GT(LargestPolygonBend(bent), 2.0);

    param.meshing.planarPolygons = true;
    const ShapeApproximationResult after = ApproximateShape(box, planar, param);
    ASSERT_TRUE(after.ok) << after.error;
    EXPECT_LT(LargestPolygonBend(planar), 0.1);
    EXPECT_EQ(after.partition.proxyCount, before.partition.proxyCount);
    EXPECT_EQ(planar.FN(), bent.FN());
    EXPECT_TRUE(after.meshing.validity.IsValid() && after.meshing.validity.IsClosed()) << after.meshing.Summary();
    int onCaps = 0;
    for (int v = 0; v < planar.VN(); ++v) {
        const int source = after.meshing.vertexSource[v];
        if (source < 0 || std::abs(std::abs(box.vert[source].cP()[2]) - 0.5f) > 1e-6f) continue;
        ++onCaps;
        EXPECT_NEAR(std::abs(planar.vert[v].cP()[2]), 0.5, 1e-6) << "output vertex " << v;
    }
    EXPECT_GE(onCaps, 8);
}
