// The meshable partition: regions that cannot be one clean planar polygon are split, k grows
// to k' and the result says why; a cube keeps its six sides; an unwelded mesh is refused.
#include "test_meshes.h"

#include <vsa/approximate_shape.h>
#include <vsa/meshable_partition.h>
#include <vsa/surface_grid.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <tuple>
#include <vector>

namespace {

using namespace vcg::tri::vsa;
using vsa_test::TMesh;

ShapeApproximationResult ApproximateSplit(const TMesh &in, TMesh &out, int k, bool meshable = true,
                                     double maxProxyFactor = 2)
{
    ShapeApproximationParam param;
    param.partition.proxyCount = k;
    param.meshable.enabled = meshable;
    param.meshable.maxProxyFactor = maxProxyFactor;
    return ApproximateShape(in, out, param);
}

/// MakeBoxWithHole(16) partitioned into k regions by 10 Lloyd iterations.
std::unique_ptr<Approximation> PartitionedBoxWithHole(int k)
{
    TMesh box;
    vsa_test::MakeBoxWithHole(box, 16);
    ApproximationParam param;
    param.proxyCount = k;
    auto approximation = std::make_unique<Approximation>(BuildIndexedMesh(box), param);
    approximation->Initialize();
    approximation->Run(10);
    return approximation;
}

TEST(MeshablePartition, CubeKeepsItsSixSidesAndK)
{
    TMesh cube, out;
    vsa_test::MakeTessellatedCube(cube, 4);
    const ShapeApproximationResult r = ApproximateSplit(cube, out, 6);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.meshable.proxiesRequested, 6);
    EXPECT_EQ(r.meshable.proxiesFinal, 6);
    EXPECT_EQ(r.meshable.rounds, 0);
    EXPECT_EQ(r.meshable.Summary(), "");
    EXPECT_EQ(r.partition.proxyCount, 6);
    EXPECT_EQ(out.FN(), 12);
    EXPECT_EQ(out.VN(), 8);
}

/// A box with a hole at k=4: two of its regions are rings (the top or the bottom with walls),
/// which no single polygon can be. Given room (k' up to 16), they are split until every region
/// is a disc that meshes cleanly (a first round cuts both rings by distance; each half holds part
/// of a face and part of the walls, and faces away, which takes three more rounds: k' = 16), the
/// log says from which k to which and why, and the meshing has no region left to cut; with the
/// stage off, k stays and the rings are cut.
TEST(MeshablePartition, RingRegionsAreSplitAndKRaisedIsReported)
{
    TMesh box;
    vsa_test::MakeBoxWithHole(box, 16);
    TMesh kept;
    const ShapeApproximationResult asked = ApproximateSplit(box, kept, 4, false);
    ASSERT_TRUE(asked.ok) << asked.error;
    EXPECT_EQ(asked.partition.proxyCount, 4);
    EXPECT_GT(asked.meshing.regionsCut, 0);

    TMesh out;
    const ShapeApproximationResult r = ApproximateSplit(box, out, 4, true, 4);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.meshable.proxiesRequested, 4);
    EXPECT_EQ(r.meshable.proxiesFinal, 16);
    EXPECT_EQ(r.meshable.rounds, 4);
    EXPECT_EQ(r.meshable.regionsLeft, 0);
    EXPECT_EQ(r.partition.proxyCount, 16);
    EXPECT_EQ(r.meshable.splits[int(RegionFault::NotDisc)], 2) << r.meshable.Summary();
    EXPECT_EQ(r.meshable.splits[int(RegionFault::FacesAway)], 9) << r.meshable.Summary();
    EXPECT_EQ(r.meshable.splits[int(RegionFault::Intersects)], 1) << r.meshable.Summary();
    EXPECT_EQ(r.meshing.regionsCut, 0);
    EXPECT_TRUE(r.meshing.validity.IsValid()) << r.meshing.validity.Summary();
    const std::string says = "k raised from 4 to " + std::to_string(r.meshable.proxiesFinal) + ":";
    bool logged = false;
    for (const std::string &m : r.partition.messages) logged |= m.find(says) == 0;
    EXPECT_TRUE(logged) << r.meshable.Summary();
}

/// Same input, parameters and seed: the same output, bit for bit.
TEST(MeshablePartition, IsDeterministic)
{
    TMesh box, a, b;
    vsa_test::MakeBoxWithHole(box, 16);
    const ShapeApproximationResult ra = ApproximateSplit(box, a, 4), rb = ApproximateSplit(box, b, 4);
    ASSERT_TRUE(ra.ok && rb.ok);
    EXPECT_EQ(ra.inputFaceRegion, rb.inputFaceRegion);
    ASSERT_EQ(a.VN(), b.VN());
    ASSERT_EQ(a.FN(), b.FN());
    for (int v = 0; v < a.VN(); ++v) EXPECT_EQ(a.vert[v].cP(), b.vert[v].cP());
}

/// The cap: k' never exceeds maxProxyFactor * k (by default 2k), and regions left at fault are
/// reported, and the meshing still makes a valid output of them.
TEST(MeshablePartition, KPrimeStaysWithinItsCap)
{
    TMesh box, out;
    vsa_test::MakeBoxWithHole(box, 16);
    const ShapeApproximationResult r = ApproximateSplit(box, out, 4);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.meshable.proxiesFinal, 8);
    EXPECT_TRUE(r.meshing.validity.IsValid()) << r.meshing.validity.Summary();
    EXPECT_GT(r.meshable.regionsLeft, 0);
    EXPECT_TRUE(r.meshable.capped);
    EXPECT_NE(r.meshable.Summary().find("still do not mesh as one planar polygon (k' at its limit, 8)"),
              std::string::npos) << r.meshable.Summary();
}

/// No limit (0): the splits go on until every region meshes as one polygon, so the meshing
/// cuts nothing; where the limit stopped them (see KPrimeStaysWithinItsCap) it did.
TEST(MeshablePartition, NoLimitSplitsUntilEveryRegionIsOnePolygon)
{
    TMesh box, out;
    vsa_test::MakeBoxWithHole(box, 16);
    const ShapeApproximationResult r = ApproximateSplit(box, out, 4, true, 0);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_GT(r.meshable.proxiesFinal, 8);
    EXPECT_EQ(r.meshable.regionsLeft, 0);
    EXPECT_FALSE(r.meshable.capped);
    EXPECT_EQ(r.meshing.regionsCut, 0);
    EXPECT_TRUE(r.meshing.validity.IsValid()) << r.meshing.validity.Summary();
    EXPECT_EQ(r.meshable.Summary().find("still do not mesh"), std::string::npos) << r.meshable.Summary();
}

/// A limit that is not a finite number >= 0 is refused before any work, with the reason.
TEST(MeshablePartition, BadLimitIsRefused)
{
    TMesh box, out;
    vsa_test::MakeBoxWithHole(box, 16);
    for (double limit : {-1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        const ShapeApproximationResult r = ApproximateSplit(box, out, 4, true, limit);
        EXPECT_FALSE(r.ok) << limit;
        EXPECT_NE(r.error.find("The limit on the regions must be a finite number"), std::string::npos) << r.error;
        EXPECT_EQ(out.FN(), 0) << limit;
    }
}

/// The trials relabel one surface round after round (AssignRegions keeps the cells of the
/// regions that did not change): every round's surface must be the one built from scratch. The rounds
/// here are those of the meshable partition (splits), then labels that cut regions into many
/// pieces, then the first labels again.
TEST(MeshablePartition, RelabelledSurfaceIsTheSurfaceBuiltAfresh)
{
    const std::unique_ptr<Approximation> box = PartitionedBoxWithHole(6);
    Approximation &approximation = *box;
    const IndexedMesh &mesh = approximation.Mesh();
    std::vector<std::vector<int>> rounds = {approximation.CurrentPartition().faceRegion};
    for (int region : {0, 3, 6}) {
        approximation.Split(region);
        rounds.push_back(approximation.CurrentPartition().faceRegion);
    }
    std::vector<int> stripes(mesh.FaceCount());
    for (int f = 0; f < mesh.FaceCount(); ++f) stripes[f] = (f / 7) % 5;
    rounds.push_back(stripes);
    rounds.push_back(rounds.front());

    MeshingSurface relabelled;
    std::string error;
    ASSERT_TRUE(BuildSurfaceTopology(mesh, relabelled, error)) << error;
    for (size_t round = 0; round < rounds.size(); ++round) {
        const int regionCount = *std::max_element(rounds[round].begin(), rounds[round].end()) + 1;
        MeshingSurface fresh;
        ASSERT_TRUE(BuildMeshingSurface(mesh, rounds[round], regionCount, fresh, error)) << error;
        ASSERT_TRUE(AssignRegions(relabelled, rounds[round], regionCount, error)) << error;
        EXPECT_EQ(relabelled.faceRegion, fresh.faceRegion) << "round " << round;
        EXPECT_EQ(relabelled.faceCell, fresh.faceCell) << "round " << round;
        EXPECT_EQ(relabelled.cellRegion, fresh.cellRegion) << "round " << round;
        EXPECT_EQ(relabelled.cellComponentFace, fresh.cellComponentFace) << "round " << round;
        EXPECT_EQ(relabelled.cellFaceOffset, fresh.cellFaceOffset) << "round " << round;
        EXPECT_EQ(relabelled.cellFaces, fresh.cellFaces) << "round " << round;
        EXPECT_EQ(relabelled.cellLoop, fresh.cellLoop) << "round " << round;
        EXPECT_EQ(relabelled.cellLoopOther, fresh.cellLoopOther) << "round " << round;
        EXPECT_EQ(relabelled.cellAreaVector, fresh.cellAreaVector) << "round " << round;
        EXPECT_EQ(relabelled.cellDoubleArea, fresh.cellDoubleArea) << "round " << round;
        EXPECT_EQ(relabelled.cellCentroid, fresh.cellCentroid) << "round " << round;
        EXPECT_EQ(relabelled.onBorder, fresh.onBorder) << "round " << round;
        EXPECT_EQ(relabelled.junction, fresh.junction) << "round " << round;
        EXPECT_EQ(relabelled.regionCount, fresh.regionCount) << "round " << round;
    }
}

/// Each trial borrows the flooding of the one before and relabels a surface set up once: round
/// after round, its verdicts must be those of a trial set up afresh on the same partition.
TEST(MeshablePartition, TrialsInTurnJudgeAsTrialsAfresh)
{
    const std::unique_ptr<Approximation> box = PartitionedBoxWithHole(4);
    Approximation &approximation = *box;
    const MeshingParam meshing;
    const MeshablePartitionParam meshable;
    detail::TrialSetup<vcg::Point3f> inTurn(approximation.Mesh(), meshing);
    int kept = 0;  // triangles whose facing-away samples a trial took from the one before
    for (int round = 0; round < 4; ++round) {
        const Partition &partition = approximation.CurrentPartition();
        std::optional<detail::CheckedPass> previous;
        if (inTurn.latest) previous = detail::CheckedPass{inTurn.latest->Best().pass, inTurn.defects, inTurn.clearance};
        const detail::RegionTrial a = detail::TrialMeshRegions<vcg::Point3f>(inTurn, partition, meshable);
        // Every triangle's samples and defects are kept for the next trial, and after the splits
        // some are taken from the last one's instead of measured again.
        const detail::MeshingPass &pass = inTurn.latest->Best().pass;
        EXPECT_EQ(inTurn.awayBits.size(), pass.triangles.size()) << "round " << round;
        EXPECT_EQ(inTurn.defects.degenerate.size(), pass.triangles.size()) << "round " << round;
        if (previous)
            for (int repeat :
                 detail::RepeatedFaces(pass, inTurn.defects.degenerate, previous->pass, previous->defects.degenerate))
                kept += repeat >= 0;
        detail::TrialSetup<vcg::Point3f> afresh(approximation.Mesh(), meshing);
        const detail::RegionTrial b = detail::TrialMeshRegions<vcg::Point3f>(afresh, partition, meshable);
        EXPECT_EQ(a.fault, b.fault) << "round " << round;
        EXPECT_EQ(a.facingAway, b.facingAway) << "round " << round;
        EXPECT_EQ(inTurn.defects.intersections, afresh.defects.intersections) << "round " << round;
        EXPECT_EQ(inTurn.defects.closePairs, afresh.defects.closePairs) << "round " << round;
        EXPECT_EQ(inTurn.defects.crossings.size(), afresh.defects.crossings.size()) << "round " << round;
        for (size_t i = 0; i < std::min(inTurn.defects.crossings.size(), afresh.defects.crossings.size()); ++i) {
            const auto &x = inTurn.defects.crossings[i], &y = afresh.defects.crossings[i];
            EXPECT_EQ(std::make_tuple(x.cell, x.edge, x.otherEdge), std::make_tuple(y.cell, y.edge, y.otherEdge));
        }
        EXPECT_EQ(inTurn.latest->Best().pass.positions, afresh.latest->Best().pass.positions) << "round " << round;
        EXPECT_EQ(inTurn.latest->Best().pass.triangles, afresh.latest->Best().pass.triangles) << "round " << round;
        const std::vector<int> regions = detail::RegionsToSplit(a, partition);
        ASSERT_FALSE(regions.empty()) << "round " << round;  // the box's rings need splits
        const std::vector<int> splitFaces =
            detail::ChooseSplitFaces(inTurn, a, regions, approximation.SeedFaces(), approximation.Mesh());
        EXPECT_EQ(splitFaces, detail::ChooseSplitFaces(afresh, b, regions, approximation.SeedFaces(),
                                                       approximation.Mesh()))
            << "round " << round;
        approximation.Split(regions.front(), splitFaces.front());
    }
    EXPECT_GT(kept, 0);
}

/// The meshing starts from the last trial's surface, its grid and floodings, which must be
/// labelled with the final partition and give the output a surface built afresh gives, and from
/// the input's intersections the trials found; a surface labelled otherwise is not used, nor its
/// grid (whose faces may go with it), nor floodings of another surface.
TEST(MeshablePartition, MeshingFromTheLastTrialIsTheSame)
{
    const std::unique_ptr<Approximation> box = PartitionedBoxWithHole(4);
    Approximation &approximation = *box;
    const MeshingParam meshing;
    MeshingStart start;
    const MeshablePartitionReport report =
        MakePartitionMeshable<vcg::Point3f>(approximation, meshing, MeshablePartitionParam(), nullptr, &start);
    ASSERT_GT(report.proxiesFinal, report.proxiesRequested);  // the box's rings were split
    ASSERT_TRUE(start.surface);
    ASSERT_TRUE(start.flooding);
    EXPECT_EQ(&start.flooding->Surface(), start.surface.get());
    const Partition &partition = approximation.CurrentPartition();
    const int regionCount = int(partition.proxies.size());
    EXPECT_TRUE(IsLabelledAs(*start.surface, partition.faceRegion, regionCount));
    ASSERT_TRUE(start.checked);
    ASSERT_TRUE(start.grid);
    ASSERT_TRUE(start.intersections);
    EXPECT_EQ(&start.intersections->Input(), &approximation.Mesh());
    const MeshingSurface &s = *start.surface;
    const int last = s.FaceCount() - 1;  // the grid is of the surface's faces: each nearest to its centroid
    for (int f : {0, last})
        EXPECT_EQ(start.grid->NearestFace((s.positions[s.faces[f][0]] + s.positions[s.faces[f][1]] +
                                           s.positions[s.faces[f][2]]) / 3.0),
                  f);
    MeshingStart mislabelled{std::make_shared<MeshingSurface>(*start.surface), start.flooding, start.checked,
                             start.grid, start.intersections};
    mislabelled.surface->faceRegion.back() = (mislabelled.surface->faceRegion.back() + 1) % regionCount;
    EXPECT_FALSE(IsLabelledAs(*mislabelled.surface, partition.faceRegion, regionCount));
    MeshingStart otherSurface{std::make_shared<MeshingSurface>(*start.surface), start.flooding, start.checked,
                              start.grid, start.intersections};
    detail::CheckedPass doubled = *start.checked;
    doubled.clearance *= 2;
    MeshingStart otherClearance{start.surface, start.flooding, doubled, start.grid, start.intersections};

    TMesh fresh, started, notUsed, notFlooded, notChecked;
    const IndexedMesh &mesh = approximation.Mesh();
    ASSERT_TRUE(BuildApproximatingMesh(mesh, partition, meshing, fresh).ok);
    ASSERT_TRUE(BuildApproximatingMesh(mesh, partition, meshing, started, nullptr, std::move(start)).ok);
    ASSERT_TRUE(BuildApproximatingMesh(mesh, partition, meshing, notFlooded, nullptr, std::move(otherSurface)).ok);
    ASSERT_TRUE(BuildApproximatingMesh(mesh, partition, meshing, notChecked, nullptr, std::move(otherClearance)).ok);
    // Last: the surface it drops is then the last to hold the faces its grid is of.
    ASSERT_TRUE(BuildApproximatingMesh(mesh, partition, meshing, notUsed, nullptr, std::move(mislabelled)).ok);
    const IndexedMesh expected = BuildIndexedMesh(fresh);
    for (const TMesh *out : {&started, &notUsed, &notFlooded, &notChecked}) {
        const IndexedMesh got = BuildIndexedMesh(*out);
        EXPECT_EQ(got.positions, expected.positions);
        EXPECT_EQ(got.faces, expected.faces);
    }
}

/// An unwelded mesh (every face its own vertices, as STL files have them) is refused with the
/// hint to weld it first.
TEST(MeshablePartition, TriangleSoupIsRefusedWithTheWeldHint)
{
    TMesh soup, out;
    vsa_test::BuildFromLists(soup, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}},
                             {{0, 1, 2}, {3, 4, 5}});
    const ShapeApproximationResult r = ApproximateSplit(soup, out, 1);
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("weld it first (MeshLab: Cleaning and Repairing > Merge Close Vertices)"),
              std::string::npos)
        << r.error;
    EXPECT_EQ(out.FN(), 0);
}

namespace {

/// Checks SurfaceGrid::NearestFace on `faces` against brute force: the nearest face, the lowest
/// index among equally near ones, with or without a hint (the answer, any face, or the answer's
/// neighbours across its edges 0 and 2, -1 on a border). Returns how many points had ties.
int ExpectNearestFaceMatchesBruteForce(const std::vector<vcg::Point3d> &positions,
                                       const std::vector<std::array<int, 3>> &faces,
                                       const std::vector<std::array<int, 3>> &neighbors,
                                       const std::vector<vcg::Point3d> &points, std::mt19937 &random)
{
    const SurfaceGrid grid(positions, faces);
    std::uniform_int_distribution<int> anyFace(0, int(faces.size()) - 1);
    int ties = 0;
    for (size_t q = 0; q < points.size(); ++q) {
        const vcg::Point3d &p = points[q];
        auto distance = [&](int f) {
            const auto &t = faces[f];
            double d;
            vcg::Point3d closest;
            vcg::TrianglePointDistance(vcg::Triangle3<double>(positions[t[0]], positions[t[1]], positions[t[2]]), p,
                                       d, closest);
            return d;
        };
        int expected = 0, equallyNear = 0;
        for (int f = 1; f < int(faces.size()); ++f)
            if (distance(f) < distance(expected)) expected = f;
        for (int f = 0; f < int(faces.size()); ++f) equallyNear += distance(f) == distance(expected);
        ties += equallyNear > 1;
        EXPECT_EQ(grid.NearestFace(p), expected) << "point " << q;
        for (int hint : {expected, anyFace(random), neighbors[expected][0], neighbors[expected][2]})
            EXPECT_EQ(grid.NearestFace(p, hint), expected) << "point " << q << ", hint " << hint;
    }
    return ties;
}

}  // namespace

/// Points around a torus, and on its vertices and edges, where faces tie.
TEST(MeshablePartition, NearestFaceMatchesBruteForce)
{
    TMesh torus;
    vsa_test::MakeTorus(torus, 2, 0.5f, 24, 12);
    const IndexedMesh im = BuildIndexedMesh(torus);
    std::mt19937 random(3);
    std::uniform_real_distribution<double> coordinate(-3.5, 3.5);
    std::vector<vcg::Point3d> points;
    for (int q = 0; q < 500; ++q) points.emplace_back(coordinate(random), coordinate(random), coordinate(random) / 3);
    for (int f = 0; f < im.FaceCount(); f += 7) {
        const auto &t = im.faces[f];
        points.push_back(im.positions[t[0]]);
        points.push_back((im.positions[t[0]] + im.positions[t[1]]) / 2);
    }
    EXPECT_GT(ExpectNearestFaceMatchesBruteForce(im.positions, im.faces, im.neighbors, points, random),
              50);  // vertices, edges
}

/// A flat polygon fanned into long slivers, as CAD exports have them, with points in its plane
/// (inside, outside, on its vertices and edges) and just off it: the samples of a flat wall lie
/// in the boxes of many slivers, which the search must tell apart exactly as brute force does.
TEST(MeshablePartition, NearestFaceMatchesBruteForceOnFlatSlivers)
{
    std::vector<vcg::Point3d> positions;
    std::vector<std::array<int, 3>> faces, neighbors;
    const int sides = 40;
    for (int i = 0; i < sides; ++i) {
        const double angle = 2 * M_PI * i / sides;
        positions.emplace_back(3 * std::cos(angle), std::sin(angle), 0);
    }
    for (int i = 1; i + 1 < sides; ++i) faces.push_back({0, i, i + 1});
    const int fanCount = int(faces.size());
    for (int f = 0; f < fanCount; ++f) neighbors.push_back({f - 1, -1, f + 1 < fanCount ? f + 1 : -1});
    std::mt19937 random(5);
    std::uniform_real_distribution<double> coordinate(-3.5, 3.5), height(-1e-3, 1e-3);
    std::vector<vcg::Point3d> points;
    for (int q = 0; q < 400; ++q) points.emplace_back(coordinate(random), coordinate(random) / 3, 0);
    for (int q = 0; q < 200; ++q) points.emplace_back(coordinate(random), coordinate(random) / 3, height(random));
    for (int i = 0; i < sides; ++i) {
        points.push_back(positions[i]);
        points.push_back((positions[0] + positions[i]) / 2);  // on a sliver's long edge
    }
    EXPECT_GT(ExpectNearestFaceMatchesBruteForce(positions, faces, neighbors, points, random), 40);
}

/// Two distinct vertices at one position, joined by an edge with two faces without area on it
/// (as CAD exports have them): each became an anchor, and output triangles on both had no area.
/// The edge is collapsed first: the output has no degenerate face; those faces get the region of
/// a face on one of their vertices.
TEST(MeshablePartition, CoincidentVerticesGiveNoDegenerateFace)
{
    TMesh cube, out;
    vsa_test::MakeTessellatedCube(cube, 3);
    const int faces = cube.FN();
    for (int corner = 0; corner < 8; ++corner) {  // at every corner of the cube, a zero-length edge
        const vcg::Point3f at(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
        int fi = 0, i = 0;
        while (fi < faces && cube.face[fi].cP(i) != at)
            if (++i == 3) i = 0, ++fi;
        ASSERT_LT(fi, faces);
        const vcg::Point3f position = cube.face[fi].cP(i);
        auto copy = vcg::tri::Allocator<TMesh>::AddVertex(cube, position);
        // After AddVertex, which may move the vertices.
        auto u = cube.face[fi].V(i), v = cube.face[fi].V((i + 1) % 3), w = cube.face[fi].V((i + 2) % 3);
        cube.face[fi].V(i) = &*copy;
        vcg::tri::Allocator<TMesh>::AddFace(cube, &*copy, u, v);
        vcg::tri::Allocator<TMesh>::AddFace(cube, w, u, &*copy);
    }
    const ShapeApproximationResult r = ApproximateSplit(cube, out, 6);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.input.degenerateFaces, 16);
    EXPECT_EQ(r.meshing.validity.degenerateFaces, 0);
    EXPECT_TRUE(r.meshing.validity.IsValid()) << r.meshing.validity.Summary();
    EXPECT_EQ(out.FN(), 12);
    EXPECT_EQ(std::count(r.inputFaceRegion.begin(), r.inputFaceRegion.end(), -1), 0);
    bool logged = false;
    for (const std::string &m : r.partition.messages) logged |= m.find("8 edges between distinct vertices") == 0;
    EXPECT_TRUE(logged);
}

}  // namespace
