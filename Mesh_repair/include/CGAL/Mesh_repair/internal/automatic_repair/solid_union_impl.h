// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_SOLID_UNION_IMPL_H
#define CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_SOLID_UNION_IMPL_H

#include <CGAL/Mesh_repair/internal/automatic_repair/solid_union.h>
#include <CGAL/Mesh_repair/internal/automatic_repair/solid_soup.h>
#include <CGAL/Mesh_repair/internal/child_process.h>

#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/helpers.h>

#include <cstring>
#include <exception>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

CGAL_MESH_REPAIR_CORE_INLINE std::string union_of_solids(const std::vector<Triangle_soup>& solids,
                                                         Triangle_soup& out) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  if (solids.size() < 2) return "fewer than two parts";
  std::vector<Core_mesh> level(solids.size());
  for (std::size_t i = 0; i < solids.size(); ++i) {
    const std::string why = solid_union::to_solid(solids[i], level[i]);
    if (!why.empty()) return why;
  }
  // Pairwise, level by level: each corefinement reads both of its operands whole, so adding the
  // parts one at a time to a growing union would be quadratic in their number (benchmarks.md,
  // "Scaling").
  while (level.size() > 1) {
    std::vector<Core_mesh> next((level.size() + 1) / 2);
    for (std::size_t i = 0; i + 1 < level.size(); i += 2) {
      try {
        if (!PMP::corefine_and_compute_union(level[i], level[i + 1], next[i / 2]))
          return "CGAL's corefinement could not compute the union (its result would not be "
                 "manifold)";
      } catch (const std::exception& e) {
        return std::string("CGAL's corefinement failed: ") + e.what();
      }
    }
    if (level.size() % 2 == 1) next.back() = std::move(level.back());
    level = std::move(next);
  }
  solid_union::to_soup(level.front(), out);
  return {};
}

namespace solid_union {

/// The body of `remove_self_intersections_of_solid`, in this process.
inline std::string autorefine(const Triangle_soup& solid, Triangle_soup& out,
                              Solid_autorefinement& measures) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  Core_mesh mesh;
  std::string why = to_closed_mesh(solid, mesh);
  if (!why.empty()) return why;
  const Core_mesh before = mesh;
  measures.area_before = PMP::area(mesh);
  try {
    // The pieces kept are those outside the volume as the faces' orientation defines it.
    if (!PMP::is_outward_oriented(mesh)) PMP::reverse_face_orientations(mesh);
    if (!PMP::experimental::autorefine_and_remove_self_intersections(mesh))
      return "CGAL's autorefinement could not remove them all";
  } catch (const std::exception& e) {
    return std::string("CGAL's autorefinement failed: ") + e.what();
  }
  if (mesh.is_empty() || !CGAL::is_closed(mesh) || !mesh.is_valid(false))
    return "CGAL's autorefinement left an open or invalid part";
  if (PMP::does_self_intersect(mesh)) return "CGAL's autorefinement left self-intersections";
  if (!PMP::does_bound_a_volume(mesh)) return "the autorefined part bounds no volume";
  measures.area_after = PMP::area(mesh);
  measures.largest_distance =
      PMP::max_distance_to_triangle_mesh<CGAL::Sequential_tag>(before.points(), mesh);
  to_soup(mesh, out);
  return {};
}

/// The result of `autorefine` as bytes, from the child process to this one.
class Autorefinement_bytes {
 public:
  static std::string write(const std::string& why, const Triangle_soup& out,
                           const Solid_autorefinement& m) {
    Autorefinement_bytes b;
    b.put(why.size());
    b.bytes_ += why;
    for (double x : {m.area_before, m.area_after, m.largest_distance}) b.put(x);
    b.put(out.points.size());
    for (const auto& p : out.points)
      for (int d = 0; d < 3; ++d) b.put(p[d]);
    b.put(out.polygons.size());
    for (const auto& t : out.polygons)
      for (int k = 0; k < 3; ++k) b.put(t.size() == 3 ? t[k] : 0);
    return b.bytes_;
  }
  /// False when the bytes are not a whole result.
  static bool read(const std::string& bytes, std::string& why, Triangle_soup& out,
                   Solid_autorefinement& m) {
    Autorefinement_bytes b;
    b.bytes_ = bytes;
    std::size_t length = 0, points = 0, triangles = 0;
    if (!b.get(length) || length > bytes.size()) return false;
    why = bytes.substr(b.at_, length);
    b.at_ += length;
    if (!b.get(m.area_before) || !b.get(m.area_after) || !b.get(m.largest_distance) ||
        !b.get(points) || points > bytes.size())
      return false;
    out = Triangle_soup();
    for (std::size_t i = 0; i < points; ++i) {
      double x = 0, y = 0, z = 0;
      if (!b.get(x) || !b.get(y) || !b.get(z)) return false;
      out.points.emplace_back(x, y, z);
    }
    if (!b.get(triangles) || triangles > bytes.size()) return false;
    for (std::size_t i = 0; i < triangles; ++i) {
      std::vector<std::size_t> t(3);
      for (std::size_t& v : t)
        if (!b.get(v) || v >= points) return false;
      out.polygons.push_back(std::move(t));
    }
    return b.at_ == bytes.size();
  }

 private:
  template <class T>
  void put(T value) {
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof value);
  }
  template <class T>
  bool get(T& value) {
    if (bytes_.size() - at_ < sizeof value) return false;
    std::memcpy(&value, bytes_.data() + at_, sizeof value);
    at_ += sizeof value;
    return true;
  }
  std::string bytes_;
  std::size_t at_ = 0;
};

}  // namespace solid_union

CGAL_MESH_REPAIR_CORE_INLINE std::string remove_self_intersections_of_solid(
    const Triangle_soup& solid, Triangle_soup& out, Solid_autorefinement& measures) {
  // In a child process (child_process.h): CGAL 5.5's experimental autorefinement crashes on
  // some parts, and the caller then takes the exact arrangement instead.
  const Child_outcome child = run_in_child_process([&solid] {
    Triangle_soup refined;
    Solid_autorefinement m;
    const std::string why = solid_union::autorefine(solid, refined, m);
    return solid_union::Autorefinement_bytes::write(why, refined, m);
  });
  if (!child.finished)
    return "CGAL's autorefinement crashed (signal " + std::to_string(child.signal) + ")";
  std::string why;
  if (!solid_union::Autorefinement_bytes::read(child.bytes, why, out, measures))
    return "CGAL's autorefinement returned no readable result";
  return why;
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_AUTOMATIC_REPAIR_SOLID_UNION_IMPL_H
