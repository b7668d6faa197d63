// Variational Shape Approximation for vcglib — planar polygons: small moves of the placed
// anchors that put every polygon of the output in one plane, where a few such moves can.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_PLANAR_POLYGONS_H
#define VSA_PLANAR_POLYGONS_H

#include <vsa/indexed_mesh.h>
#include <vsa/proxy.h>
#include <vsa/tuning.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {
namespace detail {

inline Eigen::Vector3d AsEigen(const Point3d &p) { return Eigen::Vector3d(p[0], p[1], p[2]); }

/// The polygons that can bend (four anchors or more) and, per anchor, those it belongs to.
struct PolygonIncidence
{
    std::vector<int> offset;      ///< per anchor: its polygons are polygonsOf[offset[a] .. offset[a + 1])
    std::vector<int> polygonsOf;

    PolygonIncidence(const std::vector<std::vector<int>> &polygons, int anchorCount) : offset(anchorCount + 1, 0)
    {
        for (const std::vector<int> &polygon : polygons)
            if (CanBend(polygon))
                for (int a : polygon) ++offset[a + 1];
        for (int a = 0; a < anchorCount; ++a) offset[a + 1] += offset[a];
        polygonsOf.resize(offset[anchorCount]);
        std::vector<int> next(offset.begin(), offset.end() - 1);
        for (int c = 0; c < int(polygons.size()); ++c)
            if (CanBend(polygons[c]))
                for (int a : polygons[c]) polygonsOf[next[a]++] = c;
    }
    static bool CanBend(const std::vector<int> &polygon) { return polygon.size() >= 4; }
};

/// A polygon's plane: its proxy's for a flat region, else the least squares plane of its
/// anchors, facing the proxy's side.
struct PolygonPlane
{
    Eigen::Vector3d point, normal;
};

inline PolygonPlane FitPolygonPlane(const std::vector<int> &polygon, const std::vector<Point3d> &placed,
                                    const Proxy &proxy, bool flat)
{
    const Eigen::Vector3d proxyNormal = AsEigen(proxy.normal);
    if (flat) return {AsEigen(proxy.point), proxyNormal};
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int a : polygon) centroid += AsEigen(placed[a]);
    centroid /= double(polygon.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (int a : polygon) {
        const Eigen::Vector3d d = AsEigen(placed[a]) - centroid;
        covariance += d * d.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(covariance);
    const Eigen::Vector3d normal = solver.eigenvectors().col(0);
    return {centroid, normal.dot(proxyNormal) < 0 ? Eigen::Vector3d(-normal) : normal};
}

/// How far the polygon is from its plane: its anchors' largest distance from the plane over
/// its size (their largest distance from the plane's point). About the sine of the angle its
/// triangles make with the plane.
inline double Bend(const std::vector<int> &polygon, const std::vector<Point3d> &placed, const PolygonPlane &plane)
{
    double size = 0, off = 0;
    for (int a : polygon) {
        const Eigen::Vector3d d = AsEigen(placed[a]) - plane.point;
        size = std::max(size, d.norm());
        off = std::max(off, std::abs(plane.normal.dot(d)));
    }
    return size > 0 ? off / size : 0;
}

/// What a planarization works on: the output's polygons (cells), the region of each, the
/// regions' proxies, flat flags (see FlatRegions) and fits (RegionFits::fit), per anchor its
/// surface vertex's position and how far from it the anchor may go, and the largest coordinate
/// the output holds.
struct PlanarizationInput
{
    const std::vector<std::vector<int>> &polygons;
    const std::vector<int> &polygonRegion;
    const std::vector<Proxy> &proxies;
    const std::vector<char> &flatRegion;
    const std::vector<double> &regionFit;
    const std::vector<Point3d> &origin;
    const std::vector<double> &limit;
    double largestCoordinate;

    PolygonPlane Plane(int c, const std::vector<Point3d> &placed) const
    {
        const int r = polygonRegion[c];
        return FitPolygonPlane(polygons[c], placed, proxies[r], flatRegion[r] != 0);
    }
};

/// Rounds that alternate fitting the planes of `active` polygons and moving each anchor in
/// `moving` to the least squares point of its polygons' planes, held toward `start` by a weak
/// spring (along the line of two planes nothing else holds it), within `allowance` of its start,
/// its limit from its origin and the output's range. Stops early once no anchor moves more than
/// kPlanarizeSettled of its limit: a polygon within kPlanarPolygon of its plane can still bend
/// its thin triangles, so the rounds go on until the anchors settle.
inline void RunPlanarizingRounds(const PlanarizationInput &in, const PolygonIncidence &incidence,
                                 const std::vector<int> &active, const std::vector<int> &moving,
                                 const std::vector<Point3d> &start, const std::vector<double> &allowance,
                                 std::vector<Point3d> &placed, std::vector<PolygonPlane> &planes)
{
    for (int round = 0; round < kPlanarizeRounds; ++round) {
        for (int c : active) planes[c] = in.Plane(c, placed);
        double largestStep = 0;
        for (int a : moving) {
            Eigen::Matrix3d system = kPlanarizeSpring * Eigen::Matrix3d::Identity();
            Eigen::Vector3d target = kPlanarizeSpring * AsEigen(start[a]);
            for (int k = incidence.offset[a]; k < incidence.offset[a + 1]; ++k) {
                const PolygonPlane &plane = planes[incidence.polygonsOf[k]];
                system += plane.normal * plane.normal.transpose();
                target += plane.normal * plane.normal.dot(plane.point);
            }
            const Eigen::Vector3d x = system.ldlt().solve(target);
            Point3d shift = Point3d(x[0], x[1], x[2]) - start[a];
            if (!(shift.Norm() <= allowance[a])) shift *= allowance[a] / shift.Norm();
            Point3d move = start[a] + shift - in.origin[a];
            if (!(move.Norm() <= in.limit[a])) move *= in.limit[a] / move.Norm();
            const Point3d moved = in.origin[a] + move;
            if (!(std::abs(moved[0]) <= in.largestCoordinate && std::abs(moved[1]) <= in.largestCoordinate &&
                  std::abs(moved[2]) <= in.largestCoordinate))
                continue;
            largestStep = std::max(largestStep, (moved - placed[a]).Norm() / in.limit[a]);
            placed[a] = moved;
        }
        if (largestStep <= kPlanarizeSettled) return;
    }
}

/// How far each anchor may move from where it was placed: kPlanarizeShift of its limit, and
/// kPlanarizeFit times the largest fit of its polygons' regions, so that planarizing adds no
/// more error than the regions already have.
inline std::vector<double> PlanarizingAllowance(const PlanarizationInput &in, const PolygonIncidence &incidence)
{
    std::vector<double> allowance(in.limit.size());
    for (size_t a = 0; a < allowance.size(); ++a) {
        double fit = 0;
        for (int k = incidence.offset[a]; k < incidence.offset[a + 1]; ++k)
            fit = std::max(fit, in.regionFit[in.polygonRegion[incidence.polygonsOf[k]]]);
        allowance[a] = std::min(kPlanarizeShift * in.limit[a], kPlanarizeFit * fit);
    }
    return allowance;
}

/// The polygons `candidates` grouped by the movable anchors they share, each group in
/// increasing order. Planarizing a group moves only its own anchors.
inline std::vector<std::vector<int>> PolygonGroups(const std::vector<std::vector<int>> &polygons,
                                                   const std::vector<int> &candidates,
                                                   const std::vector<char> &movable)
{
    std::vector<int> parent = SingletonSets(candidates.size());
    std::vector<int> firstWith(movable.size(), -1);  // per anchor: the first candidate that has it
    for (int i = 0; i < int(candidates.size()); ++i)
        for (int a : polygons[candidates[i]]) {
            if (!movable[a]) continue;
            if (firstWith[a] < 0) firstWith[a] = i;
            else Unite(parent, i, firstWith[a]);
        }
    std::vector<std::vector<int>> groups;
    std::vector<int> groupOf(candidates.size(), -1);
    for (int i = 0; i < int(candidates.size()); ++i) {
        const int r = FindRoot(parent, i);
        if (groupOf[r] < 0) {
            groupOf[r] = int(groups.size());
            groups.emplace_back();
        }
        groups[groupOf[r]].push_back(candidates[i]);
    }
    return groups;
}

/// Planarizes one group of polygons: rounds of RunPlanarizingRounds on its movable anchors;
/// the anchors of any polygon still bent afterwards go back to `start` and stay, and the rest
/// try again, kPlanarizeAttempts times at most, after which the whole group goes back.
inline void PlanarizeGroup(const PlanarizationInput &in, const PolygonIncidence &incidence,
                           const std::vector<int> &group, std::vector<char> &movable,
                           const std::vector<Point3d> &start, const std::vector<double> &allowance,
                           std::vector<Point3d> &placed, std::vector<PolygonPlane> &planes)
{
    std::vector<int> active, moving;
    for (int attempt = 0; attempt < kPlanarizeAttempts; ++attempt) {
        active.clear();
        moving.clear();
        for (int c : group) {
            bool moves = false;
            for (int a : in.polygons[c]) {
                placed[a] = start[a];
                if (movable[a]) moves = true, moving.push_back(a);
            }
            if (moves) active.push_back(c);
        }
        if (moving.empty()) return;
        std::sort(moving.begin(), moving.end());
        moving.erase(std::unique(moving.begin(), moving.end()), moving.end());
        RunPlanarizingRounds(in, incidence, active, moving, start, allowance, placed, planes);
        bool bent = false;
        for (int c : active)
            if (Bend(in.polygons[c], placed, in.Plane(c, placed)) > kPlanarPolygon)
                for (int a : in.polygons[c]) bent |= movable[a] != 0, movable[a] = 0;
        if (!bent) return;
    }
    for (int c : group)
        for (int a : in.polygons[c]) placed[a] = start[a];
}

/// Moves the anchors so that the polygons of four or more anchors lie in one plane, where a
/// few small moves can do it, so that moves are kept only where they buy planar polygons.
/// Only polygons already within kPlanarizeReach of planar take part: one bent more than that
/// needs moves that would change the shape (a curved region, a junction of four regions), so
/// its anchors stay where they were placed. So do the anchors of a polygon with an anchor not
/// flagged in `movable` (the repair pinned it where moving made the output intersect itself).
/// The others are planarized group by group (PolygonGroups, PlanarizeGroup): a group that a
/// repair pass leaves as it was comes out the same, bit for bit, and its cells' triangles are
/// reused (ReusableTriangles).
inline void PlanarizePolygons(const PlanarizationInput &in, std::vector<char> movable, std::vector<Point3d> &placed)
{
    const int anchorCount = int(placed.size());
    const PolygonIncidence incidence(in.polygons, anchorCount);
    std::vector<int> candidates;
    std::vector<char> stays(anchorCount, 0);
    for (int c = 0; c < int(in.polygons.size()); ++c) {
        const std::vector<int> &polygon = in.polygons[c];
        if (!PolygonIncidence::CanBend(polygon)) continue;
        const bool pinned = std::any_of(polygon.begin(), polygon.end(), [&](int a) { return !movable[a]; });
        if (!pinned && Bend(polygon, placed, in.Plane(c, placed)) <= kPlanarizeReach) candidates.push_back(c);
        else
            for (int a : polygon) stays[a] = 1;
    }
    for (int a = 0; a < anchorCount; ++a) movable[a] &= !stays[a];
    const std::vector<Point3d> start = placed;
    const std::vector<double> allowance = PlanarizingAllowance(in, incidence);
    std::vector<PolygonPlane> planes(in.polygons.size());
    for (const std::vector<int> &group : PolygonGroups(in.polygons, candidates, movable))
        PlanarizeGroup(in, incidence, group, movable, start, allowance, placed, planes);
}

}  // namespace detail
}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_PLANAR_POLYGONS_H
