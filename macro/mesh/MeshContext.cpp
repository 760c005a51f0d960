// The state of one mesh input (MeshContext: numbers, nodes, elements and
// materials read from records, with their checks) and the building blocks the
// mesh command families share (meshspec: specs, located errors, the echo).
#include "macro/mesh/MeshCommands.h"

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <ostream>

#include "macro/deck/Limits.h"

namespace c2d {

using namespace meshspec;

// ---------------------------------------------------------------------------
// MeshContext helpers

double MeshContext::number(const Record& r, std::size_t i) const {
  if (i >= r.size()) return 0.0;
  return Expression::parse(r[i]).eval(params);
}

int MeshContext::integer(const Record& r, std::size_t i, std::string_view what) const {
  if (i >= r.size()) return 0;
  return Expression::parse(r[i]).evalInt(params, what);
}

void MeshContext::ensureNode(long long n, const Record& r, std::size_t i) {
  if (n < 1)
    throw DeckError(r.fieldLoc(i),
                    "node " + std::to_string(n) + " does not exist (nodes start at 1)",
                    r.excerpt(r.fieldLoc(i)));
  if (maxNodes > 0 && n > maxNodes)
    throw DeckError(r.fieldLoc(i),
                    "node " + std::to_string(n) + " is beyond numnp = " + std::to_string(maxNodes) +
                        " of the control record",
                    r.excerpt(r.fieldLoc(i)), "raise numnp, or set it to 0 to have nodes counted");
  checkNumber(r, i, n, DeckLimits::maxNodes(), "node");
  if (n > model.numNodes()) model.resizeNodes(static_cast<int>(n));
}

int MeshContext::node(const Record& r, std::size_t i, std::string_view what) {
  const int n = integer(r, i, what);
  if (n < 1)
    throw DeckError(r.fieldLoc(i),
                    std::string(what) + " must be positive, got " + std::to_string(n),
                    r.excerpt(r.fieldLoc(i)));
  ensureNode(n, r, i);
  return n;
}

int MeshContext::elementNumber(const Record& r, std::size_t i, bool withinNumel) {
  const int e = integer(r, i, "element number");
  if (e < 1)
    throw DeckError(r.fieldLoc(i), "element number must be positive, got " + std::to_string(e),
                    r.excerpt(r.fieldLoc(i)));
  if (withinNumel && maxElements > 0 && e > maxElements)
    throw DeckError(
        r.fieldLoc(i),
        "element " + std::to_string(e) + " is beyond numel = " + std::to_string(maxElements) +
            " of the control record",
        r.excerpt(r.fieldLoc(i)), "raise numel, or set it to 0 to have elements counted");
  checkNumber(r, i, e, DeckLimits::maxElements(), "element");
  return e;
}

int MeshContext::materialNumber(const Record& r, std::size_t i) {
  const int m = integer(r, i, "material number");
  if (m < 1)
    throw DeckError(r.fieldLoc(i), "material number must be positive, got " + std::to_string(m),
                    r.excerpt(r.fieldLoc(i)));
  if (maxMaterials > 0 && m > maxMaterials)
    throw DeckError(r.fieldLoc(i),
                    "material " + std::to_string(m) + " is beyond nummat = " +
                        std::to_string(maxMaterials) + " of the control record",
                    r.excerpt(r.fieldLoc(i)), "raise nummat, or set it to 0 to have them counted");
  checkNumber(r, i, m, DeckLimits::kMaxMaterials, "material set");
  return m;
}

MeshContext::ElementRange MeshContext::elementRange(const Record& r, std::size_t i,
                                                   bool withinNumel) {
  ElementRange g;
  g.n1 = elementNumber(r, i, withinNumel);
  g.n2 = integer(r, i + 1, "last element");
  g.inc = integer(r, i + 2, "element increment");
  if (g.n2 == 0) g.n2 = g.n1;
  if (g.inc == 0) g.inc = 1;
  if (g.n2 < g.n1)
    failAt(r, i + 1, "the last element " + std::to_string(g.n2) + " comes before the first");
  if (g.inc < 0) failAt(r, i + 2, "the element increment must be positive");
  return g;
}

void MeshContext::setCoordOrigin(int n, const Record& r) {
  const Vec2 x = model.coord(n - 1);
  if (!(std::abs(x.x()) <= DeckLimits::kMaxCoordinate && std::abs(x.y()) <= DeckLimits::kMaxCoordinate)) {
    char at[160];
    std::snprintf(at, sizeof at,
                  " at (%g, %g): a coordinate beyond the largest this program takes (%g in the "
                  "deck's length unit)",
                  x.x(), x.y(), DeckLimits::kMaxCoordinate);
    throw DeckError(r.fieldLoc(0), "node " + std::to_string(n) + at,
                    r.excerpt(r.fieldLoc(0)));
  }
  if (static_cast<int>(coordOrigin.size()) < n) coordOrigin.resize(n, nullptr);
  coordOrigin[n - 1] = &r;
}

void MeshContext::maxFields(const Record& r, std::size_t max, std::string_view syntax) const {
  if (r.size() > max)
    throw DeckError(r[max].loc, "too many fields: the record is '" + std::string(syntax) + "'",
                    r.excerpt(r[max].loc));
}

namespace meshspec {

void title(std::ostream& os, const std::string& t) { os << "\n   " << t << "\n\n"; }

std::ostream& num(std::ostream& os, double v) {
  return os << std::setw(13) << std::scientific << std::setprecision(4) << v;
}

Mode readMode(const Record& head, Mode dflt) {
  if (head.size() < 2 || head[1].text.empty()) return dflt;
  if (keywordMatches(head[1].text, "ADD")) return Mode::Add;
  if (keywordMatches(head[1].text, "SET")) return Mode::Set;
  failAt(head, 1, "unknown option '" + head[1].text + "'", "the options are ADD and SET");
}


void failAt(const Record& r, std::size_t i, const std::string& msg, const std::string& hint) {
  throw DeckError(r.fieldLoc(i), msg, r.excerpt(r.fieldLoc(i)), hint);
}

FieldSpec expr(std::string name, std::string doc, std::string dflt) {
  return {std::move(name), FieldKind::Expression, std::move(dflt), std::move(doc)};
}
FieldSpec text(std::string name, std::string doc, std::string dflt) {
  return {std::move(name), FieldKind::Text, std::move(dflt), std::move(doc)};
}

CommandSpec subSpec(std::string name, std::string doc, std::vector<FieldSpec> fields) {
  CommandSpec s;
  s.name = std::move(name);
  s.doc = std::move(doc);
  s.fields = std::move(fields);
  s.section = CommandSection::SubRecord;
  return s;
}

CommandSpec meshSpec(std::string name, std::string doc, std::vector<FieldSpec> fields,
                     std::string dataSyntax, std::vector<FieldSpec> dataFields) {
  CommandSpec s;
  s.name = std::move(name);
  s.doc = std::move(doc);
  s.fields = std::move(fields);
  s.section = CommandSection::Mesh;
  s.data = dataSyntax.empty() ? DataForm::None : DataForm::Records;
  s.dataSyntax = std::move(dataSyntax);
  s.dataFields = std::move(dataFields);
  return s;
}

}  // namespace meshspec
}  // namespace c2d
