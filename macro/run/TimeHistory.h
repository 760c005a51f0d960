#pragma once
// TPLOt: time histories written every inc steps to <stem>_tplot.csv, with a
// header row: time, prop (table 1's factor, times the arc-length factor),
// with several load tables prop_1, prop_2, ... (each table's), then one column
// per requested quantity
// (disp_n_d, velo_n_d, acce_n_d, reac_n_d, stre_e_c; ener gives kinetic,
// strain, contact, external, total, dissipated, balance; mome gives momentum_x,
// momentum_y, angular_momentum; arcl gives the arc-length load factor).
// The file is written through "<name>.XXXXXX.part" (core/io/AtomicFile)
// and renamed when the run completes,
// so an interrupted run leaves nothing that looks complete; a run that fails or
// is interrupted keeps its rows as <stem>_tplot.failed.csv (keep()).
#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/io/AtomicFile.h"
#include "macro/deck/Parameters.h"
#include "macro/deck/Record.h"
#include "solvers/Analysis.h"

namespace c2d {

// The columns of a TPLOt `ener` record, in order (solvers/EnergyAccount.h).
inline constexpr std::array<const char*, 7> kEnergyColumns = {
    "kinetic", "strain", "contact", "external", "total", "dissipated", "balance"};
// The columns of a TPLOt `mome` record: linear momentum (x, y) and angular
// momentum about the origin (core/Assembler.h).
inline constexpr std::array<const char*, 3> kMomentumColumns = {"momentum_x", "momentum_y",
                                                                 "angular_momentum"};

class TimeHistory {
 public:
  enum class Kind { Disp, Velo, Acce, Reac, Stre, Ener, Arcl, Mome };
  struct Column {
    Kind kind;
    int index = 0;      // 0-based node or element
    int component = 0;  // 0-based dof or section force (N, V, M)
  };

  // The columns of TPLOt's records (DISP/VELO/ACCE/REAC node dof, STRE element
  // component, ENER, ARCL, MOME). Throws DeckError for a node, element or
  // component the model does not have.
  static std::vector<Column> columnsOf(const std::vector<Record>& data, const Parameters& params,
                                       const Model& model);

  // tables: the number of load tables in use (prop_k columns when above 1).
  TimeHistory(std::filesystem::path path, std::vector<Column> columns, int every, int tables = 1);
  // Writes a row for the committed step when step % every == 0 (reactions from
  // the residual the commit assembled).
  void record(Analysis& analysis, bool force = false);
  void finish();  // rename into place
  // The rows so far under AtomicFile::tagged(path(), tag); returns that path.
  std::filesystem::path keep(std::string_view tag) { return file_.keep(tag); }
  // Throws IoError when a row could not be written (a safe point of the run).
  void check() { file_.check(); }
  const std::filesystem::path& path() const { return file_.path(); }
  const std::vector<Column>& columns() const { return columns_; }
  // The values of the last row written (for plots and summaries).
  const std::vector<std::vector<double>>& rows() const { return rows_; }
  const std::vector<std::string>& header() const { return header_; }

 private:
  AtomicFile file_;
  std::vector<Column> columns_;
  std::vector<std::string> header_;
  std::vector<std::vector<double>> rows_;
  int every_ = 1;
  int tables_ = 1;
  int lastStep_ = -1;
};

}  // namespace c2d
