// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// mesh_repair._core: the Python side of the binding. Checks and copies the caller's arrays (the
// caller's arrays are never written), releases the GIL while operators.cpp works, polls for
// Ctrl-C and calls the progress callback from the library's visitor, and returns new numpy
// arrays that own their C++ buffers (no copy on the way out). The public API, with its defaults
// and documentation, is mesh_repair/__init__.py.
#include "binding.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cstring>
#include <sstream>

namespace py = pybind11;

namespace mesh_repair_python {
namespace {

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

// ---- the visitor -------------------------------------------------------------------------

Python_visitor::Python_visitor() : caller_(std::this_thread::get_id()) {}

Python_visitor::~Python_visitor() {
  if (!error) return;
  py::gil_scoped_acquire gil;
  delete static_cast<py::error_already_set*>(error);
}

void Python_visitor::start_step(const char* name) {
  step_ = name;
  poll(name, 0, true);
}

bool Python_visitor::progress(double fraction) {
  return poll(step_.c_str(), fraction, false);
}

void Python_visitor::end_step(const char* name) {
  poll(name, 1, true);
}

// Takes the GIL at most every 50 ms (step boundaries always), and only on the calling thread:
// Python runs signal handlers on the main thread only, and parallel steps call from workers.
bool Python_visitor::poll(const char* step, double fraction, bool force) {
  if (cancelled_) return false;
  if (std::this_thread::get_id() != caller_) return true;
  const double now = now_seconds();
  if (!force && now - last_poll_ < 0.05) return true;
  last_poll_ = now;
  py::gil_scoped_acquire gil;
  try {
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (callback) py::handle(static_cast<PyObject*>(callback))(step, fraction);
  } catch (py::error_already_set& e) {
    error = new py::error_already_set(std::move(e));
    cancelled_ = true;
  }
  return !cancelled_;
}

namespace {

// ---- arrays in -----------------------------------------------------------------------------

std::string shape_text(const py::array& a) {
  std::ostringstream out;
  out << '(';
  for (py::ssize_t i = 0; i < a.ndim(); ++i) out << (i ? ", " : "") << a.shape(i);
  out << (a.ndim() == 1 ? ",)" : ")");
  return out.str();
}

std::string dtype_text(const py::array& a) {
  return py::str(a.dtype()).cast<std::string>();
}

char dtype_kind(const py::array& a) {
  return a.dtype().attr("kind").cast<std::string>()[0];
}

// The readers' limit (internal/readers/byte_reader.h): CGAL's soup repair and orientation are
// not linear in a polygon's size, so a huge polygon would stall the call.
void check_polygon_size(std::size_t face, std::size_t size) {
  namespace readers = CGAL::Mesh_repair::internal::readers;
  if (size <= readers::max_polygon_vertices) return;
  throw Input_error("faces: face " + std::to_string(face) + ": a face of " + std::to_string(size) +
                    " vertices exceeds the limit of " +
                    std::to_string(readers::max_polygon_vertices) + " vertices per face");
}

// np.asarray(object), or ValueError naming the argument.
py::array as_array(const py::object& object, const char* what) {
  try {
    return py::module_::import("numpy").attr("asarray")(object);
  } catch (py::error_already_set&) {
    throw Input_error(std::string(what) + " cannot be read as an array");
  }
}

// `what`: "vertices", or "points" for a point set.
py::array_t<double, py::array::c_style> vertex_array(const py::object& object,
                                                     const std::string& what = "vertices") {
  const py::array a = as_array(object, what.c_str());
  const char kind = dtype_kind(a);
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw Input_error(what + " must hold real numbers (float64), got dtype " + dtype_text(a));
  if (a.ndim() != 2 || a.shape(1) != 3)
    throw Input_error(what + " must be an array of shape (n, 3), got shape " + shape_text(a));
  return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
}

py::array_t<std::int64_t, py::array::c_style> face_array(const py::array& a) {
  const char kind = dtype_kind(a);
  if (kind != 'i' && kind != 'u')
    throw Input_error("faces must hold integers (vertex indices), got dtype " + dtype_text(a));
  if (a.ndim() != 2 || (a.shape(1) < 3 && a.shape(0) > 0))
    throw Input_error("faces must be an array of shape (m, 3) (or (m, k), k >= 3), got shape " +
                      shape_text(a));
  if (a.shape(0) > 0) check_polygon_size(0, std::size_t(a.shape(1)));
  return py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
}

std::string negative_index(std::size_t face, std::int64_t index, std::size_t vertices) {
  std::ostringstream out;
  out << "input arrays: face " << face << " refers to vertex " << index << " but there are only "
      << vertices << " vertices";
  return out.str();
}

// A list of polygons of any sizes; those with fewer than three vertices are counted as a file's
// short faces are (degenerate polygons removed).
void read_polygon_list(const py::sequence& faces, std::size_t vertices, Soup& soup) {
  soup.polygons.reserve(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const py::object polygon = faces[f];
    if (!py::isinstance<py::sequence>(polygon) || py::isinstance<py::str>(polygon))
      throw Input_error("faces: polygon " + std::to_string(f) +
                        " is not a sequence of vertex indices");
    const auto items = py::reinterpret_borrow<py::sequence>(polygon);
    check_polygon_size(f, items.size());
    std::vector<std::size_t> corners;
    for (const py::handle item : items) {
      // Booleans are integers to Python and numpy, not vertex indices.
      if (!PyIndex_Check(item.ptr()) || PyBool_Check(item.ptr()) ||
          std::strcmp(Py_TYPE(item.ptr())->tp_name, "numpy.bool_") == 0)
        throw Input_error("faces: polygon " + std::to_string(f) + " holds a non-integer (" +
                          py::repr(item).cast<std::string>() + ")");
      const auto integer = py::reinterpret_steal<py::object>(PyNumber_Index(item.ptr()));
      if (!integer) {  // an __index__ that refuses, e.g. a numpy array of several items
        PyErr_Clear();
        throw Input_error("faces: polygon " + std::to_string(f) + " holds a non-integer (" +
                          py::repr(item).cast<std::string>() + ")");
      }
      const long long index = PyLong_AsLongLong(integer.ptr());
      if (index == -1 && PyErr_Occurred()) throw py::error_already_set();
      if (index < 0) throw Input_error(negative_index(f, index, vertices));
      corners.push_back(std::size_t(index));
    }
    if (corners.size() < 3)
      ++soup.short_polygons_skipped;
    else
      soup.polygons.push_back(std::move(corners));
  }
}

// The caller's mesh: a path, or (vertices, faces). The numeric arrays are checked here (with the
// GIL) and copied by `copy_arrays` (without it).
struct Source {
  Mesh_input input;
  py::array_t<double, py::array::c_style> vertices;
  py::array_t<std::int64_t, py::array::c_style> faces;
  bool face_array_given = false;
};

bool read_path(const py::object& source, Source& s) {
  if (!py::isinstance<py::str>(source)) return false;
  s.input.path = source.cast<std::string>();
  if (s.input.path.empty()) throw Input_error("the path is empty");
  return true;
}

Source read_source(const py::object& source) {
  Source s;
  if (read_path(source, s)) return s;
  const py::tuple pair = source.cast<py::tuple>();
  s.vertices = vertex_array(pair[0]);
  const py::object faces = pair[1];
  if (py::isinstance<py::array>(faces)) {
    s.faces = face_array(faces);
    s.face_array_given = true;
  } else if (py::isinstance<py::sequence>(faces) && !py::isinstance<py::str>(faces)) {
    read_polygon_list(faces, std::size_t(s.vertices.shape(0)), s.input.soup);
  } else {
    throw Input_error("faces must be an integer array of shape (m, 3) or a list of polygons");
  }
  return s;
}

// A point set: a path, or an (n, 3) array (copied by `copy_arrays`, without faces).
Source read_points_source(const py::object& source) {
  Source s;
  if (!read_path(source, s)) s.vertices = vertex_array(source, "points");
  return s;
}

void copy_arrays(Source& s) {
  if (!s.input.path.empty()) return;
  const std::size_t n = std::size_t(s.vertices.shape(0));
  const double* xyz = s.vertices.data();
  s.input.soup.points.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    s.input.soup.points.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
  if (!s.face_array_given) return;
  const std::size_t m = std::size_t(s.faces.shape(0)), k = std::size_t(s.faces.shape(1));
  const std::int64_t* corners = s.faces.data();
  s.input.soup.polygons.resize(m);
  for (std::size_t f = 0; f < m; ++f) {
    auto& polygon = s.input.soup.polygons[f];
    polygon.resize(k);
    for (std::size_t c = 0; c < k; ++c) {
      const std::int64_t index = corners[f * k + c];
      if (index < 0) throw Input_error(negative_index(f, index, n));
      polygon[c] = std::size_t(index);
    }
  }
}

// ---- arrays out ----------------------------------------------------------------------------

template <class T>
py::array_t<T> owning_array(std::vector<T>&& values, std::size_t columns) {
  auto* owned = new std::vector<T>(std::move(values));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  const py::ssize_t rows = py::ssize_t(owned->size() / columns);
  return py::array_t<T>({rows, py::ssize_t(columns)}, owned->data(), owner);
}

py::object faces_object(Mesh_output& mesh) {
  if (mesh.polygons.empty()) return owning_array(std::move(mesh.corners), mesh.face_degree);
  py::list polygons;
  for (const auto& polygon : mesh.polygons) polygons.append(py::cast(polygon));
  return std::move(polygons);
}

// (vertices, faces, report_json)
py::tuple result_tuple(Operator_output& out) {
  py::array vertices = owning_array(std::move(out.mesh.points), 3);
  return py::make_tuple(vertices, faces_object(out.mesh), out.report);
}

// ---- options -------------------------------------------------------------------------------

// Reads the options dict the Python wrapper builds; a key no operator reads is a bug there.
class Options {
 public:
  explicit Options(const py::dict& d) : dict_(d) {}
  template <class T>
  Options& get(const char* key, T& value) {
    if (dict_.contains(key)) {
      value = dict_[key].cast<T>();
      ++used_;
    }
    return *this;
  }
  void finish() const {
    if (used_ != dict_.size()) throw std::invalid_argument("unknown option given to _core");
  }

 private:
  py::dict dict_;
  std::size_t used_ = 0;
};

// Runs `work` on the caller's mesh (or points) without the GIL; turns a cancellation into the
// Python error the visitor kept (KeyboardInterrupt for Ctrl-C), after which nothing is returned.
template <class Work>
py::tuple run_source(Source s, const py::object& progress, Work work) {
  Python_visitor visitor;
  if (!progress.is_none()) visitor.callback = progress.ptr();
  Operator_output out;
  try {
    py::gil_scoped_release release;
    copy_arrays(s);
    out = work(s.input, visitor);
  } catch (const Cancelled&) {
    if (!visitor.error) {  // the library stopped without a Python error: treat as Ctrl-C
      PyErr_SetNone(PyExc_KeyboardInterrupt);
      throw py::error_already_set();
    }
    py::error_already_set error = *static_cast<py::error_already_set*>(visitor.error);
    throw error;
  }
  return result_tuple(out);
}

template <class Work>
py::tuple run(const py::object& source, const py::object& progress, Work work) {
  return run_source(read_source(source), progress, work);
}

}  // namespace
}  // namespace mesh_repair_python

PYBIND11_MODULE(_core, m) {
  using namespace mesh_repair_python;
  m.doc() = "Compiled part of mesh_repair; use the functions of the mesh_repair package.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const Input_error& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });

  m.def("read", [](const std::string& path, bool repair_soup) {
    Mesh_input input;
    input.path = path;
    Operator_output out;
    {
      py::gil_scoped_release release;
      out = read(input, repair_soup);
    }
    return result_tuple(out);
  });
  m.def("write", [](const std::string& path, const py::object& vertices, const py::object& faces,
                    bool binary) {
    Source s = read_source(py::make_tuple(vertices, faces));
    py::gil_scoped_release release;
    copy_arrays(s);
    return write(path, s.input, binary);
  });
  m.def("check", [](const py::object& source, const py::dict& d, const py::object& progress) {
    Check_options o;
    Options(d)
        .get("tolerance", o.tolerance)
        .get("tolerance_rel", o.tolerance_rel)
        .get("self_intersections", o.self_intersections)
        .finish();
    return run(source, progress,
               [&](Mesh_input& in, Python_visitor& v) { return check(in, o, v); });
  });
  m.def("repair", [](const py::object& source, const py::dict& d, const py::object& progress) {
    Repair_options o;
    Options(d)
        .get("tolerance", o.tolerance)
        .get("tolerance_rel", o.tolerance_rel)
        .get("fill", o.fill)
        .get("continuity", o.continuity)
        .get("max_hole_size", o.max_hole_size)
        .get("max_hole_edges", o.max_hole_edges)
        .get("sheet_border_ratio", o.sheet_border_ratio)
        .get("largest_component", o.largest_component)
        .get("ring_holes", o.ring_holes)
        .get("self_intersections", o.self_intersections)
        .get("remove_self_intersections", o.remove_self_intersections)
        .get("merge_intersecting_solids", o.merge_intersecting_solids)
        .get("remove_hole_fragments", o.remove_hole_fragments)
        .get("bridge_through_holes", o.bridge_through_holes)
        .get("orient_closed_parts", o.orient_closed_parts)
        .get("threads", o.threads)
        .get("seed", o.seed)
        .finish();
    return run(source, progress,
               [&](Mesh_input& in, Python_visitor& v) { return repair(in, o, v); });
  });
  m.def("fill_holes", [](const py::object& source, const py::dict& d, const py::object& progress) {
    Fill_options o;
    Options(d)
        .get("method", o.method)
        .get("continuity", o.continuity)
        .get("max_hole_edges", o.max_hole_edges)
        .get("max_hole_size", o.max_hole_size)
        .get("sheet_border_ratio", o.sheet_border_ratio)
        .get("ring_holes", o.ring_holes)
        .get("threads", o.threads)
        .get("seed", o.seed)
        .finish();
    return run(source, progress,
               [&](Mesh_input& in, Python_visitor& v) { return fill_holes(in, o, v); });
  });
  m.def("stitch", [](const py::object& source, const py::dict& d, const py::object& progress) {
    Stitch_options o;
    Options(d)
        .get("tolerance", o.tolerance)
        .get("tolerance_rel", o.tolerance_rel)
        .get("curves", o.curves)
        .get("check_self_intersections", o.check_self_intersections)
        .finish();
    return run(source, progress,
               [&](Mesh_input& in, Python_visitor& v) { return stitch(in, o, v); });
  });
  m.def("remove_slivers",
        [](const py::object& source, const py::dict& d, const py::object& progress) {
          Sliver_options o;
          Options(d)
              .get("shape_factor", o.shape_factor)
              .get("feature_angle", o.feature_angle)
              .get("edge_length", o.edge_length)
              .finish();
          return run(source, progress,
                     [&](Mesh_input& in, Python_visitor& v) { return remove_slivers(in, o, v); });
        });
  m.def("optimize", [](const py::object& source, const py::dict& d, const py::object& progress) {
    Optimize_options o;
    Options(d)
        .get("mode", o.mode)
        .get("target_ratio", o.target_ratio)
        .get("target_faces", o.target_faces)
        .get("max_deviation", o.max_deviation)
        .get("feature_angle", o.feature_angle)
        .get("min_angle", o.min_angle)
        .get("seed", o.seed)
        .finish();
    return run(source, progress,
               [&](Mesh_input& in, Python_visitor& v) { return optimize(in, o, v); });
  });
  m.def("suppress_feature",
        [](const py::object& source, const py::dict& d, const py::object& progress) {
          Suppress_options o;
          Options(d).get("faces", o.faces).get("method", o.method).get("seed", o.seed).finish();
          return run(source, progress,
                     [&](Mesh_input& in, Python_visitor& v) { return suppress_feature(in, o, v); });
        });
  m.def("smooth", [](const py::object& source, const py::dict& d, const py::object& progress) {
    Smooth_options o;
    Options(d)
        .get("method", o.method)
        .get("quads", o.quads)
        .get("iterations", o.iterations)
        .get("seed", o.seed)
        .get("threads", o.threads)
        .get("generations", o.generations)
        .get("feature_angle", o.feature_angle)
        .get("tangent_scale", o.tangent_scale)
        .get("slide_feature_nodes", o.slide_feature_nodes)
        .finish();
    return run(source, progress,
               [&](Mesh_input& in, Python_visitor& v) { return smooth(in, o, v); });
  });
  m.def("mesh_points", [](const py::object& source, const py::dict& d, const py::object& progress) {
    Mesh_points_options o;
    Options(d)
        .get("quads", o.quads)
        .get("smooth", o.smooth)
        .get("iterations", o.iterations)
        .get("seed", o.seed)
        .get("threads", o.threads)
        .get("feature_angle", o.feature_angle)
        .finish();
    Source s = read_points_source(source);
    s.input.name = "input points";
    return run_source(std::move(s), progress,
                      [&](Mesh_input& in, Python_visitor& v) { return mesh_points(in, o, v); });
  });
  m.def("bench_holes", [](const py::object& source, const py::dict& d, const py::object& progress) {
    Bench_options o;
    Options(d)
        .get("holes", o.holes)
        .get("radius", o.radius)
        .get("seeds", o.seeds)
        .get("methods", o.methods)
        .get("shape", o.shape)
        .finish();
    return run(source, progress,
               [&](Mesh_input& in, Python_visitor& v) { return bench_holes(in, o, v); });
  });
}
