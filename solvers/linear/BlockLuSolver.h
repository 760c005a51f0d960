#pragma once
// Sparse LU on dense blocks: the equations of one node (up to three) form a
// 3x3 block, the blocks are ordered by AMD on the graph of the nodes, and the
// factorization is left-looking over block columns with a fixed pivot order:
// no pivoting between blocks, the diagonal blocks inverted. A frame's tangent
// couples every dof of a node with every dof of its neighbours, so the blocks
// are dense and the kernel is a 3x3 product where a scalar sparse LU (KLU)
// gathers and scatters each entry: a factorization and solve takes half of
// KLU's refactorization time at the ten-storey decks' size, and 0.35-0.45 of
// it at 10k-40k unknowns (benchmark factorizeAndSolve).
//
// Without pivoting it suits matrices whose diagonal blocks dominate, as a
// dynamic tangent's (mass / (beta dt^2) + K) do. A factorization whose pivot
// block is near singular, or whose entries grow by more than kMaxGrowth over
// the matrix's, fails (notStable()): the caller then factors with pivoting.
#include <Eigen/Dense>
#include <vector>

#include "solvers/linear/DirectSolver.h"

namespace c2d {

class BlockLuSolver final : public DirectSolver {
 public:
  std::string name() const override { return "block-lu"; }
  void groupEquations(std::vector<int> group) override { group_ = std::move(group); }
  Status analyze(const SparseMatrix& A, bool symmetric) override;
  Status factorize(const SparseMatrix& A) override;
  int singularEquation() const override { return singular_; }

  // The last factorize() failed for want of pivoting (a near-singular pivot
  // block or growth of the entries), not for bad input.
  bool notStable() const { return notStable_; }
  int numBlocks() const { return nb_; }

 private:
  Status solveFactored(const Eigen::VectorXd& b, Eigen::VectorXd& x) override;

  using Block = Eigen::Matrix3d;
  using BlockVec = Eigen::Vector3d;

  void makeBlocks(int n);
  // Returns the block graph in factor order.
  std::vector<std::vector<int>> orderBlocks(const SparseMatrix& A);
  void symbolic(const std::vector<std::vector<int>>& adjacent);

  std::vector<int> group_;         // the caller's grouping of the equations
  int n_ = 0, nb_ = 0;
  std::vector<int> members_;       // equations of block b: members_[3b..3b+2], -1 pads
  std::vector<int> blockOf_;       // block (in factor order) of each equation
  std::vector<int> slot_;          // its row or column within the block
  // Per entry of A: its place in work_ (the block of its row, in factor
  // order, and its place within that block, column-major).
  std::vector<int> target_;
  std::vector<int> Lp_, Li_;       // block rows below the diagonal, per block column
  std::vector<int> Up_, Ui_;       // block rows above the diagonal, per block column
  std::vector<Block> Lx_, Ux_, Dinv_, work_;
  std::vector<char> zeroL_;        // per block of L: all its entries zero
  std::vector<BlockVec> y_;
  bool notStable_ = false;
  int singular_ = -1;
};

}  // namespace c2d
