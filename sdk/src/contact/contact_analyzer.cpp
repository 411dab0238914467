#include "contact/contact_analyzer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "contact/finger_valleys.hpp"
#include "contact/footprint_centre.hpp"
#include "contact/surface_normals.hpp"
#include "core/error.hpp"

namespace onetip::contact {

void ContactAnalyzerOptions::validate() const {
  if (!(contact_threshold_mm > 0) || !std::isfinite(contact_threshold_mm))
    throw InputError("contact options: contact_threshold_mm must be a positive number");
  if (!(region_fraction > 0 && region_fraction <= 1))
    throw InputError("contact options: region_fraction must be in (0, 1]");
  if (min_region_markers < 1) throw InputError("contact options: min_region_markers must be at least 1");
  if (!(valley_prominence >= 0 && valley_prominence <= 1))
    throw InputError("contact options: valley_prominence must be in [0, 1]");
  if (min_valid_markers < 3) throw InputError("contact options: min_valid_markers must be at least 3");
  if (!(min_confidence >= 0 && min_confidence <= 1)) throw InputError("contact options: min_confidence must be in [0, 1]");
}

ContactAnalyzer::ContactAnalyzer(ContactAnalyzerOptions options) : options_(options) { options_.validate(); }

namespace {

void checkSameGrid(const MarkerField& now, const MarkerField& rest) {
  auto consistent = [](const MarkerField& f) {
    return f.rows > 0 && f.cols > 0 && f.position.size() == static_cast<size_t>(f.size()) &&
           f.valid.size() == static_cast<size_t>(f.size()) &&
           (f.confidence.empty() || f.confidence.size() == static_cast<size_t>(f.size()));
  };
  if (!consistent(now)) throw InputError("contact analysis: current marker field is empty or inconsistent");
  if (!consistent(rest)) throw InputError("contact analysis: rest marker field is empty or inconsistent");
  if (now.rows != rest.rows || now.cols != rest.cols)
    throw InputError("contact analysis: current marker grid " + std::to_string(now.rows) + "x" +
                     std::to_string(now.cols) + " differs from the rest grid " + std::to_string(rest.rows) + "x" +
                     std::to_string(rest.cols));
}

}  // namespace

ContactField ContactAnalyzer::analyze(const MarkerField& now, const MarkerField& rest) const {
  checkSameGrid(now, rest);
  const size_t n = static_cast<size_t>(now.size());
  ContactField out;
  out.displacement.assign(n, Eigen::Vector3d::Zero());
  out.valid.assign(n, 0);
  out.confidence.assign(n, 0.0f);
  out.min_confidence = options_.min_confidence;
  out.region_of.assign(n, -1);
  for (size_t i = 0; i < n; ++i) {
    if (!now.valid[i]) continue;
    out.confidence[i] = now.confidence.empty() ? 1.0f : now.confidence[i];
    if (!(out.confidence[i] >= out.min_confidence)) {
      ++out.low_confidence;
      continue;
    }
    if (!rest.valid[i]) continue;
    const Eigen::Vector3d u = now.position[i] - rest.position[i];
    if (!u.allFinite()) continue;
    out.valid[i] = 1;
    out.displacement[i] = u;
    ++out.valid_markers;
    out.max_modulus_mm = std::max(out.max_modulus_mm, u.norm());
    out.max_normal_mm = std::max(out.max_normal_mm, std::abs(u.z()));
  }
  gridSurfaceNormals(out.low_confidence > 0 ? trustedMarkers(now, out) : now, out.normal, out.normal_valid);
  if (out.valid_markers < options_.min_valid_markers) {
    out.status = ContactFieldStatus::too_few_markers;
    return out;
  }
  if (!(out.max_modulus_mm > options_.contact_threshold_mm)) return out;

  out.region_cut_mm = options_.region_fraction * out.max_normal_mm;
  std::vector<double> measure(n, std::numeric_limits<double>::quiet_NaN()), normal(n, 0.0);  // NaN: not measured
  const bool by_modulus = options_.region_measure == RegionMeasure::modulus;
  for (size_t i = 0; i < n; ++i) {
    if (!out.valid[i]) continue;
    measure[i] = by_modulus ? out.displacement[i].norm() : -out.displacement[i].z();
    normal[i] = std::abs(out.displacement[i].z());
  }
  int count = 0;
  std::vector<double> cuts;
  const std::vector<int> label =
      labelFingerRegions(now.rows, now.cols, measure, normal, options_.contact_threshold_mm, options_.region_fraction,
                         options_.valley_prominence, cuts, &count);
  std::vector<ContactRegion> regions(static_cast<size_t>(count));
  for (size_t i = 0; i < n; ++i)
    if (label[i] >= 0) regions[static_cast<size_t>(label[i])].markers.push_back(static_cast<int>(i));
  for (auto& reg : regions) {
    if (static_cast<int>(reg.markers.size()) < options_.min_region_markers) continue;
    Eigen::Vector3d rest_sum = Eigen::Vector3d::Zero();
    std::vector<Eigen::Vector3d> positions;
    std::vector<double> normal_def;
    for (int id : reg.markers) {
      const size_t i = static_cast<size_t>(id);
      rest_sum += rest.position[i];
      positions.push_back(now.position[i]);
      normal_def.push_back(-out.displacement[i].z());
      reg.peak_normal_mm = std::max(reg.peak_normal_mm, normal_def.back());
    }
    reg.rest_centroid = rest_sum / static_cast<double>(reg.markers.size());
    reg.cut_mm = cuts[static_cast<size_t>(&reg - regions.data())];
    reg.footprint_centre = footprintCentre(positions, normal_def, reg.cut_mm);
    const int index = static_cast<int>(out.regions.size());
    for (int id : reg.markers) out.region_of[static_cast<size_t>(id)] = index;
    out.regions.push_back(std::move(reg));
  }
  out.in_contact = !out.regions.empty();
  return out;
}

MarkerField trustedMarkers(const MarkerField& now, const ContactField& field) {
  MarkerField out = now;
  for (size_t i = 0; i < out.valid.size() && i < field.confidence.size(); ++i)
    if (!(field.confidence[i] >= field.min_confidence)) out.valid[i] = 0;
  return out;
}

}  // namespace onetip::contact
