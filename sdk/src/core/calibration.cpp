#include "core/calibration.hpp"

#include <cmath>

#include "core/config_file.hpp"
#include "core/error.hpp"
#include "core/filestorage_io.hpp"

namespace onetip {

namespace {
bool isPinhole(const cv::Matx33d& K) {
  return K(0, 0) > 0 && K(1, 1) > 0 && K(2, 2) == 1.0 && K(1, 0) == 0 && K(2, 0) == 0 && K(2, 1) == 0;
}
bool isRotation(const cv::Matx33d& R) {
  return cv::norm(R.t() * R - cv::Matx33d::eye()) < 1e-4 && cv::determinant(R) > 0;
}
bool isBaseline(const cv::Vec3d& T) { return cv::norm(T) > 0 && std::isfinite(cv::norm(T)); }

constexpr const char* kNotPinhole = "not a pinhole intrinsic matrix (fx, fy > 0, last row 0 0 1)";
constexpr const char* kNotRotation = "not a rotation matrix";
constexpr const char* kNotBaseline = "baseline must be a non-zero finite vector";
}  // namespace

void StereoCalibration::validate() const {
  if (image_width <= 1 || image_height <= 1)
    throw InputError("calibration: image_width/image_height: must be positive");
  if (split_x <= 0 || split_x >= image_width)
    throw InputError("calibration: split_x: must lie inside the image width");
  if (!isPinhole(K_left)) throw InputError(std::string("calibration: K_left: ") + kNotPinhole);
  if (!isPinhole(K_right)) throw InputError(std::string("calibration: K_right: ") + kNotPinhole);
  if (!isRotation(R)) throw InputError(std::string("calibration: R: ") + kNotRotation);
  if (!isBaseline(T)) throw InputError(std::string("calibration: T: ") + kNotBaseline);
}

namespace {
// A matrix as cv::FileStorage writes it (a map tagged !!opencv-matrix with
// rows, cols, dt, data) or as people write it: a flat list, or a list of rows.
cv::Mat readMatrix(const ConfigNode& n, int rows, int cols) {
  const std::string shape = "a " + std::to_string(rows) + "x" + std::to_string(cols) + " matrix";
  if (!n.present()) n.fail("missing, expected " + shape);
  constexpr double kLimit = 1e7;  // pixels, mm, distortion coefficients: anything larger is not a calibration
  std::vector<double> v;
  const auto count = static_cast<std::size_t>(rows * cols);
  if (n.isMap()) {
    n.allowOnly({"rows", "cols", "dt", "data", "type_id"});
    const int got_rows = n["rows"].integer(1, 16);
    const int got_cols = n["cols"].integer(1, 16);
    if (got_rows * got_cols != rows * cols)  // 1x5 and 5x1 both hold a distortion vector
      n.fail("expected " + shape + ", got " + std::to_string(got_rows) + "x" + std::to_string(got_cols));
    v = n["data"].reals(count, -kLimit, kLimit);
  } else if (n.isSeq() && n.size() == count) {
    v = n.reals(count, -kLimit, kLimit);
  } else if (n.isSeq() && n.size() == static_cast<std::size_t>(rows)) {
    for (std::size_t r = 0; r < static_cast<std::size_t>(rows); ++r) {
      const auto row = n[r].reals(static_cast<std::size_t>(cols), -kLimit, kLimit);
      v.insert(v.end(), row.begin(), row.end());
    }
  } else {
    n.fail("expected " + shape + " (a list of " + std::to_string(count) + " numbers or an opencv-matrix)");
  }
  return cv::Mat(v, true).reshape(1, rows);
}

cv::Matx33d readIntrinsics(const ConfigNode& n) {
  const cv::Matx33d K(readMatrix(n, 3, 3));
  if (!isPinhole(K)) n.fail(kNotPinhole);
  return K;
}
}  // namespace

StereoCalibration loadCalibration(const std::string& path) {
  // Keys other than these (rms_px, notes) are allowed: the file is also OpenCV's.
  const ConfigNode root = ConfigNode::load(path);
  StereoCalibration c;
  c.image_width = root["image_width"].integer(2, 100000);
  c.image_height = root["image_height"].integer(2, 100000);
  c.split_x = root["split_x"].integer(1, c.image_width - 1);
  c.flip_left = root["flip_left"].flag();
  c.flip_right = root["flip_right"].flag();
  c.K_left = readIntrinsics(root["K_left"]);
  c.K_right = readIntrinsics(root["K_right"]);
  c.D_left = cv::Vec<double, 5>(readMatrix(root["D_left"], 1, 5));
  c.D_right = cv::Vec<double, 5>(readMatrix(root["D_right"], 1, 5));
  c.R = cv::Matx33d(readMatrix(root["R"], 3, 3));
  if (!isRotation(c.R)) root["R"].fail(kNotRotation);
  c.T = cv::Vec3d(readMatrix(root["T"], 3, 1));
  if (!isBaseline(c.T)) root["T"].fail(kNotBaseline);
  return c;
}

void saveCalibration(const StereoCalibration& c, const std::string& path, double rms_px) {
  c.validate();
  YamlWriter w;
  cv::FileStorage& fs = w.fs();
  fs << "image_width" << c.image_width << "image_height" << c.image_height;
  fs << "split_x" << c.split_x;
  fs << "flip_left" << (c.flip_left ? 1 : 0) << "flip_right" << (c.flip_right ? 1 : 0);
  fs << "K_left" << cv::Mat(c.K_left) << "D_left" << cv::Mat(c.D_left).reshape(1, 1);
  fs << "K_right" << cv::Mat(c.K_right) << "D_right" << cv::Mat(c.D_right).reshape(1, 1);
  fs << "R" << cv::Mat(c.R) << "T" << cv::Mat(c.T);
  if (rms_px >= 0) fs << "rms_px" << rms_px;
  w.save(path);
}

}  // namespace onetip
