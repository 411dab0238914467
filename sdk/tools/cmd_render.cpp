// `onetip render`: the kNN tactile renderer over a file of sensed vectors
// (docs/reference.md, "Haptic rendering"). Writes m1,m2,m3 per query; with
// --timing, `what,ms` rows load, build and query (median per query).
#include <algorithm>
#include <chrono>

#include "command.hpp"
#include "core/csv_table.hpp"
#include "core/error.hpp"
#include "haptics/knn_renderer.hpp"
#include "haptics/tactile_dataset.hpp"
#include "output_paths.hpp"

namespace onetip::tools {
namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

int runRender(const Args& args) {
  refuseOutputClashes(args, {"out", "timing"}, {"dataset", "queries"});
  refuseUnwritableOutputs(args, {"out", "timing"}, {});
  const int k = args.getInt("neighbors", 1);
  if (k < 1) throw InputError("option '--neighbors': must be at least 1");
  const std::string out_path = args.get("out");
  const auto timing_path = args.optional("timing");

  auto t0 = Clock::now();
  const haptics::TactileDataset dataset = haptics::loadDataset(args.get("dataset"));
  const double load_ms = msSince(t0);
  const haptics::QuerySet queries = haptics::readQueriesCsv(args.get("queries"));
  if (queries.channels != dataset.channels)
    throw InputError(args.get("queries") + ": has " + std::to_string(queries.channels) + " channels, the dataset " +
                     std::to_string(dataset.channels));

  t0 = Clock::now();
  const haptics::KnnRenderer renderer(dataset);
  const double build_ms = msSince(t0);

  std::vector<haptics::RenderResult> results(queries.size());
  std::vector<double> query_ms(queries.size());
  for (size_t i = 0; i < queries.size(); ++i) {
    t0 = Clock::now();
    results[i] = renderer.render(queries.row(i), k);
    query_ms[i] = msSince(t0);
    if (!results[i].found())
      throw InputError(args.get("queries") + ": query " + std::to_string(i + 1) +
                       ": no dataset row is a finite distance from it (a value overflows the search space)");
  }

  CsvWriter out(out_path, {"m1", "m2", "m3"});
  for (const auto& r : results)
    out.row({formatNumber(r.command[0]), formatNumber(r.command[1]), formatNumber(r.command[2])});
  if (timing_path) {
    std::nth_element(query_ms.begin(), query_ms.begin() + static_cast<long>(query_ms.size() / 2), query_ms.end());
    CsvWriter timing(*timing_path, {"what", "ms"});
    timing.row({"load", formatNumber(load_ms)});
    timing.row({"build", formatNumber(build_ms)});
    timing.row({"query", formatNumber(query_ms[query_ms.size() / 2])});
    out.commit();
    timing.commit();
  } else {
    out.commit();
  }
  return 0;
}

const CommandRegistrar kRender{Command{
    "render",
    "map sensed vectors to display motor commands with the kNN tactile renderer",
    {{"dataset", "dataset CSV (m1,m2,m3,s1,...,sN) or binary dataset", false, true},
     {"queries", "queries CSV (s1,...,sN)", false, true},
     {"neighbors", "number of neighbours K (inverse-squared-distance weighted mean; default 1)", false, false},
     {"out", "output CSV: m1,m2,m3 per query (degrees)", false, true},
     {"timing", "optional CSV of what,ms rows: load, build, query (median per query)", false, false}},
    runRender}};

}  // namespace
}  // namespace onetip::tools
