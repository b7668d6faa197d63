// Tests of vsa/cell_triangulation.h.
#include "meshing_fixtures.h"
#include "meshing_test_util.h"
#include "partition_test_helpers.h"
#include "test_meshes.h"

#include <vsa/cell_triangulation.h>
#include <vsa/meshing.h>

#include <gtest/gtest.h>

#include <algorithm>
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

namespace {

/// A repair sequence on the hemisphere cut into 4 x 4 tiles (many cells), and all its cells.
void MakeTiledHemisphere(RepairSequence &r, std::vector<int> &cells)
{
    MakeHemisphereRepairSequence(3, r, 4);
    ASSERT_GE(r.surface.CellCount(), 12);
    cells.resize(r.surface.CellCount());
    std::iota(cells.begin(), cells.end(), 0);
}

}  // namespace

// Cells flood at once only when they share no loop vertex: their floodings write their loops.
// Each round is also the first one free of the cell's neighbours, so rounds stay few.
TEST(CellTriangulation, DisjointCellRoundsShareNoLoopVertexAndAreTheFirstFree)
{
    RepairSequence r;
    std::vector<int> cells;
    MakeTiledHemisphere(r, cells);
    const MeshingSurface &s = r.surface;
    std::reverse(cells.begin(), cells.end());  // any order: the rounds follow it
    const detail::CellRounds rounds = detail::DisjointCellRounds(s, cells);
    EXPECT_TRUE(rounds.rest.empty());
    ASSERT_GE(rounds.disjoint.size(), 2u);
    const auto meet = [&](int a, int b) {
        const std::vector<int> &la = s.cellLoop[a], &lb = s.cellLoop[b];
        for (int v : la)
            if (std::find(lb.begin(), lb.end(), v) != lb.end()) return true;
        return false;
    };
    std::vector<int> roundOf(s.CellCount(), -1), position(s.CellCount());
    for (size_t k = 0; k < cells.size(); ++k) position[cells[k]] = int(k);
    for (size_t round = 0; round < rounds.disjoint.size(); ++round)
        for (int c : rounds.disjoint[round]) {
            EXPECT_EQ(roundOf[c], -1) << "cell " << c << " twice";
            roundOf[c] = int(round);
        }
    for (int c = 0; c < s.CellCount(); ++c) {
        ASSERT_GE(roundOf[c], 0) << "cell " << c << " left out";
        for (int d = 0; d < s.CellCount(); ++d)
            EXPECT_FALSE(d != c && roundOf[d] == roundOf[c] && meet(c, d)) << "cells " << c << " and " << d;
        for (int earlier = 0; earlier < roundOf[c]; ++earlier) {
            bool taken = false;
            for (int d : rounds.disjoint[earlier]) taken |= position[d] < position[c] && meet(c, d);
            EXPECT_TRUE(taken) << "cell " << c << " could have gone to round " << earlier;
        }
    }
}

// The cells of a pass flood on the threads, in rounds; their triples must be those of flooding
// one cell at a time, pass after pass (the updates included), on any number of threads.
TEST(CellTriangulation, TriplesOfCellsOnThreadsAreThoseOfOneCellAtATime)
{
    RepairSequence r;
    std::vector<int> cells;
    MakeTiledHemisphere(r, cells);
    const MeshingSurface &s = r.surface;
    for (int threads : {1, 2, 3}) {
        SCOPED_TRACE(threads);
        CellFlooding oneByOne(s), onThreads(s);
        for (const std::vector<char> &required : r.required) {
            const AnchorSet anchors = FreshAnchors(s, r.partition.proxies, 0.5, required);
            const auto triples = WithThreads(threads, [&] { return onThreads.TriplesOfCells(cells, anchors); });
            ASSERT_EQ(int(triples.size()), s.CellCount());
            for (int c = 0; c < s.CellCount(); ++c) {
                EXPECT_EQ(triples[c], oneByOne.Triples(c, anchors)) << "cell " << c;
                EXPECT_EQ(onThreads.VerticesDeepestFirst(c, anchors), oneByOne.VerticesDeepestFirst(c, anchors))
                    << "cell " << c;
            }
        }
    }
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
