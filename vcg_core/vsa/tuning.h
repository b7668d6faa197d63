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

}  // namespace detail
}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_TUNING_H
