// pose_campaign — the pose estimator on seeded random combined motions
// (sim/random_scenario.hpp) against the simulator's ground truth, judged by
// tests/unit/pose/campaign_score.hpp. One CSV row per run:
//   field level: the simulator's exact marker fields with Gaussian noise of
//     0.0003 mm per axis per grey level of image noise (the front end's error
//     at 2 grey levels is 0.0006 mm, docs/pose/README.md);
//   image level (the first --image-runs seeds whose run has at most
//     --image-max-frames frames): every frame rendered and processed by the
//     real front end (pipeline::FrameProcessor), marker RMSE against truth kept.
// With --world 1 every run draws the world effects too (randomScenario(seed,
// true): a creeping gel, a camera shift, hidden markers, flicker, drift; each
// in half the runs) and the last columns give their sizes and the contact
// events (tests/unit/pose/contact_events.hpp: late contact ends, false onsets);
// --world-only EFFECT puts that one effect in every run and no other, so
// its runs and their twins without it (--world 0, same seeds) differ by one cause.
// Usage: pose_campaign --out runs.csv [--runs N] [--image-runs M]
//          [--image-max-frames F] [--first-seed S] [--world 1] [--gel-recovery 0] [--gel-creep 0]
//        pose_campaign (--trace SEED | --trace-scenario FILE.yaml) [--trace-out frames.csv]
// (a trace: one run's frames, truth beside estimate, with the truly sticking
// markers (gt_stick) and how many of them the estimate labels stick (stick_true), at field level with
// 2 grey levels' noise for a scenario file)
// ms_per_frame: median wall time of contact analysis + pose per contact frame
// (field level; a campaign figure, the benchmark is bench_pose).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>

#include "campaign_score.hpp"
#include "contact_events.hpp"
#include "observable_truth.hpp"
#include "core/csv_table.hpp"
#include "rendered_replay.hpp"
#include "stick_oracle.hpp"
#include "sim/random_scenario.hpp"
#include "sim/simulator.hpp"

using namespace onetip;
using namespace onetip::poseval;

namespace {

constexpr double kFieldNoisePerGreyMm = 0.0003;

struct Args {
  int runs = 300, image_runs = 0, image_max_frames = 400;
  unsigned first_seed = 1;
  std::string parity = "all";  // odd: the seeds tuned on; even: the acceptance set; all
  pose::PoseUncertaintyOptions uncertainty;  // --sd-relative, --sd-turn, --sd-slide (what the campaign tunes)
  std::string out;  // required for a campaign: no default overwrites the committed table
  long trace = -1;
  std::string trace_scenario;
  std::string trace_out = "campaign_trace.csv";
  double trace_noise_mm = -1;  // < 0: the run's own (the campaign's noise per grey level)
  bool trace_images = false;   // the trace through rendered frames and the real front end
  bool weighted = false;
  bool oracle = false;          // --oracle: stick_oracle.hpp's registration replaces the estimate
  StickOracleOptions oracle_options;  // its labels, --oracle-slip-normals, --oracle-prior-rate-tau (noise per run)
  bool world = false;          // the world effects on (sim/random_scenario.hpp: randomScenario(seed, true))
  std::optional<sim::WorldEffect> world_only;  // --world-only: that effect in every run, the others off
  bool recovery = true;        // input/gel_recovery.hpp on (off: the contact lasts while the gel recovers)
  bool creep = true;           // input/gel_creep.hpp on (off: a held press's creep is read as depth)
};

constexpr const char* kUsage =
    "usage: pose_campaign --out runs.csv [--runs N] [--image-runs M] [--image-max-frames F] [--first-seed S]\n"
    "                     [--parity odd|even|all]  (odd seeds to tune on, even seeds to accept on)\n"
    "                     [--world 1]  (the world effects on: creep, camera shift, damage, flicker, drift)\n"
    "                     [--world-only creep|shift|damage|light|drift]  (that effect in every run, no other)\n"
    "                     [--gel-recovery 0]  (without input/gel_recovery.hpp, to compare)\n"
    "                     [--gel-creep 0]  (without input/gel_creep.hpp, to compare)\n"
    "                     [--sd-relative F] [--sd-turn DEG_PER_SQRT_S] [--sd-slide MM_PER_SQRT_S]\n"
    "                     (pose::PoseUncertaintyOptions, for tuning the reported sd on the odd seeds)\n"
    "                     [--policy adaptive|weighted]  (the estimator: pose::ModelPolicy; default adaptive)\n"
    "                     [--oracle truth|estimate|estimate-true|estimate-touching|none|self]  (stick_oracle.hpp:\n"
    "                     anchors registered with the truth's stick labels, the ceiling; with the policy's own; with\n"
    "                     those of its own that are true; its own on the touched markers; none; the oracle's own\n"
    "                     from the reweighting. The estimate is replaced by the oracle's)\n"
    "                     [--oracle-reweight 1]  (then every marker its cheapest case under the truncated cost)\n"
    "                     [--oracle-slip-normals 0]  (the oracle without the sliding markers' normal residuals)\n"
    "                     [--oracle-sliding-error 0]  (their sd the noise alone, without their slide's model error)\n"
    "                     [--oracle-prior-rate-tau S]  (the oracle's motion prior: 0 holds the motion (default);\n"
    "                     S > 0 expects the last increment again, decaying with time constant S s; inf: constant)\n"
    "       pose_campaign (--trace SEED | --trace-scenario FILE.yaml) [--trace-out frames.csv]\n"
    "                     [--trace-noise-mm SIGMA]  (marker noise per axis; the estimator is told it as its prior)\n"
    "                     [--trace-images 1]  (through rendered frames and the real front end instead)\n";

[[noreturn]] void usageError(const std::string& why) {
  std::fprintf(stderr, "pose_campaign: %s\n%s", why.c_str(), kUsage);
  std::exit(2);
}

Args parse(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; i += 2) {
    const std::string k = argv[i];
    if (k == "--help" || k == "-h") {
      std::fputs(kUsage, stdout);
      std::exit(0);
    }
    if (i + 1 >= argc) usageError("option " + k + " needs a value");
    const std::string v = argv[i + 1];
    if (k == "--runs") a.runs = std::stoi(v);
    else if (k == "--image-runs") a.image_runs = std::stoi(v);
    else if (k == "--image-max-frames") a.image_max_frames = std::stoi(v);
    else if (k == "--first-seed") a.first_seed = static_cast<unsigned>(std::stoul(v));
    else if (k == "--parity") a.parity = v;
    else if (k == "--sd-relative") a.uncertainty.relative_increment_error = std::stod(v);
    else if (k == "--sd-turn") a.uncertainty.unseen_turn_deg_per_sqrt_s = std::stod(v);
    else if (k == "--sd-slide") a.uncertainty.unseen_slide_mm_per_sqrt_s = std::stod(v);
    else if (k == "--policy") {
      if (v != "adaptive" && v != "weighted") usageError("--policy must be adaptive or weighted");
      a.weighted = v == "weighted";
    }
    else if (k == "--oracle") {
      a.oracle = true;
      if (v == "truth") a.oracle_options.labels = OracleLabels::truth;
      else if (v == "estimate") a.oracle_options.labels = OracleLabels::estimate;
      else if (v == "estimate-true") a.oracle_options.labels = OracleLabels::estimate_true;
      else if (v == "estimate-touching") a.oracle_options.labels = OracleLabels::estimate_touching;
      else if (v == "none") a.oracle_options.labels = OracleLabels::none;
      else if (v == "self") {
        a.oracle_options.labels = OracleLabels::self;
        a.oracle_options.reweight = true;  // its labels are the reweighting's
      } else usageError("--oracle must be truth, estimate, estimate-true, estimate-touching, none or self");
    }
    else if (k == "--oracle-reweight") a.oracle_options.reweight = v != "0";
    else if (k == "--oracle-slip-normals") a.oracle_options.slip_normals = v != "0";
    else if (k == "--oracle-sliding-error") a.oracle_options.sliding_model_error = v != "0";
    else if (k == "--oracle-prior-rate-tau") {
      a.oracle_options.prior_rate_tau_s = std::stod(v);
      if (!(a.oracle_options.prior_rate_tau_s >= 0)) usageError("--oracle-prior-rate-tau must be 0 or more seconds");
    }
    else if (k == "--out") a.out = v;
    else if (k == "--trace") a.trace = std::stol(v);
    else if (k == "--trace-scenario") a.trace_scenario = v;
    else if (k == "--trace-out") a.trace_out = v;
    else if (k == "--trace-noise-mm") a.trace_noise_mm = std::stod(v);
    else if (k == "--trace-images") a.trace_images = v == "1";
    else if (k == "--world") a.world = v == "1";
    else if (k == "--world-only") {
      const std::pair<const char*, sim::WorldEffect> names[] = {{"creep", sim::WorldEffect::creep},
                                                               {"shift", sim::WorldEffect::camera_shift},
                                                               {"damage", sim::WorldEffect::damage},
                                                               {"light", sim::WorldEffect::light},
                                                               {"drift", sim::WorldEffect::drift}};
      for (const auto& [name, effect] : names)
        if (v == name) a.world_only = effect;
      if (!a.world_only) usageError("--world-only must be creep, shift, damage, light or drift");
      a.world = true;
    }
    else if (k == "--gel-recovery") a.recovery = v != "0";
    else if (k == "--gel-creep") a.creep = v != "0";
    else usageError("unknown option " + k);
  }
  if (a.out.empty() && a.trace < 0 && a.trace_scenario.empty()) usageError("--out is required for a campaign");
  if (a.parity != "all" && a.parity != "odd" && a.parity != "even") usageError("--parity must be odd, even or all");
  a.uncertainty.validate();
  return a;
}

std::string num(double v) { return formatNumber(v, 5); }

std::vector<std::string> header() {
  std::vector<std::string> h = {"level", "seed", "model", "friction", "kinetic_ratio", "thickness_mm",
                                "foundation_length_mm", "marker_depth_mm", "markers", "indenter", "noise_grey",
                                "noise_mm", "blur_px", "fps", "episodes", "two_fingers", "peak_speed_mm_s",
                                "peak_rate_deg_s", "frames", "contact_frames", "working_frames", "linear_frames",
                                "contact_missed"};
  for (const char* axis : {"dx", "dy", "dz", "yaw", "pitch", "roll"}) h.push_back(std::string("rmse_") + axis);
  for (const char* axis : {"dx", "dy", "dz", "yaw", "pitch", "roll"}) h.push_back(std::string("max_") + axis);
  for (const char* c : {"longest_excess", "first_excess_frame", "excess_axis", "excess_truth_state", "excess_model",
                        "diverged", "ms_per_frame", "marker_rmse_mm", "stick_precision", "stick_recall",
                        "excess_true_stick", "gross_slip_turn_deg", "gross_slip_turn_before_excess_deg",
                        "observable_longest_excess", "observable_diverged", "judged_diverged"})
    h.push_back(c);
  for (const char* prefix : {"obs_median_", "obs_p95_", "within_2sd_", "median_sd_"})
    for (const char* axis : {"dx", "dy", "dz", "yaw", "pitch", "roll"}) h.push_back(std::string(prefix) + axis);
  h.push_back("sd_frames");
  h.push_back("sd_frames_before_gross_slip");
  // The world effects' sizes (0 when off) and the contact events (contact_events.hpp).
  for (const char* c : {"world", "creep_relaxation", "creep_time_s", "shift_px", "hidden_fraction", "flicker",
                        "exposure_step", "drift_mm", "lift_offs", "late_ends", "worst_end_lag", "false_onsets"})
    h.push_back(c);
  // The gel's creep as the tracker measured it (input/gel_creep.hpp; 0 when it did not).
  h.push_back("creep_tau_c_measured_s");
  h.push_back("creep_gain_measured");
  // Against the stricter observable truth that also holds the turn a thin stick set does not fix.
  h.push_back("fixed_longest_excess");
  h.push_back("fixed_judged_diverged");
  // 1 when the camera or a mirror moved between two frames that both touch (the view-shift test decides only
  // out of contact, vision/view_shift.hpp).
  h.push_back("shift_while_touching");
  return h;
}

// Whether the camera shift s(t) (sim/camera_shift.hpp) changes over some frame interval (t_{k-1}, t_k] whose
// two frames the truth has in contact.
bool shiftWhileTouching(const sim::CameraShiftOptions& shift, const std::vector<ReplayFrame>& frames) {
  if (shift.shift_px.norm() == 0) return false;
  const double end = shift.at_s + shift.ramp_s;
  for (size_t k = 1; k < frames.size(); ++k)
    if (frames[k - 1].gt_contact && frames[k].gt_contact && frames[k].t >= shift.at_s && frames[k - 1].t < end)
      return true;
  return false;
}

std::vector<std::string> row(const char* level, const sim::RandomConditions& c, const sim::WorldEffects& world,
                             double noise_mm, const RunScore& s, const ContactEvents& events, double ms,
                             double marker_rmse, const input::CreepModel& creep, bool shift_while_touching) {
  std::vector<std::string> r = {level, std::to_string(c.seed), std::string(sim::toString(c.model)), num(c.friction),
                                num(c.kinetic_ratio), num(c.thickness_mm), num(c.foundation_length_mm),
                                num(c.marker_depth_mm), std::to_string(c.markers), c.indenter, num(c.noise_grey),
                                num(noise_mm), num(c.blur_px), num(c.fps), std::to_string(c.episodes),
                                c.two_fingers ? "1" : "0", num(c.peak_speed_mm_s), num(c.peak_rate_deg_s),
                                std::to_string(s.frames), std::to_string(s.contact_frames),
                                std::to_string(s.working_frames), std::to_string(s.linear_frames),
                                std::to_string(s.contact_missed)};
  for (double v : s.linear_rmse) r.push_back(num(v));
  for (double v : s.max_error) r.push_back(num(v));
  r.push_back(std::to_string(s.longest_excess));
  r.push_back(std::to_string(s.first_excess_frame));
  r.push_back(std::to_string(s.excess_axis));
  r.push_back(std::string(toString(s.excess_truth_state)));
  r.push_back(std::string(pose::toString(s.excess_model)));
  r.push_back(s.diverged ? "1" : "0");
  r.push_back(num(ms));
  r.push_back(num(marker_rmse));
  r.push_back(num(s.stick_precision));
  r.push_back(num(s.stick_recall));
  r.push_back(std::to_string(s.excess_true_stick));
  r.push_back(num(s.gross_slip_turn_deg));
  r.push_back(num(s.gross_slip_turn_before_excess_deg));
  r.push_back(std::to_string(s.observable_longest_excess));
  r.push_back(s.observable_diverged ? "1" : "0");
  r.push_back(s.judged_diverged ? "1" : "0");
  for (double v : s.observable_median) r.push_back(num(v));
  for (double v : s.observable_p95) r.push_back(num(v));
  for (int v : s.within_two_sd) r.push_back(num(s.sd_frames ? static_cast<double>(v) / s.sd_frames : 0.0));
  for (double v : s.median_sd_before_gross_slip) r.push_back(num(v));
  r.push_back(std::to_string(s.sd_frames));
  r.push_back(std::to_string(s.sd_frames_before_gross_slip));
  const sim::WorldEffects& w = world;
  r.push_back(c.world_effects ? "1" : "0");
  r.push_back(num(w.viscoelastic.relaxation));
  r.push_back(num(w.viscoelastic.enabled() ? w.viscoelastic.time_s : 0.0));
  r.push_back(num(w.camera_shift.shift_px.norm()));
  r.push_back(num(w.damage.fraction));
  r.push_back(num(w.light.flicker));
  r.push_back(num(w.light.exposure_step));
  // The drift's largest final move of a rest point: its offset plus the strain at the 19.2 mm pad's corner.
  r.push_back(num(w.drift.offset_mm.norm() + std::abs(w.drift.expansion) * 9.6 * std::sqrt(2.0)));
  r.push_back(std::to_string(events.end_lag.size()));
  r.push_back(std::to_string(events.lateEnds()));
  r.push_back(std::to_string(events.worstEndLag()));
  r.push_back(std::to_string(events.onsets_untouched));
  r.push_back(num(creep.tau_c_s));
  r.push_back(num(creep.gain));
  r.push_back(std::to_string(s.fixed_longest_excess));
  r.push_back(s.fixed_judged_diverged ? "1" : "0");
  r.push_back(shift_while_touching ? "1" : "0");
  return r;
}

StickOracleOptions oracleOptions(const Args& args, double noise_mm) {
  StickOracleOptions o = args.oracle_options;
  o.noise_mm = noise_mm;
  return o;
}

// Field level: the tracker over the noisy marker fields, timed per frame.
// `creep`: the gel's creep as the tracker measured it by the end of the run.
std::vector<ReplayFrame> runField(const Recording& rec, input::PoseTrackerOptions options, double& median_ms,
                                  input::CreepModel& creep) {
  options.marker_depth_mm = rec.marker_depth_mm;  // the pad's, as the pipeline takes it from the pattern
  input::PoseTracker tracker(options);
  std::vector<ReplayFrame> frames;
  std::vector<double> ms;
  for (size_t k = 0; k < rec.frames.size(); ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    const input::TrackerResult r = tracker.update(rec.frames[k], rec.rest, rec.truth[k].t);
    const auto t1 = std::chrono::steady_clock::now();
    if (r.contact) ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    frames.push_back(replayFrame(rec.truth[k], r, rec.frames[k].size()));
  }
  creep = tracker.gelCreep();
  median_ms = 0;
  if (!ms.empty()) {
    std::nth_element(ms.begin(), ms.begin() + static_cast<long>(ms.size() / 2), ms.end());
    median_ms = ms[ms.size() / 2];
  }
  return frames;
}

void writeTrace(const std::vector<ReplayFrame>& frames, double noise_mm, const std::string& path) {
  std::vector<std::string> h = {"frame", "t", "gt_contact", "gt_state", "contact", "state", "model",
                                "region_markers", "gt_contact_markers", "region_in_contact", "n_stick", "n_slip",
                                "gt_stick", "stick_true", "regions"};
  for (const char* axis : {"dx", "dy", "dz", "yaw", "pitch", "roll"}) h.push_back(std::string("gt_") + axis);
  for (const char* axis : {"dx", "dy", "dz", "yaw", "pitch", "roll"}) h.push_back(axis);
  for (const char* axis : {"dx", "dy", "dz", "yaw", "pitch", "roll"}) h.push_back(std::string("sd_") + axis);
  for (const char* axis : {"dx", "dy", "dz", "yaw", "pitch", "roll"}) h.push_back(std::string("obs_") + axis);
  for (const char* axis : {"dx", "dy", "dz", "yaw", "pitch", "roll"}) h.push_back(std::string("fixed_obs_") + axis);
  const std::vector<Input6> observable = observableTruth(frames);
  const std::vector<Input6> fixed = observableTruth(frames, {UnseenMotion::unfixed_directions, noise_mm});
  CsvWriter out(path, h);
  for (size_t k = 0; k < frames.size(); ++k) {
    const ReplayFrame& f = frames[k];
    int touching = 0, region_touching = 0;
    for (size_t i = 0; i < f.gt_contact_markers.size(); ++i) {
      touching += f.gt_contact_markers[i] ? 1 : 0;
      region_touching += f.gt_contact_markers[i] && i < f.region.size() && f.region[i] ? 1 : 0;
    }
    std::vector<std::string> r = {std::to_string(k), num(f.t), f.gt_contact ? "1" : "0",
                                  std::string(toString(f.gt_state)), f.contact ? "1" : "0",
                                  std::string(toString(f.state)), std::string(pose::toString(f.model)),
                                  std::to_string(f.region_markers), std::to_string(touching),
                                  std::to_string(region_touching), std::to_string(f.n_stick),
                                  std::to_string(f.n_slip), std::to_string(countTrulySticking(f)),
                                  std::to_string(countLabelledTrulySticking(f)), std::to_string(f.regions)};
    for (double v : f.gt.asArray()) r.push_back(num(v));
    for (double v : f.raw.asArray()) r.push_back(num(v));
    for (double v : f.sd.asArray()) r.push_back(num(v));
    for (double v : observable[k].asArray()) r.push_back(num(v));
    for (double v : fixed[k].asArray()) r.push_back(num(v));
    out.row(r);
  }
  out.commit();
}

}  // namespace

int main(int argc, char** argv) {
  const Args args = parse(argc, argv);
  if (args.trace >= 0 || !args.trace_scenario.empty()) {
    sim::RandomScenario rs;
    if (args.trace >= 0) rs = sim::randomScenario(static_cast<unsigned>(args.trace), args.world, args.world_only);
    else rs.scenario = sim::loadScenario(args.trace_scenario);
    ReplayOptions o;
    o.noise_mm = kFieldNoisePerGreyMm * rs.conditions.noise_grey;
    if (args.trace >= 0) o.seed = static_cast<unsigned>(args.trace);  // the campaign's noise, frame for frame
    if (args.trace_noise_mm >= 0) {  // as the single-axis noise sweep (pose_accuracy_table) runs it
      o.noise_mm = args.trace_noise_mm;
      o.tracker.pose.self.prior_noise_mm = std::max(args.trace_noise_mm, 1e-5);
    }
    if (args.weighted) o.tracker.pose.policy = pose::ModelPolicy::weighted;
    double ms = 0;
    input::CreepModel creep;
    std::vector<ReplayFrame> frames;
    if (args.trace_images) {
      frames = replayRendered(rs.scenario).frames;
    } else {
      const Recording rec = record(rs.scenario, o);
      frames = runField(rec, o.tracker, ms, creep);
      if (args.oracle) applyStickOracle(rec, frames, oracleOptions(args, o.noise_mm));
    }
    writeTrace(frames, o.noise_mm, args.trace_out);
    const RunScore s = scoreRun(frames, o.noise_mm);
    std::printf("%s: diverged %d (longest %d from frame %d)\n", rs.scenario.name.c_str(), s.diverged,
                s.longest_excess, s.first_excess_frame);
    return 0;
  }
  CsvWriter out(args.out, header());
  int diverged = 0, image_done = 0;
  for (int i = 0; i < args.runs; ++i) {
    const unsigned seed = args.first_seed + static_cast<unsigned>(i);
    if ((args.parity == "odd" && seed % 2 == 0) || (args.parity == "even" && seed % 2 == 1)) continue;
    const sim::RandomScenario rs = sim::randomScenario(seed, args.world, args.world_only);
    ReplayOptions o;
    o.noise_mm = kFieldNoisePerGreyMm * rs.conditions.noise_grey;
    o.seed = seed;
    o.tracker.pose.uncertainty = args.uncertainty;
    if (args.weighted) o.tracker.pose.policy = pose::ModelPolicy::weighted;
    o.tracker.recovery.enabled = args.recovery;
    o.tracker.creep.enabled = args.creep;
    double ms = 0;
    input::CreepModel creep;
    const Recording rec = record(rs.scenario, o);
    std::vector<ReplayFrame> field = runField(rec, o.tracker, ms, creep);
    if (args.oracle) applyStickOracle(rec, field, oracleOptions(args, o.noise_mm));
    const RunScore s = scoreRun(field, o.noise_mm);
    diverged += s.judged_diverged ? 1 : 0;
    out.row(row("field", rs.conditions, rs.scenario.world, o.noise_mm, s, contactEvents(field), ms, 0, creep,
                shiftWhileTouching(rs.scenario.world.camera_shift, field)));
    if (image_done < args.image_runs && rs.scenario.defaultFrameCount() <= args.image_max_frames) {
      const RenderedReplay rr = replayRendered(rs.scenario);
      const double marker_rmse = std::sqrt((rr.marker_rmse_mm[0] * rr.marker_rmse_mm[0] +
                                            rr.marker_rmse_mm[1] * rr.marker_rmse_mm[1] +
                                            rr.marker_rmse_mm[2] * rr.marker_rmse_mm[2]) / 3.0);
      out.row(row("image", rs.conditions, rs.scenario.world, marker_rmse, scoreRun(rr.frames, marker_rmse),
                  contactEvents(rr.frames), 0, marker_rmse, input::CreepModel{},
                  shiftWhileTouching(rs.scenario.world.camera_shift, rr.frames)));
      ++image_done;
    }
    std::fprintf(stderr, "\rrun %d/%d, diverged (observable and full) %d, image runs %d", i + 1, args.runs, diverged, image_done);
  }
  std::fprintf(stderr, "\n");
  out.commit();
  return 0;
}
