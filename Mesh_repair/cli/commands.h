// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef MESH_REPAIR_CLI_COMMANDS_H
#define MESH_REPAIR_CLI_COMMANDS_H

// The table of subcommands. To add one: write cmd_<name>.cpp defining `run_<name>` and
// `<name>_help`, declare them here, add a row to `commands()` in commands.cpp and the file to
// CMakeLists.txt.

#include <string>
#include <vector>

namespace mesh_repair_cli {

struct Command {
  const char* name;
  const char* summary;
  const char* help;
  int (*run)(const std::vector<std::string>& args);
};

const std::vector<Command>& commands();

int run_check(const std::vector<std::string>& args);
extern const char* const check_help;
int run_fill(const std::vector<std::string>& args);
extern const char* const fill_help;
int run_smooth(const std::vector<std::string>& args);
extern const char* const smooth_help;
int run_mesh_points(const std::vector<std::string>& args);
extern const char* const mesh_points_help;
int run_repair(const std::vector<std::string>& args);
extern const char* const repair_help;
int run_bench(const std::vector<std::string>& args);
extern const char* const bench_help;
int run_suppress(const std::vector<std::string>& args);
extern const char* const suppress_help;
int run_stitch(const std::vector<std::string>& args);
extern const char* const stitch_help;
int run_slivers(const std::vector<std::string>& args);
extern const char* const slivers_help;
int run_optimize(const std::vector<std::string>& args);
extern const char* const optimize_help;

}  // namespace mesh_repair_cli

#endif  // MESH_REPAIR_CLI_COMMANDS_H
