// MJPEG -> grey on a 1920x1080 camera-like frame: TurboJPEG straight to grey
// (tjDecompress2, TJPF_GRAY, as capture/jpeg_grey_decoder.hpp does) against
// cv::imdecode(IMREAD_GRAYSCALE), for a grey JPEG and a colour 4:2:2 JPEG (the
// usual webcam MJPEG); YUYV -> grey for comparison. Run with
// --benchmark_format=csv for the CSV.
#include <benchmark/benchmark.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <turbojpeg.h>

#include "capture/jpeg_grey_decoder.hpp"
#include "capture/raw_decode.hpp"

namespace {

// A blurred, noisy checkerboard filling the frame, as the pad camera sees it.
cv::Mat cameraLikeFrame() {
  cv::Mat img(1080, 1920, CV_8UC1);
  for (int y = 0; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x)
      img.at<std::uint8_t>(y, x) = ((x / 48 + y / 48) % 2) ? 200 : 40;
  cv::GaussianBlur(img, img, cv::Size(0, 0), 1.5);
  cv::Mat noise(img.size(), CV_8SC1);
  cv::randn(noise, 0, 2);
  cv::add(img, noise, img, cv::noArray(), CV_8U);
  return img;
}

// Quality 90; colour frames as 4:2:2 (TurboJPEG's encoder, since OpenCV 4.6
// cannot choose the chroma subsampling).
std::vector<std::uint8_t> jpeg(bool colour) {
  cv::Mat img = cameraLikeFrame();
  if (!colour) {
    std::vector<std::uint8_t> out;
    cv::imencode(".jpg", img, out, {cv::IMWRITE_JPEG_QUALITY, 90});
    return out;
  }
  cv::cvtColor(img, img, cv::COLOR_GRAY2BGR);
  tjhandle tj = tjInitCompress();
  unsigned char* data = nullptr;
  unsigned long size = 0;
  tjCompress2(tj, img.data, img.cols, static_cast<int>(img.step[0]), img.rows, TJPF_BGR, &data,
              &size, TJSAMP_422, 90, 0);
  std::vector<std::uint8_t> out(data, data + size);
  tjFree(data);
  tjDestroy(tj);
  return out;
}

void BM_TurboJpegToGrey(benchmark::State& state) {
  const auto bytes = jpeg(state.range(0) != 0);
  onetip::capture::JpegGreyDecoder decoder;
  cv::Mat grey;
  for (auto _ : state) {
    if (!decoder.decode(bytes.data(), bytes.size(), {1920, 1080}, grey).ok)
      state.SkipWithError("decode failed");
    benchmark::DoNotOptimize(grey.data);
  }
  state.SetLabel(state.range(0) ? "colour 4:2:2" : "grey");
}

void BM_OpenCvImdecodeGrey(benchmark::State& state) {
  const auto bytes = jpeg(state.range(0) != 0);
  for (auto _ : state) {
    cv::Mat grey = cv::imdecode(bytes, cv::IMREAD_GRAYSCALE);
    if (grey.empty()) state.SkipWithError("decode failed");
    benchmark::DoNotOptimize(grey.data);
  }
  state.SetLabel(state.range(0) ? "colour 4:2:2" : "grey");
}

void BM_YuyvToGrey(benchmark::State& state) {
  std::vector<std::uint8_t> yuyv(1920u * 2u * 1080u, 128);
  cv::Mat grey;
  for (auto _ : state) {
    onetip::capture::yuyvToGrey(yuyv.data(), yuyv.size(), 1920, 1080, 3840, grey);
    benchmark::DoNotOptimize(grey.data);
  }
}

}  // namespace

BENCHMARK(BM_TurboJpegToGrey)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly();
BENCHMARK(BM_OpenCvImdecodeGrey)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly();
BENCHMARK(BM_YuyvToGrey)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly();
BENCHMARK_MAIN();
