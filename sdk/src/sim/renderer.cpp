#include "sim/renderer.hpp"

#include <opencv2/core/utility.hpp>
#include <utility>

#include "sim/image_effects.hpp"
#include "sim/marker_damage.hpp"
#include "sim/raster_view.hpp"

namespace onetip::sim {

namespace {
constexpr float kHousingGrey = 20.0F;  // the dark inside of the sensor housing, where no sheet is seen
}  // namespace

FrameRenderer::FrameRenderer(CameraRig rig) : rig_(std::move(rig)) {}

cv::Mat FrameRenderer::render(const std::vector<CheckerSheet>& sheets, const ImageEffects& effects,
                              std::uint64_t seed, const ViewDisturbances& disturbances) const {
  effects.validate();
  for (const CheckerSheet& sheet : sheets) validateSheet(sheet);  // throw here, not inside the parallel loop
  const cv::Size view(rig_.view_width, rig_.view_height);
  cv::Mat frame(view.height, 2 * view.width, CV_8UC1);
  const VirtualCamera* cameras[2] = {&rig_.left, &rig_.right};
  // The two views are independent (own buffers, own random streams), so they
  // may be drawn concurrently with identical results.
  cv::parallel_for_(cv::Range(0, 2), [&](const cv::Range& range) {
    for (int i = range.start; i < range.end; ++i) {
      VirtualCamera camera = *cameras[i];
      const Eigen::Vector2d& shift = disturbances.shift_px[static_cast<size_t>(i)];
      camera.K(0, 2) += camera.flip ? -shift.x() : shift.x();  // the pinhole view is mirrored on delivery
      camera.K(1, 2) += shift.y();
      thread_local ViewTarget target;  // reused between frames: no page faults per frame
      target.reset(view, kHousingGrey);
      const double radius2 = acceptedRadius2(camera, view);
      for (const CheckerSheet& sheet : sheets) rasterizeSheet(sheet, camera, radius2, target);
      if (!disturbances.smudges.empty())
        paintSmudges(target.grey, camera, disturbances.smudges, disturbances.smudge_radius_mm,
                     disturbances.smudge_grey);
      developView(
          target.grey, [&] { return target.coverage(); }, effects, seed, i, camera.flip,
          frame(cv::Rect(i * view.width, 0, view.width, view.height)));
    }
  });
  return frame;
}

}  // namespace onetip::sim
