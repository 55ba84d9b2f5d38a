// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef MESH_REPAIR_CLI_BATCH_H
#define MESH_REPAIR_CLI_BATCH_H

#include "common.h"

#include <string>
#include <vector>

namespace mesh_repair_cli {

/// `mesh_repair repair --batch IN_DIR --out-dir OUT_DIR [--jobs N] [--timeout S] [options]`:
/// runs `mesh_repair repair` on every mesh file of IN_DIR, each in its own process (a crash, a
/// hang past the timeout or a bad file never stops the others), at most N at once, and writes
/// OUT_DIR/summary.csv and OUT_DIR/summary.jsonl. Exit 0 when every file was repaired
/// completely, 3 when every file was repaired completely or completely but for what was kept on
/// purpose (outcome `repaired_except_kept`), 1 when some were not, 2 on bad usage.
int run_batch_repair(const Arguments& args, const std::vector<std::string>& raw_args);

}  // namespace mesh_repair_cli

#endif  // MESH_REPAIR_CLI_BATCH_H
