// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_MESH_ACCESS_H
#define CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_MESH_ACCESS_H

// What every detection step reads: the mesh, its point map, traits and index maps, bundled once
// so each step is a short function of one argument.

#include <CGAL/Mesh_repair/defect_report.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cstddef>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace detect {

template <class PolygonMesh, class VertexPointMap, class GeomTraits, class VertexIndexMap,
          class FaceIndexMap, class HalfedgeIndexMap>
struct Mesh_access {
  using Mesh = PolygonMesh;
  using Traits = GeomTraits;
  using Point = typename GeomTraits::Point_3;
  using Graph_traits = boost::graph_traits<PolygonMesh>;
  using vertex_descriptor = typename Graph_traits::vertex_descriptor;
  using halfedge_descriptor = typename Graph_traits::halfedge_descriptor;
  using face_descriptor = typename Graph_traits::face_descriptor;

  const PolygonMesh& pm;
  VertexPointMap vpm;
  GeomTraits gt;
  VertexIndexMap vim;
  FaceIndexMap fim;
  HalfedgeIndexMap him;

  decltype(auto) point(vertex_descriptor v) const { return get(vpm, v); }
  std::size_t index(vertex_descriptor v) const { return std::size_t(get(vim, v)); }
  std::size_t index(face_descriptor f) const { return std::size_t(get(fim, f)); }
  std::size_t index(halfedge_descriptor h) const { return std::size_t(get(him, h)); }

  Coordinates coordinates(vertex_descriptor v) const {
    const auto& p = point(v);
    return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  }
  Coordinates centroid(face_descriptor f) const {
    Coordinates sum{0, 0, 0};
    std::size_t n = 0;
    for (halfedge_descriptor h : halfedges_around_face(halfedge(f, pm), pm)) {
      const Coordinates c = coordinates(target(h, pm));
      for (int i = 0; i < 3; ++i) sum[i] += c[i];
      ++n;
    }
    for (int i = 0; i < 3; ++i) sum[i] /= double(n == 0 ? 1 : n);
    return sum;
  }
  bool is_triangle_face(face_descriptor f) const {
    const halfedge_descriptor h = halfedge(f, pm);
    return next(next(next(h, pm), pm), pm) == h;
  }
  Face_pair face_pair(face_descriptor f, face_descriptor g) const {
    Face_pair pair;
    pair.first = index(f);
    pair.second = index(g);
    pair.first_centroid = centroid(f);
    pair.second_centroid = centroid(g);
    if (pair.second < pair.first) {
      std::swap(pair.first, pair.second);
      std::swap(pair.first_centroid, pair.second_centroid);
    }
    return pair;
  }
};

}  // namespace detect
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_DETECT_DEFECTS_MESH_ACCESS_H
