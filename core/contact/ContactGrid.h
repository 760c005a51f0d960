#pragma once
// Broad phase of the member contact and of the crossing check: axis-aligned
// boxes binned in a uniform grid, hashed so that the grid may be as large as the
// debris field without costing memory. Building and querying are linear in the
// number of boxes when the cell size is the boxes' typical size (each box then
// covers a few cells); a box covering very many cells (a long member, a fast
// one) is kept in a list of its own that every query checks.
//
// The arrays keep their capacity: after the first build of a given size,
// build() and query() allocate nothing.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace c2d {

struct Box {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // x0 <= x1, y0 <= y1

  bool overlaps(const Box& o) const { return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1; }
  Box inflated(double r) const { return {x0 - r, y0 - r, x1 + r, y1 + r}; }
  void add(double x, double y) {
    if (x < x0) x0 = x;
    if (x > x1) x1 = x;
    if (y < y0) y0 = y;
    if (y > y1) y1 = y;
  }
  static Box point(double x, double y) { return {x, y, x, y}; }
};

class ContactGrid {
 public:
  // Bins the boxes; the cell size is their mean extent (the larger of width and
  // height), at least `minCell`.
  void build(const std::vector<Box>& boxes, double minCell);

  // Calls visit(i) once for every binned box i that overlaps b.
  template <class Visit>
  void query(const Box& b, Visit&& visit) {
    if (boxes_.empty()) return;
    if (++stamp_ == 0) {  // wrapped around: clear the stamps
      std::fill(seen_.begin(), seen_.end(), 0u);
      stamp_ = 1;
    }
    const auto visitBox = [&](int i) {
      if (seen_[i] == stamp_) return;
      seen_[i] = stamp_;
      if (boxes_[i].overlaps(b)) visit(i);
    };
    for (int i : large_) visitBox(i);
    const long cx0 = cell(b.x0 - originX_), cx1 = cell(b.x1 - originX_);
    const long cy0 = cell(b.y0 - originY_), cy1 = cell(b.y1 - originY_);
    if (double(cx1 - cx0 + 1) * double(cy1 - cy0 + 1) > double(bucketStart_.size())) {
      // A query box larger than the table: every box is a candidate.
      for (int i = 0; i < static_cast<int>(boxes_.size()); ++i) visitBox(i);
      return;
    }
    for (long cx = cx0; cx <= cx1; ++cx)
      for (long cy = cy0; cy <= cy1; ++cy) {
        const std::uint32_t h = bucket(cx, cy);
        for (std::uint32_t k = bucketStart_[h]; k < bucketStart_[h + 1]; ++k) visitBox(entries_[k]);
      }
  }

  int size() const { return static_cast<int>(boxes_.size()); }

 private:
  long cell(double x) const { return static_cast<long>(std::floor(x * invCell_)); }
  std::uint32_t bucket(long cx, long cy) const {
    const std::uint64_t h = static_cast<std::uint64_t>(cx) * 0x9E3779B97F4A7C15ull ^
                            static_cast<std::uint64_t>(cy) * 0xC2B2AE3D27D4EB4Full;
    return static_cast<std::uint32_t>((h ^ (h >> 29)) & mask_);
  }

  std::vector<Box> boxes_;
  std::vector<std::uint32_t> bucketStart_;  // size buckets + 1
  std::vector<int> entries_;                // box indices, bucket by bucket
  std::vector<int> large_;                  // boxes covering too many cells to bin
  std::vector<std::uint32_t> seen_;         // per box: the last query that visited it
  std::uint32_t stamp_ = 0;
  std::uint64_t mask_ = 0;
  double originX_ = 0, originY_ = 0, invCell_ = 1;
};

}  // namespace c2d
