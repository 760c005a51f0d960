#pragma once
// Shared by the restart tests (RestartTest, RestartFileTest): a portal that
// fails, forms hinges and joints and collapses, its loads and time histories,
// and the batch of its failure phase up to the save.
#include <string>

namespace c2d::testing {

// A fixed-base portal (columns 3 m, beam 4 m, two elements per member) with the
// six-story frame's sections: vertical loads P at the top corners (table 1),
// then a horizontal displacement of the top left node (table 2) until four
// hinges have formed (beam ends at t = 1.6255, column bases at t = 1.6638).
inline const char* const kPortal = R"(PARAmeter
  h = 3
  b = 4
  ne = 2
  P = 50

FEAP * * portal: failure, HINGE2JOINT, collapse
  0 0 0 2 3 2

COORdinates
  1 1 0 0
  ne+1 1 0 h
  2*ne+1 1 b h
  3*ne+1 0 b 0

ELEMents
  1 1 1 1 2
  ne+1 1 2 ne+1 ne+2
  2*ne+1 1 1 2*ne+1 2*ne+2
  3*ne 0 1 3*ne 3*ne+1

MATErial,1 columns
  FRAMe
    RESUltant STIFfness 3.6e6 1.2e6 48000
    CROSs section 0.12 1.6e-3
    DENSity,,2.5
    HARDening BILInear 100 245 12450 195
    SOFTening LINEar 265 -723

MATErial,2 beam
  FRAMe
    RESUltant STIFfness 3.6e6 1.2e6 48000
    CROSs section 0.12 1.6e-3
    DENSity,,2.5
    HARDening BILInear 30 150 11190 137
    SOFTening LINEar 170 -393

BOUNdary
  1 0 1 1 1
  3*ne+1 0 1 1 1
  ne+1 0 1 0 0

FORCe
  ne+1 0 0 -P 0
  2*ne+1 0 0 -P 0

FPROportional
  ne+1 0 2 0 0

DISPlacement
  ne+1 0 1 0 0

END
BATCh
)";

// Its load tables (1: the vertical loads, 2: the sway to t = 1.6) and the
// TPLOt records of the restart tests.
inline const char* const kLoads = "2\n  0 0 1 1 1e6 1\n\n2\n  0 0 1 0 2 0.6 10 1.6\n\n";
inline const char* const kTplot =
    "disp,ne+1,1\ndisp,ne+1,2\nreac,ne+1,1\nstre,1,3\nstre,3,3\nener\n\n";

// n steps of TIME, each with at most 30 Newton iterations.
inline std::string newtonLoop(const std::string& time, int n) {
  return "  LOOP,," + std::to_string(n) + "\n    " + time +
         "\n    LOOP,,30\n      TANG,,1\n    NEXT\n  NEXT\n";
}

// The failure phase, split at t = 1.64 (between the beam hinges and the column hinges).
inline const std::string kStart =
    "  PROP,,1\n  PROP,,2\n  AUTO,CUT,1e-6\n  TPLOt\n  DT,,0.25\n" + newtonLoop("TIME", 4) +
    "  DT,,0.02\n" + newtonLoop("TIME,,1.64", 1000);

}  // namespace c2d::testing
