#include "dslam/features/fast_grid.h"

#include <algorithm>
#include <stdexcept>

#include <opencv2/features2d.hpp>

namespace dslam {
namespace {

constexpr int kMargin = 3;  // [px] radius of the FAST circle

// The 16 pixels of the radius-3 circle (dx, dy), in order around it.
constexpr int kCircle[16][2] = {{0, 3},  {1, 3},  {2, 2},  {3, 1},   {3, 0},   {3, -1},
                                {2, -2}, {1, -3}, {0, -3}, {-1, -3}, {-2, -2}, {-3, -1},
                                {-3, 0}, {-3, 1}, {-2, 2}, {-1, 3}};

// Byte offsets of the circle pixels in an image with `step` bytes per row.
struct Circle {
  explicit Circle(size_t step) {
    for (int k = 0; k < 16; ++k) offset[k] = kCircle[k][1] * static_cast<int>(step) + kCircle[k][0];
  }
  int offset[16];
};

// True when the 16-bit circular `mask` has 9 consecutive bits set.
bool HasArcOf9(unsigned mask) {
  const unsigned twice = mask | (mask << 16);
  unsigned run = twice;
  for (int k = 1; k < 9; ++k) run &= twice >> k;
  return (run & 0xFFFFu) != 0;
}

// True when the pixel at `p` is a FAST-9 corner at `threshold` (cv::FAST's test: 9 contiguous
// circle pixels all brighter than centre + threshold, or all darker than centre - threshold).
bool IsCorner(const uchar* p, const Circle& circle, int threshold) {
  const int hi = p[0] + threshold, lo = p[0] - threshold;
  // Every arc of 9 holds pixel 0 or 8, and pixel 4 or 12.
  const int v0 = p[circle.offset[0]], v4 = p[circle.offset[4]];
  const int v8 = p[circle.offset[8]], v12 = p[circle.offset[12]];
  const bool may_be_brighter = (v0 > hi || v8 > hi) && (v4 > hi || v12 > hi);
  const bool may_be_darker = (v0 < lo || v8 < lo) && (v4 < lo || v12 < lo);
  if (!may_be_brighter && !may_be_darker) return false;
  unsigned brighter = 0, darker = 0;
  for (int k = 0; k < 16; ++k) {
    const int v = p[circle.offset[k]];
    brighter |= static_cast<unsigned>(v > hi) << k;
    darker |= static_cast<unsigned>(v < lo) << k;
  }
  return (may_be_brighter && HasArcOf9(brighter)) || (may_be_darker && HasArcOf9(darker));
}

// FastScore at `p` (see the header): the largest of the arcs' smallest differences, by minima
// over 2, 4, 8 and then 9 contiguous pixels.
int Score(const uchar* p, const Circle& circle) {
  int up[25], down[25];  // circle minus centre and its negative, 9 pixels past a full turn
  for (int k = 0; k < 16; ++k) {
    up[k] = p[circle.offset[k]] - p[0];
    down[k] = -up[k];
  }
  for (int k = 16; k < 25; ++k) {
    up[k] = up[k - 16];
    down[k] = down[k - 16];
  }
  // up8[k] = min(up[k .. k + 7]) for k < 16, by runs of 2 (k < 22), 4 (k < 20) and 8 pixels.
  int up8[22], down8[22];
  for (int k = 0; k < 22; ++k) {
    up8[k] = std::min(up[k], up[k + 1]);
    down8[k] = std::min(down[k], down[k + 1]);
  }
  const auto widen = [&](int width, int end) {  // in place: k + width still holds the shorter run
    for (int k = 0; k < end; ++k) {
      up8[k] = std::min(up8[k], up8[k + width]);
      down8[k] = std::min(down8[k], down8[k + width]);
    }
  };
  widen(2, 20);
  widen(4, 16);
  int best = 0;
  for (int k = 0; k < 16; ++k) {
    best = std::max(best, std::max(std::min(up8[k], up[k + 8]), std::min(down8[k], down[k + 8])));
  }
  return best - 1;
}

// The corners in column x of `cell` (its first or last) that beat every neighbour inside the
// cell (a neighbour outside it counts as 0, as in a per-cell cv::FAST call), appended to `out`.
void AddSideCorners(const cv::Mat& image, const Circle& circle, const cv::Rect& cell, int x,
                    int threshold, std::vector<cv::KeyPoint>* out) {
  for (int y = cell.y; y < cell.y + cell.height; ++y) {
    const uchar* p = image.ptr<uchar>(y) + x;
    if (!IsCorner(p, circle, threshold)) continue;
    const int score = Score(p, circle);
    bool kept = score > 0;  // a side pixel has neighbours outside the cell (0)
    for (int dy = -1; kept && dy <= 1; ++dy) {
      for (int dx = -1; kept && dx <= 1; ++dx) {
        if ((dx == 0 && dy == 0) || !cell.contains(cv::Point(x + dx, y + dy))) continue;
        // cv::FAST compares with the neighbour's score if it is a corner at `threshold`, else
        // with 0; for score >= threshold that neighbour wins exactly when it is a corner at
        // `score`.
        kept = !IsCorner(p + dy * static_cast<int>(image.step) + dx, circle, score);
      }
    }
    if (kept) out->emplace_back(static_cast<float>(x), static_cast<float>(y), 7.f, -1.f, score);
  }
}

bool RasterOrder(const cv::KeyPoint& a, const cv::KeyPoint& b) {
  return a.pt.y < b.pt.y || (a.pt.y == b.pt.y && a.pt.x < b.pt.x);
}

// Cells [first, end) of one row of `grid`, with one cv::FAST call over them: its suppression
// stops where a per-cell call's does except between neighbouring cells of the run, where the
// cells' inner first and last columns are tested again. `maxima` is scratch space (kept
// between the calls of one FastPerCell for its capacity).
void FastOnRun(const cv::Mat& image, const FastGrid& grid, int first, int end, int threshold,
               std::vector<cv::KeyPoint>* maxima, std::vector<std::vector<cv::KeyPoint>>* cells) {
  const cv::Rect left = grid.Cell(first), right = grid.Cell(end - 1);
  const cv::Rect strip(left.x - kMargin, left.y - kMargin, right.br().x - left.x + 2 * kMargin,
                       left.height + 2 * kMargin);
  maxima->clear();
  cv::FAST(image(strip), *maxima, threshold, true);
  const int row_start = first - first % grid.Cols();
  for (cv::KeyPoint& kp : *maxima) {
    kp.pt += cv::Point2f(static_cast<float>(strip.x), static_cast<float>(strip.y));
    const int x = static_cast<int>(kp.pt.x);
    const int index = row_start + (x - grid.x0) / grid.size;
    const cv::Rect cell = grid.Cell(index);
    const bool inner_side =
        (x == cell.x && index > first) || (x == cell.br().x - 1 && index < end - 1);
    if (!inner_side) (*cells)[index].push_back(kp);
  }
  const Circle circle(image.step);
  for (int index = first; index < end; ++index) {
    std::vector<cv::KeyPoint>& cell = (*cells)[index];
    const cv::Rect rect = grid.Cell(index);
    const size_t before = cell.size();
    const bool left = index > first, right = index < end - 1;  // sides next to run cells
    if (left || (right && rect.width == 1)) {
      AddSideCorners(image, circle, rect, rect.x, threshold, &cell);
    }
    if (right && rect.width > 1) {
      AddSideCorners(image, circle, rect, rect.br().x - 1, threshold, &cell);
    }
    if (cell.size() > before) std::sort(cell.begin(), cell.end(), RasterOrder);
  }
}

}  // namespace

cv::Rect FastGrid::Cell(int index) const {
  const int x = x0 + (index % Cols()) * size, y = y0 + (index / Cols()) * size;
  return cv::Rect(x, y, std::min(size, x1 - x), std::min(size, y1 - y));
}

int FastScore(const cv::Mat& image, int x, int y) {
  if (image.type() != CV_8UC1) throw std::invalid_argument("FastScore: image is not CV_8UC1");
  if (x < kMargin || y < kMargin || x + kMargin >= image.cols || y + kMargin >= image.rows) {
    throw std::invalid_argument("FastScore: pixel closer than 3 px to the border");
  }
  return Score(image.ptr<uchar>(y) + x, Circle(image.step));
}

std::vector<std::vector<cv::KeyPoint>> FastPerCell(const cv::Mat& image, const FastGrid& grid,
                                                   int threshold,
                                                   const std::vector<uint8_t>* wanted) {
  if (image.type() != CV_8UC1) throw std::invalid_argument("FastPerCell: image is not CV_8UC1");
  if (threshold < 0 || threshold > 255) throw std::invalid_argument("FastPerCell: threshold");
  if (grid.size < 1 || grid.x0 < kMargin || grid.y0 < kMargin || grid.x1 + kMargin > image.cols ||
      grid.y1 + kMargin > image.rows) {
    throw std::invalid_argument("FastPerCell: grid outside the image or its 3 px margin");
  }
  if (grid.x1 <= grid.x0 || grid.y1 <= grid.y0) return {};
  const size_t count = static_cast<size_t>(grid.Cols()) * grid.Rows();
  if (wanted != nullptr && wanted->size() != count) {
    throw std::invalid_argument("FastPerCell: one `wanted` entry per cell");
  }
  std::vector<std::vector<cv::KeyPoint>> cells(count);
  std::vector<cv::KeyPoint> maxima;
  for (int row = 0; row < grid.Rows(); ++row) {
    const int row_end = (row + 1) * grid.Cols();
    for (int first = row * grid.Cols(); first < row_end;) {
      if (wanted != nullptr && !(*wanted)[first]) {
        ++first;
        continue;
      }
      int end = first + 1;
      while (end < row_end && (wanted == nullptr || (*wanted)[end])) ++end;
      FastOnRun(image, grid, first, end, threshold, &maxima, &cells);
      first = end;
    }
  }
  return cells;
}

}  // namespace dslam
