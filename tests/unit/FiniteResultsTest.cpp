// solvers/FiniteResults: the first value of a committed state, its nodal
// forces, section forces or energies that is not a finite number is named.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "solvers/FiniteResults.h"

namespace c2d {
namespace {

TEST(FiniteResults, TheFirstValueThatIsNotFiniteIsNamed) {
  Model model;
  model.resizeNodes(2);
  State s;
  s.resize(2);
  Eigen::VectorXd r = Eigen::VectorXd::Zero(6);
  Energy e;
  EXPECT_EQ(nonFiniteResult(model, s, r, e), "");
  const double inf = std::numeric_limits<double>::infinity();
  e.contact = inf;
  EXPECT_EQ(nonFiniteResult(model, s, r, e), "the contact energy is inf");
  r[4] = std::nan("");
  EXPECT_EQ(nonFiniteResult(model, s, r, e), "the nodal force (reaction) of node 2, dof 2 is nan");
  s.v[3] = -inf;
  EXPECT_EQ(nonFiniteResult(model, s, r, e), "the velocity of node 2, dof 1 is -inf");
  s.u[2] = inf;
  EXPECT_EQ(nonFiniteResult(model, s, r, e), "the displacement of node 1, dof 3 is inf");
}

}  // namespace
}  // namespace c2d
