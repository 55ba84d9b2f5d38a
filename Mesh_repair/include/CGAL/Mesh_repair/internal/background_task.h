// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_BACKGROUND_TASK_H
#define CGAL_MESH_REPAIR_INTERNAL_BACKGROUND_TASK_H

// One piece of work run beside the caller's own: on TBB's pool when CGAL is linked with TBB
// (so `tbb::global_control` limits hold: with one thread allowed it runs at `wait()`), inline
// at `run()` otherwise.

#include <CGAL/config.h>

#include <utility>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_group.h>
#endif

namespace CGAL {
namespace Mesh_repair {
namespace internal {

class Background_task {
 public:
  Background_task() = default;
  Background_task(const Background_task&) = delete;
  Background_task& operator=(const Background_task&) = delete;
  ~Background_task() {
    try {
      wait();
    } catch (...) {
      // A destructor must not throw; the owner waits explicitly when it wants the error.
    }
  }

  template <class Work>
  void run(Work&& work) {
#ifdef CGAL_LINKED_WITH_TBB
    group_.run(std::forward<Work>(work));
    running_ = true;
#else
    work();
#endif
  }

  /// Waits for the work; rethrows what it threw. Returns at once when nothing runs.
  void wait() {
#ifdef CGAL_LINKED_WITH_TBB
    if (!running_) return;
    running_ = false;
    group_.wait();
#endif
  }

 private:
#ifdef CGAL_LINKED_WITH_TBB
  tbb::task_group group_;
  bool running_ = false;
#endif
};

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_BACKGROUND_TASK_H
