// Variational Shape Approximation for vcglib — what is wrong with a meshing pass's output:
// intersecting and close face pairs, folds (crossing polygon edges), degenerate faces.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_PASS_DEFECTS_H
#define VSA_PASS_DEFECTS_H

#include <vsa/indexed_mesh.h>
#include <vsa/mesh_validity.h>
#include <vsa/meshing_pass.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

namespace detail {

/// What is wrong with a pass's output: pairs of faces that intersect, and pairs of edges of
/// a cell's polygon that cross on the cell's plane (a chord cutting across another: the
/// polygon is not simple, and its triangulation folds, even where no face pair intersects).
struct PassDefects
{
    std::vector<std::pair<int, int>> intersections;  ///< output face pairs that meet
    /// Output face pairs that do not meet but come closer than the clearance (see FindDefects):
    /// they may meet once the output is saved as text and read back.
    std::vector<std::pair<int, int>> closePairs;
    struct Crossing
    {
        int cell, edge, otherEdge;  ///< polygon edge k joins polygon vertices k and k + 1
    };
    std::vector<Crossing> crossings;
    std::vector<char> degenerate;  ///< per face of the pass's output: DegenerateFaceMask
    /// Faces flagged in `degenerate` (anchors projected onto one point): the next pass pins
    /// their anchors.
    size_t degenerateFaces = 0;
    size_t Count() const { return intersections.size() + closePairs.size() + crossings.size() + degenerateFaces; }
    /// Whether some faces meet or come too close: what halving, keeping input faces and carving
    /// work against.
    bool HasPairs() const { return !intersections.empty() || !closePairs.empty(); }
    /// Orders outputs by their pairs: fewer that meet, then fewer close ones.
    std::pair<size_t, size_t> PairRank() const { return {intersections.size(), closePairs.size()}; }
    /// Calls visit(f, g) for each intersecting pair, then each close pair.
    template <class Visit>
    void ForEachPair(Visit visit) const
    {
        for (const auto *pairs : {&intersections, &closePairs})
            for (const auto &[f, g] : *pairs) visit(f, g);
    }
    /// Ranks passes: fewer intersecting pairs first, as they stay in the output (a crossing
    /// is only where a fold may start, and the triangulation often avoids it), then fewer
    /// close pairs, then fewer defects in all.
    bool BetterThan(const PassDefects &other) const
    {
        if (PairRank() != other.PairRank()) return PairRank() < other.PairRank();
        return Count() < other.Count();
    }
};

/// Per face of `pass`, a face of `previous` it repeats: the same corner positions in the same
/// order, and as degenerate or not (the passes' masks, see DegenerateFaceMask); else -1. Each
/// face of `previous` is repeated at most once. FacesIntersect sees nothing else of two faces,
/// so a pair of repeated faces intersects in both passes or in neither. Faces are matched by
/// their corners, not by their cells: a cell that a repair changed keeps most of its triangles.
inline std::vector<int> RepeatedFaces(const MeshingPass &pass, const std::vector<char> &degenerate,
                                      const MeshingPass &previous, const std::vector<char> &wasDegenerate)
{
    // Candidates share the surface vertex of the first corner (none for a centroid vertex).
    auto firstSource = [](const MeshingPass &p, int f) { return p.vertexSource[p.triangles[f][0]]; };
    std::vector<int> sourceOfFace(previous.triangles.size());
    int sourceCount = 0;
    for (size_t g = 0; g < sourceOfFace.size(); ++g) {
        sourceOfFace[g] = firstSource(previous, int(g));
        sourceCount = std::max(sourceCount, sourceOfFace[g] + 1);
    }
    std::vector<int> offset, facesOfSource;
    BuildOffsets(sourceOfFace, sourceCount, offset, facesOfSource);
    auto same = [&](int f, int g) {
        for (int i = 0; i < 3; ++i)
            if (pass.positions[pass.triangles[f][i]] != previous.positions[previous.triangles[g][i]]) return false;
        return degenerate[f] == wasDegenerate[g];
    };
    std::vector<int> repeats(pass.triangles.size(), -1);
    std::vector<char> taken(previous.triangles.size(), 0);
    for (int f = 0; f < int(repeats.size()); ++f) {
        const int source = firstSource(pass, f);
        if (source < 0 || source >= sourceCount) continue;
        for (int k = offset[source]; k < offset[source + 1] && repeats[f] < 0; ++k) {
            const int g = facesOfSource[k];
            if (!taken[g] && same(f, g)) repeats[f] = g, taken[g] = 1;
        }
    }
    return repeats;
}

/// The defects of `pass`, with the face pairs that come closer than `clearance` without meeting
/// (see FacesIntersect) apart; given an earlier pass and its defects (found with the same
/// clearance), only the pairs with a face that is not a repeat of that pass are tested (see
/// RepeatedFaces), and only the cells whose polygon or plane changed are searched for crossings.
/// The earlier pass may be of another labelling of the same surface (an earlier trial) or of
/// the surface this one was split from (halved or carved): cells are matched by index, and one
/// with another polygon or plane is searched anew.
/// `repeats`, if given, receives RepeatedFaces of `pass` in `previous` (empty without it).
inline PassDefects FindDefects(const MeshingPass &pass, double clearance, const MeshingPass *previous = nullptr,
                               const PassDefects *previousDefects = nullptr, std::vector<int> *repeats = nullptr)
{
    PassDefects defects;
    IndexedMesh output;  // as far as self-intersections are concerned
    output.positions = pass.positions;
    output.faces = pass.triangles;
    defects.degenerate = DegenerateFaceMask(output);
    defects.degenerateFaces = size_t(std::count(defects.degenerate.begin(), defects.degenerate.end(), 1));
    std::vector<char> fresh;  // all, without `previous`
    std::vector<int> repeatOf;      // per face of `previous`: the face of `pass` that repeats it
    std::vector<int> previousFace;  // per face of `pass`: the face of `previous` it repeats
    if (previous) {
        previousFace = RepeatedFaces(pass, defects.degenerate, *previous, previousDefects->degenerate);
        fresh.resize(previousFace.size());
        repeatOf.assign(previous->triangles.size(), -1);
        for (size_t f = 0; f < previousFace.size(); ++f) {
            fresh[f] = previousFace[f] < 0;
            if (previousFace[f] >= 0) repeatOf[previousFace[f]] = int(f);
        }
    }
    if (repeats) *repeats = std::move(previousFace);
    // Pairs found now meet or are close; the exact test tells which.
    const std::vector<std::pair<int, int>> found = SelfIntersectingPairs(output, defects.degenerate, fresh, clearance);
    for (const auto &[f, g] : found)
        (clearance <= 0 || FacesIntersect(output, f, g) ? defects.intersections : defects.closePairs)
            .emplace_back(f, g);
    if (previous) {  // a pair of repeated faces is as it was
        auto carry = [&](const std::vector<std::pair<int, int>> &known, std::vector<std::pair<int, int>> &into) {
            for (const auto &[f, g] : known)
                if (repeatOf[f] >= 0 && repeatOf[g] >= 0) into.emplace_back(std::minmax(repeatOf[f], repeatOf[g]));
            std::sort(into.begin(), into.end());
        };
        carry(previousDefects->intersections, defects.intersections);
        carry(previousDefects->closePairs, defects.closePairs);
    }
    // A cell with the polygon (SamePolygon) and the plane it had in `previous` has the crossings
    // it had there (they come in cell order).
    auto unchanged = [&](int c) {
        return c < int(previous->polygons.size()) && previous->cellMethod[c] != CellMethod::InputFaces &&
               pass.cellNormal[c] == previous->cellNormal[c] && SamePolygon(*previous, pass, c);
    };
    size_t known = 0;  // previous crossings of the cells before c
    for (int c = 0; c < int(pass.polygons.size()); ++c) {
        const size_t knownFrom = known;
        while (previous && known < previousDefects->crossings.size() && previousDefects->crossings[known].cell == c)
            ++known;
        if (pass.cellMethod[c] == CellMethod::InputFaces) continue;  // its own faces: nothing folds
        if (previous && unchanged(c))
            defects.crossings.insert(defects.crossings.end(), previousDefects->crossings.begin() + knownFrom,
                                     previousDefects->crossings.begin() + known);
        else
            for (const auto &[i, j] : CrossingPolygonEdges(pass.polygons[c], pass.positions, pass.cellNormal[c]))
                defects.crossings.push_back({c, i, j});
    }
    return defects;
}

/// A pass with its defects, found with `clearance` (see FindDefects): where a later pass may
/// start its tests from.
struct CheckedPass
{
    MeshingPass pass;
    PassDefects defects;
    double clearance = 0;
};

/// Whether `written`, indexed from the output mesh, is the output of `pass`: the same faces on
/// corners at the same positions, every vertex used. Only the vertex numbering may differ
/// then, which SelfIntersectingPairs does not see: the pass's intersections are the output's.
inline bool WritesPass(const IndexedMesh &written, const MeshingPass &pass)
{
    if (written.positions.size() != pass.positions.size() || written.faces.size() != pass.triangles.size())
        return false;
    for (size_t v = 0; v < written.positions.size(); ++v)
        if (written.positions[v] != pass.positions[written.sourceVertex[v]]) return false;
    for (size_t f = 0; f < written.faces.size(); ++f)
        for (int i = 0; i < 3; ++i)
            if (written.sourceVertex[written.faces[f][i]] != pass.triangles[f][i]) return false;
    return true;
}

}  // namespace detail

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_PASS_DEFECTS_H
