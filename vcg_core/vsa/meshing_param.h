// Variational Shape Approximation for vcglib — the meshing's parameters (MeshingParam) and
// what it reports (MeshingReport).
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_MESHING_PARAM_H
#define VSA_MESHING_PARAM_H

#include <vsa/mesh_validity.h>

#include <sstream>
#include <string>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

struct MeshingParam
{
    /// Chord subdivision (the paper's criterion): a chain between two anchors gets a new
    /// anchor at its vertex farthest from the chord while d * sin(angle between the two
    /// proxies) / |chord| exceeds this; sin counts as 1 past 90 degrees, on the mesh border
    /// and along cuts inside a region. Smaller keeps more of each region's outline (more
    /// anchors); 0 keeps every bend. 0.2 is the knee of anchors against Hausdorff distance
    /// (docs/tuning.md).
    double chordThreshold = 0.2;
    /// A chord whose points stray farther than this times its length from the input surface is
    /// split too, whatever the angle: between near-coplanar regions the paper's criterion would
    /// let a chord cut across a hole or a notch of the input. 0 turns the test off.
    double chordGapThreshold = 0.2;
    /// A chain is also split while d * sin (as above) exceeds this times the partition's own
    /// error, the largest distance of an input vertex from its region's proxy plane: the
    /// outline then adds no error the planes do not already have. Where the regions fit
    /// loosely this changes nothing; where they fit exactly (CAD meshes at large k), a long
    /// chain no longer cuts off a corner of its region. 0 leaves the paper's criterion alone.
    /// 1 lowers the error where it can for few more faces (docs/tuning.md).
    double chordErrorFactor = 1;
    /// Move each anchor onto the planes of its regions: exactly onto those of flat regions, to
    /// the average of its projections on the others (see PlaceAnchors).
    bool projectAnchors = true;
    /// Cap on that move, as a fraction of the shortest chord at the anchor.
    double maxAnchorMove = 0.5;
    /// Then, where a few small moves make them planar, move the anchors so that each region's
    /// polygon lies in one plane (see PlanarizePolygons); needs projectAnchors.
    bool planarPolygons = true;
    /// Flag the edges inside a region faux (F0/F1/F2), so each region shows as one polygon
    /// (one per disc when the region had to be cut into discs). Off by default, as the output
    /// mesh type may have no face flags; the MeshLab plugin turns it on.
    bool polygonal = false;
    /// Count self-intersecting face pairs of the output in the report (a grid pass, O(F)).
    bool checkSelfIntersections = true;
    /// Passes that add anchors where the output folds (a region's polygon crosses itself on
    /// its plane) or intersects itself, and pin anchors whose projection made it intersect;
    /// each is a new triangulation and a grid pass, run only while defects remain. 0 keeps the
    /// first output as it is. Later rounds are cheap and still remove intersections
    /// (docs/tuning.md); a repair that diverges stops early (see kRepairPatience).
    int repairRounds = 12;
    /// When those passes leave self-intersections, the cells of the intersecting faces are
    /// halved (see HalveCells) and meshed again, at most this many times: a region whose flat
    /// triangulation spans a curved part of the shape (a turbine's blades at small k) cuts through
    /// distant parts of the output, which more anchors on its outline cannot fix, while its
    /// halves follow the shape more closely. Each halving costs a meshing. 0: never, nor any
    /// carving (see maxInputFacesGrowth): cells stay as the regions are cut into discs; so does
    /// repairRounds = 0, which looks for no intersections.
    int halvingRounds = 8;
    /// Last resort, when halving leaves self-intersections: the regions concerned keep their
    /// input faces, provided that at most multiplies the output's faces by this (0: never).
    /// Where that breaks the budget or leaves pairs, a piece of each cell concerned, around the
    /// intersection, is carved out as a cell of its own and that is tried again (see
    /// kCarvingRounds; not with halvingRounds = 0). Beyond that the output keeps its
    /// intersections, reported: k is too small for the shape, or the input intersects itself there.
    double maxInputFacesGrowth = 2;
};

struct MeshingReport
{
    bool ok = false;
    std::string error;  ///< why nothing was built, when !ok

    int regions = 0;                   ///< regions with faces, all of them in the output
    int emptyRegions = 0;              ///< proxies without any face
    int regionsByFlooding = 0;         ///< triangulated by the discrete flooding alone
    int regionsByEarClipping = 0;      ///< flooding completed or replaced by ear clipping
    int regionsWithSteinerVertex = 0;  ///< needed a fan around an extra vertex
    int regionsKeptAsInput = 0;        ///< kept (in part) at the input's resolution against self-intersections
    int regionsCut = 0;                ///< not a disc (ring, islands, handle, closed, disconnected): cut into discs
    int cells = 0;                     ///< discs triangulated (regions, or their pieces)
    int cellsHalved = 0;    ///< cells halved on the way to the output (see MeshingParam::halvingRounds)
    int outputHalvingRound = 0;  ///< the halving round the output came from (0: none)
    int halvingRoundsRun = 0;    ///< halving rounds run, those after the output's included
    int piecesCarved = 0;   ///< pieces carved out of cells on the way to the output (see maxInputFacesGrowth)
    int outputCarvingRound = 0;  ///< the carving round the output came from (0: none)

    int anchors = 0;
    int junctionAnchors = 0;     ///< where three regions (or cells) meet, the border counting as one
    int loopSeedAnchors = 0;     ///< on boundary loops without any junction
    int chordAnchors = 0;        ///< from the chord criterion
    int loopAnchors = 0;         ///< completing loops to three anchors
    int duplicateChordAnchors = 0;  ///< splitting chains that joined the same two anchors
    int repairAnchors = 0;          ///< added where an earlier pass's output folded or intersected itself
    int pinnedAnchors = 0;          ///< left unprojected where projecting made the output intersect itself
    int outputRepairRound = 0;      ///< the repair round the output came from, the first pass being 0
    int passes = 0;                 ///< passes run, the first one included: the cost of the repairs
    int steinerVertices = 0;
    /// Face pairs of the output that do not meet but come closer than its files keep them apart
    /// (see detail::SavedCoordinateClearance): saved as text and read back, they may. Counted
    /// with the repair (repairRounds > 0) only.
    int closePairs = 0;

    int ignoredFaces = 0;   ///< input faces with a repeated vertex (no area)
    int splitVertices = 0;  ///< extra output-side vertices from splitting non-manifold input vertices

    std::vector<int> faceRegion;  ///< per output face: region index
    /// Per output vertex: the IndexedMesh vertex it comes from. Output vertices 0 .. anchors-1
    /// are the anchors; the rest are the extra vertices of fans, on the input vertex they
    /// sit on, or -1 for one at a cell's centroid.
    std::vector<int> vertexSource;

    MeshValidity validity;  ///< of the output mesh as written

    std::string Summary() const
    {
        std::ostringstream s;
        if (!ok) return "meshing failed: " + error;
        s << regions << " regions -> " << validity.faces << " faces, " << validity.vertices << " vertices ("
          << anchors << " anchors";
        if (steinerVertices) s << ", " << steinerVertices << " extra vertices";
        s << ")";
        if (repairAnchors) s << ", " << repairAnchors << " anchors added against folds and self-intersections";
        if (pinnedAnchors) s << ", " << pinnedAnchors << " anchors left unprojected against self-intersections";
        if (passes > 1) s << ", " << passes << " passes (output from pass " << outputRepairRound + 1 << ")";
        s << "; triangulated by flooding " << regionsByFlooding << ", ear clipping " << regionsByEarClipping;
        if (regionsWithSteinerVertex) s << ", fan around an extra vertex " << regionsWithSteinerVertex;
        if (regionsKeptAsInput) s << ", kept as input faces against self-intersections " << regionsKeptAsInput;
        if (regionsCut) s << "; " << regionsCut << " regions cut into discs";
        if (outputHalvingRound)
            s << "; " << cellsHalved << " cells halved against self-intersections (" << outputHalvingRound
              << " rounds)";
        if (outputCarvingRound)
            s << "; " << piecesCarved << " pieces carved out of cells against self-intersections ("
              << outputCarvingRound << " rounds)";
        if (emptyRegions) s << "; " << emptyRegions << " empty proxies";
        if (ignoredFaces) s << "; " << ignoredFaces << " input faces with a repeated vertex ignored";
        if (splitVertices) s << "; non-manifold input vertices split into " << splitVertices << " extra vertices";
        s << ". Output: " << validity.Summary();
        if (closePairs) s << ", " << closePairs << " face pairs closer than its text files keep apart";
        return s.str();
    }
};

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_MESHING_PARAM_H
