// The Newton loop allocates nothing: after the first iteration of a topology
// (pattern, symbolic factorization, work vectors), further iterations and steps
// call operator new zero times. Counted by replacing the global operator new in
// this test binary (the count is only read while a test arms it).
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <new>

#include "core/Model.h"
#include "elements/ElementFactory.h"
#include "solvers/Analysis.h"
#include "solvers/TimeIntegrator.h"
#include "tests/unit/FrameMaterialSupport.h"

namespace {
std::atomic<long> gAllocations{0};
std::atomic<bool> gCounting{false};
}  // namespace

void* operator new(std::size_t n) {
  if (gCounting.load(std::memory_order_relaxed)) gAllocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace c2d {
namespace {

// A cantilever of geometrically exact elements under a growing end moment.
Model rollupModel(int n, Kinematics kin) {
  Model m;
  m.resizeNodes(n + 1);
  for (int i = 0; i <= n; ++i) m.setCoord(i, Vec2(10.0 * i / n, 0.0));
  const MaterialSet mat = test::resultantFrame(kin, 1e6, 1e6, 100, 1.0, 1.0, 0.01);
  m.materials()[1] = mat;
  for (int e = 0; e < n; ++e) m.setElement(e, makeElement(mat, {e, e + 1}, m.coord(e), m.coord(e + 1)));
  m.bound(0) = {1, 1, 1};
  m.force(n) = {0, 0, 2 * 3.14159 * 100 / 10};
  return m;
}

long countedSteps(Analysis& a, int steps) {
  gAllocations = 0;
  for (int s = 0; s < steps; ++s) {
    gCounting = true;
    EXPECT_TRUE(a.advance().ok);
    for (int it = 0; it < 30; ++it) {
      IterationInfo info;
      EXPECT_TRUE(a.iterate(false, true, info).ok);
      if (info.converged) break;
    }
    gCounting = false;
    EXPECT_TRUE(a.stepConverged());
  }
  return gAllocations.load();
}

TEST(NoAllocation, CounterSeesAnAllocation) {
  gAllocations = 0;
  gCounting = true;
  auto p = std::make_unique<double>(1.0);
  gCounting = false;
  EXPECT_EQ(gAllocations.load(), 1);
}

TEST(NoAllocation, StaticNewtonLoopOfGeometricallyExactBeams) {
  Model m = rollupModel(20, Kinematics::Finite);
  Analysis a(m);
  a.setLoadFunction(1, ProportionalLoad::ramp());
  a.setDt(0.05);
  countedSteps(a, 1);  // first step: pattern, symbolic analysis, work vectors
  EXPECT_EQ(countedSteps(a, 5), 0);
}

TEST(NoAllocation, DynamicMidPointNewtonLoop) {
  Model m = rollupModel(20, Kinematics::Finite);
  Analysis a(m);
  a.setIntegrator(TimeIntegrator::midPoint(0.1, 0.1));
  a.setDt(0.01);
  countedSteps(a, 1);
  EXPECT_EQ(countedSteps(a, 5), 0);
}

TEST(NoAllocation, MemberContactAndGroundFriction) {
  // A bar of 4 elements resting across a fixed beam of 8 (member contact) and
  // the beam's neighbour, a bar sliding on the ground with friction: after the
  // first step the contact pairs are in the pattern and the search's arrays
  // have their size.
  Model m;
  // Contact radius sqrt(3 I / A) = sqrt(3e-3).
  const MaterialSet mat = test::resultantFrame(Kinematics::Finite, 1e7, 1e7, 1e4, 1.0, 1.0, 1e-3);
  m.materials()[1] = mat;
  const double h = 2 * std::sqrt(3e-3);
  auto line = [&](Vec2 a, Vec2 b, int n) {
    const int first = m.numNodes();
    m.resizeNodes(first + n + 1);
    for (int i = 0; i <= n; ++i) m.setCoord(first + i, a + (b - a) * (double(i) / n));
    for (int e = 0; e < n; ++e)
      m.setElement(m.numElements(), makeElement(mat, {first + e, first + e + 1},
                                                m.coord(first + e), m.coord(first + e + 1)));
    return first;
  };
  const int beam = line(Vec2(0, 1), Vec2(4, 1), 8);
  for (int n = beam; n <= beam + 8; ++n) m.bound(n) = {1, 1, 1};
  const int bar = line(Vec2(0.55, 1.5), Vec2(1.45, 1.5), 4);
  line(Vec2(5, 0), Vec2(6, 0), 2);
  m.gravity() = Vec2(1.0, -9.81);
  m.ground() = Ground{0.0, 1e5, -1, 0.3};
  m.memberContact() = MemberContactData{1e5, -1, -1};
  Analysis a(m);
  a.setIntegrator(TimeIntegrator::midPoint(0.1, 0.1));
  a.setDt(0.01);
  // The bar starts inside the contact distance (it lies 0.5 higher in the
  // reference configuration).
  State& s = a.state();
  s.resize(m.numNodes());
  for (int n = bar; n <= bar + 4; ++n) s.u(3 * n + 1) = s.un(3 * n + 1) = h - 0.5 - 1e-4;
  countedSteps(a, 1);
  EXPECT_GT(a.energy().contact, 0.0);
  EXPECT_EQ(countedSteps(a, 5), 0);
  EXPECT_GT(a.energy().contact, 0.0);
}

}  // namespace
}  // namespace c2d
