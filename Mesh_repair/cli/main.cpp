// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// mesh_repair: repairs defective triangle meshes and fills their holes. One subcommand per
// library operator; each lives in its own cmd_<name>.cpp so the heavy templates of one
// operator are compiled once, in parallel with the others.

#include "commands.h"
#include "common.h"

#include <CGAL/exceptions.h>

#include <cstring>
#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

namespace {

// A message on one line: line breaks become "; ".
std::string one_line(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  std::string out;
  for (char c : text) {
    if (c == '\n')
      out += "; ";
    else if (c != '\r')
      out += c;
  }
  return out;
}

void print_usage(std::ostream& out) {
  out << "usage: mesh_repair COMMAND [options]\n\ncommands:\n";
  for (const auto& command : mesh_repair_cli::commands())
    out << "  " << command.name
        << std::string(12 - std::min<std::size_t>(11, std::strlen(command.name)), ' ')
        << command.summary << '\n';
  out << "\nmesh_repair COMMAND --help describes a command.\n"
         "Exit status: 0 success, 1 defects remain or operation incomplete, 2 bad usage or "
         "input,\n3 (repair, fill) complete except what was kept on purpose (listed).\n";
}

}  // namespace

int main(int argc, char** argv) {
  using namespace mesh_repair_cli;
  install_signal_handlers();
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    print_usage(argc < 2 ? std::cerr : std::cout);
    return argc < 2 ? exit_bad_input : exit_success;
  }
  const std::string name = argv[1];
  const std::vector<std::string> args(argv + 2, argv + argc);
  for (const auto& command : commands()) {
    if (name != command.name) continue;
    if (!args.empty() && (args[0] == "--help" || args[0] == "-h")) {
      std::cout << command.help;
      return exit_success;
    }
    try {
      return command.run(args);
    } catch (const Input_error& e) {
      std::cerr << "mesh_repair " << name << ": " << e.what() << '\n';
      return exit_bad_input;
    } catch (const std::bad_alloc&) {
      std::cerr << "mesh_repair " << name << ": out of memory\n";
      return exit_bad_input;
    } catch (const CGAL::Failure_exception& e) {
      // CGAL's text spans several lines (expression, file, line); ours is one.
      std::cerr << "mesh_repair " << name << ": internal error: a CGAL check failed ("
                << one_line(e.expression().empty() ? e.message() : e.expression()) << ")\n";
      return exit_bad_input;
    } catch (const std::exception& e) {
      std::cerr << "mesh_repair " << name << ": error: " << one_line(e.what()) << '\n';
      return exit_bad_input;
    } catch (...) {
      std::cerr << "mesh_repair " << name << ": error: unknown exception\n";
      return exit_bad_input;
    }
  }
  std::cerr << "mesh_repair: unknown command '" << name << "' (see mesh_repair --help)\n";
  return exit_bad_input;
}
