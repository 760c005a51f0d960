#include "core/contact/ContactGrid.h"

namespace c2d {

namespace {
// A box covering more cells than this is not binned but checked by every query.
constexpr long kMaxCells = 64;
}  // namespace

void ContactGrid::build(const std::vector<Box>& boxes, double minCell) {
  boxes_.assign(boxes.begin(), boxes.end());
  large_.clear();
  entries_.clear();
  seen_.assign(boxes_.size(), 0u);
  stamp_ = 0;
  if (boxes_.empty()) {
    bucketStart_.assign(2, 0u);
    mask_ = 0;
    return;
  }
  double extent = 0;
  originX_ = boxes_[0].x0;
  originY_ = boxes_[0].y0;
  for (const Box& b : boxes_) {
    extent += std::max(b.x1 - b.x0, b.y1 - b.y0);
    originX_ = std::min(originX_, b.x0);
    originY_ = std::min(originY_, b.y0);
  }
  const double cellSize = std::max(extent / double(boxes_.size()), minCell > 0 ? minCell : 1e-300);
  invCell_ = 1.0 / cellSize;

  auto covered = [&](const Box& b) {
    return double(cell(b.x1 - originX_) - cell(b.x0 - originX_) + 1) *
           double(cell(b.y1 - originY_) - cell(b.y0 - originY_) + 1);
  };
  std::size_t insertions = 0;
  for (int i = 0; i < static_cast<int>(boxes_.size()); ++i) {
    const double c = covered(boxes_[i]);
    if (c > kMaxCells)
      large_.push_back(i);
    else
      insertions += static_cast<std::size_t>(c);
  }
  std::size_t buckets = 16;
  while (buckets < 2 * insertions) buckets *= 2;
  mask_ = buckets - 1;
  bucketStart_.assign(buckets + 1, 0u);

  // Counting sort of the (cell, box) entries by bucket.
  auto forCells = [&](int i, auto&& f) {
    const Box& b = boxes_[i];
    const long cx0 = cell(b.x0 - originX_), cx1 = cell(b.x1 - originX_);
    const long cy0 = cell(b.y0 - originY_), cy1 = cell(b.y1 - originY_);
    for (long cx = cx0; cx <= cx1; ++cx)
      for (long cy = cy0; cy <= cy1; ++cy) f(bucket(cx, cy));
  };
  std::size_t nextLarge = 0;
  for (int i = 0; i < static_cast<int>(boxes_.size()); ++i) {
    if (nextLarge < large_.size() && large_[nextLarge] == i) {
      ++nextLarge;
      continue;
    }
    forCells(i, [&](std::uint32_t h) { ++bucketStart_[h + 1]; });
  }
  for (std::size_t h = 0; h < buckets; ++h) bucketStart_[h + 1] += bucketStart_[h];
  entries_.resize(insertions);
  // Each bucket's start serves as its fill cursor, then the starts are shifted back.
  nextLarge = 0;
  for (int i = 0; i < static_cast<int>(boxes_.size()); ++i) {
    if (nextLarge < large_.size() && large_[nextLarge] == i) {
      ++nextLarge;
      continue;
    }
    forCells(i, [&](std::uint32_t h) { entries_[bucketStart_[h]++] = i; });
  }
  for (std::size_t h = buckets; h > 0; --h) bucketStart_[h] = bucketStart_[h - 1];
  bucketStart_[0] = 0;
}

}  // namespace c2d
