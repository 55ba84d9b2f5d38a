// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_TOUCHING_FANS_H
#define CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_TOUCHING_FANS_H

// A closed oriented triangle soup whose surface touches itself at points or along edges (the
// outer surface of parts meeting corner to corner or edge to edge), made a surface that a
// halfedge mesh holds and that no reader sees touch: each fan of triangles at such a point gets a
// point of its own, moved a little into its own side (self_union_impl.h).

#include <CGAL/Mesh_repair/internal/automatic_repair/solid_union.h>
#include <CGAL/Mesh_repair/internal/soup_edge.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace touching_fans {

using Vector = CGAL::Vector_3<Core_traits>;

/// The triangles of `soup` around the edge (`a`, `b`), `a` < `b`, of a closed oriented surface
/// that meets itself along the edge (four triangles or more), paired as they bound the solid
/// wedges: each triangle that runs from `a` to `b` with the one that follows it clockwise around
/// the direction from `a` to `b` (its inside). Sorted with exact predicates; empty when the
/// triangles do not alternate in direction or two of them lie in one half-plane.
inline std::vector<std::pair<std::size_t, std::size_t>> wedges_around_edge(
    const Triangle_soup& soup, std::size_t a, std::size_t b,
    const std::vector<std::size_t>& triangles) {
  const auto& P = soup.points;
  struct Around {
    std::size_t triangle;
    std::size_t apex;
    bool forward;  // runs from a to b
  };
  std::vector<Around> around;
  for (std::size_t t : triangles) {
    const auto& tri = soup.polygons[t];
    for (int i = 0; i < 3; ++i)
      if (tri[i] != a && tri[i] != b) around.push_back({t, tri[i], false});
    for (int i = 0; i < 3; ++i)
      if (tri[i] == a && tri[(i + 1) % 3] == b) around.back().forward = true;
  }
  for (const Around& x : around)
    if (CGAL::collinear(P[a], P[b], P[x.apex])) return {};
  // Counterclockwise around the axis from a to b, starting at the first triangle's half-plane.
  const auto& start = P[around.front().apex];
  const auto half = [&](const Around& x) {
    const CGAL::Orientation o = CGAL::orientation(P[a], P[b], start, P[x.apex]);
    if (o != CGAL::COPLANAR) return o == CGAL::POSITIVE ? 0 : 1;
    return CGAL::coplanar_orientation(P[a], P[b], start, P[x.apex]) == CGAL::POSITIVE ? 0 : 1;
  };
  const auto before = [&](const Around& x, const Around& y) {
    const int hx = half(x), hy = half(y);
    if (hx != hy) return hx < hy;
    return CGAL::orientation(P[a], P[b], P[x.apex], P[y.apex]) == CGAL::POSITIVE;
  };
  std::sort(around.begin(), around.end(), before);
  std::vector<std::pair<std::size_t, std::size_t>> wedges;
  const std::size_t n = around.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Around &x = around[i], &next = around[(i + 1) % n];
    // Strictly ordered, and alternating in direction.
    if (x.forward == next.forward || before(x, next) != (i + 1 < n)) return {};
    if (x.forward) wedges.emplace_back(x.triangle, around[(i + n - 1) % n].triangle);
  }
  return wedges;
}

inline Vector unit(const Vector& u) {
  const double length = std::sqrt(u.squared_length());
  return length > 0 ? u / length : u;
}

/// The unit vector, orthogonal to the edge (`a`, `b`), that bisects the wedge between the
/// triangles `f` (running from `a` to `b`) and `g`, clockwise from `f` around the direction
/// from `a` to `b` (as `wedges_around_edge` pairs them).
inline Vector wedge_bisector(const Triangle_soup& soup, const Soup_edge& edge, std::size_t f,
                             std::size_t g) {
  const auto& P = soup.points;
  const auto &a = P[edge.first], &b = P[edge.second];
  const auto apex = [&](std::size_t t) {
    for (std::size_t w : soup.polygons[t])
      if (w != edge.first && w != edge.second) return P[w];
    return a;
  };
  const Vector axis = b - a;
  const auto across = [&](const Core_mesh::Point& p) {
    return unit((p - a) - axis * (((p - a) * axis) / axis.squared_length()));
  };
  const Core_mesh::Point pf = apex(f), pg = apex(g);
  // Clockwise from f to g: less than a half-turn when g is on f's inner (negative) side.
  const CGAL::Orientation o = CGAL::orientation(a, b, pf, pg);
  if (o == CGAL::COPLANAR) return unit(-CGAL::cross_product(axis, pf - a));
  const Vector bisector = across(pf) + across(pg);
  return unit(o == CGAL::POSITIVE ? -bisector : bisector);
}

/// Ways into a fan of triangles from its apex, tried in turn at a point until its fans part.
enum class Into_fan {
  wedge_or_away,     ///< a wedge's bisector for a fan along a touching edge, else `away`
  away_from_others,  ///< `along_edges` less the mean of the other fans'
  along_edges,       ///< the sum of the unit vectors along the fan's edges
  towards_corners,   ///< towards the centre of the fan's other corners
  against_normal,    ///< against the fan's area-weighted normal (the surface faces outwards)
  blend,             ///< `wedge_or_away` plus `along_edges`
};
constexpr int number_of_ways = 6;

/// The points where the surface touches itself, each with its fans of triangles.
struct Touching {
  std::vector<std::pair<std::size_t, std::vector<std::vector<std::size_t>>>> points;
  std::map<Soup_edge, std::vector<std::size_t>> triangles_on_edge;
  /// Triangles joined across an edge: the two of a manifold edge, the pairs of a touching one.
  std::map<Soup_edge, std::vector<std::pair<std::size_t, std::size_t>>> joined;
};

inline Touching find_touching(const Triangle_soup& soup) {
  Touching touching;
  std::vector<boost::container::small_vector<std::size_t, 8>> triangles_at(soup.points.size());
  for (std::size_t t = 0; t < soup.polygons.size(); ++t)
    for (std::size_t i = 0; i < 3; ++i) {
      const std::size_t a = soup.polygons[t][i], b = soup.polygons[t][(i + 1) % 3];
      touching.triangles_on_edge[soup_edge(a, b)].push_back(t);
      triangles_at[a].push_back(t);
    }
  for (const auto& [edge, triangles] : touching.triangles_on_edge) {
    if (triangles.size() == 2)
      touching.joined[edge].emplace_back(triangles[0], triangles[1]);
    else if (triangles.size() > 2)
      touching.joined[edge] = wedges_around_edge(soup, edge.first, edge.second, triangles);
  }
  for (std::size_t v = 0; v < triangles_at.size(); ++v) {
    std::map<std::size_t, std::size_t> fan;  // union-find over the triangles around v
    for (std::size_t t : triangles_at[v]) fan[t] = t;
    const auto find = [&](std::size_t t) {
      while (fan[t] != t) t = fan[t] = fan[fan[t]];
      return t;
    };
    for (std::size_t t : triangles_at[v])
      for (std::size_t w : soup.polygons[t]) {
        const auto found = touching.joined.find(soup_edge(v, w));
        if (w == v || found == touching.joined.end()) continue;
        for (const auto& pair : found->second) fan[find(pair.first)] = find(pair.second);
      }
    std::map<std::size_t, std::vector<std::size_t>> fans;
    for (std::size_t t : triangles_at[v]) fans[find(t)].push_back(t);
    if (fans.size() < 2) continue;
    touching.points.emplace_back(v, std::vector<std::vector<std::size_t>>());
    for (auto& f : fans) touching.points.back().second.push_back(std::move(f.second));
  }
  return touching;
}

inline Vector along_edges(const Triangle_soup& soup, std::size_t v,
                          const std::vector<std::size_t>& fan, bool unit_edges) {
  Vector sum = CGAL::NULL_VECTOR;
  for (std::size_t t : fan)
    for (std::size_t w : soup.polygons[t])
      if (w != v)
        sum = sum + (unit_edges ? unit(soup.points[w] - soup.points[v])
                                : soup.points[w] - soup.points[v]);
  return unit(sum);
}

inline Vector against_normal(const Triangle_soup& soup, const std::vector<std::size_t>& fan) {
  Vector sum = CGAL::NULL_VECTOR;
  for (std::size_t t : fan) {
    const auto& tri = soup.polygons[t];
    sum = sum - CGAL::cross_product(soup.points[tri[1]] - soup.points[tri[0]],
                                    soup.points[tri[2]] - soup.points[tri[0]]);
  }
  return unit(sum);
}

/// The mean of the bisectors of the wedges that the fan `fan` at `v` forms along touching
/// edges (two for a point inside a chain of touching edges), if it forms any.
inline bool wedge_of_fan(const Triangle_soup& soup, const Touching& touching, std::size_t v,
                         const std::vector<std::size_t>& fan, Vector& bisector) {
  Vector sum = CGAL::NULL_VECTOR;
  std::set<Soup_edge> seen;
  for (std::size_t t : fan)
    for (std::size_t w : soup.polygons[t]) {
      const Soup_edge edge = soup_edge(v, w);
      if (w == v || touching.triangles_on_edge.at(edge).size() < 3 || !seen.insert(edge).second)
        continue;
      for (const auto& [f, g] : touching.joined.at(edge))
        if (std::count(fan.begin(), fan.end(), f)) sum = sum + wedge_bisector(soup, edge, f, g);
    }
  bisector = unit(sum);
  return !seen.empty();
}

/// The unit vectors into each fan at the touching point `k`, the `way` given.
inline std::vector<Vector> ways_into_fans(const Triangle_soup& soup, const Touching& touching,
                                          std::size_t k, Into_fan way) {
  const auto& [v, fans] = touching.points[k];
  std::vector<Vector> into;
  for (const auto& fan : fans) {
    if (way == Into_fan::towards_corners)
      into.push_back(along_edges(soup, v, fan, false));
    else if (way == Into_fan::against_normal)
      into.push_back(against_normal(soup, fan));
    else
      into.push_back(along_edges(soup, v, fan, true));
  }
  if (way == Into_fan::along_edges || way == Into_fan::towards_corners ||
      way == Into_fan::against_normal)
    return into;
  // Each fan's way less the mean of the others': along an edge where two fans touch, what
  // their ways share (the direction of the edge) cancels and what parts them remains.
  const std::vector<Vector> edges = into;
  Vector total = CGAL::NULL_VECTOR;
  for (const Vector& u : edges) total = total + u;
  for (std::size_t i = 0; i < into.size(); ++i)
    into[i] = unit(edges[i] - (total - edges[i]) / double(fans.size() - 1));
  if (way == Into_fan::away_from_others) return into;
  for (std::size_t i = 0; i < into.size(); ++i) {
    Vector bisector;
    if (wedge_of_fan(soup, touching, v, fans[i], bisector)) into[i] = bisector;
    if (way == Into_fan::blend) into[i] = unit(into[i] + edges[i]);
  }
  return into;
}

/// A quarter of the smallest height over `v` of the triangles of `fan`: moving `v` less than
/// that folds none of them (tiny closed pieces of an arrangement have fans that small).
inline double quarter_height(const Triangle_soup& soup, std::size_t v,
                             const std::vector<std::size_t>& fan) {
  double smallest = std::numeric_limits<double>::infinity();
  for (std::size_t t : fan) {
    const auto& tri = soup.polygons[t];
    const int i = int(std::find(tri.begin(), tri.end(), v) - tri.begin());
    const auto &b = soup.points[tri[(i + 1) % 3]], &c = soup.points[tri[(i + 2) % 3]];
    const double base = std::sqrt(CGAL::squared_distance(b, c));
    const double twice_area =
        std::sqrt(CGAL::cross_product(b - soup.points[v], c - soup.points[v]).squared_length());
    smallest = std::min(smallest, base > 0 ? twice_area / base : 0.0);
  }
  return smallest / 4;
}

/// `soup` with each touching point split, one point per fan, each moved by `distance` into its
/// fan the way `ways[k]` says for the touching point `k` (with `by_height[k]`, less where a
/// triangle of the fan is low: `quarter_height`). `point_of` gets, for each point of the
/// result, the touching point it comes from, or -1.
inline void separate(Triangle_soup& soup, const Touching& touching,
                     const std::vector<Into_fan>& ways, double distance,
                     const std::vector<char>& by_height, std::vector<std::ptrdiff_t>& point_of) {
  // The ways first, from the soup as it was; the points split after.
  std::vector<std::vector<Vector>> into;
  for (std::size_t k = 0; k < touching.points.size(); ++k)
    into.push_back(ways_into_fans(soup, touching, k, ways[k]));
  point_of.assign(soup.points.size(), -1);
  for (std::size_t k = 0; k < touching.points.size(); ++k) {
    // Not a structured binding: the lambda below captures them (C++17 does not allow it).
    const std::size_t v = touching.points[k].first;
    const auto& fans = touching.points[k].second;
    const Core_mesh::Point origin = soup.points[v];
    point_of[v] = std::ptrdiff_t(k);
    const auto moved = [&](std::size_t i) {
      return origin +
             into[k][i] *
                 (by_height[k] ? std::min(distance, quarter_height(soup, v, fans[i])) : distance);
    };
    const Core_mesh::Point first = moved(0);
    for (std::size_t i = 1; i < fans.size(); ++i) {
      soup.points.push_back(moved(i));
      point_of.push_back(std::ptrdiff_t(k));
      for (std::size_t t : fans[i])
        std::replace(soup.polygons[t].begin(), soup.polygons[t].end(), v, soup.points.size() - 1);
    }
    soup.points[v] = first;  // the first fan keeps the point
  }
}

}  // namespace touching_fans
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_TOUCHING_FANS_H
