// Vibrotactile output through ALSA's file plugin: the filtered AC signal is
// written as S16_LE samples; the file holds exactly the expected samples.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <thread>

#include "core/error.hpp"
#include "devices/vibrotactile_output.hpp"
#include "haptics/platform_kinematics.hpp"
#include "haptics/vibration_plant.hpp"

namespace onetip::devices {
namespace {

std::string fileConfig(const std::string& name, const std::string& path) {
  return "pcm." + name + " { type file slave.pcm { type null } file \"" + path + "\" format raw }\n";
}

std::vector<std::int16_t> readSamples(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::int16_t> s(bytes.size() / 2);
  for (size_t i = 0; i < s.size(); ++i)
    s[i] = static_cast<std::int16_t>(static_cast<std::uint8_t>(bytes[2 * i]) | (static_cast<std::uint8_t>(bytes[2 * i + 1]) << 8));
  return s;
}

TEST(VibrotactileOutput, StreamsTheFilteredSignalSampleExactly) {
  const std::string path = (std::filesystem::temp_directory_path() / ("onetip_vib_" + std::to_string(::getpid()) + ".raw")).string();
  VibrotactileOptions o;
  o.pcm = "onetip_test";
  o.alsa_config = fileConfig("onetip_test", path);
  o.gain = 0.5;
  // The renderer's filter for one platform pose, and an AC input: a 150 Hz burst plus a chirp.
  const haptics::PlatformKinematics kinematics;
  const haptics::TransferFunction tf = haptics::vibrationPlant(kinematics.forward({80.0, 80.0, 80.0}));
  haptics::VibrationChannel channel(tf);
  std::vector<double> ac(2200);
  for (size_t i = 0; i < ac.size(); ++i) {
    const double t = i / 2200.0;
    ac[i] = 0.6 * std::sin(2 * M_PI * 150 * t) + 0.3 * std::sin(2 * M_PI * (20 + 200 * t) * t);
  }
  {
    VibrotactileOutput out;
    out.open(o);
    out.writeFiltered(channel, std::span<const double>(ac).first(1000));
    out.writeFiltered(channel, std::span<const double>(ac).subspan(1000));
    EXPECT_EQ(out.framesWritten(), ac.size());
    out.close();
  }
  // Independent reference: the same IIR filter run directly.
  haptics::IirFilter filter(tf);
  const std::vector<std::int16_t> written = readSamples(path);
  ASSERT_EQ(written.size(), ac.size());
  int worst = 0, nonzero = 0;
  for (size_t i = 0; i < ac.size(); ++i) {
    const double y = std::clamp(filter.process(ac[i]) * 0.5, -1.0, 1.0);
    worst = std::max(worst, std::abs(written[i] - static_cast<int>(std::lround(y * 32767.0))));
    nonzero += written[i] != 0;
  }
  EXPECT_EQ(worst, 0);
  EXPECT_GT(nonzero, 2000);
  std::filesystem::remove(path);
}

// ALSA's null slave does not run in real time, so this checks that writes
// separated by gaps longer than the buffer keep every sample (the underrun
// recovery path runs only on a real device).
TEST(VibrotactileOutput, KeepsEverySampleAcrossGapsLongerThanTheBuffer) {
  const std::string path = (std::filesystem::temp_directory_path() / ("onetip_vib_u_" + std::to_string(::getpid()) + ".raw")).string();
  VibrotactileOptions o;
  o.pcm = "onetip_test";
  o.alsa_config = fileConfig("onetip_test", path);
  o.latency_us = 10000;
  VibrotactileOutput out;
  out.open(o);
  const std::vector<double> burst(64, 0.25);
  for (int i = 0; i < 4; ++i) {
    out.write(burst);
    std::this_thread::sleep_for(std::chrono::milliseconds(60));  // far longer than the 10 ms buffer
  }
  out.close();
  std::printf("vibrotactile: %llu underruns recovered\n", static_cast<unsigned long long>(out.underruns()));
  const auto written = readSamples(path);
  EXPECT_EQ(written.size(), 4u * 64u);
  for (std::int16_t s : written) EXPECT_EQ(s, VibrotactileOutput::toPcm(0.25, 1.0));
  std::filesystem::remove(path);
}

TEST(VibrotactileOutput, UnknownPcmFailsAtOpen) {
  VibrotactileOptions o;
  o.pcm = "onetip_no_such_pcm";
  o.alsa_config = "pcm.other { type null }\n";
  EXPECT_THROW(VibrotactileOutput().open(o), InputError);
  o.alsa_config = "pcm.broken { type file ";
  EXPECT_THROW(VibrotactileOutput().open(o), InputError);
  o.alsa_config.clear();
  o.rate_hz = 10;
  EXPECT_THROW(VibrotactileOutput().open(o), InputError);
}

}  // namespace
}  // namespace onetip::devices
