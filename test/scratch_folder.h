// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef MESH_REPAIR_TEST_SCRATCH_FOLDER_H
#define MESH_REPAIR_TEST_SCRATCH_FOLDER_H

// One scratch folder per test process under the system's temporary folder, removed when the
// process ends. ctest runs each test in its own process, so a folder removed only by the last
// test of a suite would be left behind by all the others.

#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace mesh_repair_test {

/// The folder `<temp>/<prefix><pid>`, created on the first call and removed at exit.
inline std::filesystem::path scratch_folder(const std::string& prefix) {
  struct Folder {
    std::filesystem::path path;
    ~Folder() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Folder folder{std::filesystem::temp_directory_path() /
                             (prefix + std::to_string(::getpid()))};
  std::filesystem::create_directories(folder.path);
  return folder.path;
}

}  // namespace mesh_repair_test

#endif  // MESH_REPAIR_TEST_SCRATCH_FOLDER_H
