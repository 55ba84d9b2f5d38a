// Copyright (c) 2026 Mesh_repair developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_MULTIFRONTAL_CHOLESKY_IMPL_H
#define CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_MULTIFRONTAL_CHOLESKY_IMPL_H

#include <CGAL/Mesh_repair/internal/curvature_variation/multifrontal_cholesky.h>

#include <Eigen/Cholesky>
#include <Eigen/Dense>

namespace CGAL {
namespace Mesh_repair {
namespace internal {
namespace curvature_variation {

CGAL_MESH_REPAIR_CORE_INLINE Multifrontal_cholesky::Multifrontal_cholesky(
    const Eigen::SparseMatrix<double>& H, const std::vector<std::array<double, 3>>& positions) {
  Nested_dissection dissection = nested_dissection(H, positions, leaf_size);
  order_ = std::move(dissection.order);
  new_index_.assign(order_.size(), 0);
  for (std::size_t k = 0; k < order_.size(); ++k) new_index_[std::size_t(order_[k])] = int(k);
  fronts_.resize(dissection.nodes.size());
  for (std::size_t t = 0; t < fronts_.size(); ++t) {
    fronts_[t].begin = dissection.nodes[t].begin;
    fronts_[t].end = dissection.nodes[t].end;
  }
  find_front_rows(H, dissection);
  factorise(H, dissection);
}

CGAL_MESH_REPAIR_CORE_INLINE Eigen::MatrixXd Multifrontal_cholesky::solve(
    const Eigen::MatrixXd& B) const {
  Eigen::MatrixXd Y(B.rows(), B.cols());
  for (Eigen::Index i = 0; i < B.rows(); ++i) Y.row(new_index_[std::size_t(i)]) = B.row(i);
  for (const Front& front : fronts_) {  // L y = b, children first
    const Eigen::Index k = front.end - front.begin;
    if (k == 0) continue;
    auto own = Y.middleRows(front.begin, k);
    front.L.topRows(k).triangularView<Eigen::Lower>().solveInPlace(own);
    const Eigen::MatrixXd update = front.L.bottomRows(front.L.rows() - k) * own;
    for (Eigen::Index r = 0; r < update.rows(); ++r)
      Y.row(front.rows[std::size_t(k + r)]) -= update.row(r);
  }
  for (auto it = fronts_.rbegin(); it != fronts_.rend(); ++it) {  // L^T x = y, parents first
    const Front& front = *it;
    const Eigen::Index k = front.end - front.begin;
    if (k == 0) continue;
    Eigen::MatrixXd above(front.L.rows() - k, Y.cols());
    for (Eigen::Index r = 0; r < above.rows(); ++r)
      above.row(r) = Y.row(front.rows[std::size_t(k + r)]);
    auto own = Y.middleRows(front.begin, k);
    own.noalias() -= front.L.bottomRows(above.rows()).transpose() * above;
    front.L.topRows(k).triangularView<Eigen::Lower>().transpose().solveInPlace(own);
  }
  Eigen::MatrixXd X(B.rows(), B.cols());
  for (Eigen::Index i = 0; i < B.rows(); ++i) X.row(i) = Y.row(new_index_[std::size_t(i)]);
  return X;
}

CGAL_MESH_REPAIR_CORE_INLINE void Multifrontal_cholesky::find_front_rows(
    const Eigen::SparseMatrix<double>& H, const Nested_dissection& dissection) {
  std::vector<int> mark(order_.size(), -1);
  std::vector<std::vector<int>> passed_up(fronts_.size());
  for (std::size_t t = 0; t < fronts_.size(); ++t) {
    Front& front = fronts_[t];
    std::vector<int>& rows = front.rows;
    for (int j = front.begin; j < front.end; ++j) {
      rows.push_back(j);
      mark[std::size_t(j)] = int(t);
    }
    const auto add = [&](int i) {
      if (mark[std::size_t(i)] != int(t)) {
        mark[std::size_t(i)] = int(t);
        rows.push_back(i);
      }
    };
    for (int j = front.begin; j < front.end; ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(H, order_[std::size_t(j)]); it; ++it) {
        const int i = new_index_[std::size_t(it.index())];
        if (i >= front.end) add(i);
      }
    for (int i : passed_up[t]) add(i);
    std::vector<int>().swap(passed_up[t]);
    std::sort(rows.begin() + (front.end - front.begin), rows.end());
    const int parent = dissection.nodes[t].parent;
    if (parent >= 0)
      passed_up[std::size_t(parent)].insert(passed_up[std::size_t(parent)].end(),
                                            rows.begin() + (front.end - front.begin), rows.end());
  }
}

CGAL_MESH_REPAIR_CORE_INLINE void Multifrontal_cholesky::factorise(
    const Eigen::SparseMatrix<double>& H, const Nested_dissection& dissection) {
  std::vector<int> local(order_.size(), -1);
  std::vector<Eigen::MatrixXd> updates;
  std::vector<const Front*> update_owner;
  for (std::size_t t = 0; t < fronts_.size(); ++t) {
    Front& front = fronts_[t];
    const Eigen::Index s = Eigen::Index(front.rows.size()), k = front.end - front.begin;
    for (Eigen::Index r = 0; r < s; ++r) local[std::size_t(front.rows[std::size_t(r)])] = int(r);
    Eigen::MatrixXd F = Eigen::MatrixXd::Zero(s, s);  // lower triangle used
    for (int j = front.begin; j < front.end; ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(H, order_[std::size_t(j)]); it; ++it) {
        const int i = new_index_[std::size_t(it.index())];
        if (i >= j) F(local[std::size_t(i)], local[std::size_t(j)]) += it.value();
      }
    for (int c = 0; c < dissection.nodes[t].children; ++c) {
      const Eigen::MatrixXd& U = updates.back();
      const Front& child = *update_owner.back();
      const std::size_t offset = std::size_t(child.end - child.begin);
      for (Eigen::Index a = 0; a < U.cols(); ++a) {
        const int column = local[std::size_t(child.rows[offset + std::size_t(a)])];
        for (Eigen::Index b = a; b < U.rows(); ++b)
          F(local[std::size_t(child.rows[offset + std::size_t(b)])], column) += U(b, a);
      }
      updates.pop_back();
      update_owner.pop_back();
    }
    if (k > 0) {
      Eigen::Ref<Eigen::MatrixXd> diagonal = F.topLeftCorner(k, k);
      Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> llt(diagonal);  // in place
      if (llt.info() != Eigen::Success) {
        info_ = Eigen::NumericalIssue;
        return;
      }
      Eigen::Ref<Eigen::MatrixXd> below = F.bottomLeftCorner(s - k, k);
      diagonal.triangularView<Eigen::Lower>().transpose().solveInPlace<Eigen::OnTheRight>(below);
      F.bottomRightCorner(s - k, s - k).selfadjointView<Eigen::Lower>().rankUpdate(below, -1.0);
    }
    if (dissection.nodes[t].parent >= 0) {
      updates.push_back(F.bottomRightCorner(s - k, s - k));
      update_owner.push_back(&front);
    }
    front.L = F.leftCols(k);
  }
  info_ = Eigen::Success;
}

}  // namespace curvature_variation
}  // namespace internal
}  // namespace Mesh_repair
}  // namespace CGAL

#endif  // CGAL_MESH_REPAIR_INTERNAL_CURVATURE_VARIATION_MULTIFRONTAL_CHOLESKY_IMPL_H
