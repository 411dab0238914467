#include "sim/contact_model.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "sim/contact_kernel.hpp"

namespace onetip::sim {

namespace {

// Interpolates between two poses: linear translation, slerp rotation.
Eigen::Isometry3d blend(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, double s) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  const Eigen::Quaterniond qa(a.linear()), qb(b.linear());
  out.linear() = qa.slerp(s, qb).toRotationMatrix();
  out.translation() = (1 - s) * a.translation() + s * b.translation();
  return out;
}

// Largest distance any point within `radius` of the pose origin moves.
double motionBound(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, double radius) {
  const double angle = Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
  return (b.translation() - a.translation()).norm() + angle * radius;
}

// Nodes whose gap to a body is below this are kept up to date between steps,
// since the next sub-step (<= max_substep_mm of motion) may bring them into contact.
constexpr double kCandidateGapMm = 1.0;

struct Penetration {
  double depth = 0;  // > 0 when the indenter is below the undeformed surface
  int owner = -1;
  double z_indenter = 0;
};

}  // namespace

ContactModel::ContactModel(const PadLattice& lattice, std::vector<IndenterGeometry> indenters,
                           double max_substep_mm)
    : lattice_(lattice), indenters_(std::move(indenters)), max_substep_mm_(max_substep_mm) {
  if (indenters_.empty()) throw InputError("contact model: needs at least one indenter");
  for (const auto& g : indenters_) g.validate();
  const int nu = lattice_.nu(), nv = lattice_.nv();
  const PadOptions& pad = lattice_.options();
  const double h = lattice_.spacing();
  kernel_table_.resize(static_cast<size_t>((2 * nu - 1) * (2 * nv - 1)));
  for (int db = -(nv - 1); db <= nv - 1; ++db)
    for (int da = -(nu - 1); da <= nu - 1; ++da)
      kernel_table_[static_cast<size_t>((db + nv - 1) * (2 * nu - 1) + (da + nu - 1))] = contactKernel(pad, h, da, db);
  c_t_ = tangentialComplianceRatio(pad.contact_model);
  kinetic_ratio_ = pad.contact_model == ContactModelKind::foundation ? pad.kinetic_ratio : 1.0;
  nodes_.resize(static_cast<size_t>(lattice_.nodeCount()));
  kernel_base_.resize(nodes_.size());
  kernel_offset_.resize(nodes_.size());
  for (int i = 0; i < lattice_.nodeCount(); ++i) {
    const int a = i % nu, b = i / nu;
    kernel_base_[static_cast<size_t>(i)] = (b + nv - 1) * (2 * nu - 1) + (a + nu - 1);
    kernel_offset_[static_cast<size_t>(i)] = b * (2 * nu - 1) + a;
  }
  u_cache_.assign(nodes_.size(), Eigen::Vector3d::Zero());
  u_cached_.assign(nodes_.size(), 0);
}

double ContactModel::kernel(int i, int j) const {
  return kernel_table_[static_cast<size_t>(kernel_base_[static_cast<size_t>(i)] - kernel_offset_[static_cast<size_t>(j)])];
}

const Eigen::LLT<Eigen::MatrixXd>& ContactModel::factorFor(const std::vector<int>& set, CachedFactor& slot) {
  for (const CachedFactor* cached : {&normal_factor_, &stick_factor_})
    if (!set.empty() && cached->set == set) return cached->llt;
  const int n = static_cast<int>(set.size());
  k_work_.resize(n, n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c <= r; ++c) k_work_(r, c) = kernel(set[static_cast<size_t>(r)], set[static_cast<size_t>(c)]);
  slot.llt.compute(k_work_);  // reads the lower triangle only
  slot.set = set;
  return slot.llt;
}

void ContactModel::reset(const std::vector<Eigen::Isometry3d>& poses) {
  if (poses.size() != indenters_.size()) throw InputError("contact model: one pose per indenter is needed");
  for (auto& n : nodes_) n = NodeContact{};
  active_.clear();
  gatherActiveTractions();
  u_cache_.assign(nodes_.size(), Eigen::Vector3d::Zero());
  u_cached_.assign(nodes_.size(), 0);
  poses_ = poses;
}

ContactStepStats ContactModel::advance(const std::vector<Eigen::Isometry3d>& poses) {
  if (poses.size() != indenters_.size()) throw InputError("contact model: one pose per indenter is needed");
  if (poses_.empty()) reset(poses);
  double bound = 0;
  for (size_t k = 0; k < poses.size(); ++k)
    bound = std::max(bound, motionBound(poses_[k], poses[k], std::min(footprintRadius(indenters_[k]), 12.0)));
  // Sub-steps of at most max_substep_mm each, but never more than
  // kMaxSubsteps per frame (a motion of metres in one frame is not a touch).
  const int substeps = static_cast<int>(std::clamp(std::ceil(bound / max_substep_mm_), 1.0, double(kMaxSubsteps)));
  const std::vector<Eigen::Isometry3d> start = poses_;
  std::vector<Eigen::Isometry3d> now(poses.size());
  for (int s = 1; s <= substeps; ++s) {
    for (size_t k = 0; k < poses.size(); ++k) now[k] = blend(start[k], poses[k], double(s) / substeps);
    solve(now);
  }
  poses_ = poses;
  ContactStepStats stats;
  stats.substeps = substeps;
  stats.contact_nodes = static_cast<int>(active_.size());
  for (int i : active_) stats.slip_nodes += nodes_[static_cast<size_t>(i)].slip ? 1 : 0;
  return stats;
}

void ContactModel::solve(const std::vector<Eigen::Isometry3d>& poses) {
  const int n_nodes = lattice_.nodeCount();
  auto penetrationAt = [&](int node, double x, double y) {
    Penetration best;
    const Eigen::Vector3d& rest = lattice_.surfaceRest(node);
    for (size_t k = 0; k < indenters_.size(); ++k) {
      const Eigen::Vector3d& t = poses[k].translation();
      const double reach = footprintRadius(indenters_[k]);
      if (std::abs(x - t.x()) > reach || std::abs(y - t.y()) > reach) continue;
      const auto z = lowerSurfaceZ(indenters_[k], poses[k], x, y);
      if (z && rest.z() - *z > best.depth) best = {rest.z() - *z, static_cast<int>(k), *z};
    }
    return best;
  };

  // 1. Where each node would be this step: stick nodes follow their anchors,
  //    the others keep last step's tangential displacement.
  std::vector<int> candidates;
  std::vector<Eigen::Vector2d> target(static_cast<size_t>(n_nodes), Eigen::Vector2d::Zero());
  std::vector<Penetration> pen(static_cast<size_t>(n_nodes));
  for (int i = 0; i < n_nodes; ++i) {
    NodeContact& n = nodes_[static_cast<size_t>(i)];
    const Eigen::Vector3d& rest = lattice_.surfaceRest(i);
    Eigen::Vector2d xy = rest.head<2>() + u_cache_[static_cast<size_t>(i)].head<2>();
    if (n.contact) xy = (poses[static_cast<size_t>(n.owner)] * n.anchor).head<2>();
    const Penetration p = penetrationAt(i, xy.x(), xy.y());
    if (p.depth <= 0) {
      if (n.contact) n = NodeContact{};
      continue;
    }
    if (n.contact && n.owner != p.owner) n.contact = false;  // handed to another body: re-anchor
    if (!n.contact) {
      n.owner = p.owner;
      n.anchor = poses[static_cast<size_t>(p.owner)].inverse() * Eigen::Vector3d(xy.x(), xy.y(), p.z_indenter);
    }
    target[static_cast<size_t>(i)] = xy - rest.head<2>();
    pen[static_cast<size_t>(i)] = p;
    candidates.push_back(i);
  }

  // Which nodes were slipping at the end of the last sub-step (kinetic friction).
  std::vector<char> was_slipping(static_cast<size_t>(n_nodes), 0);
  for (int i : active_) was_slipping[static_cast<size_t>(i)] = nodes_[static_cast<size_t>(i)].slip ? 1 : 0;

  // 2. Normal contact: conform on the active set, drop nodes that would pull.
  std::vector<int> A = candidates;
  Eigen::VectorXd p;
  for (int iter = 0; iter < 12 && !A.empty(); ++iter) {
    const int n = static_cast<int>(A.size());
    Eigen::VectorXd delta(n);
    for (int r = 0; r < n; ++r) delta[r] = pen[static_cast<size_t>(A[static_cast<size_t>(r)])].depth;
    p = factorFor(A, normal_factor_).solve(delta);
    std::vector<int> kept;
    for (int r = 0; r < n; ++r)
      if (p[r] > 0) kept.push_back(A[static_cast<size_t>(r)]);
    if (static_cast<int>(kept.size()) == n) break;
    A = std::move(kept);
    p.resize(0);
  }
  for (int i : candidates) {
    auto& n = nodes_[static_cast<size_t>(i)];
    n.contact = false;
    n.p = 0;
  }
  for (size_t r = 0; r < A.size() && p.size() == static_cast<Eigen::Index>(A.size()); ++r) {
    auto& n = nodes_[static_cast<size_t>(A[r])];
    n.contact = true;
    n.p = p[static_cast<Eigen::Index>(r)];
  }
  if (p.size() != static_cast<Eigen::Index>(A.size())) A.clear();
  for (int i : candidates)
    if (!nodes_[static_cast<size_t>(i)].contact) nodes_[static_cast<size_t>(i)] = NodeContact{};

  // 3. Tangential contact with the Coulomb bound: stick set S, slip set L.
  const int n = static_cast<int>(A.size());
  std::vector<char> slipping(static_cast<size_t>(n), 0);
  Eigen::MatrixX2d q = Eigen::MatrixX2d::Zero(n, 2);
  const double mu = lattice_.options().friction;
  for (int iter = 0; iter < 16 && n > 0; ++iter) {
    std::vector<int> S;
    for (int r = 0; r < n; ++r)
      if (!slipping[static_cast<size_t>(r)]) S.push_back(r);
    if (S.empty()) break;
    const int ns = static_cast<int>(S.size());
    Eigen::MatrixX2d rhs(ns, 2);
    for (int a = 0; a < ns; ++a) {
      const int ia = A[static_cast<size_t>(S[static_cast<size_t>(a)])];
      rhs.row(a) = target[static_cast<size_t>(ia)].transpose() / c_t_;
      for (int r = 0; r < n; ++r)
        if (slipping[static_cast<size_t>(r)]) rhs.row(a) -= kernel(ia, A[static_cast<size_t>(r)]) * q.row(r);
    }
    std::vector<int> stick_nodes(S.size());
    for (int a = 0; a < ns; ++a) stick_nodes[static_cast<size_t>(a)] = A[static_cast<size_t>(S[static_cast<size_t>(a)])];
    const Eigen::MatrixX2d qs = factorFor(stick_nodes, stick_factor_).solve(rhs);
    bool changed = false;
    for (int a = 0; a < ns; ++a) {
      const int r = S[static_cast<size_t>(a)];
      const int node = A[static_cast<size_t>(r)];
      const double limit = mu * (was_slipping[static_cast<size_t>(node)] ? kinetic_ratio_ : 1.0) *
                           nodes_[static_cast<size_t>(node)].p;
      q.row(r) = qs.row(a);
      const double norm = qs.row(a).norm();
      if (norm > limit * (1 + 1e-9)) {
        slipping[static_cast<size_t>(r)] = 1;
        q.row(r) *= limit / norm;
        changed = true;
      }
    }
    if (!changed) break;
  }
  active_ = A;
  for (int r = 0; r < n; ++r) {
    auto& node = nodes_[static_cast<size_t>(A[static_cast<size_t>(r)])];
    node.q = q.row(r).transpose();
    node.slip = slipping[static_cast<size_t>(r)] != 0;
  }
  gatherActiveTractions();

  // 4. Displacements near the bodies; slip nodes are re-anchored where they are.
  refreshDisplacementCache(poses);
  for (int r = 0; r < n; ++r) {
    const int i = A[static_cast<size_t>(r)];
    auto& node = nodes_[static_cast<size_t>(i)];
    if (!node.slip) continue;
    const Eigen::Vector2d xy = lattice_.surfaceRest(i).head<2>() + u_cache_[static_cast<size_t>(i)].head<2>();
    const auto z = lowerSurfaceZ(indenters_[static_cast<size_t>(node.owner)], poses[static_cast<size_t>(node.owner)],
                                 xy.x(), xy.y());
    const double zi = z ? *z : lattice_.surfaceRest(i).z() + u_cache_[static_cast<size_t>(i)].z();
    node.anchor = poses[static_cast<size_t>(node.owner)].inverse() * Eigen::Vector3d(xy.x(), xy.y(), zi);
  }
}

void ContactModel::gatherActiveTractions() {
  const size_t n = active_.size();
  active_offset_.resize(n);
  active_wx_.resize(n);
  active_wy_.resize(n);
  active_wz_.resize(n);
  for (size_t r = 0; r < n; ++r) {
    const auto& c = nodes_[static_cast<size_t>(active_[r])];
    active_offset_[r] = kernel_offset_[static_cast<size_t>(active_[r])];
    active_wx_[r] = c_t_ * c.q.x();
    active_wy_[r] = c_t_ * c.q.y();
    active_wz_[r] = -c.p;
  }
}

Eigen::Vector3d ContactModel::displacementFromActive(int node) const {
  const double* table = kernel_table_.data() + kernel_base_[static_cast<size_t>(node)];
  double ux = 0, uy = 0, uz = 0;
  for (size_t r = 0; r < active_offset_.size(); ++r) {
    const double k = table[-active_offset_[r]];
    ux += k * active_wx_[r];
    uy += k * active_wy_[r];
    uz += k * active_wz_[r];
  }
  return {ux, uy, uz};
}

void ContactModel::refreshDisplacementCache(const std::vector<Eigen::Isometry3d>& poses) {
  for (int i = 0; i < lattice_.nodeCount(); ++i) {
    const Eigen::Vector3d& rest = lattice_.surfaceRest(i);
    bool near = nodes_[static_cast<size_t>(i)].contact;
    for (size_t k = 0; k < indenters_.size() && !near; ++k) {
      const Eigen::Vector3d& t = poses[k].translation();
      const double reach = footprintRadius(indenters_[k]);
      if (std::abs(rest.x() - t.x()) > reach || std::abs(rest.y() - t.y()) > reach) continue;
      const auto z = lowerSurfaceZ(indenters_[k], poses[k], rest.x(), rest.y());
      near = z && *z - rest.z() < kCandidateGapMm;
    }
    u_cache_[static_cast<size_t>(i)] = near && !active_.empty() ? displacementFromActive(i) : Eigen::Vector3d::Zero();
    u_cached_[static_cast<size_t>(i)] = near ? 1 : 0;
  }
}

Eigen::Vector3d ContactModel::displacement(int node) const {
  if (u_cached_[static_cast<size_t>(node)]) return u_cache_[static_cast<size_t>(node)];
  return displacementFromActive(node);
}

std::vector<Eigen::Vector3d> ContactModel::allDisplacements() const {
  std::vector<Eigen::Vector3d> u(static_cast<size_t>(lattice_.nodeCount()), Eigen::Vector3d::Zero());
  if (active_.empty()) return u;
  for (int i = 0; i < lattice_.nodeCount(); ++i) u[static_cast<size_t>(i)] = displacement(i);
  return u;
}

ContactState ContactModel::state() const {
  if (active_.empty()) return ContactState::none;
  int slip = 0;
  for (int i : active_) slip += nodes_[static_cast<size_t>(i)].slip ? 1 : 0;
  if (slip == 0) return ContactState::stick;
  if (slip == static_cast<int>(active_.size())) return ContactState::slip;
  return ContactState::partial_slip;
}

}  // namespace onetip::sim
