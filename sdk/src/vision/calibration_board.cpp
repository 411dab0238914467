#include "vision/calibration_board.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace onetip::vision {

namespace {

// Mean step between neighbours along the grid's columns (dc) and rows (dr).
void meanSteps(const std::vector<cv::Point2f>& g, int rows, int cols, cv::Point2f& dc,
               cv::Point2f& dr) {
  dc = dr = {0, 0};
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c + 1 < cols; ++c) dc += g[static_cast<size_t>(r * cols + c + 1)] - g[static_cast<size_t>(r * cols + c)];
  for (int r = 0; r + 1 < rows; ++r)
    for (int c = 0; c < cols; ++c) dr += g[static_cast<size_t>((r + 1) * cols + c)] - g[static_cast<size_t>(r * cols + c)];
  dc *= 1.0f / static_cast<float>(rows * (cols - 1));
  dr *= 1.0f / static_cast<float>((rows - 1) * cols);
}

}  // namespace

namespace {

cv::Point2f unit(cv::Point2f v) { return v * (1.0f / std::max(1e-6f, std::hypot(v.x, v.y))); }

// The renumbering of a rows x cols grid that scores best: among the board's
// symmetries (transposes only when square) that keep the numbering
// right-handed in the image (col step x row step > 0, y down), the one whose
// unit col and row steps maximise score(col_step, row_step).
template <typename Score>
std::vector<cv::Point2f> renumber(const std::vector<cv::Point2f>& grid, int rows, int cols,
                                  Score score) {
  cv::Point2f dc, dr;
  meanSteps(grid, rows, cols, dc, dr);
  const bool right_handed = dc.x * dr.y - dc.y * dr.x > 0;
  float best_score = -1e30f;
  bool best_t = false, best_fc = false, best_fr = false;
  for (bool t : {false, true}) {
    if (t && rows != cols) continue;
    for (bool fc : {false, true})
      for (bool fr : {false, true}) {
        const bool mirrors = t ^ fc ^ fr;  // an odd number of reflections
        if (right_handed == mirrors) continue;  // keep the result right-handed
        // New steps: the old axis this one reads, negated when mirrored.
        const cv::Point2f col_step = (t ? dr : dc) * (fc ? -1.0f : 1.0f);
        const cv::Point2f row_step = (t ? dc : dr) * (fr ? -1.0f : 1.0f);
        const float s = score(unit(col_step), unit(row_step));
        if (s > best_score) {
          best_score = s;
          best_t = t;
          best_fc = fc;
          best_fr = fr;
        }
      }
  }
  std::vector<cv::Point2f> out(grid.size());
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const int a = best_fr ? rows - 1 - r : r;  // position along the new row axis
      const int b = best_fc ? cols - 1 - c : c;  // and along the new column axis
      const int old_r = best_t ? b : a, old_c = best_t ? a : b;
      out[static_cast<size_t>(r * cols + c)] = grid[static_cast<size_t>(old_r * cols + old_c)];
    }
  return out;
}

}  // namespace

std::vector<cv::Point2f> anchorBoardNumbering(const std::vector<cv::Point2f>& grid, int rows,
                                              int cols) {
  return renumber(grid, rows, cols,
                  [](cv::Point2f col, cv::Point2f row) { return col.x + row.y; });
}

std::vector<cv::Point2f> alignBoardNumbering(const std::vector<cv::Point2f>& reference,
                                             const std::vector<cv::Point2f>& grid, int rows,
                                             int cols) {
  cv::Point2f ref_col, ref_row;
  meanSteps(reference, rows, cols, ref_col, ref_row);
  ref_col = unit(ref_col);
  ref_row = unit(ref_row);
  return renumber(grid, rows, cols, [&](cv::Point2f col, cv::Point2f row) {
    return col.dot(ref_col) + row.dot(ref_row);
  });
}

std::optional<std::vector<cv::Point2f>> findCalibrationBoard(const ViewHalf& view,
                                                             const MarkerPattern& pattern) {
  if (view.raw.empty() || view.raw.type() != CV_8UC1)
    throw InputError("calibration board: the view must be a non-empty 8-bit grey image");
  std::vector<cv::Point2f> corners;
  const cv::Size size(pattern.cols, pattern.rows);
  if (!cv::findChessboardCorners(view.raw, size, corners,
                                 cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE) ||
      static_cast<int>(corners.size()) != pattern.count())
    return std::nullopt;
  cv::Point2f dc, dr;
  meanSteps(corners, pattern.rows, pattern.cols, dc, dr);
  const float spacing = std::min(std::hypot(dc.x, dc.y), std::hypot(dr.x, dr.y));
  const int half_window = std::clamp(static_cast<int>(0.4f * spacing), 2, 5);
  cv::cornerSubPix(view.raw, corners, cv::Size(half_window, half_window), cv::Size(-1, -1),
                   cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 30, 0.01));
  view.toViewInPlace(corners);
  return anchorBoardNumbering(corners, pattern.rows, pattern.cols);
}

}  // namespace onetip::vision
