#include "macro/run/HingesToJoints.h"

#include "macro/output/NumberText.h"

namespace c2d {

std::vector<CreatedJoint> turnHingesToJoints(Model& model, Analysis& analysis, MemberLaws laws,
                                             std::ostream& log) {
  const std::vector<CreatedJoint> joints = hingeToJoint(model, analysis.state(), laws);
  analysis.topologyChanged();
  log << "  HINGE2JOINT  " << joints.size() << " hinges became joints, members "
      << (laws == MemberLaws::Elastic ? "elastic" : "keep their laws") << "; " << model.numNodes()
      << " nodes, " << analysis.assembler().dofs().numEquations() << " equations\n";
  for (const CreatedJoint& j : joints)
    log << "    element " << j.element + 1 << ": joint master " << j.master + 1 << " slave "
        << j.slave + 1 << " (element end " << j.slaveEnd + 1 << "), relative rotation "
        << formatNumber("%.6e", j.relativeRotation) << "\n";
  return joints;
}

}  // namespace c2d
