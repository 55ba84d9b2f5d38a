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

}  // namespace mesh_repair_cli

#endif  // MESH_REPAIR_CLI_COMMANDS_H
