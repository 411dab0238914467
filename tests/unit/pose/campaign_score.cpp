#include "campaign_score.hpp"

#include <algorithm>
#include <cmath>

#include "observable_truth.hpp"

namespace onetip::poseval {

bool inWorkingRange(const Input6& g) {
  return std::abs(g.dx) <= 4 && std::abs(g.dy) <= 4 && g.dz >= -0.05 && g.dz <= 3.5 && std::abs(g.yaw) <= 15 &&
         std::abs(g.pitch) <= 40 && std::abs(g.roll) <= 40;
}

bool inLinearRange(const Input6& g) { return inWorkingRange(g) && std::abs(g.dx) <= 1.5 && std::abs(g.dy) <= 1.5; }

bool trulySticks(const ReplayFrame& f, size_t i) {
  return i < f.gt_contact_markers.size() && f.gt_contact_markers[i] && !(i < f.gt_slip.size() && f.gt_slip[i]) &&
         (f.gt_followed.empty() || (i < f.gt_followed.size() && f.gt_followed[i]));
}

int countTrulySticking(const ReplayFrame& f) {
  int n = 0;
  for (size_t i = 0; i < f.gt_contact_markers.size(); ++i) n += trulySticks(f, i) ? 1 : 0;
  return n;
}

int countLabelledTrulySticking(const ReplayFrame& f) {
  int n = 0;
  for (size_t i = 0; i < f.stick.size(); ++i) n += (f.stick[i] && trulySticks(f, i)) ? 1 : 0;
  return n;
}

namespace {

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  const size_t k = std::min(v.size() - 1, static_cast<size_t>(q * static_cast<double>(v.size())));
  std::nth_element(v.begin(), v.begin() + static_cast<long>(k), v.end());
  return v[k];
}

bool beyondDivergence(double error, size_t axis) { return std::abs(error) > (axis < 3 ? kDivergenceMm : kDivergenceDeg); }

// The longest stretch of consecutive working-range frames with an axis beyond 1 mm / 5 deg of `reference`.
int longestExcess(const std::vector<ReplayFrame>& frames, const std::vector<Input6>& reference) {
  int longest = 0, stretch = 0;
  for (size_t k = 0; k < frames.size(); ++k) {
    const ReplayFrame& f = frames[k];
    if (!f.gt_contact || !inWorkingRange(f.gt)) {
      stretch = 0;
      continue;
    }
    const std::array<double, 6> est = f.contact ? f.raw.asArray() : std::array<double, 6>{};
    const std::array<double, 6> ref = reference[k].asArray();
    bool beyond = false;
    for (size_t a = 0; a < 6; ++a) beyond = beyond || beyondDivergence(est[a] - ref[a], a);
    stretch = beyond ? stretch + 1 : 0;
    longest = std::max(longest, stretch);
  }
  return longest;
}

// Divergence and linear-range errors against the observable truth (observable_truth.hpp); divergence also
// against its stricter form, which holds what a thin stick set does not fix.
void scoreAgainstObservable(const std::vector<ReplayFrame>& frames, double noise_mm, RunScore& s) {
  const std::vector<Input6> reference = observableTruth(frames);
  s.fixed_longest_excess =
      longestExcess(frames, observableTruth(frames, {UnseenMotion::unfixed_directions, noise_mm}));
  s.observable_longest_excess = longestExcess(frames, reference);
  std::array<std::vector<double>, 6> linear;
  for (size_t k = 0; k < frames.size(); ++k) {
    const ReplayFrame& f = frames[k];
    if (!f.gt_contact || !inLinearRange(f.gt)) continue;
    const std::array<double, 6> est = f.contact ? f.raw.asArray() : std::array<double, 6>{};
    const std::array<double, 6> ref = reference[k].asArray();
    for (size_t a = 0; a < 6; ++a) linear[a].push_back(std::abs(est[a] - ref[a]));
  }
  s.observable_diverged = s.observable_longest_excess > kDivergenceFrames;
  s.judged_diverged = s.observable_diverged && s.diverged;
  s.fixed_judged_diverged = s.fixed_longest_excess > kDivergenceFrames && s.judged_diverged;
  for (size_t a = 0; a < 6; ++a) {
    s.observable_median[a] = percentile(linear[a], 0.5);
    s.observable_p95[a] = percentile(linear[a], 0.95);
  }
}

// The reported sd against the full truth's error.
void scoreUncertainty(const std::vector<ReplayFrame>& frames, RunScore& s) {
  std::array<std::vector<double>, 6> sd_before;
  bool gross_seen = false;
  for (size_t k = 0; k < frames.size(); ++k) {
    const ReplayFrame& f = frames[k];
    if (!f.gt_contact) gross_seen = false;
    else if (f.gt_state == ContactState::slip) gross_seen = true;
    if (!f.gt_contact || !f.contact || !inWorkingRange(f.gt)) continue;
    ++s.sd_frames;
    const std::array<double, 6> est = f.raw.asArray(), gt = f.gt.asArray(), sd = f.sd.asArray();
    for (size_t a = 0; a < 6; ++a) s.within_two_sd[a] += std::abs(est[a] - gt[a]) <= 2 * sd[a] ? 1 : 0;
    if (gross_seen) continue;
    ++s.sd_frames_before_gross_slip;
    for (size_t a = 0; a < 6; ++a) sd_before[a].push_back(sd[a]);
  }
  for (size_t a = 0; a < 6; ++a) s.median_sd_before_gross_slip[a] = percentile(sd_before[a], 0.5);
}

}  // namespace

RunScore scoreRun(const std::vector<ReplayFrame>& frames, double noise_mm) {
  RunScore s;
  s.frames = static_cast<int>(frames.size());
  std::array<double, 6> squares{};
  int stretch = 0, stretch_axis = -1;
  ContactState stretch_state = ContactState::none;
  pose::PoseModel stretch_model = pose::PoseModel::none;
  int stretch_true_stick = -1;
  long labelled = 0, truly = 0, both = 0;
  std::array<double, 3> turned{};  // yaw, pitch, roll while in gross slip
  std::vector<double> turned_by_frame(frames.size(), 0.0);  // the largest of the three up to each frame
  for (size_t k = 0; k < frames.size(); ++k) {
    const ReplayFrame& f = frames[k];
    if (k > 0 && f.gt_contact && frames[k - 1].gt_contact && f.gt_state == ContactState::slip) {
      turned[0] += std::abs(f.gt.yaw - frames[k - 1].gt.yaw);
      turned[1] += std::abs(f.gt.pitch - frames[k - 1].gt.pitch);
      turned[2] += std::abs(f.gt.roll - frames[k - 1].gt.roll);
    }
    turned_by_frame[k] = std::max({turned[0], turned[1], turned[2]});
    if (!f.gt_contact) {
      stretch = 0;
      continue;
    }
    ++s.contact_frames;
    s.contact_missed += f.contact ? 0 : 1;
    if (f.contact)
      for (size_t i = 0; i < f.stick.size(); ++i) {
        const bool t = trulySticks(f, i);
        labelled += f.stick[i];
        truly += t ? 1 : 0;
        both += (f.stick[i] && t) ? 1 : 0;
      }
    if (!inWorkingRange(f.gt)) {
      stretch = 0;
      continue;
    }
    ++s.working_frames;
    const std::array<double, 6> est = f.contact ? f.raw.asArray() : std::array<double, 6>{};
    const std::array<double, 6> gt = f.gt.asArray();
    int axis = -1;
    const bool linear = inLinearRange(f.gt);
    s.linear_frames += linear ? 1 : 0;
    for (size_t a = 0; a < 6; ++a) {
      const double e = std::abs(est[a] - gt[a]);
      s.max_error[a] = std::max(s.max_error[a], e);
      if (axis < 0 && beyondDivergence(e, a)) axis = static_cast<int>(a);
      if (linear) squares[a] += e * e;
    }
    stretch = axis >= 0 ? stretch + 1 : 0;
    if (stretch == 1) {
      stretch_axis = axis;
      stretch_state = f.gt_state;
      stretch_model = f.model;
      stretch_true_stick = countTrulySticking(f);
    }
    if (stretch > s.longest_excess) {
      s.longest_excess = stretch;
      s.first_excess_frame = static_cast<int>(k) - stretch + 1;
      s.excess_axis = stretch_axis;
      s.excess_truth_state = stretch_state;
      s.excess_model = stretch_model;
      s.excess_true_stick = stretch_true_stick;
    }
  }
  s.stick_precision = labelled ? static_cast<double>(both) / static_cast<double>(labelled) : 0.0;
  s.stick_recall = truly ? static_cast<double>(both) / static_cast<double>(truly) : 0.0;
  for (size_t a = 0; a < 6; ++a) s.linear_rmse[a] = s.linear_frames ? std::sqrt(squares[a] / s.linear_frames) : 0.0;
  s.diverged = s.longest_excess > kDivergenceFrames;
  s.gross_slip_turn_deg = std::max({turned[0], turned[1], turned[2]});
  s.gross_slip_turn_before_excess_deg = s.first_excess_frame >= 0
                                            ? turned_by_frame[static_cast<size_t>(s.first_excess_frame)]
                                            : s.gross_slip_turn_deg;
  scoreAgainstObservable(frames, noise_mm, s);
  scoreUncertainty(frames, s);
  return s;
}

}  // namespace onetip::poseval
