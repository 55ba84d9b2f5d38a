// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_VISITOR_H
#define CGAL_MESH_REPAIR_VISITOR_H

/// \file visitor.h
/// Progress and cancellation for every Mesh_repair operator. Pass an object with the members of
/// `Default_visitor` through CGAL's `visitor` named parameter, as `std::ref(my_visitor)` so
/// that it is used in place; override only what you need.
/// Operators never print: a command-line tool draws its progress bar from these calls.

#include <CGAL/Mesh_repair/parameters.h>

#include <type_traits>

namespace CGAL {
namespace Mesh_repair {

/// The visitor used when none is given: it ignores every event and never cancels.
struct Default_visitor {
  /// A named step (`"border cycles"`, `"self-intersections"`, ...) begins.
  void start_step(const char* /*name*/) {}
  /// Fraction in [0,1] of the current step done. Returning `false` asks the operator to stop
  /// as soon as it can leave the mesh valid; its result then says it was cancelled.
  bool progress(double /*fraction*/) { return true; }
  /// The named step ends.
  void end_step(const char* /*name*/) {}
};

namespace internal {

// Operators read the visitor with these two lines, so that a visitor passed as `std::ref(v)`
// is used in place (its state survives the call) and one passed by value is copied:
//   Default_visitor default_visitor;
//   auto&& visitor = choose_parameter(get_parameter_reference(np, CGAL::internal_np::visitor),
//                                     default_visitor);

/// Forwards progress at a bounded rate: calls the visitor only when the fraction moved by more
/// than 1/256 since the last call, so inner loops can report every iteration cheaply.
template <class Visitor>
class Progress_reporter {
 public:
  Progress_reporter(Visitor& visitor, std::size_t total) : visitor_(visitor), total_(total) {}
  /// Returns false when the visitor asked to cancel.
  bool operator()(std::size_t done) {
    if (total_ == 0) return true;
    const double fraction = double(done) / double(total_);
    if (fraction - last_ < 1.0 / 256 && done != total_) return !cancelled_;
    last_ = fraction;
    cancelled_ = !visitor_.progress(fraction);
    return !cancelled_;
  }
  bool cancelled() const { return cancelled_; }

 private:
  Visitor& visitor_;
  std::size_t total_;
  double last_ = -1.0;
  bool cancelled_ = false;
};

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_VISITOR_H
