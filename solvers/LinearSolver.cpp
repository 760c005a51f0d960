#include "solvers/LinearSolver.h"

#include "solvers/AutoSolver.h"
#include "solvers/BlockLuSolver.h"
#include "solvers/CholmodSolver.h"
#include "solvers/EigenLdltSolver.h"
#include "solvers/EigenLuSolver.h"
#include "solvers/KluSolver.h"
#include "solvers/UmfpackSolver.h"

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
