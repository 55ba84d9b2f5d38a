// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "common.h"

#include <CGAL/Mesh_repair/file_safety.h>
#include <CGAL/Mesh_repair/io.h>
#include <CGAL/Mesh_repair/repair_result.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <unistd.h>

extern char** environ;

namespace mesh_repair_cli {

Arguments::Arguments(const std::vector<std::string>& args, const std::set<std::string>& flags,
                     const std::set<std::string>& valued) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.size() > 1 && a[0] == '-' && !(a.size() > 1 && (std::isdigit(a[1]) || a[1] == '.'))) {
      std::string name = a, inline_value;
      const std::size_t eq = a.find('=');
      const bool has_inline = eq != std::string::npos;
      if (has_inline) {
        name = a.substr(0, eq);
        inline_value = a.substr(eq + 1);
      }
      if (flags.count(name) && !has_inline) {
        flags_.insert(name);
      } else if (valued.count(name)) {
        if (has_inline) {
          values_[name].push_back(inline_value);
        } else {
          if (i + 1 >= args.size()) throw Input_error("option " + name + " needs a value");
          values_[name].push_back(args[++i]);
        }
      } else {
        throw Input_error("unknown option " + name + " (see --help)");
      }
    } else {
      positional_.push_back(a);
    }
  }
}

int exit_status(CGAL::Mesh_repair::Repair_status status) {
  switch (status) {
    case CGAL::Mesh_repair::Repair_status::complete:
      return exit_success;
    case CGAL::Mesh_repair::Repair_status::complete_except_kept:
      return exit_complete_except_kept;
    default:
      return exit_incomplete;
  }
}

bool Arguments::has(const std::string& name) const {
  return flags_.count(name) > 0 || values_.count(name) > 0;
}

std::string Arguments::get(const std::string& name, const std::string& fallback) const {
  auto it = values_.find(name);
  return it == values_.end() ? fallback : it->second.back();
}

std::vector<std::string> Arguments::get_all(const std::string& name) const {
  auto it = values_.find(name);
  return it == values_.end() ? std::vector<std::string>() : it->second;
}

double Arguments::get_double(const std::string& name, double fallback) const {
  return has(name) ? parse_double(get(name), name) : fallback;
}

long long Arguments::get_int(const std::string& name, long long fallback) const {
  return has(name) ? parse_int(get(name), name) : fallback;
}

std::string usage_line(const std::string& help) {
  std::string line = help.substr(0, help.find('\n'));
  const std::string prefix = "usage: ";
  if (line.compare(0, prefix.size(), prefix) == 0) line.erase(0, prefix.size());
  return "usage: " + line + " (see --help)";
}

std::string Arguments::single_input(const std::string& usage) const {
  if (positional_.size() == 2 && !has("-o") &&
      !CGAL::Mesh_repair::mesh_format(positional_[1]).empty())
    throw Input_error("expected one input file; did you mean -o " + positional_[1] + "? " +
                      usage_line(usage));
  if (positional_.size() != 1) throw Input_error("expected one input file; " + usage_line(usage));
  const std::string& input = positional_.front();
  check_outputs(input);
  return input;
}

void Arguments::check_outputs(const std::string& input) const {
  namespace MRI = CGAL::Mesh_repair::internal;
  std::vector<std::string> outputs;
  for (const char* option : {"-o", "--report", "--json", "--summary", "--patch-out", "--picture"})
    if (has(option)) outputs.push_back(get(option));
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const std::string& out = outputs[i];
    if (out == input || MRI::same_file(out, input))
      throw Input_error(out +
                        ": is the input file; refusing to overwrite it (choose another "
                        "output)");
    for (std::size_t j = 0; j < i; ++j)
      if (out == outputs[j] || MRI::same_file(out, outputs[j]))
        throw Input_error(out + ": given for two outputs");
    const std::string error = MRI::check_writable(out);
    if (!error.empty()) throw Input_error(error);
  }
}

double parse_double(const std::string& text, const std::string& option) {
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used == text.size() && std::isfinite(v)) return v;
  } catch (const std::exception&) {
  }
  throw Input_error("option " + option + " expects a number, got '" + text + "'");
}

long long parse_int(const std::string& text, const std::string& option) {
  try {
    std::size_t used = 0;
    const long long v = std::stoll(text, &used);
    if (used == text.size()) return v;
  } catch (const std::exception&) {
  }
  throw Input_error("option " + option + " expects an integer, got '" + text + "'");
}

namespace {
// Every file this run read: no save may write over one of them (links included).
std::vector<std::string>& files_read() {
  static std::vector<std::string> files;
  return files;
}

void refuse_to_overwrite_input(const std::string& path) {
  for (const std::string& input : files_read())
    if (path == input || CGAL::Mesh_repair::same_file(path, input))
      throw Input_error(path + ": is the input file; refusing to overwrite it");
}
}  // namespace

void load_mesh(const std::string& path, Mesh& mesh, CGAL::Mesh_repair::Soup_repair_report& report,
               bool remove_zero_volume_walls) {
  files_read().push_back(path);
  CGAL::Mesh_repair::Read_options options;
  options.remove_zero_volume_walls = remove_zero_volume_walls;
  const std::string error = CGAL::Mesh_repair::read_mesh(path, mesh, report, options);
  if (!error.empty()) throw Input_error(error);
}

std::vector<std::string> read_option_file(const std::string& path) {
  namespace MI = CGAL::Mesh_repair::internal;
  files_read().push_back(path);
  std::string error = MI::precheck_file(path);
  if (!error.empty()) throw Input_error(error);
  std::vector<std::string> lines;
  error = MI::read_file_bytes(path, [&](MI::readers::Byte_reader& in) {
    try {
      for (std::string line; in.read_line(line);) lines.push_back(line);
    } catch (const MI::readers::Parse_error& e) {
      return path + ": line " + std::to_string(e.line) + ": " + e.reason;
    } catch (const std::bad_alloc&) {
      return path + ": out of memory while reading";
    }
    return std::string();
  });
  if (!error.empty()) throw Input_error(error);
  return lines;
}

void save_mesh(const std::string& path, const Mesh& mesh, bool binary) {
  refuse_to_overwrite_input(path);
  const std::string error = CGAL::Mesh_repair::write_mesh(path, mesh, binary);
  if (!error.empty()) throw Input_error(error);
}

void save_text(const std::string& path, const std::string& text) {
  refuse_to_overwrite_input(path);
  const std::string error = CGAL::Mesh_repair::write_text_file(path, text);
  if (!error.empty()) throw Input_error(error);
}

std::string describe_soup_repair(const CGAL::Mesh_repair::Soup_repair_report& r) {
  std::ostringstream out;
  auto line = [&](std::size_t n, const char* what) {
    if (n > 0) out << "  " << n << ' ' << what << '\n';
  };
  line(r.points_merged, "duplicated points merged");
  line(r.polygons_simplified, "polygons with repeated points simplified");
  line(r.polygons_split, "pinched polygons split");
  line(r.degenerate_polygons_removed, "degenerate polygons removed");
  line(r.duplicated_polygons_removed, "duplicated polygons removed");
  line(r.zero_volume_walls_removed,
       "zero-volume walls removed whole (duplicated polygons between two shells)");
  if (r.internal_walls_removed > 0)
    out << "  " << r.internal_walls_removed << " internal wall(s) removed whole ("
        << r.internal_wall_polygons_removed
        << " polygons; sheets inside a closed part, on its non-manifold edges)\n";
  line(r.isolated_points_removed, "isolated points removed");
  line(r.non_manifold_edges, "non-manifold edges (split apart)");
  line(r.non_manifold_vertices, "non-manifold vertices (duplicated)");
  line(r.vertices_duplicated, "vertices duplicated to make the soup manifold");
  line(r.polygons_reversed, "polygons reversed to orient the soup");
  line(r.polygons_triangulated, "polygons with more than three sides triangulated");
  line(r.header_lines_skipped, "header lines of no known keyword skipped as free text");
  return out.str();
}

double bbox_diagonal(const Mesh& mesh) {
  if (mesh.number_of_vertices() == 0) return 0;
  const CGAL::Bbox_3 b = CGAL::Polygon_mesh_processing::bbox(mesh);
  const double dx = b.xmax() - b.xmin(), dy = b.ymax() - b.ymin(), dz = b.zmax() - b.zmin();
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

double tolerance_option(const Arguments& args, const Mesh& mesh) {
  if (args.has("--tolerance") && args.has("--tolerance-rel"))
    throw Input_error("give either --tolerance or --tolerance-rel, not both");
  if (args.has("--tolerance")) {
    const std::string text = args.get("--tolerance");
    if (text == "auto") return -1;
    const double x = parse_double(text, "--tolerance");
    if (x < 0) throw Input_error("--tolerance must be non-negative");
    return x;
  }
  if (args.has("--tolerance-rel")) {
    const double f = args.get_double("--tolerance-rel", 0);
    if (f < 0) throw Input_error("--tolerance-rel must be non-negative");
    return f * bbox_diagonal(mesh);
  }
  return -1;
}

namespace {
volatile std::sig_atomic_t interrupted = 0;

extern "C" void on_signal(int signal_number) {
  interrupted = 1;
  const char* pending = CGAL::Mesh_repair::pending_temporary_file();
  if (pending[0] != '\0') ::unlink(pending);
  const char message[] = "\nmesh_repair: interrupted, no output written\n";
  ssize_t ignored = ::write(2, message, sizeof message - 1);
  (void)ignored;
  ::_exit(128 + signal_number);
}
}  // namespace

void install_signal_handlers() {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  std::signal(SIGHUP, on_signal);
  std::signal(SIGPIPE, on_signal);
  std::signal(SIGXFSZ, on_signal);
}

bool progress_wanted(const Arguments& args) {
  return !args.has("--quiet") && ::isatty(2);
}

Progress_bar::Progress_bar(bool enabled) : enabled_(enabled) {}

void Progress_bar::start_step(const char* name) {
  step_ = name;
  start_ = std::chrono::steady_clock::now();
  last_draw_ = start_ - std::chrono::seconds(1);
  if (enabled_) draw(0);
}

bool Progress_bar::progress(double fraction) {
  if (enabled_ && std::chrono::steady_clock::now() - last_draw_ > std::chrono::milliseconds(100))
    draw(fraction);
  return interrupted == 0;
}

void Progress_bar::end_step(const char*) {
  if (!enabled_) return;
  draw(1);
  std::cerr << '\n';
}

void Progress_bar::draw(double fraction) {
  last_draw_ = std::chrono::steady_clock::now();
  const int width = 30;
  const int filled = int(fraction * width + 0.5);
  std::fprintf(stderr, "\r%-24.24s [%.*s%*s] %3d%% %6.1fs", step_.c_str(), filled,
               "##############################", width - filled, "", int(fraction * 100 + 0.5),
               seconds_since(start_));
  std::fflush(stderr);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string script_path(const std::string& file_name) {
#ifdef MESH_REPAIR_SCRIPTS_DIR
  return std::string(MESH_REPAIR_SCRIPTS_DIR) + "/" + file_name;
#else
  return "scripts/" + file_name;
#endif
}

namespace {
std::string python_interpreter() {
  if (const char* chosen = std::getenv("MESH_REPAIR_PYTHON")) return chosen;
  return std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
}

// Runs `argv` without a shell and waits; the exit status, -1 when it did not start or exit.
int run_program(const std::vector<std::string>& argv, bool quiet) {
  std::vector<char*> c_argv;
  for (const std::string& a : argv) c_argv.push_back(const_cast<char*>(a.c_str()));
  c_argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (quiet) {
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
  }
  pid_t pid = 0;
  const int started = ::posix_spawnp(&pid, c_argv[0], &actions, nullptr, c_argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (started != 0) return -1;
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}
}  // namespace

std::string plotting_unavailable() {
  static const std::string reason = [] {
    const std::string python = python_interpreter();
    const int status = run_program({python, "-c", "import matplotlib"}, true);
    if (status == 0) return std::string();
    if (status == -1 || status == 127) return python + " cannot be run";
    return python +
           " has no matplotlib (Debian: python3-matplotlib, scripts/setup.sh --with-plots)";
  }();
  return reason;
}

int run_python_script(const std::string& script, const std::vector<std::string>& args) {
  std::vector<std::string> argv = {python_interpreter(), script};
  argv.insert(argv.end(), args.begin(), args.end());
  return run_program(argv, false);
}

}  // namespace mesh_repair_cli
