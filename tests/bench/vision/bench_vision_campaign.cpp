// The front end's tracking campaign (issue 16): simulator runs rendered
// through images (tests/bench/vision/campaign_runs.hpp), each view tracked by
// vision::GridTracker from the rest frame on, every tracked marker compared
// with the simulator's truth (campaign_score.hpp, playRun). One CSV row per frame:
//   run,kind,model,speed_sq,density,noise,blur,friction,fps,frame,motion_sq,
//   contact_markers,contact_detected,markers,detected,gross,max_error_sq,track_ms
// motion_sq: the largest 3-D motion of any marker since the previous frame,
// in squares; contact_*: markers whose node touches the finger (truth) and
// that lie in both views; *_detected: reported within 0.4 square of the truth
// in both views; gross: (marker, view) pairs reported beyond 0.4 square.
// Usage: bench_vision_campaign --out FILE.csv [--kind K] [--runs N]
//          [--random N] [--max-frames F] [--only INDEX[,INDEX...]]
// --random N adds the random combined runs of seeds 1..N (both contact
// models), each cut to its first F frames (default 150). --only plays just the
// runs of those indices (e.g. the ones that miss a target), each numbered as
// in the full campaign.
// docs/vision/make_charts.py draws the charts from the CSV.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "campaign_runs.hpp"
#include "campaign_score.hpp"
#include "sim/pad.hpp"

using namespace onetip;

namespace {

struct Totals {
  long contact = 0, contact_found = 0, gross = 0;
};

void runOne(int index, const bench::CampaignRun& run, std::ofstream& csv, Totals& totals) {
  std::vector<bench::FrameScore> scores;
  try {
    scores = bench::playRun(run);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "run %d (%s): %s\n", index, run.kind.c_str(), e.what());
    return;
  }
  const MarkerPattern& pattern = run.scenario.pad.pattern;
  double worst = 1;
  long contact = 0, found = 0, gross = 0;
  for (const bench::FrameScore& f : scores) {
    csv << index << ',' << run.kind << ',' << sim::toString(run.scenario.pad.contact_model) << ',' << run.speed_sq << ','
        << pattern.rows << ',' << run.scenario.image.noise_sigma << ',' << run.scenario.image.blur_sigma << ','
        << run.scenario.pad.friction << ',' << run.scenario.fps << ',' << f.frame << ',' << f.motion_sq << ',' << f.contact
        << ',' << f.contact_found << ',' << f.markers << ',' << f.found << ',' << f.gross << ',' << f.max_error_sq << ','
        << f.track_ms << '\n';
    if (f.contact > 0) worst = std::min(worst, static_cast<double>(f.contact_found) / f.contact);
    contact += f.contact, found += f.contact_found, gross += f.gross;
  }
  std::printf("run %2d %-9s %2dx%-2d speed %.2f sq/frame noise %.1f blur %.1f: in contact %ld/%ld (%.2f%%), worst frame %.1f%%, gross %ld\n",
              index, run.kind.c_str(), pattern.rows, pattern.cols, run.speed_sq, run.scenario.image.noise_sigma,
              run.scenario.image.blur_sigma, found, contact, 100.0 * found / std::max(contact, 1L), 100 * worst, gross);
  std::fflush(stdout);
  totals.contact += contact, totals.contact_found += found, totals.gross += gross;
}

}  // namespace

int main(int argc, char** argv) {
  std::string out, kind;
  int max_runs = 1 << 30, random = 0, max_frames = 150;
  std::set<int> only;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--out")) out = argv[i + 1];
    else if (!std::strcmp(argv[i], "--kind")) kind = argv[i + 1];
    else if (!std::strcmp(argv[i], "--runs")) max_runs = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--random")) random = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--max-frames")) max_frames = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--only")) {
      std::stringstream list(argv[i + 1]);
      for (std::string item; std::getline(list, item, ',');) only.insert(std::atoi(item.c_str()));
    }
    else {
      std::fprintf(stderr, "unknown option %s\n", argv[i]);
      return 2;
    }
  }
  if (out.empty()) {
    std::fprintf(stderr, "usage: bench_vision_campaign --out FILE.csv [--kind slide|shear|tilt|combined|random] [--runs N] [--random N] [--max-frames F] [--only INDEX[,INDEX...]]\n");
    return 2;
  }
  const std::string staging = out + ".part";
  std::ofstream csv(staging);
  if (!csv) {
    std::fprintf(stderr, "%s: cannot write\n", staging.c_str());
    return 1;
  }
  csv << "run,kind,model,speed_sq,density,noise,blur,friction,fps,frame,motion_sq,contact_markers,contact_detected,markers,detected,gross,"
         "max_error_sq,track_ms\n";
  Totals totals;
  int done = 0;
  std::vector<bench::CampaignRun> runs = bench::scriptedRuns();
  for (bench::CampaignRun& r : bench::randomRuns(random, max_frames)) runs.push_back(std::move(r));
  for (size_t i = 0; i < runs.size() && done < max_runs; ++i) {
    if ((!kind.empty() && runs[i].kind != kind) || (!only.empty() && !only.count(static_cast<int>(i)))) continue;
    runOne(static_cast<int>(i), runs[i], csv, totals);
    ++done;
  }
  csv.close();
  if (!csv || std::rename(staging.c_str(), out.c_str()) != 0) {
    std::fprintf(stderr, "%s: cannot write\n", out.c_str());
    return 1;
  }
  std::printf("all runs: in contact %ld/%ld (%.3f%%), gross %ld\n", totals.contact_found, totals.contact,
              100.0 * totals.contact_found / std::max(totals.contact, 1L), totals.gross);
  return 0;
}
