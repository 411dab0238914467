#include "input/gel_creep.hpp"

#include <algorithm>
#include <cmath>

#include "core/option_checks.hpp"
#include "input/gel_recovery.hpp"

namespace onetip::input {

namespace {

// Inverts the recorded frames 0..last with `model` from v = 0 where the contact began (creep_model.hpp) and
// returns the elastic fields e_j = u_j - v_j of frames first..last; `delayed` is left with v_last.
std::vector<std::vector<Eigen::Vector3d>> elasticFields(const std::vector<std::vector<Eigen::Vector3d>>& u,
                                                        const std::vector<double>& t,
                                                        const std::vector<std::uint8_t>& valid,
                                                        const CreepModel& model, size_t first, size_t last,
                                                        std::vector<Eigen::Vector3d>& delayed) {
  delayed.assign(u[0].size(), Eigen::Vector3d::Zero());
  std::vector<std::vector<Eigen::Vector3d>> e;
  for (size_t j = 0; j <= last; ++j) {
    model.step(delayed, u[j], valid, j > 0 ? t[j] - t[j - 1] : 0.0);
    if (j < first) continue;
    e.push_back(u[j]);
    for (size_t i = 0; i < delayed.size(); ++i) e.back()[i] -= delayed[i];
  }
  return e;
}

// The spread of fields about their per-marker mean over the valid markers: the sum of squares, and the largest
// marker's distance.
std::pair<double, double> spread(const std::vector<std::vector<Eigen::Vector3d>>& e,
                                 const std::vector<std::uint8_t>& valid) {
  double sum = 0, worst = 0;
  for (size_t i = 0; i < valid.size(); ++i) {
    if (!valid[i]) continue;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& f : e) mean += f[i];
    mean /= static_cast<double>(e.size());
    for (const auto& f : e) {
      sum += (f[i] - mean).squaredNorm();
      worst = std::max(worst, (f[i] - mean).norm());
    }
  }
  return {sum, worst};
}

// The minimum of a unimodal cost over (lo, hi) by golden section, to within 1e-6.
template <class Cost>
double goldenSection(const Cost& cost, double lo, double hi) {
  const double g = (std::sqrt(5.0) - 1) / 2;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = cost(x1), f2 = cost(x2);
  while (hi - lo > 1e-6) {
    if (f1 < f2) {
      hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo), f1 = cost(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo), f2 = cost(x2);
    }
  }
  return (lo + hi) / 2;
}

// Whether a field (u = p - rest, S, mm) holds a deformation and not only noise: its largest valid marker beyond
// `sigmas` times the noise of a difference of two measurements (the marker's and its rest's), sigma sqrt 2. A
// field of noise alone is not; and, since every frame shares the rest's noise, it reads as a copy of the last
// frame scaled by about one half.
bool holdsADeformation(const std::vector<Eigen::Vector3d>& u, const std::vector<std::uint8_t>& valid,
                       double noise_mm, double sigmas) {
  double largest = 0;
  for (size_t i = 0; i < u.size() && i < valid.size(); ++i)
    if (valid[i]) largest = std::max(largest, u[i].norm());
  return largest > sigmas * noise_mm * std::sqrt(2.0);
}

}  // namespace

void GelCreepOptions::validate() const {
  requireInRange("gel creep: fit_sigmas", fit_sigmas, 3, 100);
  requireInRange("gel creep: false_alarm", false_alarm, 1e-9, 0.1);
  requireInRange("gel creep: stop_factor", stop_factor, 1, 100);
  requireInRange("gel creep: history_frames", history_frames, 16, 100000);
  requireInRange("gel creep: max_relaxation", max_relaxation, 0.05, 0.95);
  requireInRange("gel creep: model_error", model_error, 0, 0.5);
}

CreepWindow creepWindow(const std::vector<std::vector<Eigen::Vector3d>>& u, size_t first, size_t m,
                        const std::vector<std::uint8_t>& valid, double noise_mm, double fit_sigmas,
                        double false_alarm) {
  CreepWindow out;
  if (!(noise_mm > 0) || m < 1 || first + 2 * m >= u.size()) return out;
  const auto& a = u[first];
  const auto& b = u[first + m];
  const auto& c = u[first + 2 * m];
  if (a.size() != valid.size() || b.size() != valid.size() || c.size() != valid.size()) return out;
  double dd = 0, dd2 = 0;
  int n = 0;
  for (size_t i = 0; i < valid.size(); ++i) {
    if (!valid[i]) continue;
    dd += (b[i] - a[i]).squaredNorm();
    dd2 += (b[i] - a[i]).dot(c[i] - b[i]);
    ++n;
  }
  // Without the noise's own share: B's noise enters d1 and d2 with opposite signs and each increment carries
  // two fields' noise, E<d1, d2> = <D1, D2> - 3 n sigma^2 and E<d1, d1> = |D1|^2 + 6 n sigma^2.
  const double var = noise_mm * noise_mm * n;
  dd -= 6 * var;
  dd2 += 3 * var;
  if (n < 3 || !(dd > 0)) return out;
  out.measured = true;
  out.markers = n;
  out.rho = dd2 / dd;
  out.rho_sd = noise_mm * std::sqrt(1 + (1 + out.rho) * (1 + out.rho) + out.rho * out.rho) / std::sqrt(dd);
  if (!(out.rho > fit_sigmas * out.rho_sd && out.rho < 1 - fit_sigmas * out.rho_sd)) return out;
  out.shrinking = true;
  // Every frame j after A on the exponential through A and B: u_j = (1 - w_j) A + w_j B,
  // w_j = (1 - q^(j - first)) / (1 - q^m), q = rho^(1/m).
  const double q = std::pow(out.rho, 1.0 / static_cast<double>(m));
  const auto off = [&](size_t j) {  // frame j's largest residual off the exponential, in units of its sd
    const double w = (1 - std::pow(q, static_cast<double>(j) - static_cast<double>(first))) / (1 - out.rho);
    const double s = noise_mm * std::sqrt(1 + (1 - w) * (1 - w) + w * w);
    double worst = 0;
    for (size_t i = 0; i < valid.size(); ++i)
      if (valid[i]) worst = std::max(worst, (u[j][i] - (1 - w) * a[i] - w * b[i]).norm() / s);
    return worst;
  };
  // C first, then the frames between; the first beyond the window's bound ends the test.
  const double window_bound = noiseMaximum(n * static_cast<int>(2 * m - 1), false_alarm);
  for (size_t j = first + 2 * m; j > first && out.worst_sigmas <= window_bound; --j)
    if (j != first + m) out.worst_sigmas = std::max(out.worst_sigmas, off(j));
  out.exponential = out.worst_sigmas <= window_bound;
  if (!out.exponential) return out;
  // Backwards from A while the frames stay on the same exponential (within the bound one frame's noise passes).
  const double bound = noiseMaximum(n, false_alarm);
  out.start = first;
  while (out.start > 0) {
    out.before_sigmas = off(out.start - 1);
    if (out.before_sigmas > bound) break;
    --out.start;
    out.before_sigmas = 0;
  }
  return out;
}

GelCreep::GelCreep(GelCreepOptions options) : options_(options) { options_.validate(); }

void GelCreep::reset() {
  model_ = CreepModel{};
  delayed_.clear();
  have_t_ = false;
  clearHistory();
}

void GelCreep::clearHistory() {
  history_.clear();
  history_valid_.clear();
  history_t_.clear();
  history_had_remainder_ = false;
  recovery_start_ = kNoRecovery;
}

const std::vector<Eigen::Vector3d>& GelCreep::advance(const MarkerField& now, const MarkerField& rest, double t) {
  const double dt = have_t_ ? t - last_t_ : 0.0;
  last_t_ = t;
  have_t_ = true;
  if (!model_.measured() || now.position.size() != rest.position.size()) return delayed_;
  std::vector<Eigen::Vector3d> u(now.position.size());
  std::vector<std::uint8_t> valid(now.position.size());
  for (size_t i = 0; i < u.size(); ++i) {
    u[i] = now.position[i] - rest.position[i];
    valid[i] = now.valid[i] && rest.valid[i];
  }
  model_.step(delayed_, u, valid, dt);
  return delayed_;
}

bool GelCreep::observe(const MarkerField& now, const MarkerField& rest, double t, bool in_contact,
                       double noise_mm, const std::vector<Eigen::Vector3d>& remainder, int decaying_frames) {
  if (!options_.enabled || model_.measured()) return false;
  if (now.position.size() != rest.position.size()) {
    clearHistory();
    return false;
  }
  std::vector<Eigen::Vector3d> u(now.position.size());
  std::vector<std::uint8_t> valid(u.size());
  for (size_t i = 0; i < u.size(); ++i) {
    u[i] = now.position[i] - rest.position[i];
    valid[i] = now.valid[i] && rest.valid[i];
  }
  if (!in_contact) return observeRecovery(std::move(u), valid, t, noise_mm);
  const double last_recorded_t = history_t_.empty() ? t : history_t_.back();
  if (recovery_start_ != kNoRecovery && finishRecovery(noise_mm)) {
    // A touch ended the recovery that measured the gel: this frame's field loads it from v as it now is.
    model_.step(delayed_, u, valid, t - last_recorded_t);
    return true;
  }
  if (recovery_start_ != kNoRecovery) clearHistory();  // the record after a recovery that measured nothing
  if (history_.size() >= static_cast<size_t>(options_.history_frames)) return false;
  if (history_valid_.size() != u.size()) history_valid_.assign(u.size(), 1);
  for (size_t i = 0; i < u.size(); ++i) history_valid_[i] = history_valid_[i] && valid[i];
  history_had_remainder_ = history_had_remainder_ || !remainder.empty();
  history_.push_back(std::move(u));
  history_t_.push_back(t);
  // The frames since the finger's field left, decaying as a gel does (gel_recovery.hpp), are a recovery seen
  // while the contact still holds: tried at 1, 2, 4, ... frames, so that a long decay costs log2 of its
  // frames in fits, not one per frame.
  const auto d = static_cast<size_t>(std::max(decaying_frames, 0));
  const bool decaying = d > 0 && (d & (d - 1)) == 0 && d < history_.size() && !history_had_remainder_;
  if (!identify(noise_mm) && !(decaying && identifyFromRecovery(history_.size() - 1 - d, noise_mm))) return false;
  if (remainder.size() == delayed_.size())
    for (size_t i = 0; i < delayed_.size(); ++i) delayed_[i] += remainder[i];
  clearHistory();
  return true;
}

bool GelCreep::observeRecovery(std::vector<Eigen::Vector3d> u, const std::vector<std::uint8_t>& valid, double t,
                               double noise_mm) {
  if (history_.empty() || history_had_remainder_) {
    clearHistory();
    return false;
  }
  const bool deformed = holdsADeformation(u, valid, noise_mm, options_.fit_sigmas);
  if (recovery_start_ == kNoRecovery) {
    if (!deformed) {  // the contact left nothing behind: an elastic pad, or a gel that has already recovered
      clearHistory();
      return false;
    }
    recovery_start_ = history_.size();
  } else {
    const DecayPair pair = decayPair(history_.back(), history_valid_, u, valid, noise_mm);
    const bool decaying = deformed && pair.measured && pair.alpha > 0 &&
                          pair.alpha < 1 - options_.fit_sigmas * pair.alpha_sd &&
                          pair.worst_sigmas <= noiseMaximum(pair.markers, options_.false_alarm);
    if (!decaying || history_.size() >= static_cast<size_t>(options_.history_frames)) {
      const double last_recorded_t = history_t_.back();
      const bool measured = finishRecovery(noise_mm);
      if (measured) model_.step(delayed_, u, valid, t - last_recorded_t);
      return measured;
    }
  }
  for (size_t i = 0; i < u.size() && i < history_valid_.size(); ++i) history_valid_[i] = history_valid_[i] && valid[i];
  history_.push_back(std::move(u));
  history_t_.push_back(t);
  return false;
}

bool GelCreep::finishRecovery(double noise_mm) {
  const size_t start = recovery_start_;
  const bool measured = start != kNoRecovery && history_.size() >= start + 3 && identifyFromRecovery(start, noise_mm);
  clearHistory();
  return measured;
}

bool GelCreep::identifyFromRecovery(size_t start, double noise_mm) {
  const size_t n = history_.size() - 1;
  // The gel's rate: each recovery frame a scaled copy of the one before (pooled least squares).
  double uu = 0, uv = 0;
  int markers = 0;
  for (size_t i = 0; i < history_valid_.size(); ++i) {
    if (!history_valid_[i]) continue;
    ++markers;
    for (size_t j = start + 1; j <= n; ++j) {
      uu += history_[j - 1][i].squaredNorm();
      uv += history_[j - 1][i].dot(history_[j][i]);
    }
  }
  if (markers < 3 || !(uu > 0)) return false;
  const double a = uv / uu;
  if (!(a > 0 && a < 1)) return false;
  CreepModel model;
  model.tau_c_s = (history_t_[n] - history_t_[start]) / static_cast<double>(n - start) / -std::log(a);
  // The gain that leaves no elastic field in the recovery: the sum of squares of the inverted fields of its
  // frames about zero, and their largest marker in units of its sd. Each inverted marker is the frame's
  // measurement less v, which carries the noise of the frames it was estimated from: sd sigma sqrt(1 + a^2), as
  // a decaying pair's residual (decayPair); and what one time constant misses of the gel, model_error of the
  // marker's displacement u.
  const double noise_sd = noise_mm * std::sqrt(1 + a * a);
  std::vector<Eigen::Vector3d> v;
  const auto residual = [&](double r) {
    model.gain = r / (1 - r);
    double sum = 0, worst = 0;
    size_t j = start;
    for (const auto& e : elasticFields(history_, history_t_, history_valid_, model, start, n, v)) {
      for (size_t i = 0; i < e.size(); ++i)
        if (history_valid_[i]) {
          sum += e[i].squaredNorm();
          worst = std::max(worst, e[i].norm() / std::hypot(noise_sd, options_.model_error * history_[j][i].norm()));
        }
      ++j;
    }
    return std::pair<double, double>{sum, worst};
  };
  const double r_max = options_.max_relaxation;
  const double r = goldenSection([&](double x) { return residual(x).first; }, 0, r_max);
  const double worst_sigmas = residual(r).second;  // leaves model.gain and v at r
  const bool inside = r > 1e-3 * r_max && r < r_max * (1 - 1e-3);
  if (!inside || worst_sigmas > noiseMaximum(markers * static_cast<int>(n - start + 1), options_.false_alarm))
    return false;
  model_ = model;
  delayed_ = std::move(v);
  return true;
}

bool GelCreep::identify(double noise_mm) {
  const size_t n = history_.size() - 1;
  const double k = options_.fit_sigmas;
  // Windows of 2m frames ending now, m from 2 up in steps of a quarter (the longest first).
  std::vector<size_t> lengths;
  for (size_t m = 2; 2 * m <= n; m = std::max(m + 1, m * 5 / 4)) lengths.push_back(m);
  for (auto it = lengths.rbegin(); it != lengths.rend(); ++it) {
    const size_t m = *it;
    const CreepWindow w = creepWindow(history_, n - 2 * m, m, history_valid_, noise_mm, k, options_.false_alarm);
    if (!w.exponential) continue;
    // The hold: from the frame the finger stopped (the frame before is off the exponential by more than
    // stop_factor x fit_sigmas) to now, its time course shown over at least one time constant.
    const size_t h = w.start;
    if (w.before_sigmas <= options_.stop_factor * k) continue;
    CreepModel model;
    model.tau_c_s = (history_t_[n] - history_t_[n - m]) / -std::log(w.rho);
    if (!(model.tau_c_s > 0)) continue;
    // The gain c = r / (1 - r) that stills the window's elastic fields: golden section over r in (0, 1). A
    // frame's elastic field is (u_k - a v_{k-1}) / (1 + (1 - a) c), so its spread is measured in the markers'
    // own units (and noise) times 1 + (1 - a) c, a over the window's mean frame interval.
    const double a = std::exp(-(history_t_[n] - history_t_[h]) / static_cast<double>(n - h) / model.tau_c_s);
    std::vector<Eigen::Vector3d> v;
    const auto cost = [&](double r) {
      model.gain = r / (1 - r);
      const double scale = 1 + (1 - a) * model.gain;
      const auto [sum, worst] =
          spread(elasticFields(history_, history_t_, history_valid_, model, h, n, v), history_valid_);
      return std::pair<double, double>{sum * scale * scale, worst * scale};
    };
    const double worst = cost(goldenSection([&](double r) { return cost(r).first; }, 0, 1 - 1e-9)).second;
    if (worst > noise_mm * noiseMaximum(w.markers * static_cast<int>(n - h + 1), options_.false_alarm)) continue;
    model_ = model;
    delayed_ = std::move(v);
    return true;
  }
  return false;
}

}  // namespace onetip::input
