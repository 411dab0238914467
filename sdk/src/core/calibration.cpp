#include "core/calibration.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/filestorage_io.hpp"

namespace onetip {

namespace {
void checkIntrinsics(const cv::Matx33d& K, const char* name) {
  if (!(K(0, 0) > 0) || !(K(1, 1) > 0) || K(2, 2) != 1.0 || K(1, 0) != 0 || K(2, 0) != 0 ||
      K(2, 1) != 0)
    throw InputError(std::string("calibration: ") + name +
                     ": not a pinhole intrinsic matrix (fx, fy > 0, last row 0 0 1)");
}
}  // namespace

void StereoCalibration::validate() const {
  if (image_width <= 1 || image_height <= 1)
    throw InputError("calibration: image_width/image_height: must be positive");
  if (split_x <= 0 || split_x >= image_width)
    throw InputError("calibration: split_x: must lie inside the image width");
  checkIntrinsics(K_left, "K_left");
  checkIntrinsics(K_right, "K_right");
  const cv::Matx33d RtR = R.t() * R;
  const double orth = cv::norm(RtR - cv::Matx33d::eye());
  if (!(orth < 1e-4) || !(cv::determinant(R) > 0))
    throw InputError("calibration: R: not a rotation matrix");
  if (!(cv::norm(T) > 0) || !std::isfinite(cv::norm(T)))
    throw InputError("calibration: T: baseline must be a non-zero finite vector");
}

StereoCalibration loadCalibration(const std::string& path) {
  cv::FileStorage fs = openForReading(path);
  const cv::FileNode root = fs.root();
  StereoCalibration c;
  c.image_width = readRequiredInt(root, "image_width", path);
  c.image_height = readRequiredInt(root, "image_height", path);
  c.split_x = readRequiredInt(root, "split_x", path);
  c.flip_left = readRequiredInt(root, "flip_left", path) != 0;
  c.flip_right = readRequiredInt(root, "flip_right", path) != 0;
  c.K_left = cv::Matx33d(readRequiredMat(root, "K_left", 3, 3, path));
  c.K_right = cv::Matx33d(readRequiredMat(root, "K_right", 3, 3, path));
  const cv::Mat dl = readRequiredMat(root, "D_left", 1, 5, path);
  const cv::Mat dr = readRequiredMat(root, "D_right", 1, 5, path);
  for (int i = 0; i < 5; ++i) {
    c.D_left[i] = dl.at<double>(i);
    c.D_right[i] = dr.at<double>(i);
  }
  c.R = cv::Matx33d(readRequiredMat(root, "R", 3, 3, path));
  const cv::Mat t = readRequiredMat(root, "T", 3, 1, path);
  c.T = cv::Vec3d(t.at<double>(0), t.at<double>(1), t.at<double>(2));
  try {
    c.validate();
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
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
