#include "solvers/linear/BlockLuSolver.h"

#include "core/FillOrder.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace c2d {

namespace {
// A pivot block whose 1-norm condition number exceeds this is taken as
// singular: the factorization fails and the caller pivots.
constexpr double kMaxPivotCondition = 1e12;
// Largest entry of the factors over the matrix's largest. Without pivoting the
// backward error grows with it; at 1e4 a solve keeps twelve digits, and the
// tangents this solver is for (diagonal blocks dominant) stay near 1.
constexpr double kMaxGrowth = 1e4;
constexpr int kB = 3;  // equations per block at most
// The work blocks are indexed as one array of doubles.
static_assert(sizeof(Eigen::Matrix3d) == kB * kB * sizeof(double));

double norm1(const Eigen::Matrix3d& m) { return m.cwiseAbs().colwise().sum().maxCoeff(); }
}  // namespace

void BlockLuSolver::makeBlocks(int n) {
  // Blocks in the order of their first equation; a group of more than three
  // equations is split. Without a grouping every equation is a block.
  const bool grouped = static_cast<int>(group_.size()) == n;
  std::vector<int> open;  // block currently filled by each group id
  members_.clear();
  for (int eq = 0; eq < n; ++eq) {
    const int g = grouped ? group_[eq] : -1;
    int b = -1;
    if (g >= 0) {
      if (g >= static_cast<int>(open.size())) open.resize(g + 1, -1);
      b = open[g];
    }
    if (b >= 0 && members_[kB * b + kB - 1] < 0) {
      int l = 0;
      while (members_[kB * b + l] >= 0) ++l;
      members_[kB * b + l] = eq;
      continue;
    }
    b = static_cast<int>(members_.size()) / kB;
    members_.insert(members_.end(), {eq, -1, -1});
    if (g >= 0) open[g] = b;
  }
  nb_ = static_cast<int>(members_.size()) / kB;
}

std::vector<std::vector<int>> BlockLuSolver::orderBlocks(const SparseMatrix& A) {
  // The block graph of A + A^T, ordered by AMD; blocks renumbered in that order.
  std::vector<int> natural(n_);
  for (int b = 0; b < nb_; ++b)
    for (int l = 0; l < kB; ++l)
      if (members_[kB * b + l] >= 0) natural[members_[kB * b + l]] = b;
  std::vector<std::vector<int>> adj(nb_);
  for (int c = 0; c < n_; ++c)
    for (int q = A.outerIndexPtr()[c]; q < A.outerIndexPtr()[c + 1]; ++q) {
      const int bi = natural[A.innerIndexPtr()[q]], bj = natural[c];
      if (bi == bj) continue;
      adj[bi].push_back(bj);
      adj[bj].push_back(bi);
    }
  std::vector<int> perm = fillReducingOrder(adj), position(nb_);
  if (perm.empty())
    for (int b = 0; b < nb_; ++b) perm.push_back(b);
  for (int k = 0; k < nb_; ++k) position[perm[k]] = k;
  std::vector<int> members(members_.size());
  for (int k = 0; k < nb_; ++k)
    std::copy_n(members_.begin() + kB * perm[k], kB, members.begin() + kB * k);
  members_ = std::move(members);
  std::vector<std::vector<int>> adjacent(nb_);
  for (int b = 0; b < nb_; ++b)
    for (int j : adj[b]) adjacent[position[b]].push_back(position[j]);
  blockOf_.assign(n_, -1);
  slot_.assign(n_, -1);
  for (int k = 0; k < nb_; ++k)
    for (int l = 0; l < kB; ++l)
      if (const int eq = members_[kB * k + l]; eq >= 0) {
        blockOf_[eq] = k;
        slot_[eq] = l;
      }
  return adjacent;
}

void BlockLuSolver::symbolic(const std::vector<std::vector<int>>& adjacent) {
  // The blocks of U above the diagonal in column k are the row structure of L
  // in row k: the row subtrees of the elimination tree (Liu), found by walking
  // up the tree from each block coupled to k until a block already marked.
  std::vector<int> parent(nb_, -1), mark(nb_, -1);
  std::vector<std::vector<int>> above(nb_), below(nb_);
  for (int k = 0; k < nb_; ++k) {
    mark[k] = k;
    for (int i : adjacent[k]) {
      if (i > k) continue;
      for (int j = i; mark[j] != k; j = parent[j]) {
        above[k].push_back(j);
        mark[j] = k;
        if (parent[j] < 0) parent[j] = k;
      }
    }
    // Ascending: a block's entry of U is final once the blocks before it
    // have updated it (left-looking order).
    std::sort(above[k].begin(), above[k].end());
    for (int j : above[k]) below[j].push_back(k);
  }
  Lp_.assign(nb_ + 1, 0);
  Up_.assign(nb_ + 1, 0);
  Li_.clear();
  Ui_.clear();
  for (int k = 0; k < nb_; ++k) {
    Lp_[k + 1] = Lp_[k] + static_cast<int>(below[k].size());
    Up_[k + 1] = Up_[k] + static_cast<int>(above[k].size());
    Li_.insert(Li_.end(), below[k].begin(), below[k].end());
    Ui_.insert(Ui_.end(), above[k].begin(), above[k].end());
  }
  Lx_.assign(Li_.size(), Block::Zero());
  zeroL_.assign(Li_.size(), 1);
  Ux_.assign(Ui_.size(), Block::Zero());
  Dinv_.assign(nb_, Block::Zero());
  work_.assign(nb_, Block::Zero());
  y_.assign(nb_, BlockVec::Zero());
}

Status BlockLuSolver::analyze(const SparseMatrix& A, bool /*symmetric*/) {
  factored_ = false;
  if (Status s = recordPattern(A); !s) return s;
  n_ = pattern_.size();
  makeBlocks(n_);
  symbolic(orderBlocks(A));
  // Where each entry of A goes in its block column's work blocks (the blocks
  // lie one after the other, column-major each).
  target_.resize(A.nonZeros());
  for (int c = 0; c < n_; ++c)
    for (int q = A.outerIndexPtr()[c]; q < A.outerIndexPtr()[c + 1]; ++q) {
      const int r = A.innerIndexPtr()[q];
      target_[q] = kB * kB * blockOf_[r] + slot_[r] + kB * slot_[c];
    }
  return Status::success();
}

Status BlockLuSolver::factorize(const SparseMatrix& A) {
  factored_ = false;
  notStable_ = false;
  singular_ = -1;
  if (Status s = checkPattern(A); !s) return s;
  const int* Ap = A.outerIndexPtr();
  const double* Ax = A.valuePtr();
  const double largestA = A.nonZeros() > 0 ? A.coeffs().cwiseAbs().maxCoeff() : 0.0;
  double largestU = 0;
  for (int k = 0; k < nb_; ++k) {
    for (int q = Up_[k]; q < Up_[k + 1]; ++q) work_[Ui_[q]].setZero();
    for (int p = Lp_[k]; p < Lp_[k + 1]; ++p) work_[Li_[p]].setZero();
    Block& d = work_[k];
    d.setZero();
    for (int l = 0; l < kB; ++l) {
      const int c = members_[kB * k + l];
      if (c < 0) {
        d(l, l) = 1;  // a padding equation: identity
        continue;
      }
      double* work = work_.front().data();
      for (int q = Ap[c]; q < Ap[c + 1]; ++q) work[target_[q]] = Ax[q];
    }
    // Block column k of U by the unit lower triangle of the columns before.
    for (int q = Up_[k]; q < Up_[k + 1]; ++q) {
      const int j = Ui_[q];
      Block& u = Ux_[q];
      u = work_[j];
      largestU = std::max(largestU, u.cwiseAbs().maxCoeff());
      // u held in a local copy: the compiler keeps it in registers over the
      // column (work_ and Ux_ could alias as far as it knows). A zero block of
      // U or L changes nothing (but the sign of a zero): the pile of a
      // collapse couples pairs of members that do not touch, whose blocks
      // are zero (a sixth of U's and a quarter of the products in the main
      // example with member contact).
      const Block uj = u;
      if (uj.isZero(0)) continue;
      for (int p = Lp_[j]; p < Lp_[j + 1]; ++p)
        if (!zeroL_[p]) work_[Li_[p]].noalias() -= Lx_[p] * uj;
    }
    Block& inv = Dinv_[k];
    inv = d.inverse();
    const double condition = norm1(d) * norm1(inv);
    if (!(condition <= kMaxPivotCondition)) {
      notStable_ = true;
      // The block's equation that moves most along its weakest direction.
      const Eigen::JacobiSVD<Block> svd(d, Eigen::ComputeFullV);
      int l = 0;
      svd.matrixV().col(kB - 1).cwiseAbs().maxCoeff(&l);
      singular_ = members_[kB * k + l] >= 0 ? members_[kB * k + l] : members_[kB * k];
      return Status::failure(
          "block-lu: a pivot block is singular to working precision (no pivoting between blocks)");
    }
    largestU = std::max(largestU, d.cwiseAbs().maxCoeff());
    for (int p = Lp_[k]; p < Lp_[k + 1]; ++p) {
      Lx_[p].noalias() = work_[Li_[p]] * inv;
      zeroL_[p] = Lx_[p].isZero(0);
    }
  }
  if (!(largestU <= kMaxGrowth * largestA)) {
    notStable_ = true;
    return Status::failure("block-lu: the factors' entries grow beyond the matrix's (no pivoting "
                           "between blocks)");
  }
  factored_ = true;
  return Status::success();
}

Status BlockLuSolver::solveFactored(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  for (int k = 0; k < nb_; ++k)
    for (int l = 0; l < kB; ++l) {
      const int eq = members_[kB * k + l];
      y_[k][l] = eq >= 0 ? b[eq] : 0.0;
    }
  for (int j = 0; j < nb_; ++j)
    for (int p = Lp_[j]; p < Lp_[j + 1]; ++p) y_[Li_[p]].noalias() -= Lx_[p] * y_[j];
  for (int k = nb_ - 1; k >= 0; --k) {
    y_[k] = (Dinv_[k] * y_[k]).eval();
    for (int q = Up_[k]; q < Up_[k + 1]; ++q) y_[Ui_[q]].noalias() -= Ux_[q] * y_[k];
  }
  for (int k = 0; k < nb_; ++k)
    for (int l = 0; l < kB; ++l)
      if (const int eq = members_[kB * k + l]; eq >= 0) x[eq] = y_[k][l];
  return Status::success();
}

}  // namespace c2d
