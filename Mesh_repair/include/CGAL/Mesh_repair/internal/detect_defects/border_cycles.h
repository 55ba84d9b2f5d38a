// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_BORDER_CYCLES_H
#define CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_BORDER_CYCLES_H

// Border cycles with their size, and the ring-hole test of thesis 4.4: which cycles look like
// islands lying inside another hole.

#include <CGAL/Mesh_repair/internal/detect_defects/mesh_access.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace detect {

/// One border cycle as halfedges, kept while detecting (gaps and T-junctions walk them too).
template <class Halfedge>
using Cycle_halfedges = std::vector<Halfedge>;

template <class Access>
std::vector<Cycle_halfedges<typename Access::halfedge_descriptor>> border_cycle_halfedges(
    const Access& mesh) {
  using halfedge_descriptor = typename Access::halfedge_descriptor;
  std::vector<Cycle_halfedges<halfedge_descriptor>> cycles;
  std::vector<bool> visited(num_halfedges(mesh.pm), false);
  for (halfedge_descriptor h : halfedges(mesh.pm)) {
    if (!is_border(h, mesh.pm) || visited[mesh.index(h)]) continue;
    Cycle_halfedges<halfedge_descriptor> cycle;
    for (halfedge_descriptor b = h; !visited[mesh.index(b)]; b = next(b, mesh.pm)) {
      visited[mesh.index(b)] = true;
      cycle.push_back(b);
    }
    cycles.push_back(std::move(cycle));
  }
  return cycles;
}

inline Coordinates minus(const Coordinates& a, const Coordinates& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

/// Vector area (Newell) of a closed polygon: its direction is the normal of the best-fitting
/// plane, its norm the area of a flat patch closing it.
inline Coordinates vector_area(const std::vector<Coordinates>& polygon) {
  Coordinates sum{0, 0, 0};
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const auto c = internal::cross(polygon[i], polygon[(i + 1) % polygon.size()]);
    for (int k = 0; k < 3; ++k) sum[k] += 0.5 * c[k];
  }
  return sum;
}

template <class Access>
Border_cycle describe_cycle(const Access& mesh,
                            const Cycle_halfedges<typename Access::halfedge_descriptor>& cycle) {
  Border_cycle result;
  result.edges = cycle.size();
  std::vector<Coordinates> polygon;
  polygon.reserve(cycle.size());
  for (auto h : cycle) {
    result.vertices.push_back(mesh.index(source(h, mesh.pm)));
    polygon.push_back(mesh.coordinates(source(h, mesh.pm)));
  }
  result.first_point = polygon.front();
  result.bbox.min = result.bbox.max = polygon.front();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    result.perimeter += internal::norm(minus(polygon[(i + 1) % polygon.size()], polygon[i]));
    for (int k = 0; k < 3; ++k) {
      result.bbox.min[k] = std::min(result.bbox.min[k], polygon[i][k]);
      result.bbox.max[k] = std::max(result.bbox.max[k], polygon[i][k]);
    }
  }
  // Relative to the first point, so a small hole far from the origin keeps its precision.
  std::vector<Coordinates> centred;
  for (const auto& p : polygon) centred.push_back(minus(p, polygon.front()));
  result.area = internal::norm(vector_area(centred));
  return result;
}

/// A cycle seen from its best-fitting plane: the plane's frame and the projected polygon.
template <class Traits>
struct Planar_cycle {
  Coordinates origin{0, 0, 0}, normal{0, 0, 0}, u{0, 0, 0}, v{0, 0, 0};
  std::vector<typename Traits::Point_2> polygon;
  double diameter = 0;

  typename Traits::Point_2 project(const Coordinates& p) const {
    const Coordinates d = minus(p, origin);
    return typename Traits::Point_2(internal::dot(d, u), internal::dot(d, v));
  }
  double height(const Coordinates& p) const { return internal::dot(minus(p, origin), normal); }
};

inline Coordinates normalised(const Coordinates& a) {
  const double n = internal::norm(a);
  return n > 0 ? Coordinates{a[0] / n, a[1] / n, a[2] / n} : Coordinates{0, 0, 0};
}

template <class Traits>
Planar_cycle<Traits> planar_cycle(const std::vector<Coordinates>& points, const Coordinates& normal,
                                  double diameter) {
  Planar_cycle<Traits> plane;
  plane.origin = points.front();
  plane.normal = normalised(normal);
  const Coordinates axis =
      std::abs(plane.normal[0]) < 0.9 ? Coordinates{1, 0, 0} : Coordinates{0, 1, 0};
  plane.u = normalised(internal::cross(plane.normal, axis));
  plane.v = internal::cross(plane.normal, plane.u);
  for (const auto& p : points) plane.polygon.push_back(plane.project(p));
  plane.diameter = diameter;
  return plane;
}

/// Winding-number point-in-polygon test whose every decision is an exact predicate
/// (coordinate comparisons and Orientation_2) on the projected points.
template <class Traits>
bool inside_polygon(const std::vector<typename Traits::Point_2>& polygon,
                    const typename Traits::Point_2& p, const Traits& traits) {
  auto orientation = traits.orientation_2_object();
  int winding = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const auto& a = polygon[i];
    const auto& b = polygon[(i + 1) % polygon.size()];
    const CGAL::Orientation o = orientation(a, b, p);
    if (o == CGAL::COLLINEAR && std::min(a.y(), b.y()) <= p.y() &&
        p.y() <= std::max(a.y(), b.y()) && std::min(a.x(), b.x()) <= p.x() &&
        p.x() <= std::max(a.x(), b.x()))
      return false;  // on the border: not strictly inside
    if (a.y() <= p.y()) {
      if (b.y() > p.y() && o == CGAL::LEFT_TURN) ++winding;
    } else if (b.y() <= p.y() && o == CGAL::RIGHT_TURN) {
      --winding;
    }
  }
  return winding != 0;
}

/// Per cycle: its points, its vector area and the summed normal of the faces along it.
struct Cycle_shape {
  std::vector<Coordinates> points;
  Coordinates loop_normal{0, 0, 0};     ///< vector area of the border loop
  Coordinates surface_normal{0, 0, 0};  ///< area-weighted normal of the faces along it
  double diameter = 0;
  Bounding_box bbox;
};

inline double cosine(const Coordinates& a, const Coordinates& b) {
  const double n = internal::norm(a) * internal::norm(b);
  return n > 0 ? internal::dot(a, b) / n : 0.0;
}

template <class Access>
Cycle_shape cycle_shape(const Access& mesh,
                        const Cycle_halfedges<typename Access::halfedge_descriptor>& cycle,
                        const Border_cycle& description) {
  Cycle_shape shape;
  for (auto h : cycle) {
    shape.points.push_back(mesh.coordinates(source(h, mesh.pm)));
    const auto face_halfedge = opposite(h, mesh.pm);
    const Coordinates a = mesh.coordinates(source(face_halfedge, mesh.pm));
    const Coordinates b = mesh.coordinates(target(face_halfedge, mesh.pm));
    const Coordinates c = mesh.coordinates(target(next(face_halfedge, mesh.pm), mesh.pm));
    const Coordinates n = internal::cross(minus(b, a), minus(c, a));
    for (int k = 0; k < 3; ++k) shape.surface_normal[k] += n[k];
  }
  std::vector<Coordinates> centred;
  for (const auto& p : shape.points) centred.push_back(minus(p, shape.points.front()));
  shape.loop_normal = vector_area(centred);
  shape.bbox = description.bbox;
  shape.diameter = internal::norm(minus(description.bbox.max, description.bbox.min));
  return shape;
}

// Border halfedges run counter-clockwise around a hole seen from the side the surface faces,
// and clockwise around the outer border of a patch (an island). The surface around the cycle
// must face roughly along the loop's normal for that to be meaningful (cosine 0.5).
inline bool looks_like_hole(const Cycle_shape& s) {
  return cosine(s.loop_normal, s.surface_normal) > 0.5;
}
inline bool looks_like_island_border(const Cycle_shape& s) {
  return cosine(s.loop_normal, s.surface_normal) < -0.5;
}

inline bool box_inside(const Bounding_box& inner, const Bounding_box& outer, double margin) {
  for (int k = 0; k < 3; ++k)
    if (inner.min[k] < outer.min[k] - margin || inner.max[k] > outer.max[k] + margin) return false;
  return true;
}

/// Thesis 4.4: a border cycle is an island of a hole when it bounds a patch facing the same
/// way as the surface around the hole and lies inside the hole, seen along the hole's
/// best-fitting plane. Among several enclosing holes, the smallest one is kept.
template <class Access>
void find_ring_hole_islands(
    const Access& mesh,
    const std::vector<Cycle_halfedges<typename Access::halfedge_descriptor>>& cycles,
    std::vector<Border_cycle>& descriptions) {
  using Traits = typename Access::Traits;
  if (cycles.size() < 2) return;
  std::vector<Cycle_shape> shapes;
  for (std::size_t i = 0; i < cycles.size(); ++i)
    shapes.push_back(cycle_shape(mesh, cycles[i], descriptions[i]));
  std::vector<double> enclosing_area(cycles.size(), -1);
  for (std::size_t o = 0; o < cycles.size(); ++o) {
    if (!looks_like_hole(shapes[o])) continue;
    const auto plane =
        planar_cycle<Traits>(shapes[o].points, shapes[o].loop_normal, shapes[o].diameter);
    for (std::size_t i = 0; i < cycles.size(); ++i) {
      if (i == o || !looks_like_island_border(shapes[i])) continue;
      if (cosine(shapes[i].surface_normal, shapes[o].surface_normal) <= 0) continue;
      if (!box_inside(shapes[i].bbox, shapes[o].bbox, 0.5 * shapes[o].diameter)) continue;
      const bool inside =
          std::all_of(shapes[i].points.begin(), shapes[i].points.end(), [&](const Coordinates& p) {
            return std::abs(plane.height(p)) <= plane.diameter &&
                   inside_polygon(plane.polygon, plane.project(p), mesh.gt);
          });
      if (!inside) continue;
      const double area = descriptions[o].area;
      if (enclosing_area[i] < 0 || area < enclosing_area[i]) {
        enclosing_area[i] = area;
        descriptions[i].island_of = long(o);
      }
    }
  }
}

}  // namespace detect
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_BORDER_CYCLES_H
