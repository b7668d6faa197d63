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

// --- Partition (approximation.h, seeding.h) ---

/// Lloyd changing the energy by less than this share per iteration has stalled: time to teleport.
constexpr double kTeleportStall = 1e-3;
/// From this many faces on, hierarchical seeding starts on patches: below, the faces take a second at most.
constexpr int kMultilevelFaces = 100000;
/// Patches at most this big: a coarse round costs about 1/kMaxPatchFaces of one on the faces.
constexpr int kMaxPatchFaces = 32;
/// At least this many patches per region, so that the patches' borders and energies are close to the faces'.
constexpr int kPatchesPerRegion = 16;
/// Smaller patches would save too little to be worth a coarse level: faces are seeded directly.
constexpr int kMinPatchFaces = 4;

// --- Meshable partition (meshable_partition.h) ---

/// A region faces away when more than this share of its area lies nearest to input facing the other way.
constexpr double kFacingAwayShare = 0.01;
/// Stray allowance, of the bounding-box diagonal: projected anchors move even exact planes' triangles that much.
constexpr double kStrayAllowance = 2e-3;

// --- Meshing (chords.h, cell_triangulation.h, cell_splitting.h, meshing_repair.h, meshing.h) ---

/// Points tested along a chord by the gap test: a chord strays over a hole, not at a point.
constexpr int kChordGapSamples = 8;
/// A fan whose thinnest triangle has at least this sine of its smallest angle is good enough.
constexpr double kGoodFan = 0.05;
/// Repair rounds give up after this many rounds without a better pass (see PassDefects::BetterThan)...
constexpr int kRepairPatience = 5;
/// ...once the last one has at least this many times the best one's defects: the repair diverges.
constexpr size_t kRepairDivergence = 2;
/// Halving gives up after this many rounds without fewer pairs where the input meets itself or only close pairs are left.
constexpr int kHalvingPatience = 2;
/// Carving rounds at most: a round's pieces can leave pairs that the next one's smaller pieces remove.
constexpr int kCarvingRounds = 4;
/// A carved piece is 1/kCarvedShare of its cell: small enough for the face budget, large enough to pass the crossing.
constexpr int kCarvedShare = 4;

}  // namespace detail
}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_TUNING_H
