// Variational Shape Approximation for vcglib — the tuning constants, in one place. Each has a
// one-line reason; what was measured to choose it is in docs/tuning.md.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_TUNING_H
#define VSA_TUNING_H

#include <cstddef>

namespace vcg {
namespace tri {
namespace vsa {
namespace detail {

// Partition: Lloyd (approximation.h).
constexpr double kTeleportStall = 1e-3;  ///< energy change per iteration below which Lloyd has stalled: teleport

// The snapshot (indexed_mesh.h).
constexpr int kSpatialOrderMinFaces = 1 << 16;  ///< faces in space order from here: 0.78 of the time at 75k faces, no gain measured at 13k

// The flood (partition.h).
constexpr int kFloodBlockBits = 16;        ///< 2^16 faces per block flooded on its own: 2^14 cost 2.9% energy at 3.3M faces for no speed
constexpr int kFloodExchangeWaves = 8;     ///< waves of one rank between exchanges: fewer exchanges (one per rank) cost 8% energy on gear-mid3 at k = 50
constexpr int kFloodWindowCandidates = 1 << 14;  ///< an exchange spans ranks until this many candidates wait: enough work to gain from the threads
constexpr int kFloodWindowRanks = 16;          ///< ranks per exchange at most: an offer across blocks comes late by a quarter of its error at most; 64 cost 0.5% energy

// Multilevel hierarchical seeding (seeding.h).
constexpr int kMultilevelFaces = 100000;  ///< seed on patches from this many faces: below, faces take a second at most
constexpr int kMaxPatchFaces = 32;        ///< a coarse round then costs about 1/32 of one on the faces
constexpr int kPatchesPerRegion = 16;     ///< enough patches that their borders and energies are close to the faces'
constexpr int kMinPatchFaces = 4;         ///< smaller patches save too little to be worth a coarse level
constexpr int kGroupedPatches = 4;        ///< patches per node of the early rounds' graph: rounds there cost a quarter
// Work per face or node, in progress items (ProgressTick), so that the bar moves evenly:
constexpr double kLloydItems = 5;   ///< a Lloyd iteration: marking, flooding, reading out, fitting, measuring
constexpr double kPatchItems = 10;  ///< flooding the patches and building their graph
constexpr double kCarryItems = 8;   ///< carrying the patches' regions to the faces, fitting and relaxing once
constexpr double kRoundItems = 8;   ///< a doubling round's insertions, which touch about every node a few times

// Meshable partition (meshable_partition.h).
constexpr double kTrialSetupEnd = 5;     ///< percent of the stage's bar for setting up the trials, about one trial's work
constexpr double kTrialSetupItems = 29;  ///< progress items per face of it (measured at 3.3M): the surface, its grid, a copy
constexpr double kTrialItems = 16;       ///< per face of a trial: its regions and cells, the chord bound, its pass, the stray test, choosing split faces, the split
constexpr double kInputPairsItems = 12;  ///< per face, in the first trial only: the grid and shapes of the input's faces for their own intersections
constexpr int kNearestFaceItems = 128;   ///< a nearest-face query of the facing-away test takes about as long as 128 faces' share of a pass
constexpr int kFacePairItems = 16;       ///< testing an input face against the faces near it (2.3 us at 3.3M faces) takes about as long as 16 faces' share of a pass
constexpr double kFacingAwayShare = 0.01;  ///< a region faces away past this share of its area facing the input's back
constexpr double kStrayAllowance = 2e-3;   ///< of the diagonal: projected anchors move even nearly flat regions' triangles

// Grids (surface_grid.h).
constexpr double kBoxSlack = 1e-9;  ///< the nearest-face search skips boxes and distance bounds this much beyond its best distance: far above rounding

// The final meshing's progress (meshing.h, meshing_repair.h), in progress items, as kTrialItems.
constexpr double kMeshingSetupItems = 33; ///< per input face (measured at 3.3M): the surface, its regions and cells, the chord bound, the gap test's grid
constexpr double kHalvingPasses = 4;      ///< a halving round meshes the whole surface again, with repair passes
constexpr double kFirstPassItems = 8;     ///< per surface face: the first pass's anchors, chords and cell floodings (a repair pass ticks once)
constexpr double kCheckItems = 20;        ///< per output face: indexing the written mesh, then checking it

// Anchors (anchors.h, planar_polygons.h).
constexpr double kFlatRegion = 1e-5;       ///< of the diagonal: a region this close to its plane is flat, far above float rounding
constexpr double kPlaneConstraint = 1e-3;  ///< flat planes within 2.6 degrees of parallel do not fix a point between them
constexpr double kPlanarizeReach = 0.03;   ///< a polygon bent more than this for its size needs moves that change the shape: left as placed
constexpr double kPlanarPolygon = 3e-3;    ///< anchors within this of their polygon's plane, for its size: under 0.5 degree of bend but on slivers
constexpr double kPlanarizeShift = 0.2;    ///< of an anchor's cap, the most planarizing moves it: further slid a thin plate's anchors across its thickness
constexpr double kPlanarizeFit = 1;        ///< times its regions' fit, the most planarizing moves an anchor: further raised the Hausdorff distance at large k
constexpr int kPlanarizeRounds = 20;       ///< plane fits and anchor moves per attempt: 60 or 300 made no more polygons planar
constexpr double kPlanarizeSpring = 1e-2;  ///< an anchor's pull toward its placement, against a plane's 1: it holds only free directions
constexpr double kPlanarizeSettled = 1e-6; ///< of an anchor's cap: a round that moves none further has converged
constexpr int kPlanarizeAttempts = 8;      ///< polygons left bent free their neighbours this many times before all moves are undone: CAD parts needed up to 6

// Chords and cells (chords.h, cell_triangulation.h).
constexpr int kChordGapSamples = 8;  ///< points the gap test tries along a chord: it strays over a hole, not a point
constexpr double kGoodFan = 0.05;    ///< a fan whose thinnest triangle has this sine of its smallest angle will do

// Repairs, halving, carving (meshing_repair.h, meshing.h, cell_splitting.h): see PassDefects::BetterThan.
constexpr int kRepairPatience = 5;        ///< repair rounds without a better pass before a diverging repair stops
constexpr size_t kRepairDivergence = 2;   ///< diverging: the last pass has this many times the best one's defects
constexpr int kHalvingPatience = 2;       ///< halving rounds without fewer pairs, once only input or close pairs remain
constexpr int kCarvingRounds = 4;         ///< a round's pieces can leave pairs the next one's smaller pieces remove
constexpr int kCarvedShare = 4;           ///< a piece is 1/4 of its cell: within the face budget, past the crossing

}  // namespace detail
}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_TUNING_H
