// Tests of vsa/cell_triangulation.h.
#include "meshing_fixtures.h"
#include "meshing_test_util.h"
#include "test_meshes.h"

#include <vsa/cell_triangulation.h>
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

// Repair passes update each cell's flooding instead of redoing it; the colours must be those
// of a flooding from scratch, anchors added or removed, ties between equal distances (the
// flat grid is full of them) included.
TEST(CellTriangulation, UpdatedFloodingEqualsAFreshOne)
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
TEST(CellTriangulation, FloodingCarriedOverToHalvedCellsEqualsAFreshOne)
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

TEST(CellTriangulation, CrossingPolygonEdgesAreThoseOfTestingEveryPair)
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
