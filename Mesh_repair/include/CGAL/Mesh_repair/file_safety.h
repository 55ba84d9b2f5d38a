// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_FILE_SAFETY_H
#define CGAL_MESH_REPAIR_FILE_SAFETY_H

/// \file file_safety.h
/// The file rules of `read_mesh` and `write_mesh`, for an application that writes files of its
/// own beside them (reports, logs): the format a name stands for, whether two names are one file
/// (device and inode, so hard and symbolic links count), whether a path can be written, and an
/// atomic text write (temporary file in the same folder, renamed over the target once complete;
/// stale temporaries of dead processes removed first).

#include <CGAL/Mesh_repair/internal/file_safety.h>
#include <CGAL/Mesh_repair/internal/soup_validation.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace CGAL {
namespace Mesh_repair {

/// The mesh format `filename`'s extension names ("off", "obj", "stl", "ply"), empty for none.
inline std::string mesh_format(const std::string& filename) {
  return internal::format_name(filename);
}

/// True when `a` and `b` name the same existing file.
inline bool same_file(const std::string& a, const std::string& b) {
  return internal::same_file(a, b);
}

/// Empty when `path` can be written atomically, else one line saying why not.
inline std::string check_writable(const std::string& path) {
  return internal::check_writable(path);
}

/// Writes `text` to `path` atomically; empty on success, else one line naming the file and the
/// reason. A reader of `path` sees either the old file or the whole new one.
inline std::string write_text_file(const std::string& path, const std::string& text) {
  const std::string writable = internal::check_writable(path);
  if (!writable.empty()) return writable;
  internal::remove_stale_temporaries(path);
  const std::string temporary = internal::temporary_name_for(path);
  internal::register_temporary_file(temporary);
  bool written = false;
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    written = static_cast<bool>(out);
  }
  const bool renamed = written && std::rename(temporary.c_str(), path.c_str()) == 0;
  if (!renamed) std::remove(temporary.c_str());
  internal::register_temporary_file({});
  if (!written) return path + ": cannot be written";
  if (!renamed) return path + ": cannot be renamed into place";
  return {};
}

/// The temporary file a write in progress holds ("" when none), for a signal handler to unlink
/// (async-signal-safe: a fixed buffer).
inline const char* pending_temporary_file() {
  return internal::pending_temporary_file();
}

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_FILE_SAFETY_H
