#pragma once
// Shared by the element tests: the tangent by central differences of an
// element's residual.
#include <gtest/gtest.h>

#include "core/Element.h"

namespace c2d::test {

// dr/dd by central differences with step h, each residual evaluated without tangent.
inline ElemMat centralDifferenceTangent(Element& e, const ElementKinematics& kin,
                                        const StepRule& rule, double h = 1e-6) {
  ElemMat fd;
  for (int j = 0; j < kElemDofs; ++j) {
    ElementKinematics kp = kin, km = kin;
    kp.d(j) += h;
    km.d(j) -= h;
    ElemVec rp, rm;
    ElemMat unused;
    EXPECT_TRUE(e.evaluate(kp, rule, false, rp, unused).ok);
    EXPECT_TRUE(e.evaluate(km, rule, false, rm, unused).ok);
    fd.col(j) = (rp - rm) / (2 * h);
  }
  return fd;
}

}  // namespace c2d::test
