#include "macro/run/Report.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>

#include "core/Hinge.h"
#include "elements/JointedElement.h"

namespace c2d {

namespace {

void line(std::ostream& os, const char* fmt, ...) __attribute__((format(printf, 2, 3)));
void line(std::ostream& os, const char* fmt, ...) {
  char buf[512];
  va_list ap;
  va_start(ap, fmt);
  std::vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  os << buf << '\n';
}

// FEAP prints -0.0 as 0.0 after rounding to the printed digits; so do we.
double clean(double v) { return std::abs(v) < 5e-300 ? 0.0 : v; }

void title(std::ostream& os, const char* spaced, const State& s, double loadFactor) {
  line(os, "  %s   Time %12.5E   Prop. Ld. %12.5E", spaced, s.t, loadFactor);
}

}  // namespace

void printNodalTable(std::ostream& os, NodalQuantity q, const Model& model, const State& state,
                     double loadFactor, const Eigen::VectorXd& values,
                     const std::vector<int>& nodes, bool longFormat) {
  const char* spaced = "";
  const char* col = "";
  switch (q) {
    case NodalQuantity::Displacement:
      spaced = "N o d a l   D i s p l a c e m e n t s";
      col = "Displ";
      break;
    case NodalQuantity::Velocity:
      spaced = "N o d a l   V e l o c i t i e s";
      col = "Veloc";
      break;
    case NodalQuantity::Acceleration:
      spaced = "N o d a l   A c c e l e r a t i o n s";
      col = "Accel";
      break;
    case NodalQuantity::Reaction:
      spaced = "N o d a l   R e a c t i o n s";
      col = "Reac.";
      break;
  }
  title(os, spaced, state, loadFactor);
  if (longFormat)
    line(os, "   Node          1 Coord          2 Coord          1 %s          2 %s          3 %s",
         col, col, col);
  else
    line(os, "   Node     1 Coord     2 Coord     1 %s     2 %s     3 %s", col, col, col);
  double sum[3] = {0, 0, 0};
  for (int n : nodes) {
    const Vec2& x = model.coord(n);
    const double* v = values.data() + static_cast<Eigen::Index>(n) * kNodeDofs;
    // FEAP's FORM,LONG: e17.9 instead of e12.4.
    if (longFormat)
      line(os, "%7d %16.9E %16.9E %16.9E %16.9E %16.9E", n + 1, clean(x.x()), clean(x.y()),
           clean(v[0]), clean(v[1]), clean(v[2]));
    else
      line(os, "%7d %11.4E %11.4E %11.4E %11.4E %11.4E", n + 1, clean(x.x()), clean(x.y()),
           clean(v[0]), clean(v[1]), clean(v[2]));
    for (int d = 0; d < 3; ++d) sum[d] += v[d];
  }
  if (q == NodalQuantity::Reaction) {
    if (longFormat)
      line(os, "   Sum                                   %16.9E %16.9E %16.9E", clean(sum[0]),
           clean(sum[1]), clean(sum[2]));
    else
      line(os, "   Sum                         %11.4E %11.4E %11.4E", clean(sum[0]), clean(sum[1]),
           clean(sum[2]));
  }
  os << '\n';
}

void printStressTable(std::ostream& os, Model& model, const State& state, double loadFactor,
                      const std::vector<int>& elements) {
  title(os, "E l e m e n t   S e c t i o n   F o r c e s", state, loadFactor);
  line(os, "   Elmt  Matl       N            V            M");
  for (int e : elements) {
    if (!model.hasElement(e)) {
      line(os, "%7d  removed", e + 1);
      continue;
    }
    const SectionForces f = model.element(e).sectionForces();
    line(os, "%7d %5d %12.5E %12.5E %12.5E", e + 1, model.element(e).materialNumber(), clean(f.N),
         clean(f.V), clean(f.M));
  }
  os << '\n';
}

void printHingeTable(std::ostream& os, Model& model, const State& state, double loadFactor,
                     const std::vector<int>& activationStep) {
  title(os, "S o f t e n i n g   H i n g e s", state, loadFactor);
  line(os, "   Elmt  Step      x            y          Jump        Moment     State");
  int count = 0;
  for (int e = 0; e < model.numElements(); ++e) {
    if (!model.hasElement(e)) continue;
    const auto* h = dynamic_cast<const HingeCarrier*>(&model.element(e));
    if (!h) continue;
    const HingeInfo info = h->hinge();
    if (!info.active) continue;
    const auto nodes = model.element(e).nodes();
    const Vec2 p = (1 - info.position) * model.coord(nodes[0]) + info.position * model.coord(nodes[1]);
    const int step = e < static_cast<int>(activationStep.size()) ? activationStep[e] : 0;
    line(os, "%7d %5d %12.5E %12.5E %12.5E %12.5E  %s", e + 1, step, clean(p.x()), clean(p.y()),
         clean(info.jump), clean(info.moment), info.failed ? "failed" : "active");
    ++count;
  }
  // Hinges at the element ends (HINGes ENDS, SECTion): the joints carrying
  // their laws, at their nodes or at the faces of rigid end zones (reference
  // positions); Jump is the joint's relative rotation.
  for (int e = 0; e < model.numElements(); ++e) {
    if (!model.hasElement(e)) continue;
    for (const JointedElement* j = asJointed(&model.element(e)); j; j = asJointed(&j->inner())) {
      if (!j->hingeLaw()) continue;
      const HingeInfo info = j->hingeInfo();
      const Vec2 p = model.coord(j->masterNode()) + j->arm();
      const int step = e < static_cast<int>(activationStep.size()) ? activationStep[e] : 0;
      line(os, "%7d %5d %12.5E %12.5E %12.5E %12.5E  %s, end %d", e + 1, step, clean(p.x()),
           clean(p.y()), clean(info.jump), clean(info.moment), info.failed ? "failed" : "active",
           static_cast<int>(info.position) + 1);
      ++count;
    }
  }
  line(os, "   %d hinges", count);
  os << '\n';
}

}  // namespace c2d
