// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_JSON_WRITER_H
#define CGAL_MESH_REPAIR_JSON_WRITER_H

/// \file json_writer.h
/// `Json_writer`: the streaming JSON writer of every report (the `write_json` overloads of the
/// result types). Debian 12's Boost 1.74 has no Boost.JSON, and a report needs only objects,
/// arrays, numbers, booleans and strings.

#include <CGAL/number_utils.h>

#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Mesh_repair {

class Json_writer {
 public:
  explicit Json_writer(std::ostream& out, bool pretty = true) : out_(out), pretty_(pretty) {}

  Json_writer& begin_object() { return open('{'); }
  Json_writer& end_object() { return close('}'); }
  Json_writer& begin_array() { return open('['); }
  Json_writer& end_array() { return close(']'); }

  /// Writes `"name":` inside an object; the next call writes its value.
  Json_writer& key(const std::string& name) {
    separate();
    write_string(name);
    out_ << (pretty_ ? ": " : ":");
    after_key_ = true;
    return *this;
  }

  Json_writer& value(const std::string& s) {
    return scalar([&] { write_string(s); });
  }
  Json_writer& value(const char* s) { return value(std::string(s)); }
  Json_writer& value(bool b) {
    return scalar([&] { out_ << (b ? "true" : "false"); });
  }
  Json_writer& value(double d) {
    return scalar([&] {
      if (!std::isfinite(d)) {
        out_ << "null";
        return;
      }
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, "%.10g", d);
      out_ << buffer;
    });
  }
  template <class Integer, std::enable_if_t<std::is_integral<Integer>::value, int> = 0>
  Json_writer& value(Integer i) {
    return scalar([&] { out_ << i; });
  }

  /// Writes an already serialised JSON value (an operator's own report) as the next value.
  Json_writer& raw(const std::string& json_text) {
    return scalar([&] { out_ << json_text; });
  }

  template <class T>
  Json_writer& field(const std::string& name, const T& v) {
    key(name);
    return value(v);
  }
  /// An array of three coordinates.
  template <class Point>
  Json_writer& point(const Point& p) {
    begin_array();
    value(CGAL::to_double(p.x())).value(CGAL::to_double(p.y())).value(CGAL::to_double(p.z()));
    return end_array();
  }
  template <class T>
  Json_writer& array(const std::string& name, const std::vector<T>& values) {
    key(name).begin_array();
    for (const T& v : values) value(v);
    return end_array();
  }

 private:
  template <class F>
  Json_writer& scalar(F write) {
    separate();
    write();
    return *this;
  }
  Json_writer& open(char c) {
    separate();
    out_ << c;
    first_.push_back(true);
    return *this;
  }
  Json_writer& close(char c) {
    const bool empty = first_.back();
    first_.pop_back();
    if (!empty) newline();
    out_ << c;
    if (first_.empty()) out_ << '\n';
    return *this;
  }
  void separate() {
    if (after_key_) {
      after_key_ = false;
      return;
    }
    if (first_.empty()) return;
    if (!first_.back()) out_ << ',';
    first_.back() = false;
    newline();
  }
  void newline() {
    if (!pretty_) return;
    out_ << '\n';
    for (std::size_t i = 0; i < first_.size(); ++i) out_ << "  ";
  }
  void write_string(const std::string& s) {
    out_ << '"';
    for (unsigned char c : s) {
      switch (c) {
        case '"':
          out_ << "\\\"";
          break;
        case '\\':
          out_ << "\\\\";
          break;
        case '\n':
          out_ << "\\n";
          break;
        case '\t':
          out_ << "\\t";
          break;
        case '\r':
          out_ << "\\r";
          break;
        default:
          if (c < 0x20) {
            char buffer[8];
            std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
            out_ << buffer;
          } else {
            out_ << c;
          }
      }
    }
    out_ << '"';
  }

  std::ostream& out_;
  bool pretty_;
  bool after_key_ = false;
  std::vector<bool> first_;
};

}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_JSON_WRITER_H
