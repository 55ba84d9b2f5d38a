// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_SELF_UNION_IMPL_H
#define CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_SELF_UNION_IMPL_H

#include <CGAL/Mesh_repair/internal/automatic_repair/self_union.h>
#include <CGAL/Mesh_repair/internal/automatic_repair/solid_soup.h>
#include <CGAL/Mesh_repair/internal/automatic_repair/thin_solids.h>
#include <CGAL/Mesh_repair/internal/automatic_repair/touching_fans.h>
#include <CGAL/Mesh_repair/internal/soup_edge.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_plus_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Projection_traits_xy_3.h>
#include <CGAL/Projection_traits_xz_3.h>
#include <CGAL/Projection_traits_yz_3.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/intersections.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/property_map.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

namespace self_union {

using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using Epeck_point = Epeck::Point_3;
using Epeck_segment = Epeck::Segment_3;
using Epeck_triangle = Epeck::Triangle_3;
using Epeck_vector = Epeck::Vector_3;
using Index_triangle = std::array<std::size_t, 3>;

/// One index per distinct exact point.
class Point_index {
 public:
  std::size_t operator()(const Epeck_point& p) {
    const auto inserted = index_.emplace(p, points.size());
    if (inserted.second) points.push_back(p);
    return inserted.first->second;
  }
  std::vector<Epeck_point> points;

 private:
  struct Less {
    bool operator()(const Epeck_point& a, const Epeck_point& b) const {
      return CGAL::compare_xyz(a, b) == CGAL::SMALLER;
    }
  };
  std::map<Epeck_point, std::size_t, Less> index_;
};

/// What cuts one face: the points and segments where other faces meet it.
struct Cuts {
  std::vector<Epeck_point> points;
  std::vector<Epeck_segment> segments;
};

inline void add_cut(const Epeck_point& p, const Epeck_point& q, Cuts& a, Cuts& b) {
  for (Cuts* cuts : {&a, &b}) {
    if (p == q)
      cuts->points.push_back(p);
    else
      cuts->segments.emplace_back(p, q);
  }
}

/// Adds the intersection of faces `a` and `b` that are not coplanar (a point or a segment) to
/// the cuts of both.
inline void add_intersection(const Epeck_triangle& a, const Epeck_triangle& b, Cuts& cuts_a,
                             Cuts& cuts_b) {
  const auto result = CGAL::intersection(a, b);
  if (!result) return;
  if (const Epeck_point* p = boost::get<Epeck_point>(&*result))
    add_cut(*p, *p, cuts_a, cuts_b);
  else if (const Epeck_segment* s = boost::get<Epeck_segment>(&*result))
    add_cut(s->source(), s->target(), cuts_a, cuts_b);
}

/// The pieces of the coplanar faces `group` cut along one another and along their cuts: one
/// constrained triangulation of the plane (in the coordinate plane `Projection`, onto which the
/// faces project one to one), each of its triangles given to every face that contains it, with
/// that face's orientation. Overlapping faces get the very same pieces there, which a
/// triangulation per face would not promise (cocircular points, as at the corners of
/// overlapping rectangles, have two Delaunay triangulations).
template <class Projection>
void cut_coplanar_faces(const std::vector<std::size_t>& group,
                        const std::vector<Epeck_triangle>& faces,
                        const std::unordered_map<std::size_t, Cuts>& cuts, Point_index& index,
                        std::vector<Index_triangle>& pieces) {
  // The "plus" hierarchy keeps the input constraints, so that crossing constraints are
  // intersected once each, not in cascades of exact constructions.
  using CDT = CGAL::Constrained_triangulation_plus_2<CGAL::Constrained_Delaunay_triangulation_2<
      Projection, CGAL::Default, CGAL::Exact_intersections_tag>>;
  CDT cdt;
  for (std::size_t f : group) {
    for (int i = 0; i < 3; ++i) cdt.insert_constraint(faces[f].vertex(i), faces[f].vertex(i + 1));
    const auto cut = cuts.find(f);
    if (cut == cuts.end()) continue;
    for (const Epeck_point& p : cut->second.points) cdt.insert(p);
    for (const Epeck_segment& s : cut->second.segments)
      cdt.insert_constraint(s.source(), s.target());
  }
  // Sorted: CGAL's faces come in an order that depends on memory addresses (the constraint
  // hierarchy orders its polylines by address), and the points are indexed in this order.
  std::vector<std::array<Epeck_point, 3>> triangles;
  for (auto fh : cdt.finite_face_handles()) {
    std::array<Epeck_point, 3> t{fh->vertex(0)->point(), fh->vertex(1)->point(),
                                 fh->vertex(2)->point()};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    triangles.push_back(t);
  }
  std::sort(triangles.begin(), triangles.end());
  const auto orientation = Projection().orientation_2_object();
  for (const auto& t_abc : triangles) {
    const Epeck_point &a = t_abc[0], &b = t_abc[1], &c = t_abc[2];
    const Epeck_point centroid = CGAL::centroid(a, b, c);
    const Index_triangle ccw{index(a), index(b), index(c)};
    for (std::size_t f : group) {
      const Epeck_triangle& t = faces[f];
      const CGAL::Orientation o = orientation(t.vertex(0), t.vertex(1), t.vertex(2));
      // Every edge of the face is a constraint: a piece is inside it or outside it.
      if (orientation(t.vertex(0), t.vertex(1), centroid) != o ||
          orientation(t.vertex(1), t.vertex(2), centroid) != o ||
          orientation(t.vertex(2), t.vertex(0), centroid) != o)
        continue;
      pieces.push_back(o == CGAL::CLOCKWISE ? Index_triangle{ccw[0], ccw[2], ccw[1]} : ccw);
    }
  }
}

inline void cut_coplanar_faces(const std::vector<std::size_t>& group,
                               const std::vector<Epeck_triangle>& faces,
                               const std::unordered_map<std::size_t, Cuts>& cuts,
                               Point_index& index, std::vector<Index_triangle>& pieces) {
  const Epeck_triangle& t = faces[group.front()];
  const Epeck_vector n = CGAL::normal(t.vertex(0), t.vertex(1), t.vertex(2));
  const Epeck::FT x = CGAL::abs(n.x()), y = CGAL::abs(n.y()), z = CGAL::abs(n.z());
  if (z >= x && z >= y)
    cut_coplanar_faces<CGAL::Projection_traits_xy_3<Epeck>>(group, faces, cuts, index, pieces);
  else if (y >= x)
    cut_coplanar_faces<CGAL::Projection_traits_xz_3<Epeck>>(group, faces, cuts, index, pieces);
  else
    cut_coplanar_faces<CGAL::Projection_traits_yz_3<Epeck>>(group, faces, cuts, index, pieces);
}

inline bool coplanar(const Epeck_triangle& a, const Epeck_triangle& b) {
  for (int i = 0; i < 3; ++i)
    if (!CGAL::coplanar(a.vertex(0), a.vertex(1), a.vertex(2), b.vertex(i))) return false;
  return true;
}

/// Coincident pieces (the same three points, from coplanar overlaps) as one: `face` is the
/// first piece, `multiplicity` the number of pieces oriented like it minus those reversed.
struct Piece_group {
  Index_triangle face;
  int multiplicity = 0;
};

inline std::vector<Piece_group> group_pieces(const std::vector<Index_triangle>& pieces) {
  std::map<Index_triangle, std::size_t> group_of;
  std::vector<Piece_group> groups;
  for (const Index_triangle& t : pieces) {
    Index_triangle key = t;
    std::sort(key.begin(), key.end());
    const auto inserted = group_of.emplace(key, groups.size());
    if (inserted.second) groups.push_back({t, 0});
    Piece_group& g = groups[inserted.first->second];
    // Same orientation when t is a rotation of the group's face.
    const bool same = (t[0] == g.face[0] && t[1] == g.face[1]) ||
                      (t[0] == g.face[1] && t[1] == g.face[2]) ||
                      (t[0] == g.face[2] && t[1] == g.face[0]);
    g.multiplicity += same ? 1 : -1;
  }
  return groups;
}

/// Patches: groups joined across edges where exactly two groups of multiplicity +-1 meet with
/// opposite edge directions (the surface is one oriented sheet there, so the winding numbers on
/// either side do not change from one to the other). Returns the patch of each group.
inline std::vector<std::size_t> patches_of(const std::vector<Piece_group>& groups) {
  std::vector<std::size_t> parent(groups.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](std::size_t g) {
    while (parent[g] != g) g = parent[g] = parent[parent[g]];
    return g;
  };
  std::map<Soup_edge, boost::container::small_vector<std::size_t, 2>> edges;
  for (std::size_t g = 0; g < groups.size(); ++g)
    for (int i = 0; i < 3; ++i) {
      const std::size_t a = groups[g].face[i], b = groups[g].face[(i + 1) % 3];
      edges[soup_edge(a, b)].push_back(g);
    }
  for (const auto& edge : edges) {
    if (edge.second.size() != 2) continue;
    const std::size_t g = edge.second[0], h = edge.second[1];
    if (std::abs(groups[g].multiplicity) != 1 || groups[g].multiplicity != groups[h].multiplicity)
      continue;
    const auto runs = [&](const Index_triangle& t) {  // whether t runs along the edge from first
      for (int i = 0; i < 3; ++i)
        if (t[i] == edge.first.first && t[(i + 1) % 3] == edge.first.second) return true;
      return false;
    };
    if (runs(groups[g].face) != runs(groups[h].face)) parent[find(g)] = find(h);
  }
  std::vector<std::size_t> patch(groups.size());
  for (std::size_t g = 0; g < groups.size(); ++g) patch[g] = find(g);
  return patch;
}

/// Winding numbers of the part on the two sides of one piece, by exact ray casting.
class Winding_classifier {
 public:
  Winding_classifier(const std::vector<Epeck_point>& points, const std::vector<Piece_group>& groups)
      : points_(points), groups_(groups) {
    boxes_.reserve(groups.size());
    CGAL::Bbox_3 all;
    for (const Piece_group& g : groups) {
      CGAL::Bbox_3 box;
      for (std::size_t v : g.face) box += points[v].bbox();
      boxes_.push_back(box);
      all += box;
    }
    const double diagonal =
        std::sqrt(CGAL::square(all.xmax() - all.xmin()) + CGAL::square(all.ymax() - all.ymin()) +
                  CGAL::square(all.zmax() - all.zmin()));
    margin_ = 1e-9 * diagonal + 1e-300;
  }

  /// The winding numbers on the side of group g's normal and on the other side; false when
  /// every direction tried met an edge or a vertex.
  bool classify(std::size_t g, int& front, int& back) const {
    static const double directions[][3] = {{0.5773, 0.3157, 0.7531},   {-0.6131, 0.3519, 0.7071},
                                           {0.2113, -0.9012, 0.3785},  {-0.4471, -0.5517, -0.7039},
                                           {0.8819, 0.1161, -0.4571},  {0.1237, 0.9871, -0.1013},
                                           {-0.9137, 0.2917, -0.2831}, {0.3307, -0.2393, -0.9129}};
    const Index_triangle& t = groups_[g].face;
    const Epeck_point centroid = CGAL::centroid(points_[t[0]], points_[t[1]], points_[t[2]]);
    const Epeck_vector normal = CGAL::normal(points_[t[0]], points_[t[1]], points_[t[2]]);
    for (const auto& d : directions) {
      const Epeck_vector direction(d[0], d[1], d[2]);
      const CGAL::Sign side = CGAL::sign(normal * direction);
      if (side == CGAL::ZERO) continue;
      int winding = 0;
      if (!winding_along(g, centroid, direction, winding)) continue;
      // Crossing the piece along its normal lowers the winding number by its multiplicity.
      if (side == CGAL::POSITIVE) {
        front = winding;
        back = winding + groups_[g].multiplicity;
      } else {
        back = winding;
        front = winding - groups_[g].multiplicity;
      }
      return true;
    }
    return false;
  }

 private:
  /// The winding number just off `origin` on the side of `direction`: the signed count of the
  /// pieces the ray crosses (+1 leaving through a piece's front). False on a degenerate ray.
  bool winding_along(std::size_t skip, const Epeck_point& origin, const Epeck_vector& direction,
                     int& winding) const {
    const Epeck_point ahead = origin + direction;
    const Core_traits::Ray_3 ray(
        Core_traits::Point_3(CGAL::to_double(origin.x()), CGAL::to_double(origin.y()),
                             CGAL::to_double(origin.z())),
        Core_traits::Vector_3(CGAL::to_double(direction.x()), CGAL::to_double(direction.y()),
                              CGAL::to_double(direction.z())));
    for (std::size_t h = 0; h < groups_.size(); ++h) {
      if (h == skip || groups_[h].multiplicity == 0) continue;
      const CGAL::Bbox_3& b = boxes_[h];
      // A conservative filter (boxes widened beyond the rounding of the ray's origin); the
      // decision below is exact.
      const CGAL::Bbox_3 widened(b.xmin() - margin_, b.ymin() - margin_, b.zmin() - margin_,
                                 b.xmax() + margin_, b.ymax() + margin_, b.zmax() + margin_);
      if (!CGAL::do_intersect(ray, widened)) continue;
      const Index_triangle& t = groups_[h].face;
      const Epeck_point &p = points_[t[0]], &q = points_[t[1]], &r = points_[t[2]];
      const Epeck_vector n = CGAL::normal(p, q, r);
      const CGAL::Sign at = CGAL::sign(n * (origin - p));
      const CGAL::Sign towards = CGAL::sign(n * direction);
      // The origin off the piece's plane and the ray going towards it, or no crossing; an
      // origin on the plane is not inside the piece (pieces meet only along their edges).
      if (at == CGAL::ZERO || towards == CGAL::ZERO || at == towards) continue;
      const CGAL::Orientation o1 = CGAL::orientation(origin, ahead, p, q);
      const CGAL::Orientation o2 = CGAL::orientation(origin, ahead, q, r);
      const CGAL::Orientation o3 = CGAL::orientation(origin, ahead, r, p);
      const bool has_positive =
          o1 == CGAL::POSITIVE || o2 == CGAL::POSITIVE || o3 == CGAL::POSITIVE;
      const bool has_negative =
          o1 == CGAL::NEGATIVE || o2 == CGAL::NEGATIVE || o3 == CGAL::NEGATIVE;
      if (has_positive && has_negative) continue;  // the line misses the piece
      if (o1 == CGAL::COPLANAR || o2 == CGAL::COPLANAR || o3 == CGAL::COPLANAR)
        return false;  // through an edge or a vertex: another direction
      winding += towards == CGAL::POSITIVE ? groups_[h].multiplicity : -groups_[h].multiplicity;
    }
    return true;
  }

  const std::vector<Epeck_point>& points_;
  const std::vector<Piece_group>& groups_;
  std::vector<CGAL::Bbox_3> boxes_;
  double margin_ = 0;
};

/// A power of two near 1e-9 of the diagonal of `mesh`'s bounding box.
inline double grid_spacing(const Core_mesh& mesh) {
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  const double diagonal =
      std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                CGAL::square(box.zmax() - box.zmin()));
  return diagonal > 0 ? std::exp2(std::floor(std::log2(1e-9 * diagonal))) : 0.0;
}

/// `soup` with each coordinate rounded to a multiple of `spacing` (a power of two, so that
/// the rounding is exact) where the multiple fits a double's mantissa, the points that meet
/// merged and the faces that lose a corner so dropped (needles of the noise, of no area).
inline Triangle_soup snapped_to_grid(const Triangle_soup& soup, double spacing) {
  if (!(spacing > 0) || !std::isfinite(spacing)) return soup;
  const auto snap = [&](double x) {
    const double steps = x / spacing;
    return std::abs(steps) < 0x1p52 ? std::round(steps) * spacing : x;
  };
  Triangle_soup snapped;
  std::map<std::array<double, 3>, std::size_t> index;
  std::vector<std::size_t> new_index;
  for (const auto& p : soup.points) {
    const std::array<double, 3> q{snap(p.x()), snap(p.y()), snap(p.z())};
    const auto inserted = index.emplace(q, snapped.points.size());
    if (inserted.second) snapped.points.emplace_back(q[0], q[1], q[2]);
    new_index.push_back(inserted.first->second);
  }
  for (const auto& t : soup.polygons) {
    std::vector<std::size_t> u{new_index[t[0]], new_index[t[1]], new_index[t[2]]};
    if (u[0] != u[1] && u[1] != u[2] && u[0] != u[2]) snapped.polygons.push_back(std::move(u));
  }
  return snapped;
}

/// The faces of `soup` with exact coordinates.
inline std::vector<Epeck_triangle> exact_faces(const Triangle_soup& soup) {
  std::vector<Epeck_triangle> faces;
  for (const auto& t : soup.polygons) {
    std::array<Epeck_point, 3> corners;
    for (int i = 0; i < 3; ++i) {
      const auto& p = soup.points[t[i]];
      corners[i] = Epeck_point(p.x(), p.y(), p.z());
    }
    faces.emplace_back(corners[0], corners[1], corners[2]);
  }
  return faces;
}

/// `out` as a closed mesh in `result`; an empty string, or why the outer surface cannot be
/// used. `crossing` gets the intersecting pairs of faces, if any.
inline std::string checked_outer_surface(const Triangle_soup& out, Core_mesh& result,
                                         Face_pairs& crossing) {
  result = Core_mesh();
  const std::string why = solid_union::to_closed_mesh(out, result);
  if (!why.empty()) return "its outer surface: " + why;
  if (!result.is_valid(false)) return "its outer surface is not a valid mesh";
  CGAL::Polygon_mesh_processing::self_intersections(result, std::back_inserter(crossing));
  if (!crossing.empty()) return "its outer surface intersects itself once rounded to doubles";
  return {};
}

/// The next way into the fans of each touching point that a face of `crossing` has (`point_of`
/// as `touching_fans::separate` gives it); false when one has none left, or when a crossing
/// face has no touching point.
inline bool next_ways(const Core_mesh& result, const Face_pairs& crossing,
                      const std::vector<std::ptrdiff_t>& point_of,
                      std::vector<touching_fans::Into_fan>& ways) {
  std::set<std::size_t> involved;
  for (const auto& pair : crossing) {
    bool touches = false;
    for (auto f : {pair.first, pair.second})
      for (auto v : vertices_around_face(result.halfedge(f), result))
        if (point_of[v] >= 0) {
          involved.insert(std::size_t(point_of[v]));
          touches = true;
        }
    if (!touches) return false;
  }
  for (std::size_t k : involved) {
    const int next = int(ways[k]) + 1;
    if (next == touching_fans::number_of_ways) return false;
    ways[k] = touching_fans::Into_fan(next);
  }
  return true;
}

/// Marks in `by_height` the touching points of the closed components of `result` thinner than
/// `distance` (volume below area times distance: slivers of the arrangement that a move of
/// `distance` may turn inside out); false when there is none left to mark.
inline bool mark_thin_components(const Core_mesh& result,
                                 const std::vector<std::ptrdiff_t>& point_of, double distance,
                                 std::vector<char>& by_height) {
  const Thin_components thin(result, distance);
  bool marked = false;
  for (auto f : result.faces()) {
    if (!thin.is_thin(f)) continue;
    for (auto v : vertices_around_face(result.halfedge(f), result))
      if (point_of[v] >= 0 && !by_height[std::size_t(point_of[v])]) {
        by_height[std::size_t(point_of[v])] = 1;
        marked = true;
      }
  }
  return marked;
}

/// The outer surface `result` (soup `out`) whose faces cross (`crossing`) once rounded, with the
/// thin components that cross dropped (`drop_thin_crossing_components`). An empty string when
/// what is left is a closed valid mesh free of crossings, or whose crossings all lie within one
/// component each, which region replacement can remove (counted in
/// `measures.rounding_crossings`); else why not.
inline std::string crossed_outer_surface(Core_mesh& result, Face_pairs crossing, double distance,
                                         Triangle_soup& out, Solid_autorefinement& measures) {
  const std::string folded = "its outer surface intersects itself once rounded to doubles";
  measures.thin_solids_dropped = drop_thin_crossing_components(result, crossing, distance, out);
  if (measures.thin_solids_dropped > 0) {
    crossing.clear();
    const std::string why = checked_outer_surface(out, result, crossing);
    if (!why.empty() && crossing.empty()) return why;
    if (crossing.empty() && !CGAL::Polygon_mesh_processing::does_bound_a_volume(result))
      return "its outer surface bounds no volume";
  }
  if (crosses_between_components(result, crossing)) return folded;
  measures.rounding_crossings = crossing.size();
  return {};
}

/// `out`, whose surface touches itself at the points of `touching`, with those points split and
/// moved apart by `distance` (`touching_fans::separate`), in `result`. Where a face crosses
/// another, the next way into the fans of its touching points is tried; where a thin closed
/// component keeps the surface from bounding a volume, its points move less
/// (`mark_thin_components`). An empty string, or why no way gave a surface free of
/// intersections that bounds a volume. When no way is left and the faces still cross, the
/// last surface goes to `crossed_outer_surface`.
inline std::string separated_outer_surface(const touching_fans::Touching& touching, double distance,
                                           Triangle_soup& out, Core_mesh& result,
                                           Solid_autorefinement& measures) {
  const Triangle_soup unseparated = out;
  std::vector<touching_fans::Into_fan> ways(touching.points.size(),
                                            touching_fans::Into_fan::wedge_or_away);
  std::vector<char> by_height(touching.points.size(), 0);
  for (bool retry = true; retry;) {
    out = unseparated;
    std::vector<std::ptrdiff_t> point_of;
    touching_fans::separate(out, touching, ways, distance, by_height, point_of);
    Face_pairs crossing;
    const std::string why = checked_outer_surface(out, result, crossing);
    if (!crossing.empty()) {
      retry = next_ways(result, crossing, point_of, ways);
      if (!retry) return crossed_outer_surface(result, crossing, distance, out, measures);
    } else if (!why.empty()) {
      return why;
    } else if (!CGAL::Polygon_mesh_processing::does_bound_a_volume(result)) {
      retry = mark_thin_components(result, point_of, distance, by_height);
      if (!retry) return "its outer surface bounds no volume";
    } else {
      retry = false;
    }
  }
  return {};
}

}  // namespace self_union

CGAL_MESH_REPAIR_CORE_INLINE std::string outer_surface_of_solid(const Triangle_soup& solid,
                                                                Triangle_soup& out,
                                                                Solid_autorefinement& measures,
                                                                const Self_union_limits& limits) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using namespace self_union;
  Core_mesh mesh;
  std::string why = solid_union::to_closed_mesh(solid, mesh);
  if (!why.empty()) return why;
  if (mesh.number_of_faces() > limits.max_faces) return "the part has too many faces";
  measures.area_before = PMP::area(mesh);
  // On the grid when that keeps every face a triangle: CAD exports write 1e-15 for 0, and
  // the exact arrangement of such noise has pieces 1e-15 wide that rounding would fold.
  Triangle_soup part = snapped_to_grid(solid, grid_spacing(mesh));
  Core_mesh snapped;
  if (!solid_union::to_closed_mesh(part, snapped).empty()) {
    part = solid;
    snapped = mesh;
  }
  const std::vector<Epeck_triangle> faces = exact_faces(part);
  // Faces of no area (three points on a line: caps of the noise, or of the input) bound nothing
  // and give no piece; the faces along them meet one another along their edges, and cut one
  // another there.
  std::vector<char> flat(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) flat[f] = faces[f].is_degenerate();
  Face_pairs pairs;
  PMP::self_intersections(snapped, std::back_inserter(pairs));
  if (pairs.size() > limits.max_pairs) return "the part has too many intersecting face pairs";

  // The arrangement: faces cut along their intersections, points merged exactly.
  // Coplanar intersecting faces are cut together (groups of a union-find); the others along
  // their intersection points and segments.
  std::vector<std::size_t> group_of(faces.size());
  std::iota(group_of.begin(), group_of.end(), 0);
  const auto find = [&](std::size_t f) {
    while (group_of[f] != f) f = group_of[f] = group_of[group_of[f]];
    return f;
  };
  std::unordered_map<std::size_t, Cuts> cuts;
  for (const auto& pair : pairs) {
    const std::size_t a = std::size_t(pair.first), b = std::size_t(pair.second);
    if (flat[a] || flat[b]) continue;
    if (coplanar(faces[a], faces[b]))
      group_of[find(a)] = find(b);
    else
      add_intersection(faces[a], faces[b], cuts[a], cuts[b]);
  }
  // Constraints crossing one another inside a face cost exact constructions built on exact
  // constructions; many of them (faces fanned around an axis, all crossing near it) take minutes.
  double cut_work = 0;
  for (const auto& cut : cuts) {
    const std::size_t segments = cut.second.segments.size();
    if (segments > limits.max_cuts_per_face) return "a face is cut by too many others";
    cut_work += double(segments) * double(segments);
  }
  if (cut_work > limits.max_cut_work) return "its faces are cut by too many others";
  std::map<std::size_t, std::vector<std::size_t>> groups_to_cut;
  std::vector<std::size_t> group_size(faces.size(), 0);
  for (std::size_t f = 0; f < faces.size(); ++f) ++group_size[find(f)];
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (group_size[find(f)] > 1 || cuts.count(f)) groups_to_cut[find(f)].push_back(f);
  Point_index index;
  std::vector<Index_triangle> pieces;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (flat[f] || groups_to_cut.count(find(f))) continue;
    pieces.push_back(
        {index(faces[f].vertex(0)), index(faces[f].vertex(1)), index(faces[f].vertex(2))});
  }
  for (const auto& group : groups_to_cut)
    cut_coplanar_faces(group.second, faces, cuts, index, pieces);

  // Each patch classified once, by its first piece.
  const std::vector<Piece_group> groups = group_pieces(pieces);
  const std::vector<std::size_t> patch = patches_of(groups);
  std::map<std::size_t, std::pair<int, int>> windings;
  for (std::size_t g = 0; g < groups.size(); ++g) windings.emplace(patch[g], std::pair<int, int>());
  if (double(windings.size()) * double(groups.size()) > limits.max_ray_tests)
    return "the part's arrangement has too many pieces to classify";
  const Winding_classifier classifier(index.points, groups);
  for (auto& w : windings)
    if (!classifier.classify(w.first, w.second.first, w.second.second))
      return "no ray from a piece avoided the edges of the others";

  // The pieces between winding zero and a non-zero winding, facing the zero side.
  std::vector<std::size_t> new_index(index.points.size(), std::size_t(-1));
  out = Triangle_soup();
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const auto [front, back] = windings[patch[g]];
    if ((front == 0) == (back == 0)) continue;
    Index_triangle t = groups[g].face;
    if (front != 0) std::swap(t[1], t[2]);
    std::vector<std::size_t> polygon;
    for (std::size_t v : t) {
      if (new_index[v] == std::size_t(-1)) {
        new_index[v] = out.points.size();
        const Epeck_point& p = index.points[v];
        out.points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                                CGAL::to_double(p.z()));
      }
      polygon.push_back(new_index[v]);
    }
    out.polygons.push_back(std::move(polygon));
  }

  // Where the outer surface touches itself at a point or along an edge (parts meeting corner
  // to corner or edge to edge, or at a vertex the input already split), the fans of faces there
  // are moved apart by about 1e-6 of the diagonal, each into its own side; where they still
  // meet another face, the next way into them is tried.
  const touching_fans::Touching touching = touching_fans::find_touching(out);
  // A part whose faces only touch one another (no face cut) is left to the patches of the
  // next step, which remove the faces that touch: moving the points apart would keep every
  // contact of the part with the others.
  const std::size_t solid_faces = std::size_t(std::count(flat.begin(), flat.end(), 0));
  if (!touching.points.empty() && pieces.size() == solid_faces)
    return "its faces only touch one another";
  measures.touching_vertices_separated = touching.points.size();
  Core_mesh result;
  why = separated_outer_surface(touching, 1024 * grid_spacing(mesh), out, result, measures);
  if (!why.empty()) return why;
  if (double(measures.rounding_crossings) >
      limits.max_rounding_crossing_share * double(pairs.size()))
    return "its outer surface intersects itself once rounded to doubles";
  measures.area_after = PMP::area(result);
  measures.largest_distance =
      PMP::max_distance_to_triangle_mesh<CGAL::Sequential_tag>(mesh.points(), result);
  return {};
}

CGAL_MESH_REPAIR_CORE_INLINE std::string union_of_solids_exactly(
    const std::vector<Triangle_soup>& solids, Triangle_soup& out, Solid_autorefinement& measures,
    const Self_union_limits& limits) {
  if (solids.size() < 2) return "fewer than two parts";
  Triangle_soup all;
  for (const Triangle_soup& solid : solids) {
    // Each part outward, so that the winding numbers of overlapping parts add up.
    Core_mesh mesh;
    const std::string why = solid_union::to_solid(solid, mesh);
    if (!why.empty()) return why;
    Triangle_soup outward;
    solid_union::to_soup(mesh, outward);
    const std::size_t offset = all.points.size();
    all.points.insert(all.points.end(), outward.points.begin(), outward.points.end());
    for (auto polygon : outward.polygons) {
      for (std::size_t& v : polygon) v += offset;
      all.polygons.push_back(std::move(polygon));
    }
  }
  measures = Solid_autorefinement();
  return outer_surface_of_solid(all, out, measures, limits);
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_SELF_UNION_IMPL_H
