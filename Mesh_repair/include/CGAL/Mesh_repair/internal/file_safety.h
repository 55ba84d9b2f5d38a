// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_FILE_SAFETY_H
#define CGAL_MESH_REPAIR_INTERNAL_FILE_SAFETY_H

// What keeps the files of a run safe: an output is never the input (same device and inode, so
// links count), its folder is writable before any work starts, temporary files of processes
// that died (their name carries the PID) are removed by the next write into that folder, and
// CGAL's own prints on std::cerr are silenced while it writes.

#include <CGAL/Mesh_repair/internal/soup_validation.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <dirent.h>
#include <iostream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// The folder holding `path` ("." for a bare name).
inline std::string folder_of(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

/// True when `a` and `b` name the same existing file (device and inode: hard and symbolic
/// links count).
inline bool same_file(const std::string& a, const std::string& b) {
  struct stat sa, sb;
  if (::stat(a.c_str(), &sa) != 0 || ::stat(b.c_str(), &sb) != 0) return false;
  return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

/// Empty when `path` can be written (atomically, through a temporary file in its folder):
/// the folder exists and is writable, and `path` is not a directory or a special file.
inline std::string check_writable(const std::string& path) {
  if (path.empty()) return "empty output file name";
  if (path.back() == '/') return path + ": is a directory, not a file name";
  const std::string folder = folder_of(path);
  struct stat info;
  if (::stat(folder.c_str(), &info) != 0 || !S_ISDIR(info.st_mode))
    return path + ": cannot be written (folder " + folder + " does not exist)";
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    return path + ": cannot be written (folder " + folder + " is not writable)";
  if (::stat(path.c_str(), &info) == 0) {
    if (S_ISDIR(info.st_mode)) return path + ": is a directory";
    if (!S_ISREG(info.st_mode)) return path + ": exists and is not a regular file";
  }
  return {};
}

/// Removes `.tmp-PID-*` files of `path`'s folder whose process no longer exists (a run killed
/// with SIGKILL cannot remove its own). Files of living processes are left alone.
inline void remove_stale_temporaries(const std::string& path) {
  const std::string folder = folder_of(path);
  DIR* dir = ::opendir(folder.c_str());
  if (!dir) return;
  while (const dirent* entry = ::readdir(dir)) {
    const char* name = entry->d_name;
    if (std::strncmp(name, ".tmp-", 5) != 0) continue;
    char* end = nullptr;
    errno = 0;
    const long pid = std::strtol(name + 5, &end, 10);
    if (errno != 0 || end == name + 5 || *end != '-' || pid <= 0) continue;
    if (pid == long(::getpid())) continue;
    if (::kill(pid_t(pid), 0) == 0 || errno != ESRCH) continue;  // alive, or not ours to see
    const std::string stale = (folder == "/" ? std::string() : folder) + "/" + name;
    struct stat info;
    if (::lstat(stale.c_str(), &info) == 0 && S_ISREG(info.st_mode) && info.st_uid == ::getuid())
      ::unlink(stale.c_str());
  }
  ::closedir(dir);
}

/// Sends std::cerr to nowhere while it lives (CGAL's readers and writers print there).
class Silence_cerr {
 public:
  Silence_cerr() : saved_(std::cerr.rdbuf(sink_.rdbuf())) {}
  ~Silence_cerr() { std::cerr.rdbuf(saved_); }
  Silence_cerr(const Silence_cerr&) = delete;
  Silence_cerr& operator=(const Silence_cerr&) = delete;

 private:
  std::ostringstream sink_;
  std::streambuf* saved_;
};

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_FILE_SAFETY_H
