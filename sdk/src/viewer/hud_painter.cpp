#include "viewer/hud_painter.hpp"

#include <algorithm>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <string>

#include "contact/stick_slip_classifier.hpp"

namespace onetip::viewer {

namespace {
const cv::Scalar kText(235, 235, 235, 255), kDim(160, 160, 160, 255), kStrip(20, 20, 20, 190),
    kBorder(90, 90, 90, 255), kBarBack(55, 55, 55, 255), kBar(70, 200, 255, 255), kOver(60, 60, 235, 255);
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
constexpr double kScale = 0.45;
constexpr int kLine = 17;  // text line height, pixels

std::string format(const char* fmt, double a, double b = 0, double c = 0) {
  char buf[160];
  std::snprintf(buf, sizeof buf, fmt, a, b, c);
  return buf;
}

void text(cv::Mat& canvas, const std::string& s, cv::Point at, const cv::Scalar& colour = kText) {
  cv::putText(canvas, s, at, kFont, kScale, colour, 1, cv::LINE_AA);
}

void titled(cv::Mat& canvas, const cv::Rect& panel, const std::string& title) {
  cv::rectangle(canvas, {panel.x, panel.y, panel.width, kLine + 5}, kStrip, cv::FILLED);
  cv::rectangle(canvas, panel, kBorder, 1);
  text(canvas, title, {panel.x + 6, panel.y + kLine - 1});
}

// A bar centred on zero: value / range fills half the width; red beyond it.
void centredBar(cv::Mat& canvas, const cv::Rect& bar, double value, double range) {
  cv::rectangle(canvas, bar, kBarBack, cv::FILLED);
  const int mid = bar.x + bar.width / 2;
  const double fraction = std::clamp(value / range, -1.0, 1.0);
  const int end = mid + static_cast<int>(fraction * (bar.width / 2));
  cv::rectangle(canvas, cv::Rect(cv::Point(std::min(mid, end), bar.y), cv::Point(std::max(mid, end) + 1, bar.y + bar.height)),
                std::abs(value) > range ? kOver : kBar, cv::FILLED);
  cv::line(canvas, {mid, bar.y - 2}, {mid, bar.y + bar.height + 1}, kText, 1);
}

std::string stateName(const pipeline::FrameResult& r) {
  if (r.status != pipeline::FrameStatus::ok) return pipeline::toString(r.status);
  return r.pose.contact ? std::string(toString(r.pose.state)) : "no contact";
}

void paintGauges(cv::Mat& canvas, const cv::Rect& panel, const Input6& v, const std::array<double, 6>& range) {
  titled(canvas, panel, "6-D input (gauges: full = working range)");
  const std::array<const char*, 6> names{"dx", "dy", "dz", "yaw", "pitch", "roll"};
  const std::array<const char*, 6> units{"mm", "mm", "mm", "deg", "deg", "deg"};
  const auto values = v.asArray();
  const int top = panel.y + kLine + 10, rows = 6;
  const int step = std::max(12, (panel.height - (top - panel.y) - 4) / rows);
  for (int i = 0; i < rows; ++i) {
    const int y = top + i * step;
    const auto k = static_cast<size_t>(i);
    text(canvas, names[k], {panel.x + 8, y + step / 2 + 4});
    const cv::Rect bar(panel.x + 60, y + step / 2 - 5, panel.width - 170, 10);
    centredBar(canvas, bar, values[k], range[k]);
    text(canvas, format("%+7.2f ", values[k]) + units[k],
         {bar.x + bar.width + 8, y + step / 2 + 4});
  }
}

void paintTimings(cv::Mat& canvas, const cv::Rect& panel, const ViewerFrame& f) {
  titled(canvas, panel, format("timing (ms)    view %.1f fps", f.rates.view_fps));
  const pipeline::StageTimes& t = f.result.times;
  const std::array<std::pair<const char*, double>, 8> rows{{{"source", f.rates.source_ms},
                                                            {"detect", t.detect},
                                                            {"track", t.track},
                                                            {"triangulate", t.triangulate},
                                                            {"contact", t.contact},
                                                            {"pose", t.pose},
                                                            {"process", t.process},
                                                            {"render", f.rates.render_ms}}};
  const int top = panel.y + kLine + 8;
  const int step = std::max(11, (panel.height - (top - panel.y) - 2) / static_cast<int>(rows.size()));
  const int bar_x = panel.x + 160, bar_w = panel.width - 170;
  for (size_t i = 0; i < rows.size(); ++i) {
    const int y = top + static_cast<int>(i) * step + step - 4;
    text(canvas, rows[i].first, {panel.x + 8, y}, i == 6 ? kText : kDim);
    text(canvas, format("%6.2f", rows[i].second), {panel.x + 95, y});
    const int w = static_cast<int>(std::min(1.0, rows[i].second / (1000.0 / 60.0)) * bar_w);
    cv::rectangle(canvas, {bar_x, y - 8, bar_w, 8}, kBarBack, cv::FILLED);
    cv::rectangle(canvas, {bar_x, y - 8, std::max(1, w), 8}, rows[i].second > 1000.0 / 60.0 ? kOver : kBar, cv::FILLED);
  }
}
}  // namespace

void paintHud(const PanelLayout& layout, const ViewerFrame& f, const HudSettings& s, cv::Mat& canvas) {
  if (canvas.size() != layout.window || canvas.type() != CV_8UC4) canvas.create(layout.window, CV_8UC4);
  canvas.setTo(cv::Scalar::all(0));
  const pipeline::FrameResult& r = f.result;

  titled(canvas, layout.camera, format("camera  frame %.0f  markers L %.0f  R %.0f", static_cast<double>(f.index),
                                       r.found_left, r.found_right) + "  [" + pipeline::toString(r.status) + "]");
  if (!r.message.empty())
    text(canvas, r.message, {layout.camera.x + 6, layout.camera.y + layout.camera.height - 8}, kOver);

  double max_u = 0;
  if (r.pose.field.max_modulus_mm > 0) max_u = r.pose.field.max_modulus_mm;
  titled(canvas, layout.field,
         format("deformation field (x%.0f)  max |u| %.2f mm", s.field_exaggeration, max_u));
  text(canvas, format("|u|: 0 .. %.1f mm", s.field_scale_mm), {layout.field.x + 8, layout.field.y + layout.field.height - 24},
       kDim);

  const pose::PoseStep& step = r.pose.step;
  titled(canvas, layout.contact, "contact: " + stateName(r) + "  stick " + std::to_string(step.n_stick) + "  slip " +
                                     std::to_string(step.n_slip));
  text(canvas, "green stick  red slip  blue region  grey outside",
       {layout.contact.x + 6, layout.contact.y + layout.contact.height - 8}, kDim);
  if (r.pose.pressed) text(canvas, "PRESSED", {layout.contact.x + 6, layout.contact.y + 2 * kLine + 6}, kOver);

  titled(canvas, layout.pose, format("6-D input object (translation x%.0f)", s.object_gain) +
                                  (r.pose.out_of_range ? "  OUT OF RANGE" : ""));
  text(canvas, "model: " + std::string(pose::toString(step.model)),
       {layout.pose.x + 6, layout.pose.y + layout.pose.height - 8}, kDim);

  paintGauges(canvas, layout.gauges, r.pose.raw, s.working_range);
  paintTimings(canvas, layout.timing, f);
  if (!f.hint.empty()) {
    const cv::Rect strip(layout.camera.x, layout.camera.y + kLine + 5, layout.camera.width, kLine + 4);
    cv::rectangle(canvas, strip, kStrip, cv::FILLED);
    text(canvas, f.hint, {strip.x + 6, strip.y + kLine - 2}, kDim);
  }
  int baseline = 0;
  const cv::Size source_size = cv::getTextSize(f.source, kFont, kScale, 1, &baseline);
  text(canvas, f.source,
       {layout.camera.x + layout.camera.width - 8 - source_size.width, layout.camera.y + layout.camera.height - 8},
       kDim);
}

}  // namespace onetip::viewer
