// Cost of one element evaluation (residual, with or without the tangent), the
// unit of every assembly: the geometrically exact frame under statics and the
// mid-point scheme, the same frame with the hardening and softening laws
// (members that keep their strength; the target is at most 1.5 times the
// elastic one), and the frame behind a condensed joint. The six-story
// collapse evaluates 288 of them about 16000 times.
// Run: build/tests/benchmarks --benchmark_filter=Element
#include <benchmark/benchmark.h>

#include <array>
#include <memory>

#include "core/MaterialSet.h"
#include "core/StepRule.h"
#include "elements/JointedElement.h"
#include "elements/ReissnerFrame.h"
#include "solvers/TimeIntegrator.h"
#include "tests/unit/FrameMaterialSupport.h"

namespace {

using namespace c2d;

MaterialSet frameMaterial() {
  return test::resultantFrame(Kinematics::Finite, 3.6e6, 1.2e6, 4.8e4, 2.5, 0.12, 1.6e-3);
}

// A deformed state and a committed one a step earlier (rotations of a falling member).
ElementKinematics kinematics() {
  ElementKinematics k;
  k.dn << 0.30, -0.20, 0.40, 0.35, -0.45, 0.55;
  k.d << 0.31, -0.21, 0.41, 0.36, -0.47, 0.56;
  k.vn << 0.2, -0.2, 0.1, 0.2, -0.3, 0.1;
  k.an.setZero();
  return k;
}

StepRule rule(bool midPoint) {
  return midPoint ? TimeIntegrator::midPoint(0.1, 0.1).rule(0.05)
                  : TimeIntegrator::statics().rule(0.05);
}

// Evaluations of `e` under the benchmark's arguments.
void evaluateRepeatedly(benchmark::State& st, Element& e) {
  const bool midPoint = st.range(0) != 0, tangent = st.range(1) != 0;
  const ElementKinematics kin = kinematics();
  const StepRule r = rule(midPoint);
  ElemVec f;
  ElemMat k;
  for (auto _ : st) {
    benchmark::DoNotOptimize(e.evaluate(kin, r, tangent, f, k));
    benchmark::DoNotOptimize(f.data());
    benchmark::DoNotOptimize(k.data());
  }
}

void BM_ElementReissner(benchmark::State& st) {
  ReissnerFrame e(frameMaterial(), {0, 1}, Vec2(0, 0), Vec2(0, 0.375));
  evaluateRepeatedly(st, e);
}

// The six-story columns' laws; the state above is on the second hardening branch.
void BM_ElementReissnerInelastic(benchmark::State& st) {
  MaterialSet m = frameMaterial();
  m.hardening = HardeningData{100, 245, 12450, 195};
  m.softening = SofteningData{265, -723, std::nullopt};
  ReissnerFrame e(m, {0, 1}, Vec2(0, 0), Vec2(0, 0.375));
  evaluateRepeatedly(st, e);
}

void BM_ElementJointed(benchmark::State& st) {
  JointedElement e(std::make_unique<ReissnerFrame>(frameMaterial(), std::array{0, 1}, Vec2(0, 0),
                                                   Vec2(0, 0.375)),
                   1, 2);
  evaluateRepeatedly(st, e);
}

}  // namespace

// Arguments: mid-point scheme (0 statics), tangent (0 residual only).
BENCHMARK(BM_ElementReissner)->ArgsProduct({{0, 1}, {0, 1}});
BENCHMARK(BM_ElementReissnerInelastic)->ArgsProduct({{0, 1}, {0, 1}});
BENCHMARK(BM_ElementJointed)->ArgsProduct({{0, 1}, {0, 1}});
