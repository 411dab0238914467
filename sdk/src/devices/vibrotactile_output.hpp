// devices/vibrotactile_output.hpp — the vibrotactile motor driven like audio
// (da Vinci paper: the renderer's filtered AC pressure signal to the motor).
//
// Samples are doubles in [-1, 1] full scale (times `gain`, clipped), written
// as signed 16-bit little-endian PCM, mono, at rate_hz (default the BioTac AC
// rate, 2200 Hz; ALSA's plug layer resamples when the card cannot). An
// underrun (-EPIPE) or suspend is recovered with snd_pcm_recover and the
// write resumes; underruns() counts them. `alsa_config` (optional) is extra
// ALSA configuration text, e.g. a `pcm.NAME { type file ... }` definition,
// read before opening `pcm` (then only that text defines PCMs).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "haptics/vibration_channel.hpp"

namespace onetip::devices {

struct VibrotactileOptions {
  std::string pcm = "default";
  std::string alsa_config;
  unsigned rate_hz = 2200;
  double gain = 1.0;
  unsigned latency_us = 50000;
  void validate() const;  // throws InputError naming the bad field
};

class VibrotactileOutput {
 public:
  VibrotactileOutput() = default;
  ~VibrotactileOutput();
  VibrotactileOutput(const VibrotactileOutput&) = delete;
  VibrotactileOutput& operator=(const VibrotactileOutput&) = delete;

  // InputError naming the PCM when it cannot be opened or configured.
  void open(const VibrotactileOptions& options);
  // Plays the samples (blocking until ALSA took them); recovers underruns.
  void write(std::span<const double> samples);
  // Filters the AC signal through the renderer's vibration channel, then plays it.
  void writeFiltered(haptics::VibrationChannel& channel, std::span<const double> ac_signal);
  void close();  // drains what is queued
  std::uint64_t underruns() const noexcept { return underruns_; }
  std::uint64_t framesWritten() const noexcept { return frames_; }
  // The PCM sample for one input value (for callers that check the stream).
  static std::int16_t toPcm(double sample, double gain);

 private:
  void* pcm_ = nullptr;     // snd_pcm_t*, kept out of the header
  void* config_ = nullptr;  // snd_config_t* for alsa_config
  VibrotactileOptions options_;
  std::vector<std::int16_t> buffer_;
  std::uint64_t underruns_ = 0;
  std::uint64_t frames_ = 0;
};

}  // namespace onetip::devices
