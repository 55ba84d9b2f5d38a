// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_MGA_NODE_SMOOTHING_H
#define CGAL_MESH_REPAIR_INTERNAL_MGA_NODE_SMOOTHING_H

// The sweeps of Chen et al. 3.1 (steps 2-9): every free node in turn searches each adjacent
// element with the micro-GA (or, as the paper's baseline, a conjugate-gradient search in its
// tangent plane), maps the trial positions onto the G1 surface and moves to the best one when
// it raises the fitness by at least `min_gain` and folds no element (exact orientation test).
// Sweeps repeat until no node moves.
//
// Nodes that share no element are independent, so the nodes are greedily coloured and each
// colour class is processed in parallel (TBB). Each node draws from its own generator, seeded
// from (seed, node index, sweep): the result is the same for any number of threads.

#include <CGAL/Mesh_repair/internal/c1_surface/g1_surface.h>
#include <CGAL/Mesh_repair/internal/mga/micro_ga.h>
#include <CGAL/Mesh_repair/internal/mga/node_star.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <memory>
#include <vector>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

enum class Node_optimizer { micro_ga, conjugate_gradient };

struct Node_smoothing_settings {
  Node_optimizer optimizer = Node_optimizer::micro_ga;
  Micro_ga_settings ga;
  int max_sweeps = 10;
  double min_gain = 1e-3;  // a move must raise the node's fitness (sum of alpha/beta) this much
  std::uint64_t seed = 0;
  int threads = 1;
};

struct Node_smoothing_statistics {
  int sweeps = 0;
  std::size_t moves = 0;
  std::size_t rejected_folds = 0;
  bool converged = false;
  bool cancelled = false;
};

/// Greedy colouring of the free nodes: two nodes of one element never get the same colour.
inline std::vector<std::vector<int>> independent_sets(const Polygon_arrays& mesh,
                                                      const std::vector<bool>& fixed) {
  std::vector<int> colour(mesh.points.size(), -1);
  std::vector<std::vector<int>> classes;
  std::vector<int> used_by;  // colour -> last node that saw it among its neighbours
  for (int v = 0; v < int(mesh.points.size()); ++v) {
    if (fixed[v]) continue;
    for (int k = mesh.incidence_start[v]; k < mesh.incidence_start[v + 1]; ++k) {
      const auto& face = mesh.faces[mesh.incidence[k]];
      for (int i = 0; i < mesh.degree(mesh.incidence[k]); ++i)
        if (colour[face[i]] >= 0) used_by[colour[face[i]]] = v;
    }
    int c = 0;
    while (c < int(used_by.size()) && used_by[c] == v) ++c;
    if (c == int(used_by.size())) {
      used_by.push_back(-1);
      classes.emplace_back();
    }
    colour[v] = c;
    classes[c].push_back(v);
  }
  return classes;
}

template <class Traits>
class Node_smoother {
 public:
  /// `feature_path[v]`, when given for a free node v, holds the two vertices of the feature
  /// line through v: v then slides along that line instead of searching its elements.
  Node_smoother(Polygon_arrays& mesh, const G1_surface& surface, const std::vector<bool>& fixed,
                const Node_smoothing_settings& settings, const Traits& traits,
                std::vector<std::array<int, 2>> feature_path = {})
      : mesh_(mesh),
        surface_(surface),
        fixed_(fixed),
        settings_(settings),
        traits_(traits),
        feature_path_(std::move(feature_path)) {
    host_.resize(mesh.points.size());
    for (std::size_t v = 0; v < host_.size(); ++v)
      host_[v] = v < surface.number_of_vertices() ? surface.triangle_of_vertex(int(v)) : -1;
    classes_ = independent_sets(mesh, fixed);
    stale_.assign(mesh.points.size(), 1);
#ifdef CGAL_LINKED_WITH_TBB
    // One arena for all colour classes and sweeps (creating one per class costs thread start-up
    // and hand-over each time).
    // 0: TBB's default number of threads (every operator's default).
    if (settings.threads == 0)
      // A copy: make_unique's forwarding reference would odr-use the constant, which TBB
      // declares without a definition (an undefined symbol when built at -O0).
      arena_ = std::make_unique<tbb::task_arena>(int(tbb::task_arena::automatic));
    else if (settings.threads > 1)
      arena_ = std::make_unique<tbb::task_arena>(settings.threads);
#endif
  }

  /// Runs the sweeps; `progress(fraction)` returns false to cancel between colour classes.
  template <class Progress>
  Node_smoothing_statistics run(Progress&& progress) {
    Node_smoothing_statistics statistics;
    std::size_t free_nodes = 0;
    for (const auto& c : classes_) free_nodes += c.size();
    if (free_nodes == 0) {
      statistics.converged = true;
      return statistics;
    }
    for (int sweep = 0; sweep < settings_.max_sweeps; ++sweep) {
      double gain = 0;
      for (std::size_t c = 0; c < classes_.size(); ++c) {
        gain += process_class(classes_[c], sweep, statistics);
        if (!progress((sweep + double(c + 1) / classes_.size()) / settings_.max_sweeps)) {
          statistics.cancelled = true;
          statistics.sweeps = sweep + 1;
          return statistics;
        }
      }
      statistics.sweeps = sweep + 1;
      if (gain == 0) {  // no node found a move worth min_gain: the mesh has converged
        statistics.converged = true;
        break;
      }
    }
    return statistics;
  }

 private:
  struct Move {
    double gain = 0;
    bool moved = false, rejected = false;
  };

  // A node is searched again only when it or a node of its elements moved since its last search
  // (its fitness landscape is otherwise unchanged); the first sweep searches every node.
  double process_class(const std::vector<int>& nodes, int sweep,
                       Node_smoothing_statistics& statistics) {
    std::vector<Move> moves(nodes.size());
    auto body = [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i)
        if (stale_[nodes[i]]) moves[i] = smooth_node(nodes[i], sweep);
    };
#ifdef CGAL_LINKED_WITH_TBB
    if (arena_ && nodes.size() > 64) {
      arena_->execute([&] {
        tbb::parallel_for(
            tbb::blocked_range<std::size_t>(0, nodes.size(), 32),
            [&](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); });
      });
    } else {
      body(0, nodes.size());
    }
#else
    body(0, nodes.size());
#endif
    double gain = 0;  // summed in node order, so it does not depend on the threads either
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const Move& m = moves[i];
      gain += m.gain;
      statistics.moves += m.moved;
      statistics.rejected_folds += m.rejected;
      stale_[nodes[i]] = m.moved;
      if (m.moved) mark_neighbours_stale(nodes[i]);
    }
    return gain;
  }

  void mark_neighbours_stale(int v) {
    for (int k = mesh_.incidence_start[v]; k < mesh_.incidence_start[v + 1]; ++k) {
      const int f = mesh_.incidence[k];
      for (int i = 0; i < mesh_.degree(f); ++i) stale_[mesh_.faces[f][i]] = 1;
    }
  }

  Move smooth_node(int v, int sweep) {
    const Node_star star(mesh_, v);
    if (star.elements().empty() || host_[v] < 0) return {};
    const double current = star.fitness(mesh_.points[v]);
    Splitmix64 random(settings_.seed * 0x9E3779B97F4A7C15ull ^ (std::uint64_t(v) << 20) ^
                      std::uint64_t(sweep));
    Vec3 best_position;
    const bool slides = !feature_path_.empty() && feature_path_[v][0] >= 0;
    const double best = slides ? slide_search(star, random, best_position)
                        : settings_.optimizer == Node_optimizer::micro_ga
                            ? micro_ga_search(star, random, best_position)
                            : conjugate_gradient_search(star, best_position);
    Move move;
    if (!(best > current + settings_.min_gain)) return move;
    if (!star.keeps_orientation(best_position, traits_)) {
      move.rejected = true;
      return move;
    }
    host_[v] = surface_.locate(best_position, host_[v]).triangle;
    mesh_.points[v] = best_position;
    move.moved = true;
    move.gain = best - current;
    return move;
  }

  Vec3 on_surface(const Vec3& p, int start) const {
    int host = start;
    return surface_.project(p, host);
  }

  // A node inside a feature line (option `slide_feature_nodes`) moves along the line only: its
  // position is the point at tau in (-0.5, 0.5) of the path made of the surface's curves from
  // its own input position toward its two feature neighbours (tau > 0 toward the first), so it
  // stays on the feature curve and never passes the middle of an input edge (two sliding
  // neighbours cannot cross). A micro-GA over r1 (tau = r1 - 0.5) finds the best tau; r2 plays
  // no part.
  double slide_search(const Node_star& star, Splitmix64& random, Vec3& best_position) const {
    const int v = star.node();
    const std::array<int, 2>& path = feature_path_[v];
    auto at = [&](double tau) {
      return tau >= 0 ? surface_.edge_point(v, path[0], tau)
                      : surface_.edge_point(v, path[1], -tau);
    };
    const auto result = run_micro_ga([&](double r1, double) { return star.fitness(at(r1 - 0.5)); },
                                     settings_.ga, random);
    best_position = at(result[1] - 0.5);
    return star.fitness(best_position);
  }

  // Steps 3-7: one micro-GA per adjacent element; the best over the elements wins.
  double micro_ga_search(const Node_star& star, Splitmix64& random, Vec3& best_position) const {
    double best = -1;
    std::size_t best_element = 0;
    double best_r1 = 0, best_r2 = 0;
    const int start = host_[star.node()];
    Vec3 v1, v2, v3;
    int hint = start;  // the walk starts where the previous trial of this element was found
    auto position = [&](double r1, double r2) {  // eq. 3
      return surface_.project((1 - r2) * v1 + (r2 * (1 - r1)) * v2 + (r1 * r2) * v3, hint);
    };
    for (std::size_t e = 0; e < star.elements().size(); ++e) {
      star.search_triangle(e, v1, v2, v3);
      hint = start;
      const auto result =
          run_micro_ga([&](double r1, double r2) { return star.fitness(position(r1, r2)); },
                       settings_.ga, random);
      if (result[0] > best) {
        best = result[0];
        best_element = e, best_r1 = result[1], best_r2 = result[2];
      }
    }
    // Only the winner's point is mapped again, from the node's host; its fitness is taken again
    // so that the gain belongs to exactly that point (a walk from another start can end in the
    // neighbouring patch when the point lies on a patch edge).
    if (best < 0) return best;
    star.search_triangle(best_element, v1, v2, v3);
    hint = start;
    best_position = position(best_r1, best_r2);
    return star.fitness(best_position);
  }

  // The paper's baseline (Garimella et al.): Polak-Ribiere conjugate gradient on the fitness
  // over the node's tangent plane, central-difference gradient, backtracking line search, each
  // trial mapped onto the surface. `max_generations` bounds the CG iterations.
  double conjugate_gradient_search(const Node_star& star, Vec3& best_position) const {
    const int v = star.node();
    const Vec3 origin = mesh_.points[v];
    Vec3 normal;
    double edge_length = 0;
    for (const auto& element : star.elements()) {
      normal += normalized(element.reference_normal);
      edge_length += norm(mesh_.points[element.ring[1]] - origin);
    }
    edge_length /= double(star.elements().size());
    Vec3 t1, t2;
    tangent_frame(normalized(normal), t1, t2);
    const int start = host_[v];
    auto objective = [&](const Eigen::Vector2d& x) {
      return star.fitness(on_surface(origin + x[0] * t1 + x[1] * t2, start));
    };
    const double h = 1e-3 * edge_length;
    auto gradient = [&](const Eigen::Vector2d& x) {
      Eigen::Vector2d g;
      for (int i = 0; i < 2; ++i) {
        Eigen::Vector2d step = Eigen::Vector2d::Zero();
        step[i] = h;
        g[i] = (objective(x + step) - objective(x - step)) / (2 * h);
      }
      return g;
    };
    Eigen::Vector2d x = Eigen::Vector2d::Zero();
    double value = objective(x);
    Eigen::Vector2d g = gradient(x), direction = g;
    for (int iteration = 0; iteration < settings_.ga.max_generations; ++iteration) {
      if (direction.norm() == 0) break;
      double step = 0.2 * edge_length / direction.norm();
      bool improved = false;
      for (int halving = 0; halving < 8 && !improved; ++halving, step *= 0.5) {
        const double trial = objective(x + step * direction);
        if (trial > value) {
          x += step * direction;
          value = trial;
          improved = true;
        }
      }
      if (!improved) break;
      const Eigen::Vector2d new_g = gradient(x);
      const double beta = std::max(0.0, new_g.dot(new_g - g) / std::max(g.dot(g), 1e-300));
      direction = new_g + beta * direction;
      g = new_g;
    }
    best_position = on_surface(origin + x[0] * t1 + x[1] * t2, start);
    return value;
  }

  Polygon_arrays& mesh_;
  const G1_surface& surface_;
  const std::vector<bool>& fixed_;
  Node_smoothing_settings settings_;
  const Traits& traits_;
  std::vector<int> host_;
  std::vector<char> stale_;
  std::vector<std::vector<int>> classes_;
  std::vector<std::array<int, 2>> feature_path_;  // empty, or {-1, -1} for nodes that do not slide
#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::task_arena> arena_;
#endif
};

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_MGA_NODE_SMOOTHING_H
