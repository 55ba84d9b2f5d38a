// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_HOLE_BENCHMARK_PUNCH_H
#define CGAL_MESH_REPAIR_INTERNAL_HOLE_BENCHMARK_PUNCH_H

// Punching holes for the ground-truth benchmark: a region of faces is grown around a centre
// vertex in the order of a shape-dependent normalised distance rho (rho < 1 inside the hole),
// keeping the region a topological disc at every step, then removed. The removed faces are kept
// as the truth.

#include <CGAL/Mesh_repair/internal/hole_benchmark/types.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Random.h>
#include <CGAL/squared_distance_3.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace hole_benchmark {

// Semi-axis ratio of elongated holes (the same area as the disc of the requested radius).
constexpr double elongation = 1.7320508075688772;  // sqrt(3): aspect ratio 3
// Crenellations of jagged holes: the radius alternates between (1 +- jag_amplitude) r.
constexpr double jag_amplitude = 0.3;
constexpr int jag_teeth = 7;
// A hole whose border is shorter than this fraction of the flat disc's perimeter 2 pi r is the
// cap of a thin protrusion (a trunk's tip, a finger) rather than a hole in a surface: refused.
constexpr double min_perimeter_fraction = 0.5;
// A ring hole keeps the island of the faces with rho below this fraction of the hole radius.
constexpr double island_fraction = 0.45;

template <class Vector>
Vector unit(const Vector& v) {
  const double length = std::sqrt(CGAL::to_double(v.squared_length()));
  return length > 0 ? v / length : v;
}

// The tangent frame (t1, t2, n) at the centre, from the vertex normal and a random direction.
template <class Vector>
std::array<Vector, 3> tangent_frame(const Vector& normal, CGAL::Random& random) {
  const Vector n = unit(normal);
  Vector t1(0, 0, 0);
  while (t1.squared_length() < 1e-6) {
    const Vector guess(random.get_double(-1, 1), random.get_double(-1, 1),
                       random.get_double(-1, 1));
    t1 = guess - (guess * n) * n;
  }
  t1 = unit(t1);
  return {t1, CGAL::cross_product(n, t1), n};
}

// The normalised distance rho of every vertex within reach: Dijkstra over the edges with a
// metric stretched along t1 for elongated holes, divided by the (crenellated) radius for jagged
// ones. Vertices not reached keep infinity.
template <class PolygonMesh, class VertexPointMap, class DistanceMap, class Vector>
void normalised_distances(const PolygonMesh& pm, VertexPointMap vpm,
                          typename boost::graph_traits<PolygonMesh>::vertex_descriptor centre,
                          double radius, Hole_shape shape, const std::array<Vector, 3>& frame,
                          double phase, DistanceMap rho) {
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  const double infinity = std::numeric_limits<double>::infinity();
  for (vertex_descriptor v : vertices(pm)) put(rho, v, infinity);
  const double stretch = shape == Hole_shape::elongated ? elongation : 1.0;
  auto edge_length = [&](const Vector& e) {
    const double a = (e * frame[0]) / stretch, b = (e * frame[1]) * stretch, c = e * frame[2];
    return std::sqrt(a * a + b * b + c * c);
  };
  // Geodesic-ish distance first (plain Dijkstra), then divided by the local radius.
  const double reach = radius * (1.0 + jag_amplitude) * 1.5;
  using Entry = std::pair<double, vertex_descriptor>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  std::vector<vertex_descriptor> reached;
  put(rho, centre, 0.0);
  queue.push({0.0, centre});
  while (!queue.empty()) {
    const auto [distance, v] = queue.top();
    queue.pop();
    if (distance > get(rho, v)) continue;
    reached.push_back(v);
    for (auto h : CGAL::halfedges_around_target(v, pm)) {
      const vertex_descriptor w = source(h, pm);
      const double candidate = distance + edge_length(get(vpm, w) - get(vpm, v));
      if (candidate < get(rho, w) && candidate <= reach) {
        put(rho, w, candidate);
        queue.push({candidate, w});
      }
    }
  }
  const auto c = get(vpm, centre);
  for (vertex_descriptor v : reached) {
    double local_radius = radius;
    if (shape == Hole_shape::jagged) {
      const Vector d = get(vpm, v) - c;
      const double angle = std::atan2(d * frame[1], d * frame[0]);
      const double wave = std::sin(jag_teeth * angle + phase) >= 0 ? 1.0 : -1.0;
      local_radius = radius * (1.0 + jag_amplitude * wave);
    }
    put(rho, v, get(rho, v) / local_radius);
  }
}

// Region growing that keeps the region a topological disc. `allowed(f)` says whether face f may
// join (inside the shape, away from borders and other holes).
template <class PolygonMesh>
class Disc_region {
 public:
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<PolygonMesh>::halfedge_descriptor;

  explicit Disc_region(const PolygonMesh& pm) : pm_(pm) {}

  // Grows from `seed` in increasing `priority`, adding faces while `allowed` says so.
  template <class Priority, class Allowed>
  void grow(face_descriptor seed, Priority priority, Allowed allowed) {
    using Entry = std::pair<double, face_descriptor>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    queue.push({priority(seed), seed});
    while (!queue.empty()) {
      const face_descriptor f = queue.top().second;
      queue.pop();
      if (members_.count(f) || !allowed(f) || !keeps_disc(f)) continue;
      members_.insert(f);
      order_.push_back(f);
      for (halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, pm_), pm_)) {
        const face_descriptor g = face(opposite(h, pm_), pm_);
        if (g != boost::graph_traits<PolygonMesh>::null_face() && !members_.count(g))
          queue.push({priority(g), g});
      }
    }
  }

  bool has(face_descriptor f) const { return members_.count(f) > 0; }
  const std::vector<face_descriptor>& faces() const { return order_; }

  // Whether vertex v lies on the region's border (some but not all of its faces are members).
  bool on_border(vertex_descriptor v) const {
    bool some = false, all = true;
    for (halfedge_descriptor h : CGAL::halfedges_around_target(v, pm_)) {
      const face_descriptor f = face(h, pm_);
      const bool member = f != boost::graph_traits<PolygonMesh>::null_face() && members_.count(f);
      some = some || member;
      all = all && member;
    }
    return some && !all;
  }
  bool touches(vertex_descriptor v) const {
    for (halfedge_descriptor h : CGAL::halfedges_around_target(v, pm_)) {
      const face_descriptor f = face(h, pm_);
      if (f != boost::graph_traits<PolygonMesh>::null_face() && members_.count(f)) return true;
    }
    return false;
  }

 private:
  // A triangle joins a disc and leaves a disc iff it shares one edge and its third vertex is not
  // on the region, or shares two edges whose common vertex then has all its faces in the region.
  // The first face is always accepted.
  bool keeps_disc(face_descriptor f) const {
    if (members_.empty()) return true;
    std::vector<halfedge_descriptor> shared, free;
    for (halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, pm_), pm_)) {
      const face_descriptor g = face(opposite(h, pm_), pm_);
      if (g != boost::graph_traits<PolygonMesh>::null_face() && members_.count(g))
        shared.push_back(h);
      else
        free.push_back(h);
    }
    if (shared.size() == 1) {
      const vertex_descriptor apex = target(next(shared[0], pm_), pm_);
      return !touches(apex);
    }
    if (shared.size() == 2) {
      // the vertex common to both shared edges becomes interior: all its other faces are members
      const vertex_descriptor common = target(shared[0], pm_) == source(shared[1], pm_)
                                           ? target(shared[0], pm_)
                                           : source(shared[0], pm_);
      for (halfedge_descriptor h : CGAL::halfedges_around_target(common, pm_)) {
        const face_descriptor g = face(h, pm_);
        if (g == f) continue;
        if (g == boost::graph_traits<PolygonMesh>::null_face() || !members_.count(g)) return false;
      }
      return true;
    }
    return false;
  }

  const PolygonMesh& pm_;
  std::set<face_descriptor> members_;
  std::vector<face_descriptor> order_;
};

template <class PolygonMesh, class VertexPointMap>
double face_angle_deg(typename boost::graph_traits<PolygonMesh>::face_descriptor f,
                      typename boost::graph_traits<PolygonMesh>::face_descriptor g,
                      const PolygonMesh& pm, VertexPointMap vpm) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  const auto nf = PMP::compute_face_normal(f, pm, CGAL::parameters::vertex_point_map(vpm));
  const auto ng = PMP::compute_face_normal(g, pm, CGAL::parameters::vertex_point_map(vpm));
  const double sine = std::sqrt(CGAL::to_double(CGAL::cross_product(nf, ng).squared_length()));
  return std::atan2(sine, CGAL::to_double(nf * ng)) * 180.0 / CGAL_PI;
}

// The faces `faces` of `pm` as a mesh of their own.
template <class Point, class PolygonMesh, class VertexPointMap, class FaceRange>
CGAL::Surface_mesh<Point> extract_faces(const PolygonMesh& pm, VertexPointMap vpm,
                                        const FaceRange& faces) {
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  std::map<vertex_descriptor, std::size_t> index;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  for (auto f : faces) {
    std::vector<std::size_t> polygon;
    for (vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, pm), pm)) {
      auto inserted = index.emplace(v, points.size());
      if (inserted.second) points.push_back(get(vpm, v));
      polygon.push_back(inserted.first->second);
    }
    polygons.push_back(polygon);
  }
  CGAL::Surface_mesh<Point> patch;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, patch);
  return patch;
}

// The vertices in a random order, as candidate hole centres: Fisher-Yates with the seeded random.
template <class PolygonMesh>
std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> shuffled_vertices(
    const PolygonMesh& pm, CGAL::Random& random) {
  std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> order(
      vertices(pm).begin(), vertices(pm).end());
  for (std::size_t i = order.size(); i > 1; --i)
    std::swap(order[i - 1], order[std::size_t(random.get_int(0, int(i)))]);
  return order;
}

template <class PolygonMesh, class VertexPointMap>
class Hole_puncher {
 public:
  using GT = boost::graph_traits<PolygonMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using face_descriptor = typename GT::face_descriptor;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  using Vector = typename CGAL::Kernel_traits<Point>::Kernel::Vector_3;
  using Hole = Punched_hole<PolygonMesh, Point>;

  Hole_puncher(PolygonMesh& pm, VertexPointMap vpm, Hole_shape shape, double radius)
      : pm_(pm),
        vpm_(vpm),
        shape_(shape),
        radius_(radius),
        forbidden_(get(CGAL::dynamic_vertex_property_t<char>(), pm)),
        rho_(get(CGAL::dynamic_vertex_property_t<double>(), pm)) {
    // Holes never touch the mesh's own borders.
    for (vertex_descriptor v : vertices(pm_))
      put(forbidden_, v, CGAL::is_border(v, pm_) != boost::none);
  }

  // Tries a hole around `centre`; false (mesh untouched) when it would touch a border or another
  // hole, or when a ring hole has no room for its island.
  bool available(vertex_descriptor centre) const { return !get(forbidden_, centre); }

  bool try_punch(vertex_descriptor centre, CGAL::Random& random, Hole& hole) {
    const auto frame = tangent_frame(Vector(CGAL::Polygon_mesh_processing::compute_vertex_normal(
                                         centre, pm_, CGAL::parameters::vertex_point_map(vpm_))),
                                     random);
    normalised_distances(pm_, vpm_, centre, radius_, shape_, frame,
                         random.get_double(0, 2 * CGAL_PI), rho_);
    bool blocked = false;
    auto face_rho = [&](face_descriptor f) { return this->face_rho(f); };
    auto allowed = [&](face_descriptor f) {
      if (face_rho(f) >= 1) return false;
      for (vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, pm_), pm_))
        if (get(forbidden_, v)) blocked = true;
      return !blocked;
    };
    Disc_region<PolygonMesh> region(pm_);
    region.grow(seed_face(centre), face_rho, allowed);
    if (blocked || region.faces().empty() || is_protrusion_cap(region)) return false;
    Disc_region<PolygonMesh> island(pm_);
    if (shape_ == Hole_shape::ring && !grow_island(centre, region, island)) return false;
    std::vector<face_descriptor> removed;
    for (face_descriptor f : region.faces())
      if (!island.has(f)) removed.push_back(f);
    forbid_around(region);
    record_truth(centre, removed, island, hole);
    for (face_descriptor f : removed) CGAL::Euler::remove_face(halfedge(f, pm_), pm_);
    measure_outer_border(hole);
    return true;
  }

 private:
  double face_rho(face_descriptor f) const {
    double sum = 0;
    int count = 0;
    for (vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, pm_), pm_)) {
      sum += get(rho_, v);
      ++count;
    }
    return sum / count;
  }

  bool is_protrusion_cap(const Disc_region<PolygonMesh>& region) const {
    double perimeter = 0;
    for (face_descriptor f : region.faces())
      for (halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, pm_), pm_))
        if (!region.has(face(opposite(h, pm_), pm_)))
          perimeter += std::sqrt(CGAL::to_double(
              CGAL::squared_distance(get(vpm_, source(h, pm_)), get(vpm_, target(h, pm_)))));
    return perimeter < min_perimeter_fraction * 2 * CGAL_PI * radius_;
  }

  face_descriptor seed_face(vertex_descriptor centre) const {
    for (halfedge_descriptor h : CGAL::halfedges_around_target(centre, pm_))
      if (face(h, pm_) != GT::null_face()) return face(h, pm_);
    return GT::null_face();
  }

  // The island of a ring hole: the faces of the hole with rho below island_fraction, grown as a
  // disc that keeps away from the hole's border so that the removed annulus separates them.
  bool grow_island(vertex_descriptor centre, const Disc_region<PolygonMesh>& region,
                   Disc_region<PolygonMesh>& island) {
    auto face_rho = [&](face_descriptor f) { return this->face_rho(f); };
    auto allowed = [&](face_descriptor f) {
      if (!region.has(f) || face_rho(f) >= island_fraction) return false;
      for (vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, pm_), pm_))
        if (region.on_border(v)) return false;
      return true;
    };
    const face_descriptor seed = seed_face(centre);
    if (seed == GT::null_face() || !allowed(seed)) return false;
    island.grow(seed, face_rho, allowed);
    return !island.faces().empty() && island.faces().size() < region.faces().size();
  }

  // Later holes keep one ring of vertices away from this one.
  void forbid_around(const Disc_region<PolygonMesh>& region) {
    std::vector<vertex_descriptor> touched;
    for (face_descriptor f : region.faces())
      for (vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, pm_), pm_))
        for (vertex_descriptor w : CGAL::vertices_around_target(v, pm_)) touched.push_back(w);
    for (vertex_descriptor v : touched) put(forbidden_, v, true);
  }

  void record_truth(vertex_descriptor centre, const std::vector<face_descriptor>& removed,
                    const Disc_region<PolygonMesh>& island, Hole& hole) {
    hole.centre = get(vpm_, centre);
    hole.requested_radius = radius_;
    hole.removed_faces = removed.size();
    hole.removed_patch = extract_faces<Point>(pm_, vpm_, removed);
    const std::set<face_descriptor> removed_set(removed.begin(), removed.end());
    bool outer_found = false;
    for (face_descriptor f : removed) {
      for (halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, pm_), pm_)) {
        const face_descriptor g = face(opposite(h, pm_), pm_);
        if (removed_set.count(g)) continue;
        hole.border.emplace_back(h, face_angle_deg(f, g, pm_, vpm_));
        if (island.has(g)) {
          if (hole.island_border_halfedges.empty()) hole.island_border_halfedges.push_back(h);
        } else if (!outer_found) {
          hole.border_halfedge = h;
          outer_found = true;
        }
      }
    }
  }

  void measure_outer_border(Hole& hole) const {
    double radius_sum = 0;
    for (halfedge_descriptor h : CGAL::halfedges_around_face(hole.border_halfedge, pm_)) {
      ++hole.outer_border_edges;
      hole.outer_perimeter += std::sqrt(CGAL::to_double(
          CGAL::squared_distance(get(vpm_, source(h, pm_)), get(vpm_, target(h, pm_)))));
      radius_sum += get(rho_, target(h, pm_));
    }
    // rho is distance over radius: back to model units (the nominal radius for jagged holes).
    hole.achieved_radius = radius_ * radius_sum / double(hole.outer_border_edges);
  }

  PolygonMesh& pm_;
  VertexPointMap vpm_;
  Hole_shape shape_;
  double radius_;
  // char, not bool: OpenMesh stores a bool property in a std::vector<bool>, whose
  // elements its property map cannot return by reference (does not compile).
  typename boost::property_map<PolygonMesh, CGAL::dynamic_vertex_property_t<char>>::type forbidden_;
  typename boost::property_map<PolygonMesh, CGAL::dynamic_vertex_property_t<double>>::type rho_;
};

// (The return type is spelt out, not `auto`, so that the compiled core can instantiate it once.)
template <class PolygonMesh, class VertexPointMap>
Punch_result<PolygonMesh, typename boost::property_traits<VertexPointMap>::value_type> punch_holes(
    PolygonMesh& pm, VertexPointMap vpm, std::size_t number_of_holes, double radius_fraction,
    Hole_shape shape, unsigned int seed) {
  using Puncher = Hole_puncher<PolygonMesh, VertexPointMap>;
  Punch_result<PolygonMesh, typename Puncher::Point> result;
  result.requested = number_of_holes;
  const CGAL::Bbox_3 box =
      CGAL::Polygon_mesh_processing::bbox(pm, CGAL::parameters::vertex_point_map(vpm));
  result.bbox_diagonal =
      std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                CGAL::square(box.zmax() - box.zmin()));
  CGAL::Random random(seed);
  Puncher puncher(pm, vpm, shape, radius_fraction * result.bbox_diagonal);
  const std::size_t max_attempts = std::max<std::size_t>(64, 32 * number_of_holes);
  for (auto centre : shuffled_vertices(pm, random)) {
    if (result.holes.size() == number_of_holes || result.attempts == max_attempts) break;
    if (!puncher.available(centre)) continue;
    ++result.attempts;
    typename Puncher::Hole hole;
    if (puncher.try_punch(centre, random, hole)) result.holes.push_back(std::move(hole));
  }
  if (result.holes.size() < number_of_holes)
    result.shortfall = "only " + std::to_string(result.holes.size()) + " of " +
                       std::to_string(number_of_holes) + " holes fit after " +
                       std::to_string(result.attempts) +
                       " centres (holes keep away from borders and from each other)";
  return result;
}

/// The one simple hole puncher of the tests and benchmarks (the ground-truth benchmark grows its
/// holes with `punch_holes` above): removes the faces whose vertices all lie within `radius` of
/// `center` and that are reached from the first such face (in face order) through such faces,
/// then, repeatedly, the faces left hanging by two border edges, so that the hole's border is
/// one simple cycle in the usual cases. Returns the first border halfedge (in halfedge order)
/// whose target lies within 1.5 `radius` of `center`, the null halfedge when no face was
/// inside; `removed`, when given, receives the number of faces removed.
template <class PolygonMesh, class Point>
typename boost::graph_traits<PolygonMesh>::halfedge_descriptor punch_ball_hole(
    PolygonMesh& pm, const Point& center, double radius, std::size_t* removed = nullptr) {
  using GT = boost::graph_traits<PolygonMesh>;
  using face_descriptor = typename GT::face_descriptor;
  auto vpm = get(CGAL::vertex_point, pm);
  auto within = [&](typename GT::vertex_descriptor v, double r) {
    return CGAL::squared_distance(get(vpm, v), center) <= r * r;
  };
  auto inside = [&](face_descriptor f) {
    for (auto v : CGAL::vertices_around_face(halfedge(f, pm), pm))
      if (!within(v, radius)) return false;
    return true;
  };
  std::set<face_descriptor> region;
  std::queue<face_descriptor> queue;
  for (face_descriptor f : faces(pm)) {
    if (inside(f)) {
      queue.push(f);
      region.insert(f);
      break;
    }
  }
  while (!queue.empty()) {
    const face_descriptor f = queue.front();
    queue.pop();
    for (auto h : CGAL::halfedges_around_face(halfedge(f, pm), pm)) {
      const face_descriptor g = face(opposite(h, pm), pm);
      if (g != GT::null_face() && !region.count(g) && inside(g)) {
        region.insert(g);
        queue.push(g);
      }
    }
  }
  for (face_descriptor f : region) CGAL::Euler::remove_face(halfedge(f, pm), pm);
  std::size_t count = region.size();
  for (bool again = !region.empty(); again;) {
    again = false;
    for (face_descriptor f : faces(pm)) {
      int border_edges = 0;
      for (auto h : CGAL::halfedges_around_face(halfedge(f, pm), pm))
        border_edges += is_border(opposite(h, pm), pm) ? 1 : 0;
      if (border_edges >= 2) {
        CGAL::Euler::remove_face(halfedge(f, pm), pm);
        ++count;
        again = true;
        break;
      }
    }
  }
  if (removed) *removed = count;
  if (count == 0) return GT::null_halfedge();
  for (auto h : halfedges(pm))
    if (is_border(h, pm) && within(target(h, pm), 1.5 * radius)) return h;
  return GT::null_halfedge();
}

}  // namespace hole_benchmark
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_HOLE_BENCHMARK_PUNCH_H
