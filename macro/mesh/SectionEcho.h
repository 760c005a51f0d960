#pragma once
// The log's echo of an RC section (SECTion, REBAr, STIRrups): its data and
// everything derived from it (materials/RcSection.h, Confinement.h,
// HingeLength.h say how).
#include <ostream>
#include <string>

#include "core/MaterialSet.h"

namespace c2d {

// One line "name value" of the material echo.
void echoLine(std::ostream& os, const std::string& name, double v);
// Requires mat.rc.
void echoSection(std::ostream& os, const MaterialSet& mat);

}  // namespace c2d
