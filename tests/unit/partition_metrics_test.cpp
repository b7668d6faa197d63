// The L2,1 and L2 metrics: closed forms against numerical integration, fits against known planes.
#include "partition_test_helpers.h"

#include <vsa/face_geometry.h>
#include <vsa/metrics.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace vcg::tri::vsa;
using vcg::Point3d;
using vsa_test::TestRandom;

namespace {

IndexedMesh OneTriangle(const Point3d &a, const Point3d &b, const Point3d &c)
{
    IndexedMesh im;
    im.positions = {a, b, c};
    im.faces = {{0, 1, 2}};
    return im;
}

Point3d RandomPoint(TestRandom &random, double scale)
{
    return Point3d(random.Uniform(-scale, scale), random.Uniform(-scale, scale), random.Uniform(-scale, scale));
}

Proxy RandomProxy(TestRandom &random)
{
    Point3d n = RandomPoint(random, 1);
    return {RandomPoint(random, 2), n / n.Norm()};
}

/// Midpoint rule over the n^2 congruent sub-triangles of (a, b, c): sum of area_i * g(centroid_i).
template <class Integrand>
double IntegrateOverTriangle(const Point3d &a, const Point3d &b, const Point3d &c, int n, Integrand g)
{
    const Point3d u = (b - a) / n, v = (c - a) / n;
    const double subArea = 0.5 * (u ^ v).Norm();
    double sum = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; i + j < n; ++j) {
            sum += g(a + u * (i + 1.0 / 3) + v * (j + 1.0 / 3));            // upright sub-triangle
            if (i + j + 1 < n) sum += g(a + u * (i + 2.0 / 3) + v * (j + 2.0 / 3));  // inverted one
        }
    return sum * subArea;
}

}  // namespace

TEST(PartitionMetrics, L21FaceErrorMatchesIntegration)
{
    TestRandom random(21);
    for (int trial = 0; trial < 20; ++trial) {
        const Point3d a = RandomPoint(random, 1), b = RandomPoint(random, 1), c = RandomPoint(random, 1);
        const FaceGeometry g = ComputeFaceGeometry(OneTriangle(a, b, c), false);
        const Proxy p = RandomProxy(random);
        const Point3d n = ((b - a) ^ (c - a)).Normalize();
        const double integrated =
            IntegrateOverTriangle(a, b, c, 50, [&](const Point3d &) { return (n - p.normal).SquaredNorm(); });
        EXPECT_NEAR(L21Metric(g).Error(0, p), integrated, 1e-12 * (1 + integrated));
    }
}

TEST(PartitionMetrics, L2FaceErrorMatchesIntegrationAndVertexFormula)
{
    TestRandom random(2);
    for (int trial = 0; trial < 20; ++trial) {
        const Point3d a = RandomPoint(random, 1), b = RandomPoint(random, 1), c = RandomPoint(random, 1);
        const FaceGeometry g = ComputeFaceGeometry(OneTriangle(a, b, c), true);
        const Proxy p = RandomProxy(random);
        const auto distance = [&](const Point3d &x) { return p.normal * (x - p.point); };
        // The midpoint rule is exact for linear integrands; for d^2 its error is O(1/n^2).
        const double integrated =
            IntegrateOverTriangle(a, b, c, 400, [&](const Point3d &x) { return distance(x) * distance(x); });
        const double d1 = distance(a), d2 = distance(b), d3 = distance(c);
        const double vertexFormula =
            g.area[0] / 6 * (d1 * d1 + d2 * d2 + d3 * d3 + d1 * d2 + d2 * d3 + d3 * d1);
        const double error = L2Metric(g).Error(0, p);
        EXPECT_NEAR(error, vertexFormula, 1e-12 * (1 + vertexFormula));
        EXPECT_NEAR(error, integrated, 1e-5 * integrated + 1e-12);
    }
}

TEST(PartitionMetrics, L2FitRecoversThePlaneOfAPlanarPatch)
{
    // A tilted 10x10 grid of triangles far from the origin, where cancellation would show;
    // built in double so that it is planar to double precision.
    const Point3d origin(1000, -2000, 500), u(3, 1, 0.5), v(-1, 2, 4);
    IndexedMesh im;
    const int n = 10;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) im.positions.push_back(origin + u * (double(i) / n) + v * (double(j) / n));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i;
            im.faces.push_back({a, a + 1, a + n + 2});
            im.faces.push_back({a, a + n + 2, a + n + 1});
        }
    const FaceGeometry g = ComputeFaceGeometry(im, true);
    const L2Metric metric(g);
    L2Metric::Moments moments = metric.EmptyMoments(g.centroid[0]);
    for (int f = 0; f < im.FaceCount(); ++f) metric.Add(moments, f);
    const Proxy p = metric.Fit(moments, {g.centroid[0], Point3d(0, 0, 1)});

    const Point3d expected = (u ^ v) / (u ^ v).Norm();
    EXPECT_NEAR(p.normal * expected, 1.0, 1e-12);  // same plane, oriented like the faces
    for (const Point3d &x : im.positions) EXPECT_NEAR(p.normal * (x - p.point), 0.0, 1e-9);
    EXPECT_NEAR((p.point - (origin + (u + v) * 0.5)).Norm(), 0.0, 1e-9);
    EXPECT_NEAR(metric.Energy(moments, p), 0.0, 1e-12);
}

TEST(PartitionMetrics, L21FitIsTheNormalizedAreaWeightedMeanNormal)
{
    // Two faces: one of area 2 facing +z, one of area 1 facing +x.
    IndexedMesh im;
    im.positions = {Point3d(0, 0, 0), Point3d(2, 0, 0), Point3d(0, 2, 0), Point3d(5, 0, 0), Point3d(5, 1, 0),
                    Point3d(5, 0, 2)};
    im.faces = {{0, 1, 2}, {3, 4, 5}};
    const FaceGeometry g = ComputeFaceGeometry(im, false);
    ASSERT_DOUBLE_EQ(g.area[0], 2);
    ASSERT_DOUBLE_EQ(g.area[1], 1);
    const L21Metric metric(g);
    L21Metric::Moments moments = metric.EmptyMoments(Point3d(0, 0, 0));
    metric.Add(moments, 0);
    metric.Add(moments, 1);
    // A set fallback, unused here: Point3d{} would be uninitialized.
    const Proxy p = metric.Fit(moments, {Point3d(0, 0, 0), Point3d(0, 0, 1)});
    const Point3d expected = Point3d(1, 0, 2) / std::sqrt(5.0);
    EXPECT_NEAR((p.normal - expected).Norm(), 0, 1e-15);
    const Point3d centroid = (g.centroid[0] * 2 + g.centroid[1]) / 3;
    EXPECT_NEAR((p.point - centroid).Norm(), 0, 1e-15);
    // Energy 2|z - N|^2 + |x - N|^2, and the closed form from the moments agrees.
    const double energy = 2 * (Point3d(0, 0, 1) - expected).SquaredNorm() + (Point3d(1, 0, 0) - expected).SquaredNorm();
    EXPECT_NEAR(metric.Error(0, p) + metric.Error(1, p), energy, 1e-15);
    EXPECT_NEAR(metric.Energy(moments, p), energy, 1e-14);
}

/// Energy(moments, proxy) is the sum of the face errors for any proxy, also after merging
/// moments taken about different reference points.
template <class Metric>
void CheckMomentsEnergy(bool withSecondMoments)
{
    const IndexedMesh im = vsa_test::LoadCgalMesh("fandisk.off");
    const FaceGeometry g = ComputeFaceGeometry(im, withSecondMoments);
    const Metric metric(g);
    TestRandom random(7);
    for (int trial = 0; trial < 5; ++trial) {
        const Proxy p = RandomProxy(random);
        typename Metric::Moments low = metric.EmptyMoments(RandomPoint(random, 3));
        typename Metric::Moments high = metric.EmptyMoments(RandomPoint(random, 3));
        double sum = 0;
        const int half = im.FaceCount() / 2;
        for (int f = 0; f < im.FaceCount(); ++f) {
            metric.Add(f < half ? low : high, f);
            sum += metric.Error(f, p);
        }
        // The fit of the (open) first half minimizes its energy: a random proxy does worse.
        const Proxy fitted = metric.Fit(low, p);
        double fittedSum = 0, randomSum = 0;
        for (int f = 0; f < half; ++f) {
            fittedSum += metric.Error(f, fitted);
            randomSum += metric.Error(f, p);
        }
        EXPECT_NEAR(metric.Energy(low, fitted), fittedSum, 1e-9 * fittedSum);
        EXPECT_LT(fittedSum, randomSum);
        metric.Add(low, high);
        EXPECT_NEAR(metric.Energy(low, p), sum, 1e-9 * sum);
    }
}

TEST(PartitionMetrics, L21MomentsGiveTheSumOfFaceErrors) { CheckMomentsEnergy<L21Metric>(false); }
TEST(PartitionMetrics, L2MomentsGiveTheSumOfFaceErrors) { CheckMomentsEnergy<L2Metric>(true); }

TEST(PartitionMetrics, DegenerateFacesHaveNoNormalAndNoError)
{
    // Collinear and repeated vertices: zero area; they weigh nothing and produce no NaN.
    IndexedMesh im;
    im.positions = {Point3d(0, 0, 0), Point3d(1, 1, 1), Point3d(2, 2, 2)};
    im.faces = {{0, 1, 2}, {0, 0, 1}};
    const FaceGeometry g = ComputeFaceGeometry(im, true);
    const Proxy p{Point3d(5, 0, 0), Point3d(0, 1, 0)};
    for (int f = 0; f < 2; ++f) {
        EXPECT_EQ(g.area[f], 0);
        EXPECT_EQ(g.normal[f], Point3d(0, 0, 0));
        EXPECT_EQ(L21Metric(g).Error(f, p), 0);
        EXPECT_EQ(L2Metric(g).Error(f, p), 0);
    }
    // A region of degenerate faces has no fit: it keeps the fallback plane, with a unit normal.
    L2Metric::Moments moments = L2Metric(g).EmptyMoments(Point3d(0, 0, 0));
    L2Metric(g).Add(moments, 0);
    const Proxy kept = L2Metric(g).Fit(moments, {Point3d(1, 2, 3), Point3d(0, 0, 0)});
    EXPECT_EQ(kept.point, Point3d(1, 2, 3));
    EXPECT_DOUBLE_EQ(kept.normal.Norm(), 1.0);
}

/// On the geometry of every third face of fandisk alone, the listed-faces metric gives each of
/// those faces the bits of `Metric` on the whole mesh's geometry: data, errors, moments, scale.
template <class Metric>
void CheckListedFacesMetric(bool withSecondMoments)
{
    const IndexedMesh im = vsa_test::LoadCgalMesh("fandisk.off");
    const FaceGeometry whole = ComputeFaceGeometry(im, withSecondMoments);
    std::vector<int> faces;
    for (int f = 1; f < im.FaceCount(); f += 3) faces.push_back(f);
    const FaceGeometry some = ComputeFaceGeometryOf(im, faces, withSecondMoments, whole.maxArea, whole.diagonal);
    ASSERT_EQ(some.FaceCount(), int(faces.size()));
    std::vector<int> entry(im.FaceCount(), -1);
    for (size_t i = 0; i < faces.size(); ++i) entry[faces[i]] = int(i);
    const Metric metric(whole);
    const ListedFacesMetric<Metric> listed(some, faces, entry);
    EXPECT_EQ(listed.Find(0), -1);
    entry[0] = 0;  // face 0 as the first entry of another list, which the map may hold too
    EXPECT_EQ(listed.Find(0), -1);
    EXPECT_EQ(listed.ErrorScale(), metric.ErrorScale());
    TestRandom random(3);
    const Proxy p = RandomProxy(random);
    typename Metric::Moments fromWhole = metric.EmptyMoments(Point3d(1, 0, 0));
    typename Metric::Moments fromListed = listed.EmptyMoments(Point3d(1, 0, 0));
    for (size_t i = 0; i < faces.size(); ++i) {
        const int f = faces[i];
        ASSERT_EQ(listed.Listed(f), int(i));
        ASSERT_EQ(listed.Find(f), int(i));
        EXPECT_EQ(some.area[i], whole.area[f]);
        EXPECT_EQ(some.normal[i], whole.normal[f]);
        EXPECT_EQ(some.centroid[i], whole.centroid[f]);
        EXPECT_EQ(listed.Error(f, p), metric.Error(f, p));
        EXPECT_EQ(listed.Error(listed.Data(f), p), metric.Error(metric.Data(f), p));
        metric.Add(fromWhole, f);
        listed.Add(fromListed, f);
    }
    const Proxy a = metric.Fit(fromWhole, p), b = listed.Fit(fromListed, p);
    EXPECT_EQ(a.point, b.point);
    EXPECT_EQ(a.normal, b.normal);
    EXPECT_EQ(metric.Energy(fromWhole, p), listed.Energy(fromListed, p));
}

TEST(PartitionMetrics, L21OnListedFacesIsTheSameBits) { CheckListedFacesMetric<L21Metric>(false); }
TEST(PartitionMetrics, L2OnListedFacesIsTheSameBits) { CheckListedFacesMetric<L2Metric>(true); }
