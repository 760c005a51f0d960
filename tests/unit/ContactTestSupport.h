#pragma once
// Shared by the contact tests: rods of geometrically exact elements, positions,
// linear momentum, the assembled tangent against central differences of the
// assembled residual and the zero crossings of a time history (a time step's
// Newton iterations: ElementTestSupport.h).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "core/Assembler.h"
#include "core/Model.h"
#include "core/State.h"
#include "elements/ReissnerFrame.h"
#include "solvers/Analysis.h"
#include "tests/unit/ElementTestSupport.h"

namespace c2d::test {

inline constexpr double kGravity = 9.81;

// Resultant stiffnesses; mass rhoA per length and rotary inertia rhoI per
// length (density 1: A = rhoA, I = rhoI, so that the contact radius is
// sqrt(3 rhoI / rhoA)).
inline MaterialSet rod(int number, double ea, double ga, double ei, double rhoA, double rhoI) {
  MaterialSet m;
  m.number = number;
  m.elementType = "FRAMe";
  m.kinematics = Kinematics::Finite;
  m.resEA = ea;
  m.resGA = ga;
  m.resEI = ei;
  m.density = 1.0;
  m.A = rhoA;
  m.I = rhoI;
  return m;
}

// n elements of material `mat` on a straight line from node `from` to a new
// end point; returns the last node.
inline int addRod(Model& m, int from, const Vec2& to, int n, int mat = 1) {
  const Vec2 x0 = m.coord(from);
  int prev = from;
  for (int i = 1; i <= n; ++i) {
    const int node = m.addNode(x0 + (to - x0) * (double(i) / n));
    m.setElement(m.numElements(),
                 std::make_unique<ReissnerFrame>(m.materials().at(mat), std::array{prev, node},
                                                 m.coord(prev), m.coord(node)));
    prev = node;
  }
  return prev;
}

// The tangent tests' state: positions at t_n of amplitude u0 and a step of
// amplitude du, both varying from dof to dof, and rates at t_n.
inline void scatteredState(State& s, double u0, double du) {
  for (int i = 0; i < s.u.size(); ++i) {
    s.un(i) = u0 * std::sin(1.3 * i);
    s.u(i) = s.un(i) + du * std::cos(0.7 * i);
    s.vn(i) = 0.3 * std::sin(2.1 * i);
    s.an(i) = std::cos(0.4 * i);
  }
}

// A rod from a to b in a new chain of nodes; returns its first node.
inline int newRod(Model& m, const Vec2& a, const Vec2& b, int n, int mat = 1) {
  const int first = m.addNode(a);
  addRod(m, first, b, n, mat);
  return first;
}

inline Vec2 position(const Model& m, const State& s, int node) {
  return m.coord(node) + s.u.segment<2>(3 * node);
}

// Linear momentum sum M v over the elements (translations).
inline Vec2 linearMomentum(const Model& m, const State& s) {
  Vec2 p = Vec2::Zero();
  for (int e = 0; e < m.numElements(); ++e) {
    const Element& el = m.element(e);
    const auto nodes = el.nodes();
    ElemVec v;
    for (int a = 0; a < 2; ++a) v.segment<3>(3 * a) = s.v.segment<3>(3 * nodes[a]);
    const ElemVec mv = el.mass() * v;
    p += mv.segment<2>(0) + mv.segment<2>(3);
  }
  return p;
}

inline double totalMass(const Model& m) {
  double total = 0;
  for (int e = 0; e < m.numElements(); ++e) {
    const ElemMat me = m.element(e).mass();
    total += me(0, 0) + me(0, 3) + me(3, 0) + me(3, 3);
  }
  return total;
}

// Largest difference between the assembled tangent and central differences of
// the assembled residual, relative to the tangent's largest entry.
inline double tangentError(Model& m, State& s, const StepRule& rule, double h = 1e-7) {
  Assembler as(m);
  as.refresh();
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(s.u.size());
  EXPECT_TRUE(as.assemble(s, rule, ones, true).ok);
  const Eigen::MatrixXd k = Eigen::MatrixXd(as.tangent());
  const DofMap& dofs = as.dofs();
  Eigen::MatrixXd fd = Eigen::MatrixXd::Zero(dofs.numEquations(), dofs.numEquations());
  for (int n = 0; n < m.numNodes(); ++n)
    for (int d = 0; d < 3; ++d) {
      const int eq = dofs.eq(n, d);
      if (eq < 0 || dofs.aliased(n)) continue;
      Eigen::VectorXd rp, rm;
      s.u(3 * n + d) += h;
      EXPECT_TRUE(as.assemble(s, rule, ones, false).ok);
      as.toEquations(as.nodalResidual(), rp);
      s.u(3 * n + d) -= 2 * h;
      EXPECT_TRUE(as.assemble(s, rule, ones, false).ok);
      as.toEquations(as.nodalResidual(), rm);
      s.u(3 * n + d) += h;
      fd.col(eq) = (rp - rm) / (2 * h);
    }
  return (fd - k).cwiseAbs().maxCoeff() / k.cwiseAbs().maxCoeff();
}

// Roots of y(t) from cubic interpolation through the four samples around each
// sign change.
inline std::vector<double> zeroCrossings(const std::vector<double>& t,
                                         const std::vector<double>& y) {
  std::vector<double> roots;
  for (size_t i = 1; i + 2 < y.size(); ++i) {
    if ((y[i] > 0) == (y[i + 1] > 0)) continue;
    auto p = [&](double x, double& dp) {
      double v = 0;
      dp = 0;
      for (size_t a = i - 1; a <= i + 2; ++a) {
        double la = 1, dla = 0;
        for (size_t b = i - 1; b <= i + 2; ++b) {
          if (b == a) continue;
          dla = dla * (x - t[b]) / (t[a] - t[b]) + la / (t[a] - t[b]);
          la *= (x - t[b]) / (t[a] - t[b]);
        }
        v += y[a] * la;
        dp += y[a] * dla;
      }
      return v;
    };
    double x = t[i] - y[i] * (t[i + 1] - t[i]) / (y[i + 1] - y[i]);
    for (int it = 0; it < 20; ++it) {
      double dp = 0;
      const double v = p(x, dp);
      x -= v / dp;
    }
    roots.push_back(x);
  }
  return roots;
}

}  // namespace c2d::test
