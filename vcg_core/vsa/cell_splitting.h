// Variational Shape Approximation for vcglib — splitting cells of the meshing surface
// against self-intersections: halving a cell, or carving a piece out of it around an
// intersection. The new pieces become cells when the surface's cells are rebuilt.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_CELL_SPLITTING_H
#define VSA_CELL_SPLITTING_H

#include <vsa/meshing_surface.h>
#include <vsa/tuning.h>

#include <algorithm>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

namespace detail {

/// The faces of piece `piece` (MeshingSurface::facePiece) reachable from `seeds` through shared
/// edges, in breadth-first order, at most `limit` of them; nearest[f] is the index in `seeds`
/// of the seed that f was reached from. `reached` is scratch, 0 per face, and left so.
inline std::vector<int> SpreadInPiece(const MeshingSurface &s, int piece, const std::vector<int> &seeds, size_t limit,
                                      std::vector<char> &reached, std::vector<int> &nearest)
{
    std::vector<int> order;
    auto reach = [&](int f, int seed) {
        reached[f] = 1;
        nearest[f] = seed;
        order.push_back(f);
    };
    for (size_t i = 0; i < seeds.size() && order.size() < limit; ++i) reach(seeds[i], int(i));
    for (size_t head = 0; head < order.size(); ++head)
        for (int g : s.neighbors[order[head]])
            if (order.size() < limit && g >= 0 && s.facePiece[g] == piece && !reached[g])
                reach(g, nearest[order[head]]);
    for (int f : order) reached[f] = 0;
    return order;
}

}  // namespace detail

/// Gives every cell a piece of its own, and each cell flagged in `flagged` two, so that
/// rebuilding the cells (detail::BuildCellsAndLoops) keeps the others and halves these: into
/// the faces nearer (in edge hops) to one or the other of two far-apart faces of the cell. The
/// halves keep the region and its proxy; the cut between them is a boundary chain like any
/// other, subdivided where it bends. Returns how many cells it halved (a cell of one face
/// cannot be).
inline int HalveCells(MeshingSurface &s, const std::vector<char> &flagged)
{
    s.facePiece = s.faceCell;
    int nextPiece = s.CellCount(), halved = 0;
    std::vector<char> reached(s.FaceCount(), 0);
    std::vector<int> nearest(s.FaceCount(), -1);
    auto spread = [&](int c, const std::vector<int> &seeds) {  // the whole cell
        return detail::SpreadInPiece(s, c, seeds, s.cellFaces.size(), reached, nearest);
    };
    for (int c = 0; c < s.CellCount(); ++c) {
        if (!flagged[c] || s.CellFaceCount(c) < 2) continue;
        const int first = spread(c, {s.cellFaces[s.cellFaceOffset[c]]}).back();
        const int second = spread(c, {first}).back();
        for (int f : spread(c, {first, second}))
            if (nearest[f] == 1) s.facePiece[f] = nextPiece;
        ++nextPiece;
        ++halved;
    }
    return halved;
}

/// Gives every cell a piece of its own, and cuts a piece out of the cell of each face in
/// `seeds`: the faces nearest to the seed in edge hops, a share of the cell (see kCarvedShare),
/// unless an earlier seed's piece took this seed. Rebuilding the cells
/// (detail::BuildCellsAndLoops) keeps the other cells, and makes each piece a cell, and the
/// rest of its cell one or more (cut into discs where the piece left a ring). The pieces keep
/// the region and its proxy. Returns how many pieces it cut (a cell of one face has none).
inline int CarveCells(MeshingSurface &s, const std::vector<int> &seeds)
{
    s.facePiece = s.faceCell;
    int nextPiece = s.CellCount(), carved = 0;
    std::vector<char> reached(s.FaceCount(), 0);
    std::vector<int> nearest(s.FaceCount(), -1);
    for (int seed : seeds) {
        const int c = s.faceCell[seed], cellFaces = s.CellFaceCount(c);
        if (s.facePiece[seed] != c || cellFaces < 2) continue;
        const size_t share = std::max(1, cellFaces / detail::kCarvedShare);
        for (int f : detail::SpreadInPiece(s, c, {seed}, share, reached, nearest)) s.facePiece[f] = nextPiece;
        ++nextPiece;
        ++carved;
    }
    return carved;
}

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_CELL_SPLITTING_H
