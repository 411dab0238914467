// qemu_camera/guest_report.hpp — what the camera drills' guest program
// (camera_guest) prints and measures. Every line starts with "ONETIP " so the
// host (check_camera.py) finds it among the kernel's console output. Times are
// milliseconds on CLOCK_MONOTONIC (std::chrono::steady_clock).
#pragma once

#include <chrono>
#include <cstdint>
#include <opencv2/core.hpp>

#include "capture/v4l2_source.hpp"

namespace onetip::qemu_camera {

using Clock = std::chrono::steady_clock;
using capture::Frame;
using capture::FrameStatus;
using capture::V4l2Source;
using capture::V4l2SourceOptions;

double msSince(Clock::time_point t0);

// 64-bit FNV-1a of a byte string and of an 8-bit image's pixels (row by row).
std::uint64_t fnv1a(const std::uint8_t* data, std::size_t n);
std::uint64_t hashImage(const cv::Mat& grey);

// "ONETIP <tag> <fourcc> <width> <height> <fps>"
void printFormat(const char* tag, const capture::V4l2Source& source);
// "ONETIP FRAME <index> <status> <timestamp_s> <cols> <rows> <mean> <stddev> <call_ms> [<message>]"
void printFrame(const capture::Frame& f, double call_ms);
// "ONETIP COUNTERS <delivered> <skipped> <errors>"
void printCounters(const capture::V4l2Source& source);

// Pulls frames until `count` are ok (at most 3 * count + 10 calls), printing each; returns the ok count.
int receive(capture::V4l2Source& source, int count);

// After an unplug: pulls frames (at most `max_calls`), printing each and every error event
// ("ONETIP EVENT error <message>"), until one is ok; then prints
// "ONETIP RECOVERED <ms since back> <ms since unplug>" and returns true.
bool awaitRecovery(capture::V4l2Source& source, int max_calls, Clock::time_point back, Clock::time_point unplug);

}  // namespace onetip::qemu_camera
