#include "capture/image_file.hpp"

#include <png.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace onetip::capture {

namespace {

std::uint32_t be16(const std::uint8_t* p) { return static_cast<std::uint32_t>(p[0] << 8 | p[1]); }
std::uint32_t le16(const std::uint8_t* p) { return static_cast<std::uint32_t>(p[1] << 8 | p[0]); }
std::uint32_t be32(const std::uint8_t* p) { return be16(p) << 16 | be16(p + 2); }
std::uint32_t le32(const std::uint8_t* p) { return le16(p + 2) << 16 | le16(p); }

// A header's declaration: the image size and the largest block a decoder
// allocates at once for it (a TIFF strip or tile may exceed the image).
struct Declared {
  cv::Size size;
  std::int64_t block_pixels = 0;
};

std::optional<Declared> sizeOf(std::int64_t w, std::int64_t h) {
  if (w <= 0 || h <= 0 || w > (1 << 30) || h > (1 << 30)) return Declared{{-1, -1}, 0};  // declared, but absurd
  return Declared{{static_cast<int>(w), static_cast<int>(h)}, w * h};
}

std::optional<Declared> pngSize(const std::uint8_t* d, std::size_t n) {
  static const std::uint8_t sig[8] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
  if (n < 24 || !std::equal(sig, sig + 8, d) || !std::equal(d + 12, d + 16, "IHDR")) return std::nullopt;
  return sizeOf(be32(d + 16), be32(d + 20));
}

bool isJpegFrameMarker(std::uint8_t m) {  // SOF0..SOF15 except DHT (C4), JPG (C8), DAC (CC)
  return m >= 0xC0 && m <= 0xCF && m != 0xC4 && m != 0xC8 && m != 0xCC;
}

std::optional<Declared> jpegSize(const std::uint8_t* d, std::size_t n) {
  if (n < 4 || d[0] != 0xFF || d[1] != 0xD8) return std::nullopt;
  std::size_t i = 2;
  while (i + 1 < n) {
    if (d[i] != 0xFF) return std::nullopt;
    while (i + 1 < n && d[i + 1] == 0xFF) ++i;  // fill bytes
    if (i + 1 >= n) break;
    const std::uint8_t m = d[i + 1];
    i += 2;
    if (m == 0x01 || (m >= 0xD0 && m <= 0xD8)) continue;  // markers without a segment
    if (m == 0xD9 || m == 0xDA || i + 2 > n) return std::nullopt;  // EOI / scan before any frame header
    const std::size_t length = be16(d + i);
    if (length < 2) return std::nullopt;
    if (isJpegFrameMarker(m)) {
      if (i + 7 > n) return std::nullopt;
      return sizeOf(be16(d + i + 5), be16(d + i + 3));  // P, Y (height), X (width)
    }
    i += length;
  }
  return std::nullopt;
}

std::optional<Declared> bmpSize(const std::uint8_t* d, std::size_t n) {
  if (n < 26 || d[0] != 'B' || d[1] != 'M') return std::nullopt;
  if (le32(d + 14) == 12) return sizeOf(le16(d + 18), le16(d + 20));  // OS/2 core header
  const auto h = static_cast<std::int32_t>(le32(d + 22));             // negative: top-down rows
  return sizeOf(static_cast<std::int32_t>(le32(d + 18)), h < 0 ? -static_cast<std::int64_t>(h) : h);
}

// TIFF: the first IFD's ImageWidth (256) and ImageLength (257), and the block
// libtiff decodes at once: a strip of RowsPerStrip (278) rows, or a tile of
// TileWidth (322) x TileLength (323). A size tag given twice or with a count
// other than one is ambiguous (libtiff keeps the first, a naive reader the
// last: a fuzzer found 10000x20617 hiding behind a second ImageLength of 47),
// so it is refused as an impossible size.
std::optional<Declared> tiffSize(const std::uint8_t* d, std::size_t n) {
  if (n < 8) return std::nullopt;
  const bool le = d[0] == 'I' && d[1] == 'I' && d[2] == 42 && d[3] == 0;
  const bool be = d[0] == 'M' && d[1] == 'M' && d[2] == 0 && d[3] == 42;
  if (!le && !be) return std::nullopt;
  const auto u16 = [&](std::size_t at) { return le ? le16(d + at) : be16(d + at); };
  const auto u32 = [&](std::size_t at) { return le ? le32(d + at) : be32(d + at); };
  const std::size_t ifd = u32(4);
  if (ifd > n || n - ifd < 2) return std::nullopt;
  const std::size_t entries = u16(ifd);
  constexpr std::uint32_t kTags[] = {256, 257, 278, 322, 323};  // width, length, rows per strip, tile w, tile l
  std::int64_t value[5] = {-1, -1, -1, -1, -1};
  bool ambiguous = false;
  for (std::size_t k = 0; k < entries; ++k) {
    const std::size_t e = ifd + 2 + 12 * k;
    if (e + 12 > n) return std::nullopt;
    const std::uint32_t tag = u16(e), type = u16(e + 2);
    const auto* slot = std::find(std::begin(kTags), std::end(kTags), tag);
    if (slot == std::end(kTags)) continue;
    std::int64_t& v = value[slot - std::begin(kTags)];
    ambiguous |= v != -1 || u32(e + 4) != 1;
    v = type == 3 ? u16(e + 8) : type == 4 ? u32(e + 8) : -2;
  }
  const std::int64_t w = value[0], h = value[1], rows = value[2], tile_w = value[3], tile_h = value[4];
  if (w == -1 || h == -1) return std::nullopt;
  std::optional<Declared> out = sizeOf(w, h);
  if (ambiguous || out->size.width <= 0) return Declared{{-1, -1}, 0};
  const auto dim = [](std::int64_t v) { return std::clamp<std::int64_t>(v, 1, 1 << 30); };  // no overflow below
  if (tile_w != -1 || tile_h != -1) {
    out->block_pixels = dim(tile_w) * dim(tile_h);
  } else if (rows > 0 && rows != 0xFFFFFFFF) {  // 2^32 - 1 (the default) or 0: one strip of all rows
    out->block_pixels = w * dim(rows);
  }
  return out;
}

std::string sizeText(cv::Size s) { return std::to_string(s.width) + "x" + std::to_string(s.height); }

std::optional<Declared> declaredImage(const std::uint8_t* data, std::size_t bytes) {
  if (!data) return std::nullopt;
  for (auto reader : {pngSize, jpegSize, bmpSize, tiffSize})
    if (auto s = reader(data, bytes)) return s;
  return std::nullopt;
}

// PNG files are decoded here with libpng rather than by cv::imdecode: OpenCV's
// PNG reader leaves libpng's default error and warning handlers in place, so
// through it a damaged file prints a raw "libpng error: ..." (or "libpng
// warning: ...") line to stderr beside our own message. Here errors become the one-line
// reason and warnings are dropped (the image decodes anyway). The
// transformations are OpenCV's for IMREAD_GRAYSCALE (imgcodecs grfmt_png.cpp),
// so the pixels are the same: 16-bit samples keep their high byte, alpha is
// stripped, a palette and 1/2/4-bit grey expand to 8 bits, and colour becomes
// grey with png_set_rgb_to_gray(0.299, 0.587), i.e. Y = 0.299 R + 0.587 G + 0.114 B.
// libpng reports errors by longjmp, so the two functions that call it with
// setjmp hold only plain data.
struct PngInput {
  const std::uint8_t* data;
  std::size_t size;
  std::size_t at;
  char message[200];
};

void pngError(png_structp png, png_const_charp message) {
  auto* in = static_cast<PngInput*>(png_get_error_ptr(png));
  std::snprintf(in->message, sizeof in->message, "%s", message ? message : "unknown libpng error");
  png_longjmp(png, 1);
}

void pngWarning(png_structp, png_const_charp) {}

void pngRead(png_structp png, png_bytep out, png_size_t n) {
  auto* in = static_cast<PngInput*>(png_get_io_ptr(png));
  if (n > in->size - in->at) png_error(png, "the file ends early (truncated)");
  std::memcpy(out, in->data + in->at, n);
  in->at += n;
}

// Reads the header and sets OpenCV's grey transformations; false after a libpng error.
bool pngStart(png_structp png, png_infop info, png_uint_32* width, png_uint_32* height) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_info(png, info);
  int depth = 0, colour = 0;
  png_get_IHDR(png, info, width, height, &depth, &colour, nullptr, nullptr, nullptr);
  if (depth == 16) png_set_strip_16(png);
  png_set_strip_alpha(png);
  if (colour == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if ((colour & PNG_COLOR_MASK_COLOR) == 0 && depth < 8) png_set_expand_gray_1_2_4_to_8(png);
  png_set_rgb_to_gray(png, 1, 0.299, 0.587);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  return true;
}

// Decodes every row (and reads to IEND, checking each chunk's CRC); false after a libpng error.
bool pngRows(png_structp png, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_image(png, rows);
  png_read_end(png, nullptr);
  return true;
}

struct PngReader {
  png_structp png = nullptr;
  png_infop info = nullptr;
  ~PngReader() { png_destroy_read_struct(&png, info ? &info : nullptr, nullptr); }
};

// A PNG (whose header declared `declared`) to 8-bit grey, or the reason it cannot be.
GreyImage decodePngGrey(const std::uint8_t* data, std::size_t bytes, cv::Size declared) {
  GreyImage out;
  PngInput in{data, bytes, 0, {}};
  PngReader reader;
  reader.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &in, pngError, pngWarning);
  if (reader.png) reader.info = png_create_info_struct(reader.png);
  if (!reader.png || !reader.info) {
    out.problem = "cannot decode the PNG: libpng could not start";
    return out;
  }
  png_set_read_fn(reader.png, &in, pngRead);
  png_uint_32 width = 0, height = 0;
  if (pngStart(reader.png, reader.info, &width, &height)) {
    if (cv::Size(static_cast<int>(width), static_cast<int>(height)) != declared ||
        png_get_channels(reader.png, reader.info) != 1 || png_get_bit_depth(reader.png, reader.info) != 8 ||
        png_get_rowbytes(reader.png, reader.info) != width) {
      out.problem = "cannot decode the PNG: unexpected layout after conversion to 8-bit grey";
      return out;
    }
    cv::Mat grey(declared, CV_8UC1);
    std::vector<png_bytep> rows(static_cast<std::size_t>(grey.rows));
    for (int y = 0; y < grey.rows; ++y) rows[static_cast<std::size_t>(y)] = grey.ptr<png_byte>(y);
    if (pngRows(reader.png, rows.data())) {
      out.grey = grey;
      return out;
    }
  }
  out.problem = std::string("cannot decode the PNG: ") + in.message;
  return out;
}

bool isPng(const std::uint8_t* data, std::size_t bytes) { return bytes >= 8 && png_sig_cmp(data, 0, 8) == 0; }

}  // namespace

std::optional<cv::Size> declaredImageSize(const std::uint8_t* data, std::size_t bytes) {
  const std::optional<Declared> d = declaredImage(data, bytes);
  return d ? std::optional<cv::Size>(d->size) : std::nullopt;
}

std::optional<std::string> imageHeaderProblem(const std::uint8_t* data, std::size_t bytes, const ImageLimits& limits,
                                              cv::Size& declared) {
  const std::optional<Declared> image = declaredImage(data, bytes);
  if (!image) return "not a PNG, JPEG, BMP or TIFF image (unrecognised or truncated header)";
  declared = image->size;
  if (declared.width <= 0) return "the image header declares an impossible size (absurd, or a size tag given twice)";
  if (limits.expected.width > 0 && declared != limits.expected)
    return "wrong frame size " + sizeText(declared) + " (expected " + sizeText(limits.expected) + ")";
  if (static_cast<std::int64_t>(declared.width) * declared.height > limits.max_pixels)
    return "the image header declares " + sizeText(declared) + " pixels, more than the " +
           std::to_string(limits.max_pixels) + "-pixel bound";
  if (image->block_pixels > limits.max_pixels)
    return "the image header declares a strip or tile of " + std::to_string(image->block_pixels) +
           " pixels, more than the " + std::to_string(limits.max_pixels) + "-pixel bound";
  return std::nullopt;
}

std::optional<std::string> readFileBytes(const std::string& path, std::size_t max_bytes,
                                         std::vector<std::uint8_t>& bytes) {
  const std::string problem = inputFileProblem(path);  // a folder opens, and says it holds 2^63 - 1 bytes
  if (!problem.empty()) return problem;
  errno = 0;
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  const std::streamoff size = in ? static_cast<std::streamoff>(in.tellg()) : -1;
  if (size < 0) return errno != 0 ? std::string("cannot read the file (") + std::strerror(errno) + ")" : "cannot read the file";
  if (static_cast<std::uint64_t>(size) > max_bytes)
    return "file of " + std::to_string(size) + " bytes, over the " + std::to_string(max_bytes) +
           "-byte bound for one frame";
  bytes.resize(static_cast<std::size_t>(size));
  in.seekg(0);
  if (!bytes.empty() && !in.read(reinterpret_cast<char*>(bytes.data()), size)) return "cannot read the file";
  return std::nullopt;
}

GreyImage decodeGreyImage(const std::uint8_t* data, std::size_t bytes, const ImageLimits& limits) {
  GreyImage out;
  cv::Size declared;
  out.problem = imageHeaderProblem(data, bytes, limits, declared);
  if (out.problem) return out;
  if (isPng(data, bytes)) return decodePngGrey(data, bytes, declared);
  try {
    const cv::Mat buffer(1, static_cast<int>(bytes), CV_8UC1, const_cast<std::uint8_t*>(data));
    out.grey = cv::imdecode(buffer, cv::IMREAD_GRAYSCALE);
  } catch (const std::exception& e) {
    out.grey.release();
    out.problem = std::string("cannot decode: ") + e.what();
    return out;
  }
  if (out.grey.empty())
    out.problem = "empty frame (could not be decoded)";
  else if (out.grey.size() != declared)
    out.problem = "decoded size " + sizeText(out.grey.size()) + " differs from the header's " + sizeText(declared);
  if (out.problem) out.grey.release();
  return out;
}

GreyImage readGreyImage(const std::string& path, const ImageLimits& limits) {
  GreyImage out;
  std::vector<std::uint8_t> bytes;
  out.problem = readFileBytes(path, limits.max_file_bytes, bytes);
  if (out.problem) return out;
  return decodeGreyImage(bytes.data(), bytes.size(), limits);
}

cv::Mat loadGreyImage(const std::string& path, cv::Size expected) {
  ImageLimits limits;
  limits.expected = expected;
  GreyImage image = readGreyImage(path, limits);
  if (image.problem) throw InputError(path + ": " + *image.problem);
  return image.grey;
}

}  // namespace onetip::capture
