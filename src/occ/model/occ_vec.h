// Small conversions shared by the occ layer: OpenCASCADE points and vectors to Vec3
// (and the elapsed seconds the face meshers record, from core/elapsed.h).
#pragma once

#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include "core/elapsed.h"
#include "core/geometry/vec3.h"

namespace tquad {

inline Vec3 to_vec3(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
inline Vec3 to_vec3(const gp_Vec& v) { return {v.X(), v.Y(), v.Z()}; }

}  // namespace tquad
