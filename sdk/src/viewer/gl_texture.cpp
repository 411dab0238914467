#include "viewer/gl_texture.hpp"

#include <stdexcept>

namespace onetip::viewer {

GlTexture::GlTexture() {
  glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

GlTexture::~GlTexture() { glDeleteTextures(1, &texture_); }

namespace {
void checkUploadable(const cv::Mat& image) {
  if (image.empty() || (image.type() != CV_8UC1 && image.type() != CV_8UC4))
    throw std::invalid_argument("GlTexture::upload: expected a non-empty CV_8UC1 or CV_8UC4 image");
}
GLenum pixelFormat(const cv::Mat& image) { return image.type() == CV_8UC1 ? GL_RED : GL_BGRA; }
}  // namespace

void GlTexture::upload(const cv::Mat& image) {
  checkUploadable(image);
  const cv::Mat pixels = image.isContinuous() ? image : image.clone();
  const bool grey = pixels.type() == CV_8UC1;
  glBindTexture(GL_TEXTURE_2D, texture_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const GLenum format = pixelFormat(pixels);
  if (pixels.size() != size_ || pixels.type() != type_) {
    glTexImage2D(GL_TEXTURE_2D, 0, grey ? GL_R8 : GL_RGBA8, pixels.cols, pixels.rows, 0, format, GL_UNSIGNED_BYTE,
                 pixels.data);
    size_ = pixels.size();
    type_ = pixels.type();
  } else {
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, pixels.cols, pixels.rows, format, GL_UNSIGNED_BYTE, pixels.data);
  }
}

void GlTexture::uploadRegions(const cv::Mat& image, const std::vector<cv::Rect>& regions) {
  checkUploadable(image);
  if (image.size() != size_ || image.type() != type_) {
    upload(image);
    return;
  }
  const cv::Rect whole({0, 0}, image.size());
  glBindTexture(GL_TEXTURE_2D, texture_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, static_cast<GLint>(image.step1() / static_cast<size_t>(image.channels())));
  for (const cv::Rect& r : regions) {
    if ((r & whole) != r) {
      glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
      throw std::invalid_argument("GlTexture::uploadRegions: a region lies outside the image");
    }
    glTexSubImage2D(GL_TEXTURE_2D, 0, r.x, r.y, r.width, r.height, pixelFormat(image), GL_UNSIGNED_BYTE,
                    image.ptr(r.y, r.x));
  }
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
}

void GlTexture::bind(int unit) const {
  glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
  glBindTexture(GL_TEXTURE_2D, texture_);
}

}  // namespace onetip::viewer
