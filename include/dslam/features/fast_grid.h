#pragma once
// FAST-9 corners with non-maximum suppression inside each cell of a grid: the keypoints cv::FAST
// gives when it is called once per cell (on the cell plus its 3-pixel margin), found with one
// cv::FAST call per row of cells instead (per-cell calls are mostly set-up and scalar code).
//
// Why they can be equal: cv::FAST's score of a pixel (the largest threshold at which it is still a
// corner, FastScore below) depends only on its 16 circle pixels, not on the region FAST is called
// on. A per-cell call suppresses a corner only by its neighbours inside the cell (outside the
// detection area a score counts as 0). A call over a row of cells suppresses within the row's
// lines as a per-cell call does; only in the cells' first and last columns, where neighbouring
// cells meet, its rule differs, and there the corners are tested again here with the cell's
// neighbours only.

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

namespace dslam {

/// Square cells of `size` px covering [x0, x1) x [y0, y1) of an image, row-major; the last row
/// and column of cells are cut at x1 and y1.
struct FastGrid {
  int x0 = 0, y0 = 0;  ///< [px] first detection pixel (at least 3 from the image border)
  int x1 = 0, y1 = 0;  ///< [px] end of the detection area (at least 3 from the border)
  int size = 30;       ///< [px] cell side

  int Cols() const { return (x1 - x0 + size - 1) / size; }
  int Rows() const { return (y1 - y0 + size - 1) / size; }
  /// [px] cell `index` (row-major) in image pixels.
  cv::Rect Cell(int index) const;
};

/// FAST-9 score of pixel (x, y) of a CV_8UC1 image as cv::FAST defines it, -1 when the pixel is
/// not a corner at threshold 0: over every arc of 9 contiguous pixels of the radius-3 circle, the
/// smallest difference to the centre, all brighter or all darker, minus 1. The pixel is a corner
/// at threshold t exactly when its score is at least t. (x, y) must be 3 px inside the image.
int FastScore(const cv::Mat& image, int x, int y);

/// The keypoints (image pixels, response = FAST score, size 7, angle -1, raster order) that
/// cv::FAST(image(cell + 3 px margin), kps, threshold, true) finds in every cell of `grid`:
/// identical, cell by cell. With `wanted` (one entry per cell), only the cells with a non-zero
/// entry are searched, the others stay empty. One cv::FAST call per run of neighbouring searched
/// cells in a row of the grid. `image` is CV_8UC1, threshold in [0, 255], the grid inside the
/// image with a 3 px margin (else std::invalid_argument).
std::vector<std::vector<cv::KeyPoint>> FastPerCell(const cv::Mat& image, const FastGrid& grid,
                                                   int threshold,
                                                   const std::vector<uint8_t>* wanted = nullptr);

}  // namespace dslam
