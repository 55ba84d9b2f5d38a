// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "batch.h"

#include <CGAL/Mesh_repair/file_safety.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>
#include <sys/wait.h>
#include <unistd.h>

namespace mesh_repair_cli {
namespace {

namespace fs = std::filesystem;

struct Job {
  fs::path input, output, report, summary, log;
  pid_t pid = -1;
  std::chrono::steady_clock::time_point start;
  int status = -1;  ///< exit status of the child, or -1 when it did not exit normally
  /// "repaired", "repaired_except_kept", "incomplete", "failed", "crashed", "timeout"
  std::string outcome;
  double seconds = 0;
  std::map<std::string, std::string> figures;  ///< from the child's summary file
  std::string note;                            ///< why an entry was not run
};

// Options passed on to each child: everything but the batch options themselves.
std::vector<std::string> child_options(const std::vector<std::string>& raw) {
  static const std::set<std::string> batch_only = {"--batch", "--out-dir", "--jobs",   "--timeout",
                                                   "-o",      "--report",  "--summary"};
  std::vector<std::string> kept;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    const std::string name = raw[i].substr(0, raw[i].find('='));
    if (batch_only.count(name)) {
      if (raw[i].find('=') == std::string::npos) ++i;  // skip its value too
      continue;
    }
    kept.push_back(raw[i]);
  }
  kept.push_back("--quiet");
  return kept;
}

// Every entry of the folder, sorted. Mesh files are repaired; the others get a summary row
// without a run: "skipped" (another extension, a folder) or "failed" (a mesh name that is not
// a regular file, such as a link to /dev/zero, or a dangling link).
std::vector<fs::path> folder_entries(const fs::path& folder) {
  std::vector<fs::path> entries;
  for (const auto& entry : fs::directory_iterator(folder)) entries.push_back(entry.path());
  std::sort(entries.begin(), entries.end());
  return entries;
}

// Why `file` is not run, or an empty string when it is.
std::string not_run_reason(const fs::path& file, std::string& outcome) {
  std::error_code error;
  const fs::file_status status = fs::status(file, error);
  const bool mesh_name = !CGAL::Mesh_repair::mesh_format(file.string()).empty();
  if (!mesh_name || fs::is_directory(status)) {
    outcome = "skipped";
    return fs::is_directory(status) ? "a folder" : "not a mesh file (.off .obj .stl .ply)";
  }
  outcome = "failed";
  if (error || !fs::exists(status)) return "a dangling link";
  if (!fs::is_regular_file(status)) return "not a regular file";
  outcome.clear();
  return {};
}

pid_t start_child(Job& job, const std::vector<std::string>& options) {
  std::vector<std::string> words = {
      "mesh_repair",       "repair",    job.input.string(),  "-o", job.output.string(), "--report",
      job.report.string(), "--summary", job.summary.string()};
  words.insert(words.end(), options.begin(), options.end());
  job.start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid != 0) return pid;
  // Child: its output goes to a log beside the report.
  std::FILE* log = std::fopen(job.log.c_str(), "w");
  if (log) {
    ::dup2(::fileno(log), 1);
    ::dup2(::fileno(log), 2);
  }
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(&w[0]);
  argv.push_back(nullptr);
  ::execv("/proc/self/exe", argv.data());
  ::_exit(127);
}

void read_figures(Job& job) {
  std::ifstream in(job.summary);
  std::string line;
  while (std::getline(in, line)) {
    const std::size_t eq = line.find('=');
    if (eq != std::string::npos) job.figures[line.substr(0, eq)] = line.substr(eq + 1);
  }
  std::error_code ignored;
  fs::remove(job.summary, ignored);
}

void finish(Job& job, int raw_status, bool timed_out) {
  job.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - job.start).count();
  if (timed_out) {
    job.outcome = "timeout";
  } else if (WIFEXITED(raw_status)) {
    job.status = WEXITSTATUS(raw_status);
    job.outcome = job.status == exit_success                ? "repaired"
                  : job.status == exit_complete_except_kept ? "repaired_except_kept"
                  : job.status == exit_incomplete           ? "incomplete"
                                                            : "failed";
  } else {
    job.outcome = "crashed";
  }
  read_figures(job);
}

const std::vector<std::string> figure_keys = {"repair_status",
                                              "faces_before",
                                              "faces_after",
                                              "holes",
                                              "holes_filled",
                                              "holes_failed",
                                              "holes_too_large",
                                              "sheet_borders_left_open",
                                              "border_cycles_after",
                                              "closed",
                                              "valid",
                                              "manifold",
                                              "self_intersections_before",
                                              "self_intersections_after",
                                              "only_holes_before"};

void write_summaries(const fs::path& out_dir, const std::vector<Job>& jobs) {
  std::ostringstream csv, jsonl;
  csv << "file,outcome,exit_status,seconds";
  for (const auto& k : figure_keys) csv << ',' << k;
  csv << ",note\n";
  for (const Job& job : jobs) {
    csv << job.input.filename().string() << ',' << job.outcome << ',' << job.status << ','
        << job.seconds;
    jsonl << "{\"file\":\"" << job.input.filename().string() << "\",\"outcome\":\"" << job.outcome
          << "\",\"exit_status\":" << job.status << ",\"seconds\":" << job.seconds;
    for (const auto& k : figure_keys) {
      auto it = job.figures.find(k);
      const std::string value = it == job.figures.end() ? "" : it->second;
      csv << ',' << value;
      const bool text = k == "repair_status" && !value.empty();
      jsonl << ",\"" << k << "\":" << (value.empty() ? "null" : text ? '"' + value + '"' : value);
    }
    csv << ',' << job.note << '\n';
    jsonl << ",\"note\":\"" << job.note << "\"}\n";
  }
  save_text((out_dir / "summary.csv").string(), csv.str());
  save_text((out_dir / "summary.jsonl").string(), jsonl.str());
}

}  // namespace

int run_batch_repair(const Arguments& args, const std::vector<std::string>& raw_args) {
  const fs::path in_dir = args.get("--batch");
  const fs::path out_dir = args.get("--out-dir");
  if (out_dir.empty()) throw Input_error("--batch needs --out-dir OUT_DIR");
  if (!fs::is_directory(in_dir)) throw Input_error(in_dir.string() + ": not a directory");
  if (!args.positional().empty()) throw Input_error("--batch takes no input file");
  const long long jobs_at_once = args.get_int("--jobs", 1);
  const double timeout = args.get_double("--timeout", 600);
  if (jobs_at_once < 1) throw Input_error("--jobs must be at least 1");
  if (timeout <= 0) throw Input_error("--timeout must be positive");
  fs::create_directories(out_dir);
  if (fs::equivalent(in_dir, out_dir))
    throw Input_error("--out-dir must differ from the input folder");

  const std::vector<std::string> options = child_options(raw_args);
  std::vector<Job> jobs;
  std::size_t not_run = 0;
  for (const fs::path& file : folder_entries(in_dir)) {
    Job job;
    job.input = file;
    job.note = not_run_reason(file, job.outcome);
    if (!job.note.empty()) {
      job.status = job.outcome == "failed" ? int(exit_bad_input) : -1;
      ++not_run;
      jobs.push_back(job);
      continue;
    }
    job.output = out_dir / file.filename();
    // Named after the whole file name: sphere.off, sphere.ply and sphere.stl are three jobs.
    const std::string name = file.filename().string();
    job.report = out_dir / (name + ".report.json");
    job.summary = out_dir / ("." + name + ".summary");
    job.log = out_dir / (name + ".log");
    jobs.push_back(job);
  }
  std::cout << "batch: " << jobs.size() - not_run << " mesh files in " << in_dir.string() << " ("
            << not_run << " other entries listed, not run), " << jobs_at_once << " at once\n";

  std::size_t next = 0, running = 0, done = not_run;
  while (done < jobs.size()) {
    while (running < std::size_t(jobs_at_once) && next < jobs.size()) {
      if (jobs[next].note.empty()) {
        jobs[next].pid = start_child(jobs[next], options);
        ++running;
      }
      ++next;
    }
    for (Job& job : jobs) {
      if (job.pid <= 0) continue;
      int raw = 0;
      const pid_t got = ::waitpid(job.pid, &raw, WNOHANG);
      const bool timed_out =
          got == 0 &&
          std::chrono::duration<double>(std::chrono::steady_clock::now() - job.start).count() >
              timeout;
      if (timed_out) {
        ::kill(job.pid, SIGKILL);
        ::waitpid(job.pid, &raw, 0);
      }
      if (got == 0 && !timed_out) continue;
      finish(job, raw, timed_out);
      job.pid = -1;
      --running;
      ++done;
      std::cout << "[" << done << "/" << jobs.size() << "] " << job.input.filename().string()
                << ": " << job.outcome << " (" << job.seconds << " s)\n"
                << std::flush;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  write_summaries(out_dir, jobs);
  std::map<std::string, int> outcomes;
  for (const Job& job : jobs) ++outcomes[job.outcome];
  std::cout << "batch done:";
  for (const auto& o : outcomes) std::cout << ' ' << o.second << ' ' << o.first;
  std::cout << "\nsummary: " << (out_dir / "summary.csv").string() << ", "
            << (out_dir / "summary.jsonl").string() << '\n';
  const int complete = outcomes["repaired"] + outcomes["skipped"];
  if (complete == int(jobs.size())) return exit_success;
  return complete + outcomes["repaired_except_kept"] == int(jobs.size()) ? exit_complete_except_kept
                                                                         : exit_incomplete;
}

}  // namespace mesh_repair_cli
