#pragma once
/// \file
/// The thrust an azimuth may give, as convex pieces: its disc as the polygon inscribed in it,
/// each corner scaled by the unit's thrust factor in that direction (a `loss` table of
/// interaction losses), cut to its allowed directions.
///
/// With a factor that dips (the slipstream onto a neighbour's hull), the polygon is star-shaped
/// about the origin but not convex: it is split at its reflex corners into fans from the origin,
/// each convex and at most a half turn wide, and each fan is cut by the allowed arcs
/// (allowed_arcs()). Without a loss table and without forbidden sectors the whole polygon is one
/// piece; with sectors the pieces are the arcs of today's allocation.

#include <vector>

#include <Eigen/Core>

#include "dynpos/model/thruster_unit.hpp"

namespace dynpos::model {

/// The factor at direction α [rad]: linear in the angle between the table's points, round the
/// circle (the last point joins the first); 1 for an empty table.
double loss_factor(const std::vector<LossPoint>& loss, double alpha_rad);

/// One convex piece of an azimuth's thrust region, its forces over the rating: the directions
/// of `wedge` (a span of at most π) and inside every edge n·f ≤ d.
struct ConvexPiece {
  AllowedArc wedge;
  std::vector<Eigen::Vector2d> normals;  ///< outward, unit length
  std::vector<double> distances;         ///< > 0
};

/// The convex pieces of an azimuth with `loss` (may be empty) and `forbidden_deg` sectors, on
/// the polygon of `sides` corners at j·2π/sides (the allocation's), in order of direction.
std::vector<ConvexPiece> azimuth_pieces(const std::vector<LossPoint>& loss,
                                        const std::vector<AngleSector>& forbidden_deg, int sides);

}  // namespace dynpos::model
