// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_CHILD_PROCESS_H
#define CGAL_MESH_REPAIR_INTERNAL_CHILD_PROCESS_H

// A dependency call that can crash the process, run in a forked child: CGAL 5.5's experimental
// autorefinement ends in a segmentation fault on some closed parts (its output builder, on a
// radio model of Debian's sweethome3d-furniture; CGAL issue 3183, fixed only by CGAL 6's
// `autorefine_triangle_soup`). A crash there ends the child, and the caller takes another way.
// The child runs one sequential computation on a copy-on-write image of the process, writes its
// result to a pipe and leaves with `_exit` (no destructor, no atexit handler of the parent runs).

#include <cerrno>
#include <cstdio>
#include <functional>
#include <string>

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(undefined_behavior_sanitizer)
#define CGAL_MESH_REPAIR_SANITIZED 1
#endif
#elif defined(__SANITIZE_ADDRESS__)
#define CGAL_MESH_REPAIR_SANITIZED 1
#endif
#ifdef CGAL_MESH_REPAIR_SANITIZED
#include <sanitizer/common_interface_defs.h>
#endif

#if defined(__unix__) || defined(__APPLE__)
#include <csignal>
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#define CGAL_MESH_REPAIR_HAS_FORK 1
#endif

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// How `run_in_child_process` ended: `finished` with the bytes `work` returned, or not, with
/// the signal that ended the child (0 when it exited otherwise).
struct Child_outcome {
  bool finished = false;
  int signal = 0;
  std::string bytes;
};

#ifdef CGAL_MESH_REPAIR_HAS_FORK
inline bool write_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += std::size_t(n);
  }
  return true;
}

inline std::string read_all(int fd) {
  std::string bytes;
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    bytes.append(buffer, std::size_t(n));
  }
  return bytes;
}
#endif

/// Runs `work` in a child process and returns what it returned. Where processes cannot be
/// forked (another system, or `fork` fails), `work` runs in this process.
inline Child_outcome run_in_child_process(const std::function<std::string()>& work) {
  Child_outcome outcome;
#ifdef CGAL_MESH_REPAIR_HAS_FORK
  int fds[2];
  if (::pipe(fds) == 0) {
    std::fflush(nullptr);  // nothing buffered is written twice
    const pid_t pid = ::fork();
    if (pid == 0) {
      ::close(fds[0]);
      const struct rlimit no_core = {0, 0};
      ::setrlimit(RLIMIT_CORE, &no_core);  // a crash leaves no core file behind
      // nor a message: glibc's "free(): invalid next size" from inside the dependency means
      // nothing to the user, whose report says what crashed.
      const int null = ::open("/dev/null", O_WRONLY);
      if (null >= 0) {
        ::dup2(null, 2);
        ::close(null);
      }
#ifdef CGAL_MESH_REPAIR_SANITIZED
      // A sanitizer's finding in the child is a crash of the dependency, which the child is
      // there to contain: it ends the child as the crash would in a release build, instead of
      // running the fuzzer's death callback, which would report it as the parent's.
      __sanitizer_set_death_callback([] {
        std::signal(SIGSEGV, SIG_DFL);
        std::raise(SIGSEGV);
      });
#endif
      bool written = false;
      try {
        written = write_all(fds[1], work());
      } catch (...) {
      }
      ::_exit(written ? 0 : 1);
    }
    ::close(fds[1]);
    if (pid > 0) {
      outcome.bytes = read_all(fds[0]);
      ::close(fds[0]);
      int status = 0;
      while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      outcome.finished = WIFEXITED(status) && WEXITSTATUS(status) == 0;
      outcome.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
      if (!outcome.finished) outcome.bytes.clear();
      return outcome;
    }
    ::close(fds[0]);
  }
#endif
  outcome.bytes = work();
  outcome.finished = true;
  return outcome;
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_CHILD_PROCESS_H
