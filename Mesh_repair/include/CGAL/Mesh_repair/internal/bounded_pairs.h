// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_BOUNDED_PAIRS_H
#define CGAL_MESH_REPAIR_INTERNAL_BOUNDED_PAIRS_H

// Enumerations whose output can be quadratic in the input (intersecting face pairs, coplanar
// overlaps, border gaps, T-junctions) stop after a limit proportional to the element count: a
// self-overlapping {5000/1999} star polygon has 11.9 M intersecting pairs of its 4998 fan
// triangles (110 s, 3 GB before the limit). The first `limit` pairs are kept and the caller
// records that the count is a lower bound. Every step that enumerates such pairs goes through
// this header, so the limit and its meaning are the same everywhere.

#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// Pairs kept by a bounded enumeration over `elements` elements (faces, border vertices):
/// max(100000, 10 x elements). Proportional to the input; a mesh with local defects has far fewer
/// pairs than faces, so only inputs that intersect themselves everywhere reach it.
inline std::size_t default_pair_limit(std::size_t elements) {
  return std::max<std::size_t>(100000, 10 * elements);
}

/// `limit` if set (non-zero), else `default_pair_limit(elements)`.
inline std::size_t pair_limit(std::size_t limit, std::size_t elements) {
  return limit > 0 ? limit : default_pair_limit(elements);
}

/// The pairs an enumeration found: at most its limit; `truncated` when more exist (the count is
/// then a lower bound).
template <class Pair>
struct Bounded_pairs {
  std::vector<Pair> pairs;
  bool truncated = false;
};

/// Collects pairs into `found` up to `limit`; the next one sets `found.truncated` and throws
/// `Pair_limit_reached`, which the enumeration's caller catches right there (CGAL's box passes
/// have no other way to stop early).
template <class Pair>
class Bounded_collector {
 public:
  struct Pair_limit_reached {};

  Bounded_collector(Bounded_pairs<Pair>& found, std::size_t limit) : found_(found), limit_(limit) {}

  void add(Pair pair) {
    if (found_.pairs.size() >= limit_) {
      found_.truncated = true;
      throw Pair_limit_reached();
    }
    found_.pairs.push_back(std::move(pair));
  }
  bool full() const { return found_.truncated; }

  /// An output iterator over `add`, for CGAL functions that write pairs.
  class Inserter {
   public:
    using iterator_category = std::output_iterator_tag;
    using value_type = void;
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    using reference = void;
    explicit Inserter(Bounded_collector* collector) : collector_(collector) {}
    Inserter& operator*() { return *this; }
    Inserter& operator++() { return *this; }
    Inserter operator++(int) { return *this; }
    template <class T>
    Inserter& operator=(T&& pair) {
      collector_->add(Pair(std::forward<T>(pair)));
      return *this;
    }

   private:
    Bounded_collector* collector_;
  };
  Inserter inserter() { return Inserter(this); }

  /// Runs `enumerate(*this)` and stops it at the limit.
  template <class Enumerate>
  void run(Enumerate&& enumerate) {
    try {
      enumerate(*this);
    } catch (const Pair_limit_reached&) {
    }
  }

 private:
  Bounded_pairs<Pair>& found_;
  std::size_t limit_;
};

/// Runs `enumerate(collector)` with a collector of at most `limit` pairs.
template <class Pair, class Enumerate>
Bounded_pairs<Pair> bounded_pairs(std::size_t limit, Enumerate&& enumerate) {
  Bounded_pairs<Pair> found;
  Bounded_collector<Pair> collector(found, limit);
  collector.run(std::forward<Enumerate>(enumerate));
  return found;
}

/// Candidate pairs a filtering enumeration may examine (box pairs whose boxes overlap, of which
/// only a few are kept): `spend()` once per candidate; past `limit` it throws `Exhausted`, which
/// `run` catches, and `exhausted()` tells the caller the enumeration is incomplete. For a box
/// pass over `elements` boxes: `candidate_limit(elements)`, ten times the pair limit.
class Pair_budget {
 public:
  struct Exhausted {};

  explicit Pair_budget(std::size_t limit) : limit_(limit) {}
  void spend() {
    if (++spent_ > limit_) {
      exhausted_ = true;
      throw Exhausted();
    }
  }
  bool exhausted() const { return exhausted_; }
  std::size_t limit() const { return limit_; }

  template <class Enumerate>
  void run(Enumerate&& enumerate) {
    try {
      enumerate();
    } catch (const Exhausted&) {
    }
  }

 private:
  std::size_t limit_, spent_ = 0;
  bool exhausted_ = false;
};

inline std::size_t candidate_limit(std::size_t elements) {
  return 10 * default_pair_limit(elements);
}

/// Intersecting face pairs by CGAL's box passes and CGAL's own test of two faces
/// (`Strict_intersect_faces`: a shared vertex or edge is no intersection), as in
/// `self_intersections`, with two bounds: at most `limit` pairs, and at most
/// `candidate_limit` box pairs examined (the faces' boxes overlap, not always the faces). On a
/// fan of n thin triangles overlapping at its centre nearly every box meets every other:
/// n^2 / 2 candidates (50 M and 25 s for a {9998/3} star) for few pairs. Past either bound the
/// enumeration stops and `truncated` says the count is a lower bound. A degenerate face of
/// `first` is a pair with itself. Sequential: CGAL's Parallel_tag pass collects every candidate
/// pair in a concurrent vector before writing any (no early stop, memory quadratic on these
/// inputs), and costs 2.7x the processor time of the sequential one (bench_check, 1.1 M faces).
template <class TriangleMesh, class VertexPointMap, class GeomTraits>
class Bounded_face_intersections {
 public:
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using Pair = std::pair<face_descriptor, face_descriptor>;

  Bounded_face_intersections(const TriangleMesh& tm, VertexPointMap vpm, const GeomTraits& traits)
      : tm_(tm), vpm_(vpm), traits_(traits) {}

  /// Pairs within `first`, and between `first` and `second` when `second` is given.
  template <class FaceRange>
  Bounded_pairs<Pair> find(const FaceRange& first, const std::vector<face_descriptor>* second,
                           std::size_t limit) const {
    Bounded_pairs<Pair> found;
    Bounded_collector<Pair> collector(found, limit);
    std::vector<Box> first_boxes, second_boxes;
    collector.run([&](Bounded_collector<Pair>& c) {
      first_boxes = boxes_of(first, &c);
      if (second) second_boxes = boxes_of(*second, nullptr);
    });
    if (found.truncated) return found;
    std::vector<const Box*> a = pointers(first_boxes), b = pointers(second_boxes);
    Pair_budget budget(candidate_limit(a.size() + b.size()));
    using Inserter = typename Bounded_collector<Pair>::Inserter;
    const CGAL::Polygon_mesh_processing::internal::Strict_intersect_faces<
        Box, TriangleMesh, VertexPointMap, GeomTraits, Inserter>
        test(tm_, vpm_, traits_, collector.inserter());
    auto examine = [&](const Box* x, const Box* y) {
      budget.spend();
      test(x, y);
    };
    const std::ptrdiff_t cutoff = 2000;  // CGAL's own in self_intersections
    budget.run([&] {
      collector.run([&](Bounded_collector<Pair>&) {
        CGAL::box_self_intersection_d<CGAL::Sequential_tag>(a.begin(), a.end(), examine, cutoff);
        if (second)
          CGAL::box_intersection_d<CGAL::Sequential_tag>(a.begin(), a.end(), b.begin(), b.end(),
                                                         examine, cutoff);
      });
    });
    found.truncated = found.truncated || budget.exhausted();
    return found;
  }

 private:
  using Box =
      CGAL::Box_intersection_d::Box_with_info_d<double, 3, face_descriptor,
                                                CGAL::Box_intersection_d::ID_FROM_BOX_ADDRESS>;

  template <class FaceRange>
  std::vector<Box> boxes_of(const FaceRange& faces, Bounded_collector<Pair>* degenerate) const {
    std::vector<Box> boxes;
    for (face_descriptor f : faces) {
      const auto h = halfedge(f, tm_);
      const auto& p = get(vpm_, target(h, tm_));
      const auto& q = get(vpm_, target(next(h, tm_), tm_));
      const auto& r = get(vpm_, source(h, tm_));
      if (!traits_.collinear_3_object()(p, q, r))
        boxes.emplace_back(p.bbox() + q.bbox() + r.bbox(), f);
      else if (degenerate)
        degenerate->add(Pair(f, f));
    }
    return boxes;
  }
  static std::vector<const Box*> pointers(const std::vector<Box>& boxes) {
    std::vector<const Box*> result;
    result.reserve(boxes.size());
    for (const Box& b : boxes) result.push_back(&b);
    return result;
  }

  const TriangleMesh& tm_;
  VertexPointMap vpm_;
  const GeomTraits& traits_;
};

/// The pairs of intersecting faces of `face_range` (`Bounded_face_intersections`), stopped after
/// `limit` pairs (0: the default limit of the face count) or the candidate limit; `np` may hold
/// `vertex_point_map` and `geom_traits`.
template <class FaceRange, class TriangleMesh, class NamedParameters>
Bounded_pairs<std::pair<typename boost::graph_traits<TriangleMesh>::face_descriptor,
                        typename boost::graph_traits<TriangleMesh>::face_descriptor>>
bounded_self_intersections(const FaceRange& face_range, const TriangleMesh& tm, std::size_t limit,
                           const NamedParameters& np) {
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using GT = typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type;
  using VPM = typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type;
  const GT traits = choose_parameter<GT>(get_parameter(np, CGAL::internal_np::geom_traits));
  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                   get_const_property_map(boost::vertex_point, tm));
  return Bounded_face_intersections<TriangleMesh, VPM, GT>(tm, vpm, traits)
      .find(face_range, nullptr, pair_limit(limit, num_faces(tm)));
}

/// The pairs of `Bounded_face_intersections` over `first` and `second` together that hold a
/// face of `first`: pairs within `first` and pairs of `first` x `second`. Pairs within `second`
/// are not examined: around a patch whose surroundings overlap themselves everywhere (a
/// self-overlapping fan) they are quadratic in number and already known.
template <class TriangleMesh, class VertexPointMap, class GeomTraits>
Bounded_pairs<std::pair<typename boost::graph_traits<TriangleMesh>::face_descriptor,
                        typename boost::graph_traits<TriangleMesh>::face_descriptor>>
bounded_intersections_involving(
    const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& first,
    const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& second,
    const TriangleMesh& tm, std::size_t limit, VertexPointMap vpm, const GeomTraits& traits) {
  return Bounded_face_intersections<TriangleMesh, VertexPointMap, GeomTraits>(tm, vpm, traits)
      .find(first, &second, limit);
}

/// The same on every face of `tm` with its default point map.
template <class TriangleMesh>
auto bounded_self_intersections(const TriangleMesh& tm, std::size_t limit = 0) {
  return bounded_self_intersections(faces(tm), tm, limit, CGAL::parameters::default_values());
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_BOUNDED_PAIRS_H
