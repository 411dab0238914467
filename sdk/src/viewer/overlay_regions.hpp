// viewer/overlay_regions.hpp — where a transparent overlay has content, so the
// renderer blends only there (on llvmpipe a full-window blend is the most
// expensive thing the viewer draws).
//
// The BGRA overlay (straight alpha, pixels, top-left origin) is cut into
// tile x tile squares (the last row and column clipped to the image); the
// squares that hold a pixel with alpha > 0 are merged into horizontal runs,
// and runs spanning the same columns in consecutive tile rows into one
// rectangle. The rectangles cover every such pixel, do not overlap, and lie
// inside the image; an empty overlay gives none, a full one the whole image.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace onetip::viewer {

// Throws std::invalid_argument unless `bgra` is a non-empty CV_8UC4 image and tile >= 1.
std::vector<cv::Rect> overlayRegions(const cv::Mat& bgra, int tile = 16);

}  // namespace onetip::viewer
