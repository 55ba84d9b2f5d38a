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

/// CGAL's `self_intersections` on `faces`, stopped after `limit` pairs (0: the default limit
/// of the face count). Sequential: CGAL's Parallel_tag pass collects every candidate pair in a
/// concurrent vector before writing any (no early stop, memory quadratic on these inputs), and
/// costs 2.7x the processor time of the sequential one (bench_check, 1.1 M faces).
template <class FaceRange, class TriangleMesh, class NamedParameters>
Bounded_pairs<std::pair<typename boost::graph_traits<TriangleMesh>::face_descriptor,
                        typename boost::graph_traits<TriangleMesh>::face_descriptor>>
bounded_self_intersections(const FaceRange& face_range, const TriangleMesh& tm, std::size_t limit,
                           const NamedParameters& np) {
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using Pair = std::pair<face_descriptor, face_descriptor>;
  return bounded_pairs<Pair>(
      pair_limit(limit, num_faces(tm)), [&](Bounded_collector<Pair>& collector) {
        CGAL::Polygon_mesh_processing::self_intersections<CGAL::Sequential_tag>(
            face_range, tm, collector.inserter(), np);
      });
}

/// The pairs of CGAL's `self_intersections` over `first` and `second` together that hold a face
/// of `first`: pairs within `first` and pairs of `first` x `second`, stopped after `limit`
/// pairs. Pairs within `second` are not examined: around a patch whose surroundings overlap
/// themselves everywhere (a self-overlapping fan) they are quadratic in number and already known.
/// Two faces are tested by CGAL's own test (a shared vertex or edge is no intersection) and a
/// degenerate face of `first` is a pair with itself, as in `self_intersections`.
template <class TriangleMesh, class VertexPointMap, class GeomTraits>
Bounded_pairs<std::pair<typename boost::graph_traits<TriangleMesh>::face_descriptor,
                        typename boost::graph_traits<TriangleMesh>::face_descriptor>>
bounded_intersections_involving(
    const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& first,
    const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& second,
    const TriangleMesh& tm, std::size_t limit, VertexPointMap vpm, const GeomTraits& traits) {
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using Pair = std::pair<face_descriptor, face_descriptor>;
  using Box =
      CGAL::Box_intersection_d::Box_with_info_d<double, 3, face_descriptor,
                                                CGAL::Box_intersection_d::ID_FROM_BOX_ADDRESS>;
  return bounded_pairs<Pair>(limit, [&](Bounded_collector<Pair>& collector) {
    auto boxes_of = [&](const std::vector<face_descriptor>& faces, bool degenerate_is_a_pair) {
      std::vector<Box> boxes;
      boxes.reserve(faces.size());
      for (face_descriptor f : faces) {
        const auto h = halfedge(f, tm);
        const auto& p = get(vpm, target(h, tm));
        const auto& q = get(vpm, target(next(h, tm), tm));
        const auto& r = get(vpm, source(h, tm));
        if (!traits.collinear_3_object()(p, q, r))
          boxes.emplace_back(p.bbox() + q.bbox() + r.bbox(), f);
        else if (degenerate_is_a_pair)
          collector.add(Pair(f, f));
      }
      return boxes;
    };
    std::vector<Box> first_boxes = boxes_of(first, true), second_boxes = boxes_of(second, false);
    std::vector<const Box*> first_ptr, second_ptr;
    for (const Box& b : first_boxes) first_ptr.push_back(&b);
    for (const Box& b : second_boxes) second_ptr.push_back(&b);
    using Inserter = typename Bounded_collector<Pair>::Inserter;
    CGAL::Polygon_mesh_processing::internal::Strict_intersect_faces<
        Box, TriangleMesh, VertexPointMap, GeomTraits, Inserter>
        test(tm, vpm, traits, collector.inserter());
    const std::ptrdiff_t cutoff = 2000;  // CGAL's own in self_intersections
    CGAL::box_self_intersection_d<CGAL::Sequential_tag>(first_ptr.begin(), first_ptr.end(), test,
                                                        cutoff);
    CGAL::box_intersection_d<CGAL::Sequential_tag>(
        first_ptr.begin(), first_ptr.end(), second_ptr.begin(), second_ptr.end(), test, cutoff);
  });
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
