// temporary exploration (not committed)
#include <cstdio>
#include <cstdlib>
#include "replay_metrics.hpp"
using namespace onetip;
using namespace onetip::poseval;
int main(int argc, char** argv) {
  double noise = argc > 2 ? atof(argv[2]) : 0.012;
  double drop = argc > 3 ? atof(argv[3]) : 0;
  ReplayOptions o; o.noise_mm = noise; o.drop_fraction = drop;
  auto frames = replay(sampleScenario(argv[1]), o);
  auto all = [](const ReplayFrame&) { return true; };
  auto r = axisRmse(frames, composedOf, all);
  auto e = axisRmse(frames, eulerSumOf, all);
  printf("composed RMSE n=%d: %.4f %.4f %.4f | %.3f %.3f %.3f\n", r.frames, r.rmse[0], r.rmse[1], r.rmse[2], r.rmse[3], r.rmse[4], r.rmse[5]);
  printf("euler    RMSE n=%d: %.4f %.4f %.4f | %.3f %.3f %.3f\n", e.frames, e.rmse[0], e.rmse[1], e.rmse[2], e.rmse[3], e.rmse[4], e.rmse[5]);
  auto c = slipF1(frames);
  printf("slip P %.3f R %.3f F1 %.3f (tp %ld fp %ld fn %ld)  IoU %.3f\n", c.precision, c.recall, c.f1, c.true_positive, c.false_positive, c.false_negative, regionIoU(frames));
  auto w = worstExcessStep(frames);
  printf("worst excess step: %.3f %.3f %.3f %.3f %.3f %.3f\n", w[0], w[1], w[2], w[3], w[4], w[5]);
  if (getenv("VERBOSE")) for (size_t k = 0; k < frames.size(); ++k) { auto& f = frames[k];
    int ngc=0, ngs=0, nr=0, ns=0; for (size_t i=0;i<f.region.size();++i){ngc+=f.gt_contact_markers[i]; ngs+=f.gt_slip[i]; nr+=f.region[i]; ns+=f.slip[i];}
    printf("%3zu t=%.2f gc%d c%d gs=%d s=%d m=%d | gt %.3f %.3f %.3f %.2f %.2f %.2f | est %.3f %.3f %.3f %.2f %.2f %.2f | gtc %d gts %d reg %d slip %d R%d\n", k, f.t, f.gt_contact, f.contact, (int)f.gt_state, (int)f.state, (int)f.model,
      f.gt.dx, f.gt.dy, f.gt.dz, f.gt.yaw, f.gt.pitch, f.gt.roll, f.raw.dx, f.raw.dy, f.raw.dz, f.raw.yaw, f.raw.pitch, f.raw.roll, ngc, ngs, nr, ns, f.regions); }
}
