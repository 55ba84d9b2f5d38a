// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// mesh_repair suppress: feature suppression by hole repair (thesis 6.1) and implant patches
// (thesis 6.2). Removes the selected faces, fills every hole this opens with any fill method and
// optionally writes each fill patch as its own mesh, thickened to a closed solid on request.
#include "commands.h"
#include "common.h"

#include <CGAL/Mesh_repair/suppress_feature.h>
#include <CGAL/Mesh_repair/json_writer.h>
#include <CGAL/Mesh_repair/io.h>
#include <CGAL/Mesh_repair/implant_patch.h>

#include <charconv>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <unordered_set>

namespace mesh_repair_cli {

const char* const suppress_help =
    "usage: mesh_repair suppress IN -o OUT (--faces FILE | --sphere X,Y,Z,R |\n"
    "                           --box X0,Y0,Z0,X1,Y1,Z1) [--method M] [--seed S]\n"
    "                           [--patch-out P.off [--thickness T]] [--report R.json] [--quiet]\n"
    "\n"
    "Feature suppression (thesis 6.1): removes the selected faces of IN and fills every hole\n"
    "this opens with a hole-filling method, so the feature is replaced by a surface predicted\n"
    "from its surroundings. Holes that IN already had are left as they are.\n"
    "\n"
    "  --faces FILE      face indices (0-based, in IN's face order), separated by white space\n"
    "  --sphere X,Y,Z,R  the faces whose centroid lies in this ball\n"
    "  --box X0,Y0,Z0,X1,Y1,Z1  the faces whose centroid lies in this axis-aligned box\n"
    "  --method M        shape_prediction (default), advancing_front, liepa,\n"
    "                    curvature_variation or auto\n"
    "  --seed S          random seed of the randomised methods (default 0)\n"
    "  --patch-out P.off implant patch (thesis 6.2): each fill patch as its own mesh\n"
    "                    (P.off for one hole, P_1.off, P_2.off, ... for several)\n"
    "  --thickness T     thicken each written patch into a closed solid of thickness T, offset\n"
    "                    against the surface normals (into the model)\n"
    "  --report R.json   what was removed and how each hole was filled\n"
    "\n"
    "Exit status: 0 every opened hole filled, 1 some hole left open, 2 bad usage or input.\n";

namespace {

std::vector<double> parse_list(const std::string& text, std::size_t count,
                               const std::string& option) {
  std::vector<double> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) values.push_back(parse_double(item, option));
  if (values.size() != count)
    throw Input_error(option + " needs " + std::to_string(count) + " comma-separated numbers");
  return values;
}

std::vector<Mesh::Face_index> selected_faces(const Arguments& arguments, const Mesh& mesh) {
  const int selectors =
      int(arguments.has("--faces")) + int(arguments.has("--sphere")) + int(arguments.has("--box"));
  if (selectors != 1) throw Input_error("give exactly one of --faces, --sphere, --box");
  std::vector<Mesh::Face_index> faces;
  if (arguments.has("--faces")) {
    const std::string path = arguments.get("--faces");
    const std::vector<std::string> lines = read_option_file(path);
    for (std::size_t number = 0; number < lines.size(); ++number) {
      std::istringstream words(lines[number]);
      for (std::string word; words >> word;) {
        const std::string where = path + ": line " + std::to_string(number + 1) + ": ";
        std::size_t index = 0;
        const auto parsed = std::from_chars(word.data(), word.data() + word.size(), index);
        if (parsed.ec != std::errc() || parsed.ptr != word.data() + word.size())
          throw Input_error(where + "expected a face index, found '" + word.substr(0, 40) + "'");
        if (index >= mesh.number_of_faces())
          throw Input_error(where + "face index " + word + " out of range (the mesh has " +
                            std::to_string(mesh.number_of_faces()) + " faces)");
        faces.push_back(Mesh::Face_index(Mesh::size_type(index)));
      }
    }
    return faces;
  }
  std::function<bool(const Point&)> inside;
  if (arguments.has("--sphere")) {
    const auto s = parse_list(arguments.get("--sphere"), 4, "--sphere");
    inside = [s](const Point& c) {
      return CGAL::squared_distance(c, Point(s[0], s[1], s[2])) <= s[3] * s[3];
    };
  } else {
    const auto b = parse_list(arguments.get("--box"), 6, "--box");
    inside = [b](const Point& c) {
      return c.x() >= b[0] && c.y() >= b[1] && c.z() >= b[2] && c.x() <= b[3] && c.y() <= b[4] &&
             c.z() <= b[5];
    };
  }
  for (auto f : mesh.faces()) {
    const auto h = mesh.halfedge(f);
    const Point c = CGAL::centroid(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
                                   mesh.point(mesh.target(mesh.next(h))));
    if (inside(c)) faces.push_back(f);
  }
  return faces;
}

std::string numbered_path(const std::string& path, std::size_t k, std::size_t count) {
  if (count == 1) return path;
  const auto dot = path.find_last_of('.');
  const std::string stem = dot == std::string::npos ? path : path.substr(0, dot);
  const std::string ext = dot == std::string::npos ? "" : path.substr(dot);
  return stem + "_" + std::to_string(k + 1) + ext;
}

}  // namespace

int run_suppress(const std::vector<std::string>& args) {
  namespace MR = CGAL::Mesh_repair;
  Arguments arguments(args, {"--quiet"},
                      {"-o", "--faces", "--sphere", "--box", "--method", "--seed", "--patch-out",
                       "--thickness", "--report"});
  const std::string input = arguments.single_input(suppress_help);
  if (!arguments.has("-o")) throw Input_error("missing -o OUT");
  MR::Fill_method method = MR::Fill_method::shape_prediction;
  if (arguments.has("--method") && !MR::fill_method_from_string(arguments.get("--method"), method))
    throw Input_error("unknown method '" + arguments.get("--method") + "'");
  const long long seed = arguments.get_int("--seed", 0);
  const double thickness = arguments.get_double("--thickness", 0);
  if (thickness < 0) throw Input_error("--thickness must not be negative");
  if (arguments.has("--thickness") && !arguments.has("--patch-out"))
    throw Input_error("--thickness needs --patch-out");

  Mesh mesh;
  MR::Soup_repair_report soup;
  load_mesh(input, mesh, soup);
  const std::vector<Mesh::Face_index> faces = selected_faces(arguments, mesh);
  if (faces.empty()) throw Input_error("the selection contains no face");

  Progress_bar progress(progress_wanted(arguments));
  auto suppression = MR::suppress_feature(mesh, faces,
                                          MR::parameters::fill_method(method)
                                              .random_seed(static_cast<unsigned int>(seed))
                                              .visitor(std::ref(progress)));
  const std::size_t hole_count = suppression.holes_opened;
  const std::vector<MR::Hole_fill_report>& reports = suppression.holes;
  const std::vector<MR::Fill_patch<Mesh>>& patches = suppression.patches;
  // The implants are taken out before the garbage is collected: that renumbers the faces.
  std::vector<Mesh> implants;
  if (arguments.has("--patch-out")) {
    for (std::size_t k = 0; k < patches.size(); ++k) {
      if (!reports[k].filled || patches[k].faces.empty()) continue;
      implants.push_back(MR::extract_patch(mesh, patches[k].faces));
      if (thickness > 0) implants.back() = MR::thicken_patch(implants.back(), thickness);
    }
  }
  mesh.collect_garbage();
  save_mesh(arguments.get("-o"), mesh);

  std::size_t open = 0, written = 0;
  for (const auto& r : reports) open += (!r.filled && !r.skipped) ? 1 : 0;
  std::cout << input << ": removed " << faces.size() << " faces, opened " << hole_count
            << " holes, filled " << hole_count - open << " with " << MR::to_string(method) << "\n";
  for (std::size_t k = 0; k < reports.size(); ++k) {
    const auto& r = reports[k];
    if (!r.filled && !r.skipped)
      std::cout << "  hole " << k + 1 << " left open: " << r.failure << "\n";
    for (const auto& f : r.fallbacks) std::cout << "  hole " << k + 1 << " fallback: " << f << "\n";
  }
  if (arguments.has("--patch-out")) {
    for (const Mesh& implant : implants) {
      save_mesh(numbered_path(arguments.get("--patch-out"), written, implants.size()), implant);
      ++written;
    }
    std::cout << "wrote " << written << " implant patch" << (written == 1 ? "" : "es") << "\n";
  }
  if (arguments.has("--report")) {
    std::ostringstream text;
    MR::Json_writer json(text);
    json.begin_object();
    json.key("input").value(input);
    json.key("removed_faces").value(faces.size());
    json.key("method").value(MR::to_string(method));
    json.key("holes").begin_array();
    for (const auto& r : reports) {
      json.begin_object();
      json.key("filled").value(r.filled);
      json.key("used").value(MR::to_string(r.used));
      json.key("border_edges").value(r.border_edges);
      json.key("faces_created").value(r.faces_created);
      json.key("vertices_created").value(r.vertices_created);
      json.key("failure").value(r.failure);
      json.key("seconds").value(r.seconds);
      json.end_object();
    }
    json.end_array();
    json.key("implant_patches_written").value(written);
    json.end_object();
    save_text(arguments.get("--report"), text.str());
  }
  return open == 0 ? exit_success : exit_incomplete;
}

}  // namespace mesh_repair_cli
