// Variational Shape Approximation for vcglib — chains and the chord criterion: the runs of
// a cell's boundary loop between consecutive anchors, and when a chain gets another anchor
// so that its chord (the output edge joining its ends) follows it.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_CHORDS_H
#define VSA_CHORDS_H

#include <vsa/meshing_surface.h>
#include <vsa/parallel.h>
#include <vsa/proxy.h>
#include <vsa/surface_grid.h>
#include <vsa/tuning.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

namespace detail {

/// Distance from p to the line through a and b, or to a when a and b coincide.
inline double DistanceToChord(const Point3d &p, const Point3d &a, const Point3d &b)
{
    const Point3d ab = b - a;
    const double length = ab.Norm();
    if (!(length > 0)) return (p - a).Norm();
    return ((p - a) ^ ab).Norm() / length;
}

/// The vertex of loop positions (from, to) (exclusive, `to` may pass the loop's end) that is
/// farthest from the chord of loop positions from and to; -1 when the run has no interior.
inline int FarthestFromChord(const MeshingSurface &s, int c, int from, int to, double *distance = nullptr)
{
    const std::vector<int> &loop = s.cellLoop[c];
    const int m = int(loop.size());
    const Point3d &a = s.positions[loop[from % m]], &b = s.positions[loop[to % m]];
    int best = -1;
    double bestDistance = -1;
    for (int t = from + 1; t < to; ++t) {
        const double d = DistanceToChord(s.positions[loop[t % m]], a, b);
        if (d > bestDistance) best = t, bestDistance = d;
    }
    if (distance) *distance = bestDistance;
    return best;
}

/// The run of loop positions from one anchor to the next, (from, to) with to > from. A
/// chain lies between two given cells (or a cell and the border) all along: where the cell
/// across changes, three cells meet, and that vertex is a junction anchor.
struct ChainRun
{
    int cell, from, to;
};

/// Every chain once: from the side of its lower-numbered cell, border chains from their cell.
inline std::vector<ChainRun> CanonicalChains(const MeshingSurface &s, const std::vector<char> &isAnchor)
{
    std::vector<ChainRun> chains;
    for (int c = 0; c < s.CellCount(); ++c) {
        const std::vector<int> &loop = s.cellLoop[c];
        const int m = int(loop.size());
        const int first = int(std::find_if(loop.begin(), loop.end(), [&](int v) { return isAnchor[v] != 0; }) -
                              loop.begin());
        // From each anchor to the next, the last one back to the first (`to` past the end).
        for (int from = first, to = first + 1; to <= first + m; ++to) {
            if (!isAnchor[loop[to % m]]) continue;
            const int across = s.cellLoopOther[c][from];
            if (across < 0 || across > c) chains.push_back({c, from, to});
            from = to;
        }
    }
    return chains;
}

/// The weight of the dihedral angle in the chord criterion: sin of the angle between the
/// proxies on the two sides of a chain. It saturates at 1 beyond 90 degrees, where a plain
/// sine would fall back to 0 for a sharp fold (the two sides of a thin plate). A chain on
/// the mesh border, and a cut between two cells of one region, get 1: nothing on their other
/// side decides where they run, so the chord must follow them.
inline double ChainAngleWeight(const MeshingSurface &s, const std::vector<Proxy> &proxies, int cell, int across)
{
    if (across < 0 || s.cellRegion[across] == s.cellRegion[cell]) return 1.0;
    const Point3d &a = proxies[s.cellRegion[cell]].normal, &b = proxies[s.cellRegion[across]].normal;
    return a * b < 0 ? 1.0 : (a ^ b).Norm();
}

/// The paper's criterion weighs a chain's bend by the angle between its two proxies, as if the
/// chord ran over the surface like the chain does. Between near-coplanar regions whose chain
/// swings around a hole or a notch of the input, the chord crosses empty space instead; this
/// test finds chords that stray farther than `threshold` times their length from the input.
class ChordGapTest
{
public:
    /// `grid`: a SurfaceGrid of these faces to borrow, or nullptr to build one when needed.
    ChordGapTest(const std::vector<Point3d> &positions, const std::vector<std::array<int, 3>> &faces, double threshold,
                 const SurfaceGrid *grid = nullptr)
        : positions_(positions), faces_(faces), threshold_(threshold), borrowed_(grid)
    {
    }

    /// Whether Strays(a, b, chainDeviation) queries the grid. When it does not, the chain runs
    /// from a to b within chainDeviation of the chord, so every point of the chord has a chain
    /// point, on the surface, at most that far.
    bool Queries(const Point3d &a, const Point3d &b, double chainDeviation) const
    {
        return chainDeviation > threshold_ * (b - a).Norm();
    }

    /// Whether the grid is there, borrowed or built: Strays then only reads, on any thread.
    bool HasGrid() const { return borrowed_ || surface_; }

    /// Builds the grid now, if it is not there (most meshings never need it).
    void BuildGrid()
    {
        if (!HasGrid()) surface_ = std::make_unique<SurfaceGrid>(positions_, faces_);
    }

    /// `chainDeviation`: the farthest distance of the chain's vertices from the chord a-b. Needs
    /// the grid when it Queries.
    bool Strays(const Point3d &a, const Point3d &b, double chainDeviation) const
    {
        if (!Queries(a, b, chainDeviation)) return false;
        const double allowed = threshold_ * (b - a).Norm();
        const SurfaceGrid &grid = borrowed_ ? *borrowed_ : *surface_;
        for (int i = 1; i < kChordGapSamples; ++i)
            if (!grid.HasFaceWithin(a + (b - a) * (double(i) / kChordGapSamples), allowed)) return true;
        return false;
    }

private:
    const std::vector<Point3d> &positions_;
    const std::vector<std::array<int, 3>> &faces_;
    double threshold_;
    const SurfaceGrid *borrowed_ = nullptr;
    std::unique_ptr<SurfaceGrid> surface_;
};

/// How far each region's input lies from its plane (the farthest of its vertices), and the
/// size of the surface: what the chord bound, the anchors' flat regions and the stray test all
/// measure against, in one pass over the faces for given regions and planes.
struct RegionFits
{
    std::vector<double> fit;  ///< per region
    double diagonal = 0;      ///< of the surface's bounding box
};

inline RegionFits MeasureRegionFits(const MeshingSurface &s, const std::vector<Proxy> &proxies)
{
    RegionFits fits;
    fits.fit.assign(proxies.size(), 0);
    const auto farther = [](double &fit, double other) { fit = std::max(fit, other); };
    SumByKey(
        size_t(s.FaceCount()), fits.fit, [&](size_t f) { return s.faceRegion[f]; },
        [&](double &fit, size_t f) {
            const Proxy &proxy = proxies[s.faceRegion[f]];
            for (int v : s.faces[f]) farther(fit, std::abs((s.positions[v] - proxy.point) * proxy.normal));
        },
        farther);
    Box3d box;
    for (const Point3d &p : s.positions) box.Add(p);
    fits.diagonal = box.Diag();
    return fits;
}

/// How far any chain may stray from its chord (d * weight, see ChainAngleWeight), whatever
/// its length: `factor` times the partition's own error, the largest distance of a vertex from
/// its region's proxy plane. The paper's criterion alone lets a long chain cut a corner of its
/// region by up to threshold * |chord|, far more than the planes' error once they fit well (a
/// CAD mesh whose regions are exactly planar kept its cut corners for any k). Planes within
/// 1e-6 times the bounding-box diagonal count as exact, so that rounding does not split
/// straight chains. Infinite when factor is 0.
inline double ChordDeviationBound(const RegionFits &fits, double factor)
{
    if (!(factor > 0)) return std::numeric_limits<double>::infinity();
    double planeError = 0;
    for (double fit : fits.fit) planeError = std::max(planeError, fit);
    return std::max(factor * planeError, 1e-6 * fits.diagonal);
}

/// The chord subdivision of chains: each chain is split recursively at its vertex farthest
/// from the chord while d * weight / |chord| exceeds the threshold (see ChainAngleWeight) or
/// d * weight exceeds `maxDeviation` (see ChordDeviationBound), or while the chord strays from
/// the surface (the gap test, when given); a chain from an anchor back to itself is always
/// split. A chain's splits depend on nothing but its cell and loop positions, so they are
/// remembered: repair passes ask again for every chain they did not change.
class ChainSubdivision
{
public:
    ChainSubdivision(const MeshingSurface &s, const std::vector<Proxy> &proxies, double threshold,
                     double maxDeviation = std::numeric_limits<double>::infinity(), ChordGapTest *gap = nullptr)
        : s_(s), proxies_(proxies), threshold_(threshold), maxDeviation_(maxDeviation), gap_(gap)
    {
    }

    /// Loop positions (of chain.cell's loop, within (chain.from, chain.to)) that get anchors,
    /// once SubdivideNew has seen the chain.
    const std::vector<int> &Splits(const ChainRun &chain) const { return splits_.at(Key(chain)); }

    /// Subdivides those of `chains` not subdivided yet, on every thread. The threads never
    /// build the gap test's grid: the chains that need it wait until it is built, on every
    /// thread, and are subdivided then.
    void SubdivideNew(const std::vector<ChainRun> &chains)
    {
        std::vector<const ChainRun *> fresh;
        for (const ChainRun &chain : chains)
            if (!splits_.count(Key(chain))) fresh.push_back(&chain);
        std::vector<std::optional<std::vector<int>>> found(fresh.size());
        SubdivideUnfound(fresh, found);
        if (std::any_of(found.begin(), found.end(), [](const auto &splits) { return !splits; })) {
            gap_->BuildGrid();
            SubdivideUnfound(fresh, found);
        }
        for (size_t k = 0; k < fresh.size(); ++k) splits_.emplace(Key(*fresh[k]), std::move(*found[k]));
    }

private:
    const MeshingSurface &s_;
    const std::vector<Proxy> &proxies_;
    double threshold_;
    double maxDeviation_;
    ChordGapTest *gap_;
    std::map<std::array<int, 3>, std::vector<int>> splits_;  ///< by (cell, from, to)

    static std::array<int, 3> Key(const ChainRun &chain) { return {chain.cell, chain.from, chain.to}; }

    /// Subdivides, on every thread, the chains of `chains` that have no splits in `found` yet.
    void SubdivideUnfound(const std::vector<const ChainRun *> &chains,
                          std::vector<std::optional<std::vector<int>>> &found) const
    {
        const auto length = [&](int k) { return size_t(chains[k]->to - chains[k]->from); };
        size_t vertices = 0;
        for (size_t k = 0; k < chains.size(); ++k) vertices += found[k] ? 0 : length(int(k));
        ForEachGroup(int(chains.size()), vertices, length, [&](int k) {
            if (!found[k]) found[k] = Subdivide(*chains[k]);
        });
    }

    /// The chain's splits, or nothing when it needs the gap test's grid and the grid is not there.
    std::optional<std::vector<int>> Subdivide(const ChainRun &chain) const
    {
        const std::vector<int> &loop = s_.cellLoop[chain.cell];
        const int m = int(loop.size());
        const double weight = ChainAngleWeight(s_, proxies_, chain.cell, s_.cellLoopOther[chain.cell][chain.from]);
        std::vector<int> splits;
        std::vector<std::pair<int, int>> stack = {{chain.from, chain.to}};
        while (!stack.empty()) {
            const auto [from, to] = stack.back();
            stack.pop_back();
            if (to - from < 2) continue;
            double distance = 0;
            const int split = FarthestFromChord(s_, chain.cell, from, to, &distance);
            const Point3d &a = s_.positions[loop[from % m]], &b = s_.positions[loop[to % m]];
            const bool closedChain = loop[to % m] == loop[from % m];
            const double deviation = distance * weight;
            if (!closedChain && !(deviation > threshold_ * (b - a).Norm()) && !(deviation > maxDeviation_)) {
                if (!gap_) continue;
                if (!gap_->HasGrid() && gap_->Queries(a, b, distance)) return std::nullopt;
                if (!gap_->Strays(a, b, distance)) continue;
            }
            splits.push_back(split);
            stack.push_back({split, to});
            stack.push_back({from, split});
        }
        return splits;
    }
};

}  // namespace detail

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_CHORDS_H
