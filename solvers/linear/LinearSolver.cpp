#include "solvers/linear/LinearSolver.h"

#include "solvers/linear/AutoSolver.h"
#include "solvers/linear/BlockLuSolver.h"
#include "solvers/linear/CholmodSolver.h"
#include "solvers/linear/EigenLdltSolver.h"
#include "solvers/linear/EigenLuSolver.h"
#include "solvers/linear/KluSolver.h"
#include "solvers/linear/UmfpackSolver.h"

namespace c2d {

std::unique_ptr<LinearSolver> makeLinearSolver(std::string_view name) {
  if (name == "auto") return std::make_unique<AutoSolver>();
  if (name == "cholmod") return std::make_unique<CholmodSolver>();
  if (name == "umfpack") return std::make_unique<UmfpackSolver>();
  if (name == "klu") return std::make_unique<KluSolver>();
  if (name == "block-lu") return std::make_unique<BlockLuSolver>();
  if (name == "eigen-ldlt") return std::make_unique<EigenLdltSolver>();
  if (name == "eigen-lu") return std::make_unique<EigenLuSolver>();
  return nullptr;
}

std::vector<std::string> linearSolverNames() {
  return {"auto", "cholmod", "umfpack", "klu", "block-lu", "eigen-ldlt", "eigen-lu"};
}

}  // namespace c2d
