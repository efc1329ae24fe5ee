// mesh_sector_in_halves: a cone's tip flattened into a sector (its apex, two straight
// sides of equal count from it, a rim between) meshed as two three-sided halves split
// by the sector's bisector from the apex.
//
// On the surface the sector's two sides are one line (the seam), so the apex is an
// interior node: with the whole sector as one three-sided region a single quad would
// meet it, with both its sides on the seam (collapsed). The disk around the pole puts
// four quads there; split in two, two quads meet the apex. On a cone of half-angle a
// a quad's corner at the tip, between chords along generators a quarter or a half
// turn apart, is at most 2 asin(sin a sin 45 deg) or 2 a: for a = 18.4 degrees, 25.9
// or 36.9 degrees.
#pragma once

#include <optional>
#include <vector>

#include "core/templates/mesher.h"

namespace tquad {

// `loop`: the sector's points in the plane, either orientation; `apex`, `rim_start`
// and `rim_end` are loop positions, the loop running apex -> rim_start (first side)
// -> rim_end (the rim) -> apex (second side). The bisector ends at the rim node that
// splits it into two even counts nearest its angular middle, and takes the first
// side's spacing. The loop's points come first in the mesh, bit-exact. Nothing when
// the two sides' counts differ, the rim's count is odd or under 4, or a half cannot
// be meshed.
std::optional<QuadMesh> mesh_sector_in_halves(const std::vector<Vec3>& loop, int apex, int rim_start, int rim_end,
                                              const MeshOptions& options = {});

}  // namespace tquad
