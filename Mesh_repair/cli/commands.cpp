// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands.h"

namespace mesh_repair_cli {

const std::vector<Command>& commands() {
  static const std::vector<Command> table = {
      {"check", "report every defect of a mesh (text and JSON)", check_help, run_check},
  };
  return table;
}

}  // namespace mesh_repair_cli
