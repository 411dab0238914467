#include "devices/vibrotactile_output.hpp"

#include <alsa/asoundlib.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace onetip::devices {
namespace {
snd_pcm_t* pcmOf(void* p) { return static_cast<snd_pcm_t*>(p); }
}  // namespace

void VibrotactileOptions::validate() const {
  if (pcm.empty()) throw InputError("VibrotactileOptions.pcm: empty");
  if (rate_hz < 1000 || rate_hz > 192000) throw InputError("VibrotactileOptions.rate_hz: must be in [1000, 192000]");
  if (!(gain > 0.0 && std::isfinite(gain))) throw InputError("VibrotactileOptions.gain: must be positive");
  if (latency_us < 1000 || latency_us > 2000000) throw InputError("VibrotactileOptions.latency_us: must be in [1000, 2000000]");
}

VibrotactileOutput::~VibrotactileOutput() { close(); }

std::int16_t VibrotactileOutput::toPcm(double sample, double gain) {
  const double v = std::isfinite(sample) ? std::clamp(sample * gain, -1.0, 1.0) : 0.0;
  return static_cast<std::int16_t>(std::lround(v * 32767.0));
}

void VibrotactileOutput::open(const VibrotactileOptions& options) {
  options.validate();
  close();
  options_ = options;
  const std::string where = "vibrotactile PCM '" + options.pcm + "'";
  snd_pcm_t* pcm = nullptr;
  int err = 0;
  if (options.alsa_config.empty()) {
    err = snd_pcm_open(&pcm, options.pcm.c_str(), SND_PCM_STREAM_PLAYBACK, 0);
  } else {
    snd_config_t* config = nullptr;
    snd_input_t* input = nullptr;
    err = snd_config_top(&config);
    if (err >= 0) err = snd_input_buffer_open(&input, options.alsa_config.data(), static_cast<ssize_t>(options.alsa_config.size()));
    if (err >= 0) err = snd_config_load(config, input);
    if (input) snd_input_close(input);
    if (err < 0) {
      if (config) snd_config_delete(config);
      throw InputError(where + ": bad ALSA configuration text (" + snd_strerror(err) + ")");
    }
    config_ = config;
    err = snd_pcm_open_lconf(&pcm, options.pcm.c_str(), SND_PCM_STREAM_PLAYBACK, 0, config);
  }
  if (err < 0) {
    close();
    throw InputError(where + ": cannot open (" + snd_strerror(err) + ")");
  }
  pcm_ = pcm;
  err = snd_pcm_set_params(pcm, SND_PCM_FORMAT_S16_LE, SND_PCM_ACCESS_RW_INTERLEAVED, 1, options.rate_hz, 1,
                           options.latency_us);
  if (err < 0) {
    close();
    throw InputError(where + ": cannot play mono 16-bit at " + std::to_string(options.rate_hz) + " Hz (" +
                     snd_strerror(err) + ")");
  }
  underruns_ = frames_ = 0;
}

void VibrotactileOutput::write(std::span<const double> samples) {
  if (!pcm_) throw InputError("vibrotactile output: not open");
  buffer_.resize(samples.size());
  std::transform(samples.begin(), samples.end(), buffer_.begin(), [&](double s) { return toPcm(s, options_.gain); });
  size_t done = 0;
  while (done < buffer_.size()) {
    const snd_pcm_sframes_t n =
        snd_pcm_writei(pcmOf(pcm_), buffer_.data() + done, static_cast<snd_pcm_uframes_t>(buffer_.size() - done));
    if (n >= 0) {
      done += static_cast<size_t>(n);
      continue;
    }
    if (n == -EPIPE) ++underruns_;
    if (snd_pcm_recover(pcmOf(pcm_), static_cast<int>(n), 1) < 0)
      throw InputError("vibrotactile PCM '" + options_.pcm + "': write failed (" + snd_strerror(static_cast<int>(n)) + ")");
  }
  frames_ += done;
}

void VibrotactileOutput::writeFiltered(haptics::VibrationChannel& channel, std::span<const double> ac_signal) {
  std::vector<double> filtered(ac_signal.size());
  std::transform(ac_signal.begin(), ac_signal.end(), filtered.begin(), [&](double x) { return channel.process(x); });
  write(filtered);
}

void VibrotactileOutput::close() {
  if (pcm_) {
    snd_pcm_drain(pcmOf(pcm_));
    snd_pcm_close(pcmOf(pcm_));
    pcm_ = nullptr;
  }
  if (config_) {
    snd_config_delete(static_cast<snd_config_t*>(config_));
    config_ = nullptr;
  }
}

}  // namespace onetip::devices
