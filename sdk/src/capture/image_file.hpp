// capture/image_file.hpp — image files to 8-bit grey, with the size checked
// before any pixel is decoded.
//
// A file's header can claim any size (a 68-byte PNG can declare 40000x40000
// pixels, and OpenCV would then allocate 1.6 GB or throw). So the declared
// width and height are read from the header first (PNG IHDR, JPEG SOFn,
// BMP info header, TIFF first IFD) and compared with what the caller expects:
// the stream's frame size when known, otherwise a bound on the pixel count.
// Only then is the image decoded to grey: PNG with libpng, its error and
// warning messages caught (OpenCV's PNG reader let libpng print them to
// stderr), other formats with cv::imdecode inside a try block. Every failure
// is a one-line reason, never an exception, a stray line on stderr or a large
// allocation.
#pragma once

#include <cstddef>
#include <cstdint>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

namespace onetip::capture {

struct ImageLimits {
  cv::Size expected{0, 0};                 // {0, 0}: any size within the bounds below
  std::int64_t max_pixels = 40'000'000;    // width * height (40 Mpx: 40 MB grey)
  std::size_t max_file_bytes = 256u << 20; // larger files are not read at all
};

// The width and height the header declares, or nullopt when the bytes are not
// a PNG, JPEG, BMP or TIFF header this reader understands.
std::optional<cv::Size> declaredImageSize(const std::uint8_t* data, std::size_t bytes);

// Why an image with these bytes must not be decoded under `limits` (unknown
// format, impossible size, not the expected size, over the pixel bound), or
// nullopt with `declared` set to its size.
std::optional<std::string> imageHeaderProblem(const std::uint8_t* data, std::size_t bytes, const ImageLimits& limits,
                                              cv::Size& declared);
// Reads a whole file of at most max_bytes; the reason when it cannot.
std::optional<std::string> readFileBytes(const std::string& path, std::size_t max_bytes,
                                         std::vector<std::uint8_t>& bytes);

struct GreyImage {
  cv::Mat grey;                        // CV_8UC1 when ok
  std::optional<std::string> problem;  // why not, when the image is unusable
};

// Decodes encoded image bytes to grey after the header check.
GreyImage decodeGreyImage(const std::uint8_t* data, std::size_t bytes, const ImageLimits& limits);
// Reads and decodes a file (bounded read); problems name nothing but the fault.
GreyImage readGreyImage(const std::string& path, const ImageLimits& limits);
// readGreyImage of a single image (a rest-state reference) of the size `expected`
// ({0, 0}: any within the bounds); throws InputError "<path>: <problem>".
cv::Mat loadGreyImage(const std::string& path, cv::Size expected);

}  // namespace onetip::capture
