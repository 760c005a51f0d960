// The member contact pairs' step starts (core/contact/PairStarts): what a pair
// keeps over a step's iterations follows the state at t_n.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "ContactTestSupport.h"
#include "core/contact/MemberContact.h"
#include "solvers/TimeIntegrator.h"

namespace c2d {
namespace {

using test::newRod;
using test::rod;

TEST(MemberContactModel, APairsKeptStepStartFollowsTheStateAtTn) {
  // evaluate() keeps what a pair's step start gives (memory, side, reach,
  // penetration at t_n, law) over the step's iterations. A change of the
  // pair memory or of the rates at t_n at the same positions starts anew:
  // the forces are those a member contact that kept nothing finds.
  Model m;
  m.materials()[1] = rod(1, 2e3, 1e3, 30.0, 1.0, 1e-3);    // r = 0.055
  m.materials()[2] = rod(2, 4e3, 2e3, 50.0, 2.0, 1.5e-3);  // r = 0.047
  newRod(m, Vec2(-0.2, 0.09), Vec2(1.2, 0.02), 4);
  const int bar = newRod(m, Vec2(-0.3, -0.51), Vec2(1.1, -0.5), 4, 2);
  m.memberContact() = MemberContactData{5e3, 0.5, -1, 0.5, 0.3};
  State s;
  s.resize(m.numNodes());
  test::scatteredState(s, 0.004, 0.006);
  for (int n = bar; n < m.numNodes(); ++n) {
    s.un(3 * n + 1) += 0.5;
    s.u(3 * n + 1) += 0.5;
  }
  const StepRule rule = TimeIntegrator::newmark(0.25, 0.5).rule(0.05);
  // Every candidate's force (zero where it has none), the keys of those with one.
  auto forces = [&](MemberContact& mc, std::vector<std::uint64_t>* touching = nullptr) {
    const MemberContact::Nearby nearby = mc.nearby(m, s, mc.slack());
    std::vector<double> out;
    PairVec f;
    PairMat k;
    for (std::size_t i = 0; i < nearby.candidates.size(); ++i) {
      f.setZero();
      if (mc.evaluate(static_cast<int>(i), m, s, rule, true, f, k) && touching)
        touching->push_back(nearby.candidates[i].key());
      out.insert(out.end(), f.data(), f.data() + f.size());
    }
    return out;
  };
  Assembler kept(m);
  kept.refresh();
  std::vector<std::uint64_t> touching;
  forces(*kept.memberContact(), &touching);
  ASSERT_GE(touching.size(), 2u);
  auto fresh = [&] {
    Assembler a(m);
    a.refresh();
    return forces(*a.memberContact());
  };
  // The rates at t_n (Newmark's dashpot reads them).
  for (int i = 0; i < s.u.size(); ++i) {
    s.vn(i) += 0.2 * std::cos(1.7 * i);
    s.an(i) -= 0.5 * std::sin(0.9 * i);
  }
  EXPECT_EQ(forces(*kept.memberContact()), fresh());
  // A memory: a loading point beyond the present penetration (the pair
  // unloads on its crushing branch) and a stretched friction spring.
  s.pairs = {PairMemory{touching[0], 0.05, 0.0, 0.002, 0.102, 0}};
  EXPECT_EQ(forces(*kept.memberContact()), fresh());
}

}  // namespace
}  // namespace c2d
