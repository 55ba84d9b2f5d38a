// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_MGA_MICRO_GA_H
#define CGAL_MESH_REPAIR_INTERNAL_MGA_MICRO_GA_H

// The micro-genetic algorithm of Chen et al. 3.1 (after Krishnakumar 1989) on the two design
// variables of one element (3.2): binary strings, population 5, elitism, roulette selection of
// four parents that include the best, single-point crossover with probability 1, no mutation; on
// convergence (the population agrees with the best on 95% of the bits) the best is kept and the
// four others are drawn afresh.

#include <algorithm>
#include <array>
#include <cstdint>

namespace CGAL {
namespace Mesh_repair {
namespace internal {

/// splitmix64: a tiny, fast, well-mixed generator. Each node seeds its own, so a node's draws
/// do not depend on which thread or in which order nodes are processed.
class Splitmix64 {
 public:
  explicit Splitmix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return double(next() >> 11) * (1.0 / 9007199254740992.0); }

 private:
  std::uint64_t state_;
};

struct Micro_ga_settings {
  int population_size = 5;     // the paper's (Krishnakumar's) choice
  int max_generations = 10;    // generations per element and per sweep, restarts included
  int bits_per_variable = 10;  // resolution 1/1024 of r1 and of r2
};

template <class Population>
bool converged(const Population& population, int size, int bits) {
  int differing = 0;
  for (int i = 1; i < size; ++i) differing += __builtin_popcount(population[i] ^ population[0]);
  return differing * 20 <= (size - 1) * bits;  // at most 5% of the bits differ from the best
}

// Roulette selection of parents (the best, at index 0, is always one of them), then single-point
// crossover of consecutive pairs into slots 1..size-1; slot 0 keeps the elite.
template <class Population, class Scores>
void reproduce(Population& population, const Scores& score, int size, int bits,
               Splitmix64& random) {
  double total = 0;
  for (int i = 0; i < size; ++i) total += std::max(score[i], 0.0);
  Population parents = population;
  for (int k = 1; k < size - 1; ++k) {
    double ticket = random.uniform() * total;
    int chosen = 0;
    for (int i = 0; i < size; ++i) {
      chosen = i;
      ticket -= std::max(score[i], 0.0);
      if (ticket <= 0) break;
    }
    parents[k] = population[total > 0 ? chosen : int(random.next() % std::uint64_t(size))];
  }
  for (int k = 1; k < size; k += 2) {
    const std::uint32_t a = parents[k - 1], b = parents[k];
    const int cut = 1 + int(random.next() % std::uint64_t(bits - 1));
    const std::uint32_t low = (1u << cut) - 1;
    population[k] = (a & low) | (b & ~low);
    if (k + 1 < size) population[k + 1] = (b & low) | (a & ~low);
  }
}

/// Maximises `fitness(r1, r2)` over 0 < r1 < 1, 0 < r2 < 0.5 (eq. 2-3). Returns the best
/// (fitness, r1, r2) seen.
template <class Fitness>
std::array<double, 3> run_micro_ga(const Fitness& fitness, const Micro_ga_settings& settings,
                                   Splitmix64& random) {
  constexpr int max_population = 16;
  const int size = std::min(std::max(settings.population_size, 2), max_population);
  const int bits = settings.bits_per_variable;
  const std::uint32_t mask = (1u << (2 * bits)) - 1;
  const double scale = 1.0 / double(1u << bits);
  auto decode = [&](std::uint32_t string) {
    const std::uint32_t low = string & ((1u << bits) - 1), high = string >> bits;
    return std::array<double, 2>{(low + 0.5) * scale, 0.5 * (high + 0.5) * scale};
  };
  std::array<std::uint32_t, max_population> population{};
  std::array<double, max_population> score{};
  // Strings already evaluated in this run: crossover of equal parents and restarts reproduce
  // strings often, and the fitness is a pure function of the string, so a repeated string reuses
  // its score (same result, fewer surface projections).
  constexpr int memo_capacity = 64;
  std::array<std::uint32_t, memo_capacity> seen;
  std::array<double, memo_capacity> seen_score;
  int seen_count = 0;
  auto evaluate = [&](int i) {
    const std::uint32_t string = population[i];
    for (int k = 0; k < seen_count; ++k)
      if (seen[k] == string) {
        score[i] = seen_score[k];
        return;
      }
    const auto r = decode(string);
    score[i] = fitness(r[0], r[1]);
    if (seen_count < memo_capacity) seen[seen_count] = string, seen_score[seen_count++] = score[i];
  };
  for (int i = 0; i < size; ++i) {
    population[i] = std::uint32_t(random.next()) & mask;
    evaluate(i);
  }
  auto best_index = [&] {
    int best = 0;
    for (int i = 1; i < size; ++i)
      if (score[i] > score[best]) best = i;
    return best;
  };
  for (int generation = 0; generation < settings.max_generations; ++generation) {
    const int best = best_index();
    std::swap(population[0], population[best]);
    std::swap(score[0], score[best]);
    if (converged(population, size, 2 * bits)) {
      for (int i = 1; i < size; ++i) population[i] = std::uint32_t(random.next()) & mask;
    } else {
      reproduce(population, score, size, 2 * bits, random);
    }
    for (int i = 1; i < size; ++i) evaluate(i);
  }
  const int best = best_index();
  const auto r = decode(population[best]);
  return {score[best], r[0], r[1]};
}

}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_MGA_MICRO_GA_H
