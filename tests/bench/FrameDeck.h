#pragma once
// Generator of the benchmark deck: an S-story, B-bay plane frame (story 3 m,
// bay 4 m, 0.3 x 0.4 m sections, E = 30 GPa) with N geometrically exact
// elements per member; vertical forces at the column tops in 10 steps (table 1),
// then a displacement-controlled push of the top-left node to 2% roof drift in
// 100 steps (table 2, FPROportional).
#include <sstream>
#include <string>

namespace c2d::bench {

inline std::string frameDeck(int stories, int bays, int perMember, int pushSteps = 100) {
  std::ostringstream d;
  const int cols = bays + 1;
  auto grid = [&](int i, int j) { return i * cols + j + 1; };
  d << "FEAP * * frame " << stories << " x " << bays << ", " << perMember << " elements per member\n"
    << "  0 0 0 2 3 2\n\nCOORdinates\n";
  for (int i = 0; i <= stories; ++i)
    for (int j = 0; j < cols; ++j) d << "  " << grid(i, j) << " 0 " << 4.0 * j << " " << 3.0 * i << "\n";
  int next = grid(stories, bays) + 1;
  std::ostringstream elems;
  int e = 1;
  auto member = [&](int a, int b, double xa, double ya, double xb, double yb) {
    int prev = a;
    for (int k = 1; k <= perMember; ++k) {
      int node = b;
      if (k < perMember) {
        node = next++;
        const double s = static_cast<double>(k) / perMember;
        d << "  " << node << " 0 " << xa + s * (xb - xa) << " " << ya + s * (yb - ya) << "\n";
      }
      elems << "  " << e++ << " 0 1 " << prev << " " << node << "\n";
      prev = node;
    }
  };
  for (int i = 0; i < stories; ++i)
    for (int j = 0; j < cols; ++j) member(grid(i, j), grid(i + 1, j), 4.0 * j, 3.0 * i, 4.0 * j, 3.0 * (i + 1));
  for (int i = 1; i <= stories; ++i)
    for (int j = 0; j < bays; ++j) member(grid(i, j), grid(i, j + 1), 4.0 * j, 3.0 * i, 4.0 * (j + 1), 3.0 * i);
  d << "\nELEMents\n" << elems.str() << "\nMATErial,1\n  FRAMe\n    ELAStic ISOTropic 30e6 0.2\n"
    << "    CROSs section 0.12 1.6e-3\n    FINIte\n\nBOUNdary\n";
  for (int j = 0; j < cols; ++j) d << "  " << grid(0, j) << " 0 1 1 1\n";
  const int top = grid(stories, 0);
  d << "  " << top << " 0 1 0 0\n\nFORCe\n";
  for (int i = 1; i <= stories; ++i)
    for (int j = 0; j < cols; ++j) d << "  " << grid(i, j) << " 0 0 -100 0\n";
  d << "\nFPROportional\n  " << top << " 0 2 0 0\n\nDISPlacement\n  " << top << " 0 "
    << 0.02 * 3.0 * stories << " 0 0\n\nEND\nBATCh\n  PROP,,1\n  PROP,,2\n  DT,,0.1\n"
    << "  LOOP,,10\n    TIME\n    LOOP,,20\n      TANG,,1\n    NEXT\n  NEXT\n"
    << "  DT,," << 1.0 / pushSteps << "\n  LOOP,," << pushSteps
    << "\n    TIME\n    LOOP,,20\n      TANG,,1\n    NEXT\n  NEXT\nEND\n"
    << "2\n  0 0 1 1 1000 1\n\n2\n  0 0 1 0 2 1\n\nSTOP\n";
  return d.str();
}

}  // namespace c2d::bench
