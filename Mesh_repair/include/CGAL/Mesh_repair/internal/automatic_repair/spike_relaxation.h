// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_SPIKE_RELAXATION_H
#define CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_SPIKE_RELAXATION_H

// Spikes: a vertex thrown off the surface (a scanner's outlier, a vertex moved by a bad edit)
// makes its fan cut through the faces around it. Removing the fan with its rings and refilling
// it (region_replacement.h) loses the faces; on a coarse part the rings soon reach a quarter
// of it and nothing is done. Moving the vertex back to the centre of its neighbours keeps every
// face and fixes the fan, and it is kept only where CGAL's exact face test then finds no face
// of the fan intersecting any face.

#include <CGAL/Mesh_repair/internal/bounded_pairs.h>
#include <CGAL/Mesh_repair/internal/vec3.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// What the relaxation of spikes did, over all its rounds.
struct Spike_relaxation_report {
  std::size_t vertices_moved = 0;
  std::size_t rounds = 0;  ///< rounds that moved a vertex
  double largest_move = 0;
};

/// A vertex is taken for a spike when it lies farther from the centre of its neighbours than
/// this fraction of their mean spacing (the mean length of the edges between consecutive
/// neighbours): on a smooth surface the distance is of the order of the curvature times the
/// squared spacing, a vertex moved by one mean edge length or more is far past it.
constexpr double min_spike_offset_in_spacings = 0.5;
/// Farther than this many spacings from the centre, the vertex is not a local spike but a shape
/// (a thin sheet folded over, a long needle); it is left to the other repairs.
constexpr double max_spike_offset_in_spacings = 5;
/// Sweeps of the moved spikes towards the centres of their neighbours: one puts a lone spike
/// there; neighbouring spikes need several (the error of a cluster of k spikes side by side
/// shrinks by about a factor 1 - 1/k per sweep).
constexpr int relaxation_sweeps = 10;

/// Moves the spikes of intersecting face pairs back onto the surface, one round per call.
template <class PolygonMesh, class VertexPointMap>
class Spike_relaxer {
 public:
  using GT = boost::graph_traits<PolygonMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using face_descriptor = typename GT::face_descriptor;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;

  Spike_relaxer(PolygonMesh& pm, VertexPointMap vpm) : pm_(pm), vpm_(vpm) {}

  /// One round over the intersecting `pairs`: per pair, the vertex of its two faces farthest
  /// from the centre of its neighbours (relative to their spacing) is moved there, and kept
  /// there only if no face around it intersects any face afterwards. Returns the vertices kept
  /// moved.
  template <class PairRange, class GeomTraits>
  std::size_t relax(const PairRange& pairs, const GeomTraits& traits,
                    Spike_relaxation_report& report) {
    std::unordered_map<vertex_descriptor, Point> moved;  // vertex -> its position before
    for (const auto& pair : pairs) {
      const vertex_descriptor spike = likeliest_spike(pair.first, pair.second);
      if (spike == GT::null_vertex() || moved.count(spike)) continue;
      moved.emplace(spike, get(vpm_, spike));
    }
    // Spikes side by side (a scan's noisy patch) move together: Jacobi sweeps, the other
    // vertices fixed, bring them to a membrane over their fixed neighbours.
    for (int sweep = 0; sweep < relaxation_sweeps; ++sweep) {
      std::vector<std::pair<vertex_descriptor, Vec3>> targets;
      for (const auto& entry : moved)
        targets.emplace_back(entry.first, neighbour_centre(entry.first));
      for (const auto& target : targets)
        put(vpm_, target.first, Point(target.second[0], target.second[1], target.second[2]));
    }
    const std::vector<face_descriptor> nearby = faces_near(moved);
    // Undoing a move changes the fans of its moved neighbours: check again until none is bad.
    for (std::size_t pass = 0; !moved.empty(); ++pass) {
      std::vector<vertex_descriptor> bad = bad_moves(moved, nearby, traits, pass > 8);
      if (bad.empty()) break;
      for (vertex_descriptor v : bad) {
        put(vpm_, v, moved.at(v));
        moved.erase(v);
      }
    }
    for (const auto& entry : moved)
      report.largest_move = std::max(
          report.largest_move, norm(to_array(get(vpm_, entry.first)) - to_array(entry.second)));
    report.vertices_moved += moved.size();
    report.rounds += moved.empty() ? 0 : 1;
    return moved.size();
  }

 private:
  std::vector<vertex_descriptor> neighbours(vertex_descriptor v) const {
    std::vector<vertex_descriptor> around;
    for (vertex_descriptor w : vertices_around_target(halfedge(v, pm_), pm_)) around.push_back(w);
    return around;
  }

  Vec3 neighbour_centre(vertex_descriptor v) const {
    Vec3 sum{0, 0, 0};
    const auto around = neighbours(v);
    for (vertex_descriptor w : around) sum = sum + to_array(get(vpm_, w));
    return (1.0 / double(around.size())) * sum;
  }

  /// Distance to the centre of the neighbours over their mean spacing; 0 for a vertex on a
  /// border (its neighbours do not surround it) or with fewer than three neighbours.
  double spike_score(vertex_descriptor v) const {
    if (is_border(v, pm_)) return 0;
    const auto around = neighbours(v);
    if (around.size() < 3) return 0;
    double spacing = 0;
    for (std::size_t i = 0; i < around.size(); ++i)
      spacing += norm(to_array(get(vpm_, around[i])) -
                      to_array(get(vpm_, around[(i + 1) % around.size()])));
    spacing /= double(around.size());
    const double offset = norm(to_array(get(vpm_, v)) - neighbour_centre(v));
    return spacing > 0 ? offset / spacing : 0;
  }

  /// The vertex of the two faces farthest from the centre of its neighbours, if it is a spike;
  /// none if it is too far to be one (its neighbours are no spikes: they are merely near it),
  /// and none if the faces have distinct corners at one point: sheets that touch there (a pinch
  /// kept split, a CAD part's corners on another's) are a contact, and moving a corner apart would
  /// change the shape.
  vertex_descriptor likeliest_spike(face_descriptor f, face_descriptor g) const {
    for (vertex_descriptor v : vertices_around_face(halfedge(f, pm_), pm_))
      for (vertex_descriptor w : vertices_around_face(halfedge(g, pm_), pm_))
        if (v != w && get(vpm_, v) == get(vpm_, w)) return GT::null_vertex();
    vertex_descriptor best = GT::null_vertex();
    double best_score = 0;
    for (face_descriptor face : {f, g})
      for (vertex_descriptor v : vertices_around_face(halfedge(face, pm_), pm_)) {
        const double score = spike_score(v);
        if (score > best_score) {
          best_score = score;
          best = v;
        }
      }
    const bool spike =
        best_score > min_spike_offset_in_spacings && best_score <= max_spike_offset_in_spacings;
    return spike ? best : GT::null_vertex();
  }

  std::vector<face_descriptor> star(vertex_descriptor v) const {
    std::vector<face_descriptor> faces;
    for (face_descriptor f : faces_around_target(halfedge(v, pm_), pm_))
      if (f != GT::null_face()) faces.push_back(f);
    return faces;
  }

  /// The faces whose boxes meet the box of a moved fan, its vertices at their old and their new
  /// places: whatever a fan can meet, whichever of its moved vertices are put back.
  std::vector<face_descriptor> faces_near(
      const std::unordered_map<vertex_descriptor, Point>& moved) const {
    using Box =
        CGAL::Box_intersection_d::Box_with_info_d<double, 3, face_descriptor,
                                                  CGAL::Box_intersection_d::ID_FROM_BOX_ADDRESS>;
    auto both_places = [&](vertex_descriptor v) {
      const auto before = moved.find(v);
      const CGAL::Bbox_3 now = get(vpm_, v).bbox();
      return before == moved.end() ? now : now + before->second.bbox();
    };
    std::vector<Box> fans, all;
    for (const auto& entry : moved) {
      CGAL::Bbox_3 box = both_places(entry.first);
      for (vertex_descriptor w : neighbours(entry.first)) box += both_places(w);
      fans.emplace_back(box, face_descriptor());
    }
    for (face_descriptor f : faces(pm_))
      all.emplace_back(CGAL::Polygon_mesh_processing::face_bbox(
                           f, pm_, CGAL::parameters::vertex_point_map(vpm_)),
                       f);
    std::unordered_set<face_descriptor> near;
    CGAL::box_intersection_d(fans.begin(), fans.end(), all.begin(), all.end(),
                             [&](const Box&, const Box& b) { near.insert(b.info()); });
    return {near.begin(), near.end()};
  }

  /// The moved vertices whose fan meets a face (CGAL's exact test) or turned a face over
  /// against the fan's mean orientation; with `all`, every one of them (the last resort of a
  /// check that does not settle).
  template <class GeomTraits>
  std::vector<vertex_descriptor> bad_moves(
      const std::unordered_map<vertex_descriptor, Point>& moved,
      const std::vector<face_descriptor>& nearby, const GeomTraits& traits, bool all) const {
    std::vector<vertex_descriptor> bad;
    if (all) {
      for (const auto& entry : moved) bad.push_back(entry.first);
      return bad;
    }
    std::vector<face_descriptor> fans;
    std::unordered_set<face_descriptor> in_fans;
    for (const auto& entry : moved)
      for (face_descriptor f : star(entry.first))
        if (in_fans.insert(f).second) fans.push_back(f);
    std::vector<face_descriptor> others;
    for (face_descriptor f : nearby)
      if (!in_fans.count(f)) others.push_back(f);
    const auto found = bounded_intersections_involving(
        fans, others, pm_, default_pair_limit(fans.size() + others.size()), vpm_, traits);
    std::unordered_set<face_descriptor> meeting;
    for (const auto& pair : found.pairs) meeting.insert({pair.first, pair.second});
    for (const auto& entry : moved) {
      bool fine = !found.truncated && !turns_a_face_over(entry.first);
      for (face_descriptor f : star(entry.first)) fine = fine && !meeting.count(f);
      if (!fine) bad.push_back(entry.first);
    }
    return bad;
  }

  /// A face of the fan whose normal points against the fan's vector area: the vertex went
  /// through the surface rather than back onto it.
  bool turns_a_face_over(vertex_descriptor v) const {
    const Vec3 p = to_array(get(vpm_, v));
    std::vector<Vec3> normals;
    Vec3 mean{0, 0, 0};
    for (auto h : halfedges_around_target(halfedge(v, pm_), pm_)) {
      if (is_border(h, pm_)) continue;
      const Vec3 a = to_array(get(vpm_, target(next(h, pm_), pm_)));
      const Vec3 b = to_array(get(vpm_, source(h, pm_)));
      normals.push_back(cross(a - p, b - p));
      mean = mean + cross(a, b);
    }
    for (const Vec3& n : normals)
      if (dot(n, mean) <= 0) return true;
    return false;
  }

  PolygonMesh& pm_;
  VertexPointMap vpm_;
};

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_SPIKE_RELAXATION_H
