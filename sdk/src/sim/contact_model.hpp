// sim/contact_model.hpp — quasi-static contact mechanics of the pad, step by step.
//
// Layer response (boundary-element form): a surface traction (q_x, q_y, p) on
// node j displaces node i by K(r_ij) * (c_t q_x, c_t q_y, -p), with the kernel K
// and the tangential-to-normal compliance ratio c_t of the pad's contact model
// (sim/contact_kernel.hpp: halfspace, the Boussinesq response of an
// incompressible layer damped over its thickness, c_t = 1.5; or foundation, a
// Pasternak foundation, c_t = 1.0). Tractions are in units of compliance (mm),
// so only ratios matter and no Young's modulus is needed for kinematics.
//
// Normal contact (Signorini): the active set A holds the nodes the indenter
// penetrates; on A the surface conforms to the indenter, K_AA p = delta, and
// nodes with p <= 0 leave A.
// Tangential contact (brush / Cattaneo-Mindlin): each node in contact is anchored
// to a material point of the indenter (in the indenter's frame) when it first
// touches. A stick node's tangential displacement is prescribed by its anchor's
// current position; the traction it needs must satisfy |q| <= mu p, else the
// node slips, carries |q| = mu p along its trial traction, and is re-anchored
// where it ends up. In the foundation model friction is static/kinetic: a node
// that slipped in the previous sub-step is bounded by kinetic_ratio * mu p
// (it keeps slipping until its stick traction falls below that). Slip starts at the contact edge (where p -> 0) and the stick
// region shrinks inwards; when no node can stick the contact slides as a whole.
// Prediction (Ciavarella-Jager superposition, exact for the uncoupled
// halfspace model): sliding the indenter by s at constant approach delta, the
// stick region is the contact region at approach delta - s / (mu c_t), and
// gross slip starts at s = mu c_t delta (1.5 mm at delta = 1 mm, mu = 1).
// History lives in the anchors, so the model must be advanced step by step;
// advance() sub-steps so no indenter point moves more than max_substep_mm
// (at most kMaxSubsteps sub-steps per call: 1000 x 0.1 mm = 10 cm per frame).
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <vector>

#include "onetip/types.hpp"
#include "sim/indenter.hpp"
#include "sim/pad.hpp"

namespace onetip::sim {

constexpr int kMaxSubsteps = 1000;

struct NodeContact {
  bool contact = false;
  bool slip = false;
  int owner = -1;               // indenter index
  Eigen::Vector3d anchor{0, 0, 0};  // material point of the owner, its local frame
  double p = 0;                 // normal traction (compliance units, mm)
  Eigen::Vector2d q{0, 0};      // tangential traction
};

struct ContactStepStats {
  int contact_nodes = 0;
  int slip_nodes = 0;
  int substeps = 0;
};

class ContactModel {
 public:
  ContactModel(const PadLattice& lattice, std::vector<IndenterGeometry> indenters,
               double max_substep_mm = 0.1);

  // Releases every contact: zero tractions, zero displacement, no anchors.
  void reset(const std::vector<Eigen::Isometry3d>& poses);
  // Moves the indenters to `poses` (one per indenter) through sub-steps.
  ContactStepStats advance(const std::vector<Eigen::Isometry3d>& poses);

  // Displacement of a node's surface (and marker layer) point, P frame, mm.
  // Nodes near the indenters come from the cache the last step filled.
  Eigen::Vector3d displacement(int node) const;
  // Displacements of every lattice node (for rendering), row-major like the lattice.
  std::vector<Eigen::Vector3d> allDisplacements() const;

  const NodeContact& node(int i) const { return nodes_[static_cast<size_t>(i)]; }
  const std::vector<int>& activeNodes() const { return active_; }
  ContactState state() const;
  const std::vector<Eigen::Isometry3d>& poses() const { return poses_; }

 private:
  void solve(const std::vector<Eigen::Isometry3d>& poses);
  double kernel(int i, int j) const;
  // Cholesky factor of K_SS for a node set S. Two are kept across steps, the
  // normal contact set and the stick set, and reused while S stays the same
  // (a held or slowly moving contact keeps its sets for many steps).
  struct CachedFactor {
    std::vector<int> set;
    Eigen::LLT<Eigen::MatrixXd> llt;
  };
  const Eigen::LLT<Eigen::MatrixXd>& factorFor(const std::vector<int>& set, CachedFactor& slot);
  void gatherActiveTractions();
  Eigen::Vector3d displacementFromActive(int node) const;
  void refreshDisplacementCache(const std::vector<Eigen::Isometry3d>& poses);

  const PadLattice& lattice_;
  std::vector<IndenterGeometry> indenters_;
  double max_substep_mm_;
  double c_t_ = 1.5;            // tangential-to-normal compliance ratio of the model
  double kinetic_ratio_ = 1.0;  // bound of a slipping node, relative to mu p
  std::vector<double> kernel_table_;  // by lattice offset (da, db)
  // kernel(i, j) = kernel_table_[kernel_base_[i] - kernel_offset_[j]]
  std::vector<int> kernel_base_, kernel_offset_;
  std::vector<NodeContact> nodes_;
  std::vector<int> active_;
  std::vector<Eigen::Vector3d> u_cache_;  // displacement of nodes near the indenters
  std::vector<char> u_cached_;            // which nodes u_cache_ holds
  // Workspace kept across steps (no allocation while the contact size holds).
  Eigen::MatrixXd k_work_;
  CachedFactor normal_factor_, stick_factor_;
  // Active nodes' kernel offsets and weighted tractions (c_t q_x, c_t q_y, -p), for displacement sums.
  std::vector<int> active_offset_;
  std::vector<double> active_wx_, active_wy_, active_wz_;
  std::vector<Eigen::Isometry3d> poses_;
};

}  // namespace onetip::sim
