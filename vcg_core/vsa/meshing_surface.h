// Variational Shape Approximation for vcglib — the surface the meshing stage walks: an
// oriented 2-manifold with boundary, its regions cut into topological discs ("cells"), and
// the boundary loop of every cell. Anchors are chosen on these loops (anchors.h); the runs
// of a loop between consecutive anchors are the chains (chords.h).
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_MESHING_SURFACE_H
#define VSA_MESHING_SURFACE_H

#include <vsa/indexed_mesh.h>
#include <vsa/parallel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

/// One of the surface's arrays that do not depend on the partition (positions, faces, their
/// links), which copies of a surface share: set once by BuildSurfaceTopology, read-only after.
/// The meshable split relabels two surfaces in turn, and the halving rounds copy theirs.
template <class T>
class SharedArray
{
public:
    SharedArray &operator=(std::vector<T> &&values)
    {
        auto shared = std::make_shared<const std::vector<T>>(std::move(values));
        data_ = shared->data();
        size_ = shared->size();
        values_ = std::move(shared);
        return *this;
    }
    const T &operator[](size_t i) const { return data_[i]; }
    size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    const T *begin() const { return data_; }
    const T *end() const { return data_ + size_; }
    operator const std::vector<T> &() const { return values_ ? *values_ : Empty(); }

private:
    static const std::vector<T> &Empty()
    {
        static const std::vector<T> empty;
        return empty;
    }

    std::shared_ptr<const std::vector<T>> values_;
    const T *data_ = nullptr;  ///< values_'s, read without going through the shared pointer
    size_t size_ = 0;
};

/// The partitioned input as an oriented 2-manifold with boundary, cut into disc cells.
///
/// Why cells: a region that is a disc has one boundary loop, and any triangulation of the
/// anchor polygon of that loop is a disc; glued along shared chords, such discs give back
/// the input's topology exactly. A region that is not a disc (a ring, a region with islands,
/// a whole closed component, a region through a handle) is cut into several discs that keep
/// the region's proxy; the cuts carry no dihedral angle, so they add no anchors beyond what
/// the topology needs, and the output faces of all its cells still belong to the region.
struct MeshingSurface
{
    SharedArray<Point3d> positions;          ///< per vertex
    SharedArray<int> sourceVertex;           ///< vertex -> IndexedMesh vertex
    SharedArray<std::array<int, 3>> faces;   ///< in the input's orientation
    SharedArray<std::array<int, 3>> neighbors;  ///< face across edge i (faces[f][i] -> faces[f][i+1]), -1 on border
    SharedArray<int> sourceFace;             ///< face -> IndexedMesh face
    std::vector<int> faceRegion;             ///< face -> region (partition label)
    /// face -> piece of its region: no cell spans two (see HalveCells); empty: one piece per region
    std::vector<int> facePiece;
    std::vector<int> faceCell;               ///< face -> cell
    std::vector<int> cellRegion;             ///< cell -> region
    /// cell -> lowest face of the component it was cut from (connected faces of one region and
    /// one piece): cells are numbered in this order, a component's cells in the order grown
    std::vector<int> cellComponentFace;
    std::vector<int> cellFaceOffset, cellFaces;      ///< faces of cell c: cellFaces[cellFaceOffset[c] .. c+1)
    SharedArray<int> vertexFaceOffset, vertexFaces;  ///< faces around vertex v, same layout
    /// The boundary loop of each cell: its vertices in order, the cell on the left (the
    /// loop runs along the input's half-edges). cellLoopOther[c][i] is the cell across the
    /// loop edge loop[i] -> loop[i+1], or -1 where that edge is on the mesh border.
    std::vector<std::vector<int>> cellLoop;
    std::vector<std::vector<int>> cellLoopOther;
    /// Per cell: the sum of its faces' cross products (twice its area-weighted normal), the sum
    /// of their norms (twice its area), and the centroid of its faces weighted by their areas.
    std::vector<Point3d> cellAreaVector;
    std::vector<double> cellDoubleArea;
    std::vector<Point3d> cellCentroid;
    /// Per vertex: on the mesh border; a junction, i.e. on three or more boundary edges
    /// (between cells, or on the border), where three cells, or two and the border, meet.
    std::vector<char> onBorder, junction;
    int regionCount = 0;

    // What was done to the input to make it walkable.
    int ignoredFaces = 0;       ///< faces with a repeated vertex: no area, no edges
    int splitVertices = 0;      ///< extra vertices made by splitting non-manifold vertices per fan

    int VertexCount() const { return int(positions.size()); }
    int FaceCount() const { return int(faces.size()); }
    int CellCount() const { return int(cellRegion.size()); }
    int CellFaceCount(int c) const { return cellFaceOffset[c + 1] - cellFaceOffset[c]; }
    int PieceOf(int f) const { return facePiece.empty() ? 0 : facePiece[f]; }
    /// Face f's normal times twice its area, following its vertex order.
    Point3d DoubleAreaVector(int f) const
    {
        const auto &t = faces[f];
        return (positions[t[1]] - positions[t[0]]) ^ (positions[t[2]] - positions[t[0]]);
    }
};

namespace detail {

/// Index j of the edge of face g that runs opposite to edge i of face f (its twin), on a
/// MeshingSurface or a linked IndexedMesh.
template <class Mesh>
int TwinEdge(const Mesh &s, int f, int i)
{
    const int g = s.neighbors[f][i], from = s.faces[f][(i + 1) % 3];
    for (int j = 0; j < 3; ++j)
        if (s.faces[g][j] == from) return j;
    return -1;
}

/// Gives the corners of `m` new vertices, one per key (keyOf(corner), below keyCount): the first
/// key of each vertex of `m` (in corner order) keeps that vertex's number, the others get
/// numbers after them, in the order corners first use them; then the vertices no corner uses
/// are dropped, the others keeping their order. So a mesh whose vertices are all used and have
/// one key each keeps its numbers. `sourceVertex` gets each new vertex's vertex of `m`;
/// returns how many vertices the keys added. keyOf(corner) is asked before that corner gets its
/// new vertex.
template <class KeyOf>
int NumberVerticesPerKey(IndexedMesh &m, size_t keyCount, KeyOf &&keyOf, std::vector<int> &sourceVertex)
{
    const int cornerCount = 3 * m.FaceCount();
    const int vertexCount = m.VertexCount();
    std::vector<int> newVertex(keyCount, -1);
    std::vector<char> used(size_t(vertexCount), 0);
    std::vector<int> extraSource;  // per extra vertex, numbered vertexCount + its index
    ProgressCounter progress;
    for (int c = 0; c < cornerCount; ++c) {
        progress.Count();
        int &vertex = m.faces[c / 3][c % 3];
        int &fresh = newVertex[size_t(keyOf(c))];
        if (fresh < 0) {
            if (!used[vertex]) {
                used[vertex] = 1;
                fresh = vertex;
            } else {
                fresh = vertexCount + int(extraSource.size());
                extraSource.push_back(vertex);
            }
        }
        vertex = fresh;
    }
    std::vector<int> kept(size_t(vertexCount), -1);  // the new number of each used vertex
    sourceVertex.clear();
    for (int v = 0; v < vertexCount; ++v)
        if (used[v]) {
            kept[v] = int(sourceVertex.size());
            sourceVertex.push_back(v);
        }
    const int usedCount = int(sourceVertex.size());
    sourceVertex.insert(sourceVertex.end(), extraSource.begin(), extraSource.end());
    sourceVertex.shrink_to_fit();  // the surface keeps these arrays: no room to spare
    if (usedCount < vertexCount)
        for (auto &t : m.faces)
            for (int &v : t) v = v < vertexCount ? kept[v] : v - vertexCount + usedCount;
    std::vector<Point3d> positions(sourceVertex.size());
    for (size_t v = 0; v < sourceVertex.size(); ++v) positions[v] = m.positions[size_t(sourceVertex[v])];
    m.positions.swap(positions);
    return int(extraSource.size());
}

/// The faces around each vertex of `m`, in face order: vertexFaces[offset[v] .. offset[v + 1]).
inline void FacesAroundVertices(const IndexedMesh &m, std::vector<int> &offset, std::vector<int> &faces)
{
    BuildLists(
        size_t(m.FaceCount()),
        [&m](size_t f, auto &&add) {
            for (int v : m.faces[f]) add(v, int(f));
        },
        m.VertexCount(), offset, faces);
}

/// Gives every fan of faces around a vertex of `m` (linked) its own vertex, so that each vertex
/// has one fan (a disc, or a half-disc on the border). Corners are joined across linked edges.
/// `sourceVertex` gets each vertex's vertex of `m` before; returns how many vertices it added.
inline int SplitVerticesPerFan(IndexedMesh &m, std::vector<int> &sourceVertex)
{
    const int faceCount = m.FaceCount();
    std::vector<int> cornerParent = SingletonSets(size_t(faceCount) * 3);
    for (int f = 0; f < faceCount; ++f)
        for (int i = 0; i < 3; ++i) {
            const int g = m.neighbors[f][i];
            if (g < f) continue;  // each linked edge once; skips the border
            const int j = TwinEdge(m, f, i);
            Unite(cornerParent, 3 * f + i, 3 * g + (j + 1) % 3);
            Unite(cornerParent, 3 * f + (i + 1) % 3, 3 * g + j);
        }
    return NumberVerticesPerKey(m, cornerParent.size(), [&](int c) { return FindRoot(cornerParent, c); },
                                sourceVertex);
}

/// Scratch of the disc growths. A growth reads and writes only the faces of its own region
/// (DiscGrower::Mine guards every other read), so the growths of different regions share the
/// per-face arrays from different threads; vertices are shared by regions, so each thread has
/// its own per-vertex marks.
struct DiscScratch
{
    explicit DiscScratch(size_t faceCount)
        : hop(faceCount, -1), queued(faceCount, 0), seen(faceCount, 0), slot(faceCount, 0), inSlot(MaxThreads())
    {
    }
    std::vector<int> hop;      ///< per face: breadth-first distance, -1 where not reached
    std::vector<char> queued;  ///< per face: allowed in the current growth
    std::vector<char> seen;    ///< per face: already in a component
    std::vector<char> slot;    ///< per face with faceCell == kGrowing: the disc it grows in
    /// per thread, per vertex: bit b set when on the disc growing in slot b
    std::vector<std::vector<unsigned char>> inSlot;

    /// The calling thread's inSlot, made on first use.
    std::vector<unsigned char> &VertexMarks(int vertexCount)
    {
        std::vector<unsigned char> &marks = inSlot[ThreadIndex()];
        if (marks.empty()) marks.assign(size_t(vertexCount), 0);
        return marks;
    }
};

/// Grows disc cells over the connected sets of faces of one region, numbering them in the
/// order they are made: faceCell holds that number until CutFreeFaces numbers the cells.
///
/// A face joins a growing disc only if the disc stays a disc: it shares one edge with it and
/// its third vertex is new to the disc, or it shares two edges (closing a notch). Growing one
/// disc from one face covers any face set that is a disc; otherwise two discs grow in turn
/// from two far-apart faces, so that a ring or a closed region is cut into halves instead of
/// leaving a thin seam, and what neither covers is cut again the same way.
class DiscGrower
{
public:
    DiscGrower(MeshingSurface &s, DiscScratch &scratch, int region)
        : s_(s), x_(scratch), inSlot_(scratch.VertexMarks(s.VertexCount())), region_(region)
    {
    }

    /// Cuts `component` (faces of the region and one piece, connected through edges, none in a
    /// cell yet) into discs.
    void Decompose(const std::vector<int> &component)
    {
        piece_ = s_.PieceOf(component.front());
        const std::vector<int> added = GrowSeveral({component.front()}, component).front();
        if (added.size() == component.size()) {
            Commit(added);
            return;
        }
        Undo(added);
        std::vector<std::vector<int>> pending = {component};
        while (!pending.empty()) {
            const std::vector<int> piece = std::move(pending.back());
            pending.pop_back();
            const int first = FarthestFace(piece, piece.front());
            const int second = FarthestFace(piece, first);
            std::vector<int> seeds = {first};
            if (second != first) seeds.push_back(second);
            for (const std::vector<int> &disc : GrowSeveral(seeds, piece)) Commit(disc);
            for (std::vector<int> &rest : UnassignedComponents(piece)) pending.push_back(std::move(rest));
        }
    }

    /// Makes `disc` (faces of the region that form a disc, none in a cell yet) the next disc.
    void Commit(const std::vector<int> &disc)
    {
        for (int f : disc) s_.faceCell[f] = discCount_;
        ++discCount_;
    }

    int DiscCount() const { return discCount_; }

private:
    static constexpr int kFree = -1;     ///< faceCell of a face in no cell yet
    static constexpr int kGrowing = -2;  ///< faceCell of a face in a disc being grown

    MeshingSurface &s_;
    DiscScratch &x_;
    std::vector<unsigned char> &inSlot_;  ///< the calling thread's (DiscScratch::inSlot)
    const int region_;
    int piece_ = 0;  ///< the piece of the component being cut
    int discCount_ = 0;

    /// Whether f is a face of the region and piece being cut. The growth reads and writes no
    /// other face's state: other regions' faces may be growing on other threads.
    bool Mine(int f) const { return f >= 0 && s_.faceRegion[f] == region_ && s_.PieceOf(f) == piece_; }

    bool Allowed(int f) const { return Mine(f) && x_.queued[f] && s_.faceCell[f] == kFree; }

    bool Growing(int f, int slot) const { return Mine(f) && s_.faceCell[f] == kGrowing && x_.slot[f] == slot; }

    bool CanJoin(int f, int slot) const
    {
        int sharedEdges = 0, lastShared = -1;
        for (int i = 0; i < 3; ++i)
            if (Growing(s_.neighbors[f][i], slot)) {
                ++sharedEdges;
                lastShared = i;
            }
        if (sharedEdges == 2) return true;
        if (sharedEdges != 1) return false;  // 3 would close a sphere; 0 is not adjacent
        const int apex = s_.faces[f][(lastShared + 2) % 3];
        return !(inSlot_[apex] & (1u << slot));
    }

    void Join(int f, int slot, std::vector<int> &disc)
    {
        s_.faceCell[f] = kGrowing;
        x_.slot[f] = char(slot);
        for (int v : s_.faces[f]) inSlot_[v] |= (1u << slot);
        disc.push_back(f);
    }

    /// Grows one disc per seed (at most two), taking turns one face at a time, breadth first.
    std::vector<std::vector<int>> GrowSeveral(const std::vector<int> &seeds, const std::vector<int> &piece)
    {
        for (int f : piece) x_.queued[f] = 1;
        std::vector<std::vector<int>> discs(seeds.size());
        std::vector<std::deque<int>> fronts(seeds.size());
        for (size_t slot = 0; slot < seeds.size(); ++slot) {
            Join(seeds[slot], int(slot), discs[slot]);
            PushNeighbors(seeds[slot], fronts[slot]);
        }
        for (bool active = true; active;) {
            active = false;
            for (size_t slot = 0; slot < seeds.size(); ++slot) {
                while (!fronts[slot].empty()) {
                    const int f = fronts[slot].front();
                    fronts[slot].pop_front();
                    if (!Allowed(f) || !CanJoin(f, int(slot))) continue;  // retried when a neighbour joins
                    Join(f, int(slot), discs[slot]);
                    PushNeighbors(f, fronts[slot]);
                    active = true;
                    break;
                }
            }
        }
        for (int f : piece) x_.queued[f] = 0;
        for (const std::vector<int> &disc : discs)
            for (int f : disc)
                for (int v : s_.faces[f]) inSlot_[v] = 0;
        return discs;
    }

    void PushNeighbors(int f, std::deque<int> &front) const
    {
        for (int g : s_.neighbors[f])
            if (Allowed(g)) front.push_back(g);
    }

    void Undo(const std::vector<int> &disc)
    {
        for (int f : disc) s_.faceCell[f] = kFree;
    }

    /// The face of `piece` farthest from `start` in edge hops (first one found on ties).
    int FarthestFace(const std::vector<int> &piece, int start)
    {
        for (int f : piece) x_.queued[f] = 1;
        std::vector<int> order = {start};
        x_.hop[start] = 0;
        for (size_t head = 0; head < order.size(); ++head)
            for (int g : s_.neighbors[order[head]])
                if (Allowed(g) && x_.hop[g] < 0) {
                    x_.hop[g] = x_.hop[order[head]] + 1;
                    order.push_back(g);
                }
        const int farthest = order.back();
        for (int f : order) x_.hop[f] = -1;
        for (int f : piece) x_.queued[f] = 0;
        return farthest;
    }

    std::vector<std::vector<int>> UnassignedComponents(const std::vector<int> &piece)
    {
        std::vector<std::vector<int>> components;
        for (int f : piece) x_.queued[f] = 1;
        for (int start : piece) {
            if (!Allowed(start)) continue;
            std::vector<int> component = {start};
            x_.queued[start] = 0;
            for (size_t head = 0; head < component.size(); ++head)
                for (int g : s_.neighbors[component[head]])
                    if (Allowed(g)) {
                        x_.queued[g] = 0;
                        component.push_back(g);
                    }
            std::sort(component.begin(), component.end());
            components.push_back(std::move(component));
        }
        for (int f : piece) x_.queued[f] = 0;
        return components;
    }
};

/// A component cut by CutRegion: its lowest face and the discs it was cut into.
struct CutComponent
{
    int lowestFace;
    int discs;
};

/// Cuts the free faces of `region` (`first` to `last`, ascending) into discs, component by
/// component in order of their lowest face (see CutFreeFaces); faceCell gets each face's disc,
/// numbered within the region.
inline std::vector<CutComponent> CutRegion(MeshingSurface &s, DiscScratch &scratch, int region, const int *first,
                                           const int *last, const std::vector<int> &previousCell,
                                           const std::vector<int> &previousOffset)
{
    DiscGrower grower(s, scratch, region);
    std::vector<CutComponent> cut;
    for (; first != last; ++first) {
        const int start = *first;
        if (scratch.seen[start]) continue;
        const int piece = s.PieceOf(start);
        const int before = previousCell.empty() ? -1 : previousCell[start];
        std::vector<int> component = {start};
        scratch.seen[start] = 1;
        bool inOneCell = before >= 0;
        for (size_t head = 0; head < component.size(); ++head)
            for (int g : s.neighbors[component[head]])
                if (g >= 0 && s.faceRegion[g] == region && s.PieceOf(g) == piece && !scratch.seen[g]) {
                    scratch.seen[g] = 1;
                    component.push_back(g);
                    inOneCell = inOneCell && previousCell[g] == before;
                }
        const int discsBefore = grower.DiscCount();
        if (inOneCell && int(component.size()) == previousOffset[before + 1] - previousOffset[before]) {
            grower.Commit(component);
        } else {
            std::sort(component.begin(), component.end());
            grower.Decompose(component);
        }
        cut.push_back({start, grower.DiscCount() - discsBefore});
    }
    return cut;
}

/// Cuts the components of the faces in no cell (faceCell -1) into disc cells numbered from
/// CellCount() on, in order of their lowest face. The free faces of region r are
/// freeFaces[freeOffset[r] .. r+1), ascending. A component that was cell `before` of
/// `previousCell` (per face, or empty) and `previousOffset` whole is a disc, and stays one cell
/// without being grown again. Regions are cut on every core, each on its own (CutRegion); the
/// cells are numbered after, so the numbers do not depend on the threads.
inline void CutFreeFaces(MeshingSurface &s, const std::vector<int> &freeOffset, const std::vector<int> &freeFaces,
                         const std::vector<int> &previousCell, const std::vector<int> &previousOffset)
{
    const int faceCount = s.FaceCount(), regionCount = int(freeOffset.size()) - 1;
    // Each per-face array is fresh memory, hundreds of megabytes at millions of faces: the
    // ticks keep the progress bar moving between them.
    ProgressTick(faceCount);
    DiscScratch scratch(faceCount);
    ProgressTick(faceCount);
    std::vector<std::vector<CutComponent>> cut(regionCount);
    const auto facesOf = [&freeOffset](int r) { return freeOffset[r + 1] - freeOffset[r]; };
    ForEachGroup(regionCount, freeFaces.size(), facesOf, [&](int r) {
        const int *faces = freeFaces.data();
        cut[r] = CutRegion(s, scratch, r, faces + freeOffset[r], faces + freeOffset[r + 1], previousCell,
                           previousOffset);
    });

    // Each region's discs become cells in order of their components' lowest faces.
    std::vector<std::pair<int, int>> order;  // (lowest face, region)
    for (int r = 0; r < regionCount; ++r)
        for (const CutComponent &c : cut[r]) order.emplace_back(c.lowestFace, r);
    std::sort(order.begin(), order.end());
    std::vector<std::vector<int>> cellOfDisc(regionCount);
    std::vector<size_t> nextComponent(regionCount, 0);
    for (const auto &entry : order) {
        const int r = entry.second;
        const CutComponent &c = cut[r][nextComponent[r]++];
        for (int d = 0; d < c.discs; ++d) {
            cellOfDisc[r].push_back(s.CellCount());
            s.cellRegion.push_back(r);
            s.cellComponentFace.push_back(c.lowestFace);
        }
    }
    ForEachGroup(regionCount, freeFaces.size(), facesOf, [&](int r) {
        for (int k = freeOffset[r]; k < freeOffset[r + 1]; ++k) {
            int &cell = s.faceCell[freeFaces[k]];
            cell = cellOfDisc[r][cell];
        }
    });
}

/// Cuts every region into disc cells: components of a region's piece (faces of one region and
/// one piece, connected through edges) in order of their lowest face. When `s` has cells
/// already (rebuilding after HalveCells), a component that is one of them, whole, is a disc
/// and stays one cell without being grown again.
inline void BuildCells(MeshingSurface &s)
{
    const int faceCount = s.FaceCount();
    std::vector<int> previousCell;
    if (s.faceCell.size() == size_t(faceCount)) previousCell.swap(s.faceCell);
    const std::vector<int> previousOffset = std::move(s.cellFaceOffset);
    s.faceCell.assign(faceCount, -1);
    s.cellRegion.clear();
    s.cellComponentFace.clear();
    std::vector<int> regionOffset, regionFaces;
    BuildOffsets(s.faceRegion, s.regionCount, regionOffset, regionFaces);
    CutFreeFaces(s, regionOffset, regionFaces, previousCell, previousOffset);
    BuildOffsets(s.faceCell, s.CellCount(), s.cellFaceOffset, s.cellFaces);
}

/// The faces of `cells` in all.
inline size_t CellFaceTotal(const MeshingSurface &s, const std::vector<int> &cells)
{
    size_t total = 0;
    for (int c : cells) total += size_t(s.CellFaceCount(c));
    return total;
}

/// Fills the area vector, area and centroid of cell c (see MeshingSurface), summing its faces
/// in order.
inline void MeasureCell(MeshingSurface &s, int c)
{
    Point3d areaVector(0, 0, 0), centroid(0, 0, 0);
    double doubleArea = 0;
    for (int k = s.cellFaceOffset[c]; k < s.cellFaceOffset[c + 1]; ++k) {
        const int f = s.cellFaces[k];
        const auto &t = s.faces[f];
        const Point3d n = s.DoubleAreaVector(f);
        const double norm = n.Norm();
        areaVector += n;
        doubleArea += norm;
        centroid += (s.positions[t[0]] + s.positions[t[1]] + s.positions[t[2]]) * (norm / 3);
    }
    // Sums in locals, stored once: neighbouring cells' entries share cache lines across threads.
    s.cellAreaVector[c] = areaVector;
    s.cellDoubleArea[c] = doubleArea;
    s.cellCentroid[c] = centroid / (doubleArea > 0 ? doubleArea : 1.0);
}

/// Fills the cells' area vectors, areas and centroids, cell by cell on every core: each cell
/// sums its own faces in order, so the bits do not depend on the threads.
inline void MeasureCells(MeshingSurface &s)
{
    s.cellAreaVector.assign(s.CellCount(), Point3d(0, 0, 0));
    s.cellDoubleArea.assign(s.CellCount(), 0);
    s.cellCentroid.assign(s.CellCount(), Point3d(0, 0, 0));
    const auto facesOf = [&s](int c) { return s.CellFaceCount(c); };
    ForEachGroup(s.CellCount(), size_t(s.FaceCount()), facesOf, [&s](int c) { MeasureCell(s, c); });
}

/// Whether vertex v is on three boundary edges or more (between cells, or on the border).
inline bool IsJunction(const MeshingSurface &s, int v)
{
    int halfEdges = 0;  // boundary edges at v, one per face beside them: border edges count twice
    for (int k = s.vertexFaceOffset[v]; k < s.vertexFaceOffset[v + 1]; ++k) {
        const int f = s.vertexFaces[k];
        for (int i = 0; i < 3; ++i) {
            if (s.faces[f][i] != v && s.faces[f][(i + 1) % 3] != v) continue;
            const int g = s.neighbors[f][i];
            if (g < 0) halfEdges += 2;
            else if (s.faceCell[g] != s.faceCell[f]) ++halfEdges;
        }
    }
    return halfEdges >= 6;
}

/// Fills onBorder and junction (see MeshingSurface).
inline void MarkBoundaryVertices(MeshingSurface &s)
{
    s.onBorder.assign(s.VertexCount(), 0);
    ProgressCounter progress;
    for (int f = 0; f < s.FaceCount(); ++f, progress.Count())
        for (int i = 0; i < 3; ++i)
            if (s.neighbors[f][i] < 0) s.onBorder[s.faces[f][i]] = s.onBorder[s.faces[f][(i + 1) % 3]] = 1;
    s.junction.resize(s.VertexCount());
    ForEachChunk(size_t(s.VertexCount()), [&s](int, size_t begin, size_t end) {
        for (size_t v = begin; v < end; ++v) s.junction[v] = IsJunction(s, int(v));
    });
}

inline bool IsCellBoundary(const MeshingSurface &s, int f, int i)
{
    const int g = s.neighbors[f][i];
    return g < 0 || s.faceCell[g] != s.faceCell[f];
}

/// Follows the boundary of cell `c` into s.cellLoop[c] and s.cellLoopOther[c]. A cell is a disc,
/// so its boundary is one simple loop; anything else means a bug upstream and is returned as
/// the reason, not papered over.
inline std::string TraceCellLoop(MeshingSurface &s, int c)
{
    const auto notSimple = [c] {
        return "internal error: the boundary of cell " + std::to_string(c) + " is not a simple loop";
    };
    int startFace = -1, startEdge = -1, boundaryEdges = 0;
    for (int k = s.cellFaceOffset[c]; k < s.cellFaceOffset[c + 1]; ++k) {
        const int f = s.cellFaces[k];
        for (int i = 0; i < 3; ++i)
            if (IsCellBoundary(s, f, i)) {
                ++boundaryEdges;
                if (startFace < 0) startFace = f, startEdge = i;
            }
    }
    if (startFace < 0) return "internal error: a cell without boundary (cell " + std::to_string(c) + ")";
    // Built here and moved in once: neighbouring cells' vectors share cache lines across threads.
    std::vector<int> loop, other;
    int f = startFace, i = startEdge;
    do {
        if (int(loop.size()) >= boundaryEdges) return notSimple();
        loop.push_back(s.faces[f][i]);
        const int g = s.neighbors[f][i];
        other.push_back(g < 0 ? -1 : s.faceCell[g]);
        // Turn around the head vertex inside the cell to the next boundary edge.
        int cf = f, ci = (i + 1) % 3;
        for (int turns = 0; !IsCellBoundary(s, cf, ci); ++turns) {
            if (turns > s.FaceCount())
                return "internal error: lost walking around a vertex of cell " + std::to_string(c);
            const int g2 = s.neighbors[cf][ci];
            const int j = TwinEdge(s, cf, ci);
            cf = g2;
            ci = (j + 1) % 3;
        }
        f = cf;
        i = ci;
    } while (f != startFace || i != startEdge);
    std::vector<int> sorted = loop;  // a vertex twice: the cell pinches there
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return notSimple();
    if (int(loop.size()) != boundaryEdges)
        return "internal error: cell " + std::to_string(c) + " has more than one boundary loop";
    s.cellLoop[c] = std::move(loop);
    s.cellLoopOther[c] = std::move(other);
    return {};
}

/// Traces the boundary loops of `cells` (TraceCellLoop), cell by cell on every core; false with
/// the first cell's reason in `error` if one is not a simple loop.
inline bool TraceCellLoops(MeshingSurface &s, const std::vector<int> &cells, std::string &error)
{
    std::vector<std::string> errors(cells.size());
    const auto facesOf = [&](int k) { return s.CellFaceCount(cells[k]); };
    ForEachGroup(int(cells.size()), CellFaceTotal(s, cells), facesOf,
                 [&](int k) { errors[k] = TraceCellLoop(s, cells[k]); });
    for (const std::string &e : errors)
        if (!e.empty()) {
            error = e;
            return false;
        }
    return true;
}

/// TraceCellLoops for every cell.
inline bool TraceCellLoops(MeshingSurface &s, std::string &error)
{
    s.cellLoop.assign(s.CellCount(), {});
    s.cellLoopOther.assign(s.CellCount(), {});
    std::vector<int> cells(s.CellCount());
    std::iota(cells.begin(), cells.end(), 0);
    return TraceCellLoops(s, cells, error);
}

/// Cuts the regions of `s` into cells along their pieces (s.facePiece), and traces the cells.
inline bool BuildCellsAndLoops(MeshingSurface &s, std::string &error)
{
    BuildCells(s);
    MeasureCells(s);
    MarkBoundaryVertices(s);
    return TraceCellLoops(s, error);
}

/// Numbers the cells of `s` in order of their component's lowest face, a component's cells in
/// the order they were grown (the order BuildCells gives), leaving out those that `live` does
/// not mark. Returns the new index of each old cell, -1 for those left out; faceCell and
/// cellFaces are left to the caller.
inline std::vector<int> RenumberCells(MeshingSurface &s, const std::vector<char> &live)
{
    std::vector<int> order;
    for (int c = 0; c < s.CellCount(); ++c)
        if (live[c]) order.push_back(c);
    std::sort(order.begin(), order.end(), [&s](int a, int b) {
        return s.cellComponentFace[a] != s.cellComponentFace[b] ? s.cellComponentFace[a] < s.cellComponentFace[b]
                                                                : a < b;
    });
    std::vector<int> newIndex(s.CellCount(), -1), region(order.size()), componentFace(order.size());
    for (size_t n = 0; n < order.size(); ++n) {
        newIndex[order[n]] = int(n);
        region[n] = s.cellRegion[order[n]];
        componentFace[n] = s.cellComponentFace[order[n]];
    }
    s.cellRegion.swap(region);
    s.cellComponentFace.swap(componentFace);
    return newIndex;
}

/// Recomputes the junctions at the vertices of `faces`, on every core: given the faces of the
/// regions a relabelling changed, the only vertices whose boundary edges can change.
inline void UpdateJunctions(MeshingSurface &s, const std::vector<int> &faces)
{
    std::vector<char> touched(s.VertexCount(), 0);
    for (int f : faces)
        for (int v : s.faces[f]) touched[v] = 1;
    ForEachChunk(size_t(s.VertexCount()), [&](int, size_t begin, size_t end) {
        for (size_t v = begin; v < end; ++v)
            if (touched[v]) s.junction[v] = IsJunction(s, int(v));
    });
}

/// BuildCellsAndLoops for a surface whose cells were built before (one piece per region) and
/// whose faces then changed regions from `previousRegion` to s.faceRegion: the cells of the
/// regions that neither lost nor gained a face keep their faces, measures and loops, only
/// renumbered; the other regions are cut again. The same surface, bit for bit, at the cost of
/// the regions that changed (a round of the meshable partition splits a few).
inline bool RebuildChangedCells(MeshingSurface &s, const std::vector<int> &previousRegion, int previousRegionCount,
                                std::string &error)
{
    const int faceCount = s.FaceCount(), previousCells = s.CellCount();
    std::vector<char> changed(std::max(previousRegionCount, s.regionCount), 0);
    for (int f : ItemsWhere(faceCount, [&](size_t f) { return previousRegion[f] != s.faceRegion[f]; }))
        changed[previousRegion[f]] = changed[s.faceRegion[f]] = 1;
    // A face is in a changed region before iff after: it either kept its region or changed it.
    const std::vector<int> freeFaces = ItemsWhere(faceCount, [&](size_t f) { return changed[s.faceRegion[f]] != 0; });
    for (int f : freeFaces) s.faceCell[f] = -1;
    std::vector<int> freeOffset, byRegion;
    BuildOffsets(
        freeFaces.size(), [&](size_t k) { return s.faceRegion[freeFaces[k]]; }, s.regionCount, freeOffset, byRegion);
    for (int &k : byRegion) k = freeFaces[k];
    CutFreeFaces(s, freeOffset, byRegion, {}, {});
    std::vector<char> live(s.CellCount(), 1);
    for (int c = 0; c < previousCells; ++c) live[c] = !changed[s.cellRegion[c]];
    const std::vector<int> newIndex = RenumberCells(s, live);
    ForEachChunk(s.faceCell.size(), [&](int, size_t begin, size_t end) {
        for (size_t f = begin; f < end; ++f) s.faceCell[f] = newIndex[s.faceCell[f]];
    });
    BuildOffsets(s.faceCell, s.CellCount(), s.cellFaceOffset, s.cellFaces);

    const std::vector<Point3d> areaVector = std::move(s.cellAreaVector), centroid = std::move(s.cellCentroid);
    const std::vector<double> doubleArea = std::move(s.cellDoubleArea);
    std::vector<std::vector<int>> loop = std::move(s.cellLoop), other = std::move(s.cellLoopOther);
    s.cellAreaVector.assign(s.CellCount(), Point3d(0, 0, 0));
    s.cellDoubleArea.assign(s.CellCount(), 0);
    s.cellCentroid.assign(s.CellCount(), Point3d(0, 0, 0));
    s.cellLoop.assign(s.CellCount(), {});
    s.cellLoopOther.assign(s.CellCount(), {});
    // Kept cells keep their measures and loops; a loop is traced again where it runs along a
    // changed region, whose cells across it are new.
    std::vector<int> traced, fresh;
    for (int c = 0; c < previousCells; ++c) {
        const int n = newIndex[c];
        if (n < 0) continue;
        s.cellAreaVector[n] = areaVector[c];
        s.cellDoubleArea[n] = doubleArea[c];
        s.cellCentroid[n] = centroid[c];
        bool alongChanged = false;
        for (int &o : other[c]) {
            if (o >= 0 && newIndex[o] < 0) alongChanged = true;
            if (o >= 0) o = newIndex[o];
        }
        if (alongChanged) {
            traced.push_back(n);
        } else {
            s.cellLoop[n] = std::move(loop[c]);
            s.cellLoopOther[n] = std::move(other[c]);
        }
    }
    for (int c = previousCells; c < int(newIndex.size()); ++c) fresh.push_back(newIndex[c]);
    const auto facesOf = [&s, &fresh](int k) { return s.CellFaceCount(fresh[k]); };
    ForEachGroup(int(fresh.size()), CellFaceTotal(s, fresh), facesOf, [&](int k) { MeasureCell(s, fresh[k]); });
    UpdateJunctions(s, freeFaces);
    traced.insert(traced.end(), fresh.begin(), fresh.end());
    std::sort(traced.begin(), traced.end());
    return TraceCellLoops(s, traced, error);
}

}  // namespace detail

/// Why BuildMeshingSurface refuses a mesh whose faces with three distinct vertices have these
/// diagnostics (see LinkFaces), in words meant for the user; empty if it does not.
inline std::string MeshingRefusal(const MeshDiagnostics &diag)
{
    if (diag.nonManifoldEdges > 0)
        return "the mesh has " + std::to_string(diag.nonManifoldEdges) +
               " non-manifold edges (shared by more than two faces); repair them first "
               "(MeshLab: Cleaning and Repairing > Repair non Manifold Edges)";
    if (diag.inconsistentEdges > 0)
        return "the mesh is not consistently oriented (" + std::to_string(diag.inconsistentEdges) +
               " edges are walked the same way by both faces); orient it first "
               "(MeshLab: Normals > Re-Orient all faces coherently)";
    return {};
}

/// MeshingRefusal known before any partition, from `im` and its BuildIndexedMesh diagnostics.
/// Those count the edges of every face, BuildMeshingSurface only those of faces with three
/// distinct vertices: with a face that repeats a vertex the counts may differ, and only
/// BuildMeshingSurface can tell (empty here).
inline std::string MeshingRefusal(const IndexedMesh &im, const MeshDiagnostics &diag)
{
    if (std::any_of(im.faces.begin(), im.faces.end(), RepeatsVertex)) return {};
    return MeshingRefusal(diag);
}

/// Builds the part of the meshing surface that does not depend on the partition: its faces,
/// their links and the vertices split per fan, with regions and cells still empty (see
/// AssignRegions); or returns false with the reason in `error`.
///
/// Accepted input: finite coordinates; every edge shared by at most two faces, walked in
/// opposite directions by them (an edge-manifold, consistently oriented mesh, possibly open,
/// possibly with several components). Faces with a repeated vertex are ignored (they have no
/// area); vertices where several fans of faces meet are split per fan, so such a vertex
/// becomes several output vertices at the same place.
inline bool BuildSurfaceTopology(const IndexedMesh &im, MeshingSurface &s, std::string &error)
{
    s = MeshingSurface();
    for (const Point3d &p : im.positions)
        if (!IsFinite(p)) {
            error = "the mesh has vertices with NaN or infinite coordinates";
            return false;
        }
    IndexedMesh kept;
    kept.positions = im.positions;
    kept.faces.reserve(im.faces.size());  // the surface keeps these arrays: no room to spare
    std::vector<int> sourceFace;
    sourceFace.reserve(im.faces.size());
    ProgressCounter progress;
    for (int f = 0; f < im.FaceCount(); ++f) {
        progress.Count();
        const auto &t = im.faces[f];
        if (RepeatsVertex(t)) {
            ++s.ignoredFaces;
            continue;
        }
        kept.faces.push_back(t);
        sourceFace.push_back(f);
    }
    if (kept.faces.empty()) {
        error = "the mesh has no faces with three distinct vertices";
        return false;
    }
    // With no face left out, the surface's faces are the snapshot's, which are linked already:
    // its links and counts stand, and with one fan per vertex there is nothing to split.
    const bool linked = s.ignoredFaces == 0 && im.diagnostics && im.neighbors.size() == im.faces.size();
    MeshDiagnostics diag;
    if (linked) {
        kept.neighbors = im.neighbors;
        diag = *im.diagnostics;
    } else {
        detail::LinkFaces(kept, diag);
    }
    error = MeshingRefusal(diag);
    if (!error.empty()) return false;
    // With one fan per vertex and every vertex used, SplitVerticesPerFan would keep every
    // number: a snapshot like that skips its serial pass over the corners.
    std::vector<int> sourceVertex, vertexFaceOffset, vertexFaces;
    if (linked && diag.nonManifoldVertices == 0) detail::FacesAroundVertices(kept, vertexFaceOffset, vertexFaces);
    const bool everyVertexUsed = !vertexFaceOffset.empty() &&  // no two equal offsets: no empty list
                                 std::adjacent_find(vertexFaceOffset.begin(), vertexFaceOffset.end()) ==
                                     vertexFaceOffset.end();
    if (everyVertexUsed) {
        sourceVertex.resize(kept.positions.size());
        std::iota(sourceVertex.begin(), sourceVertex.end(), 0);
    } else {
        s.splitVertices = detail::SplitVerticesPerFan(kept, sourceVertex);
        detail::FacesAroundVertices(kept, vertexFaceOffset, vertexFaces);
    }
    s.positions = std::move(kept.positions);
    s.sourceVertex = std::move(sourceVertex);
    s.faces = std::move(kept.faces);
    s.neighbors = std::move(kept.neighbors);
    s.sourceFace = std::move(sourceFace);
    s.vertexFaceOffset = std::move(vertexFaceOffset);
    s.vertexFaces = std::move(vertexFaces);
    return true;
}

/// Labels the faces of a surface from BuildSurfaceTopology with their regions (`faceRegion` per
/// IndexedMesh face) and cuts the regions into disc cells; false with the reason in `error` if
/// the cells do not trace. A surface labelled before keeps, as they were, the cells of the
/// regions whose faces did not change (see RebuildChangedCells): the trials of the meshable
/// partition relabel one surface round after round, and most regions do not change.
inline bool AssignRegions(MeshingSurface &s, const std::vector<int> &faceRegion, int regionCount, std::string &error)
{
    const bool relabel = s.faceCell.size() == size_t(s.FaceCount()) && s.facePiece.empty();
    const int previousRegionCount = s.regionCount;
    std::vector<int> previousRegion;
    if (relabel) previousRegion.swap(s.faceRegion);
    s.regionCount = regionCount;
    ResizeReporting(s.faceRegion, size_t(s.FaceCount()));  // fresh memory each trial
    ForEachChunk(size_t(s.FaceCount()), [&](int, size_t begin, size_t end) {
        for (size_t f = begin; f < end; ++f) s.faceRegion[f] = faceRegion[s.sourceFace[f]];
    });
    std::vector<int>().swap(s.facePiece);  // one piece per region, and no memory for it
    const bool built = relabel ? detail::RebuildChangedCells(s, previousRegion, previousRegionCount, error)
                               : detail::BuildCellsAndLoops(s, error);
    if (!built) s.faceCell.clear();  // half-built cells: the next labels start afresh
    return built;
}

/// Whether `s` has cells and labels its faces as `faceRegion` (per IndexedMesh face) does, with
/// one piece per region: what BuildMeshingSurface gives for these labels.
inline bool IsLabelledAs(const MeshingSurface &s, const std::vector<int> &faceRegion, int regionCount)
{
    if (s.regionCount != regionCount || !s.facePiece.empty() || s.faceCell.size() != size_t(s.FaceCount()) ||
        s.faceRegion.size() != size_t(s.FaceCount()))
        return false;
    for (int f = 0; f < s.FaceCount(); ++f)
        if (s.sourceFace[f] >= int(faceRegion.size()) || s.faceRegion[f] != faceRegion[s.sourceFace[f]]) return false;
    return true;
}

/// Builds the surface the meshing stage walks (BuildSurfaceTopology, then AssignRegions), or
/// returns false with the reason in `error`.
inline bool BuildMeshingSurface(const IndexedMesh &im, const std::vector<int> &faceRegion, int regionCount,
                                MeshingSurface &s, std::string &error)
{
    return BuildSurfaceTopology(im, s, error) && AssignRegions(s, faceRegion, regionCount, error);
}

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_MESHING_SURFACE_H
