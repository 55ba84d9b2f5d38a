// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_VISITOR_H
#define CGAL_MESH_REPAIR_VISITOR_H

/// \file visitor.h
/// Progress and cancellation for every Mesh_repair operator. Pass an object with the members of
/// `Default_visitor` through CGAL's `visitor` named parameter: as `std::ref(my_visitor)` it is
/// used in place (its state survives the call), by value it is copied; override only what you
/// need. Every operator reports its steps with balanced `start_step`/`end_step` calls, also when
/// it is cancelled.
/// Operators never print: a command-line tool draws its progress bar from these calls.

#include <CGAL/Mesh_repair/parameters.h>

#include <functional>
#include <type_traits>
#include <utility>

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

/// A reference to any visitor, of one type: the compiled operators take it, so a visitor of a
/// new type does not instantiate them again. It does not own the visitor it refers to.
class Any_visitor {
 public:
  // Not for Any_visitor itself: a copy refers to the same visitor, not to the copied reference.
  template <class Visitor,
            class = std::enable_if_t<!std::is_same<std::decay_t<Visitor>, Any_visitor>::value>>
  explicit Any_visitor(Visitor& visitor)
      : object_(&visitor),
        start_(&start<Visitor>),
        progress_(&forward_progress<Visitor>),
        end_(&end<Visitor>) {}
  Any_visitor(const Any_visitor&) = default;
  Any_visitor& operator=(const Any_visitor&) = default;

  void start_step(const char* name) { start_(object_, name); }
  bool progress(double fraction) { return progress_(object_, fraction); }
  void end_step(const char* name) { end_(object_, name); }

 private:
  template <class Visitor>
  static void start(void* v, const char* name) {
    static_cast<Visitor*>(v)->start_step(name);
  }
  template <class Visitor>
  static bool forward_progress(void* v, double fraction) {
    return static_cast<Visitor*>(v)->progress(fraction);
  }
  template <class Visitor>
  static void end(void* v, const char* name) {
    static_cast<Visitor*>(v)->end_step(name);
  }
  void* object_;
  void (*start_)(void*, const char*);
  bool (*progress_)(void*, double);
  void (*end_)(void*, const char*);
};

namespace internal {

/// The visitor of a named-parameter pack, ready to be called: the caller's object itself when it
/// was passed as `std::ref(v)` (its state survives the call), a copy when it was passed by value,
/// a `Default_visitor` when none was passed.
///   internal::Visitor_parameter<NamedParameters> visitor(np);
///   run(..., visitor.get());
template <class NamedParameters>
class Visitor_parameter {
  using Reference = decltype(CGAL::parameters::get_parameter_reference(
      std::declval<const NamedParameters&>(), CGAL::internal_np::visitor));
  using Found = std::remove_reference_t<Reference>;
  static constexpr bool absent =
      std::is_same<std::decay_t<Reference>, CGAL::internal_np::Param_not_found>::value;
  // std::ref(v): CGAL hands out a non-const reference, kept; by value: a copy or a const
  // reference into the pack, copied.
  static constexpr bool by_reference =
      std::is_lvalue_reference<Reference>::value && !std::is_const<Found>::value;
  using Stored = std::conditional_t<
      absent, Default_visitor,
      std::conditional_t<by_reference, std::reference_wrapper<Found>, std::decay_t<Found>>>;

 public:
  explicit Visitor_parameter(const NamedParameters& np) : stored_(make(np)) {}
  Any_visitor get() { return Any_visitor(unwrap(stored_)); }

 private:
  static Stored make(const NamedParameters& np) {
    if constexpr (absent) {
      (void)np;
      return Default_visitor();
    } else {
      return Stored(CGAL::parameters::get_parameter_reference(np, CGAL::internal_np::visitor));
    }
  }
  template <class T>
  static T& unwrap(std::reference_wrapper<T> r) {
    return r.get();
  }
  template <class T>
  static T& unwrap(T& t) {
    return t;
  }
  Stored stored_;
};

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
