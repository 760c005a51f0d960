#pragma once
// The material sub-records of the bending laws (deck language section 5):
//   HARDening BILInear Mc My Kh1 Kh2 / HARDening NEGAtive Mc My Kh1 Kh2
//   SOFTening LINEar Mu Ks [thetaR [Mr]] / SOFTening NEGAtive Mu Ks
//   SECTion RECTangular b h fc fy [Es [fu eu]] (or TEE, CIRCular, ANNUlar:
//     macro/mesh/SectionShapeRecords) with REBAr d1 A1 [d2 A2 ...] (or
//     REBAr RING n A c) and STIRrups Asw s [fyw]
//   INTEraction CURVe N1 Mu1 N2 Mu2 ...
//   HINGes ENDS / HINGes MIDPoint
// Their specs (--help), binding into a MaterialSet, the checks that need the
// whole set, the derivation of an RC section's laws and the log's echo.
#include <ostream>
#include <vector>

#include "core/MaterialSet.h"
#include "macro/deck/CommandSpec.h"
#include "macro/mesh/MeshCommands.h"

namespace c2d {

// A REBAr RING record's values (its bars are placed once the shape is known).
struct RingRecord {
  const Record* record = nullptr;
  int n = 0;
  double area = 0, cover = 0;
};

// The records of one MATErial set that these sub-records gave.
struct LawRecords {
  const Record* hardening = nullptr;
  const Record* hardeningNeg = nullptr;
  const Record* softening = nullptr;
  const Record* softeningNeg = nullptr;
  const Record* section = nullptr;
  std::vector<const Record*> rebar;  // layers (REBAr d1 A1 ...)
  std::vector<RingRecord> rings;     // REBAr RING n A c
  const Record* stirrups = nullptr;
  const Record* interaction = nullptr;
  const Record* hinges = nullptr;
};

void registerLawRecords(CommandRegistry& registry);
// Binds record r (spec s) when it is one of these sub-records; false otherwise.
bool bindLawRecord(MeshContext& ctx, const Record& r, const CommandSpec& s, MaterialSet& mat,
                   LawRecords& seen);
// After the set's records (head: MATErial,m; the records that gave the elastic
// data, or null): the checks that need the whole set and the derivation of
// the section's laws (materials/SectionLaws.h). DeckError at the record at
// fault.
void finishLawRecords(const Record& head, const LawRecords& seen, MaterialSet& mat,
                      const Record* elastic, const Record* cross, const Record* resultant);
// The laws' lines of the material echo: hardening and softening (both signs),
// hinge site, interaction curve, and an RC section's data with everything
// derived from it (materials/RcSection.h says how).
void echoLaws(std::ostream& os, const MaterialSet& mat);

}  // namespace c2d
