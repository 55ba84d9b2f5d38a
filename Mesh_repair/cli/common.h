// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef MESH_REPAIR_CLI_COMMON_H
#define MESH_REPAIR_CLI_COMMON_H

// What every subcommand of `mesh_repair` shares: the mesh type, option parsing, exit codes,
// loading and atomic saving, the progress bar and SIGINT handling. Subcommands stay thin: they
// parse options, call one library operator and print its result.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
struct Soup_repair_report;
enum class Repair_status;
}  // namespace Mesh_repair
}  // namespace CGAL

namespace mesh_repair_cli {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

/// Exit statuses of every command. `exit_complete_except_kept`: `repair` and `fill` did
/// everything asked and left only what was kept on purpose (holes over the size limits, outlines
/// of open sheets, the input's own self-intersections).
enum Exit_status {
  exit_success = 0,
  exit_incomplete = 1,
  exit_bad_input = 2,
  exit_complete_except_kept = 3
};

/// The exit status of a repair status: complete 0, complete_except_kept 3, incomplete 1.
int exit_status(CGAL::Mesh_repair::Repair_status status);

/// Bad usage or unreadable input: the command prints `what()` on one line and exits with 2.
struct Input_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Options of one command. Each command declares the flags (no value) and the valued options it
/// accepts; anything else is a usage error. Valued options may repeat (`get_all`).
/// The first line of a command's help, for a one-line usage error.
std::string usage_line(const std::string& help);

class Arguments {
 public:
  Arguments(const std::vector<std::string>& args, const std::set<std::string>& flags,
            const std::set<std::string>& valued);
  bool has(const std::string& name) const;
  std::string get(const std::string& name, const std::string& fallback = {}) const;
  std::vector<std::string> get_all(const std::string& name) const;
  double get_double(const std::string& name, double fallback) const;
  long long get_int(const std::string& name, long long fallback) const;
  const std::vector<std::string>& positional() const { return positional_; }
  /// The single input file, or a usage error naming `usage`. Also checks, before any work,
  /// that every output (-o, --report, --json, --summary, --patch-out, --picture) is writable and is
  /// not the input (same device and inode, so links count) nor another output.
  std::string single_input(const std::string& usage) const;
  /// The output checks of `single_input`.
  void check_outputs(const std::string& input) const;

 private:
  std::set<std::string> flags_;
  std::map<std::string, std::vector<std::string>> values_;
  std::vector<std::string> positional_;
};

/// Parses a number or throws Input_error naming the option.
double parse_double(const std::string& text, const std::string& option);
long long parse_int(const std::string& text, const std::string& option);

/// Reads, validates and repairs `path` as a polygon soup into `mesh` (see io.h); throws
/// Input_error with one line on failure. `remove_zero_volume_walls`: see `Read_options`
/// (`repair` sets it; the soup stage of the others is CGAL's reading).
void load_mesh(const std::string& path, Mesh& mesh, CGAL::Mesh_repair::Soup_repair_report& report,
               bool remove_zero_volume_walls = false);

/// The text of a file an option names (`--faces`, `--constraints`), read with the mesh readers'
/// rules: a regular, readable file, not sparse, no NUL or other control byte, lines of at most
/// 64 MB; one line per element of the result, line ends removed. Throws Input_error
/// "FILE: line N: reason". The file counts as an input (no output may overwrite it).
std::vector<std::string> read_option_file(const std::string& path);

/// Writes `mesh` atomically; throws Input_error on failure. `binary` for STL/PLY.
void save_mesh(const std::string& path, const Mesh& mesh, bool binary = false);

/// Writes `text` to `path` atomically (reports); throws Input_error on failure.
void save_text(const std::string& path, const std::string& text);

/// One line per soup-stage change, for the readable summaries.
std::string describe_soup_repair(const CGAL::Mesh_repair::Soup_repair_report& report);

/// The tolerance of `--tolerance X` (absolute) or `--tolerance-rel F` (fraction of the
/// bounding-box diagonal of `mesh`); negative when neither is given (operators then derive it).
double tolerance_option(const Arguments& args, const Mesh& mesh);

/// Length of the bounding-box diagonal.
double bbox_diagonal(const Mesh& mesh);

/// Progress bar on stderr when it is a terminal and `--quiet` is not given; also reports SIGINT
/// as a cancellation. Models the library's visitor (start_step, progress, end_step).
class Progress_bar {
 public:
  explicit Progress_bar(bool enabled);
  void start_step(const char* name);
  bool progress(double fraction);
  void end_step(const char* name);

 private:
  void draw(double fraction);
  bool enabled_;
  std::string step_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

/// True when stderr is a terminal and the user did not ask for quiet.
bool progress_wanted(const Arguments& args);

/// Installs the SIGINT/SIGTERM handler: removes a pending temporary output file and exits 130.
void install_signal_handlers();

/// Seconds since `start`.
double seconds_since(std::chrono::steady_clock::time_point start);

/// The file `file_name` of the source tree's scripts/ folder (plot and picture scripts).
std::string script_path(const std::string& file_name);

/// Why the scripts cannot draw (one line: no interpreter, or no matplotlib), empty when they can.
/// The interpreter is $MESH_REPAIR_PYTHON, else Debian's /usr/bin/python3, which has
/// python3-matplotlib even when another python3 comes first in PATH, else python3 of PATH.
/// Checked once per run.
std::string plotting_unavailable();

/// Runs `script` with that interpreter and `args` (no shell: any character in a path is safe);
/// its exit status, or -1 when it could not be started or was killed.
int run_python_script(const std::string& script, const std::vector<std::string>& args);

}  // namespace mesh_repair_cli

#endif  // MESH_REPAIR_CLI_COMMON_H
