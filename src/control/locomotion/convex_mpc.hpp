// Convex MPC on the single-rigid-body model (Di Carlo et al. 2018): 13 states
// x = [roll, pitch, yaw, p(3), omega(3), v(3), g], 12 inputs (world-frame foot forces),
// yaw-only rotation, exact discretisation, condensed to one dense QP over the forces of the
// feet in stance (swing-foot variables removed), friction pyramid and force limits.
#pragma once

#include <Eigen/Core>
#include <array>
#include <memory>

#include "control/locomotion/gait_table.hpp"
#include "control/qp/qp_problem.hpp"
#include "control/qp/qp_solution.hpp"
#include "control/qp/qp_solver.hpp"
#include "core/joint_layout.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {

inline constexpr int kMpcHorizon = 10;
inline constexpr int kSrbStates = 13;

struct ConvexMpcConfig {
  double dt_s = kGaitSegmentS;  // one MPC step = one gait segment
  double mass_kg = robot::kMpcMassKg;
  Eigen::Vector3d inertia_diag{robot::kMpcInertiaDiag[0], robot::kMpcInertiaDiag[1], robot::kMpcInertiaDiag[2]};
  // state weights: roll, pitch, yaw, x, y, z, wx, wy, wz, vx, vy, vz
  std::array<double, 12> state_weights{1.0, 0.25, 10, 2, 2, 50, 0, 0, 0.3, 0.2, 0.2, 0.1};
  // x, y weight of a stand that holds the trunk over its feet (MpcInput::hold_position): at the
  // walking gaits' 2, a steady 20 N sideways drifted the planted stand off its feet at 0.2 m/s
  double stand_position_weight = 40.0;
  // while only the front or only the rear pair stands (the bound), yaw and yaw rate weigh this
  // share of their weights: that pair turns the trunk only by sideways forces at its feet, and
  // those roll the trunk over them. At the full weight (10 against roll's 1) the MPC traded roll
  // for yaw until the other foot of the pair unloaded and the trunk rolled over the loaded one (a
  // bound entered turning and sideways, the soak's most common fall)
  double lone_pair_yaw_weight_share = 0.3;
  double force_weight = 4e-5;
  double friction = 0.4;
  double force_max_n = 150.0;
};

// the friction pyramid the MPC keeps each foot's force within
enum class FrictionPyramid {
  // |fx| <= mu fz and |fy| <= mu fz (world axes): up to mu sqrt(2) along a diagonal, within a
  // ground of friction 2 mu in every direction
  Square,
  // |fx| + |fy| <= mu fz: within mu in every direction (MuJoCo's pyramidal cone of friction mu
  // is this diamond, a real ground's round cone holds it)
  Diamond,
};

// what the MPC needs each solve
struct MpcInput {
  Eigen::Matrix<double, kSrbStates, 1> x0;  // current state (g entry = -robot::kGravityMPerS2)
  // reference trajectory, one state per horizon step (k = 1..horizon)
  std::array<Eigen::Matrix<double, kSrbStates, 1>, kMpcHorizon> x_ref;
  // foot positions relative to the COM now, world frame (a foot in the air: where it will land)
  std::array<Eigen::Vector3d, kNumLegs> foot_from_com;
  // how far the COM has moved at the start of each horizon step (zero for the first): the feet's
  // lever arms at step k are foot_from_com - com_shift[k]
  std::array<Eigen::Vector3d, kMpcHorizon> com_shift = zero_shifts();

  static std::array<Eigen::Vector3d, kMpcHorizon> zero_shifts() {
    std::array<Eigen::Vector3d, kMpcHorizon> shifts;
    for (auto& shift : shifts) shift.setZero();
    return shifts;
  }
  // contact table over the horizon
  std::array<std::array<bool, kNumLegs>, kMpcHorizon> contact;
  // friction coefficient of the ground for this solve; 0: the configured one
  double friction = 0.0;
  FrictionPyramid pyramid = FrictionPyramid::Square;
  // a planted stand that leans on its feet instead of stepping: x, y weigh stand_position_weight
  bool hold_position = false;
};

struct MpcOutput {
  // forces of the first step, world frame, the ground's force on each foot
  std::array<Eigen::Vector3d, kNumLegs> forces{};
  qp::QpStatus status = qp::QpStatus::InvalidInput;
  int variables = 0;
};

// every foot on the ground at every step of the horizon
bool stands_throughout(const std::array<std::array<bool, kNumLegs>, kMpcHorizon>& contact);

class ConvexMpc {
 public:
  ConvexMpc(const ConvexMpcConfig& config, std::unique_ptr<qp::QpSolver> solver);

  // builds the QP for this input (exposed for tests and benchmarks)
  void build(const MpcInput& input);
  const qp::QpProblem& problem() const { return problem_; }
  // build + solve; NaN in the input or a failed solve gives a status other than Solved
  MpcOutput solve(const MpcInput& input);

  // continuous dynamics at a yaw angle and foot positions (exposed for tests)
  static void continuous_dynamics(const ConvexMpcConfig& config, double yaw,
                                  const std::array<Eigen::Vector3d, kNumLegs>& foot_from_com,
                                  Eigen::Matrix<double, kSrbStates, kSrbStates>& a,
                                  Eigen::Matrix<double, kSrbStates, 3 * kNumLegs>& b);
  // its two halves: A depends on the yaw alone; B also on the feet's lever arms, which change
  // along the horizon
  static void state_matrix(double yaw, Eigen::Matrix<double, kSrbStates, kSrbStates>& a);
  static void input_matrix(const ConvexMpcConfig& config, double yaw,
                           const std::array<Eigen::Vector3d, kNumLegs>& foot_from_com,
                           Eigen::Matrix<double, kSrbStates, 3 * kNumLegs>& b);
  // Ad = exp(A dt) and the hold factor G = integral of exp(A s) over [0, dt] (Bd = G B), from one
  // matrix exponential
  static void zero_order_hold(const Eigen::Matrix<double, kSrbStates, kSrbStates>& a, double dt,
                              Eigen::Matrix<double, kSrbStates, kSrbStates>& ad,
                              Eigen::Matrix<double, kSrbStates, kSrbStates>& hold);
  // exact zero-order-hold discretisation: Ad, Bd = G B
  static void discretize(const Eigen::Matrix<double, kSrbStates, kSrbStates>& a,
                         const Eigen::Matrix<double, kSrbStates, 3 * kNumLegs>& b, double dt,
                         Eigen::Matrix<double, kSrbStates, kSrbStates>& ad,
                         Eigen::Matrix<double, kSrbStates, 3 * kNumLegs>& bd);

 private:
  ConvexMpcConfig config_;
  std::unique_ptr<qp::QpSolver> solver_;
  qp::QpProblem problem_;
  qp::QpSolution solution_;
  // condensed prediction X = Aqp x0 + Bqp U over all 12 * horizon inputs
  Eigen::Matrix<double, kSrbStates * kMpcHorizon, kSrbStates> a_qp_;
  Eigen::Matrix<double, kSrbStates * kMpcHorizon, 3 * kNumLegs * kMpcHorizon> b_qp_;
  // the inputs kept in the QP (feet in stance): index into the 12 * horizon inputs
  std::array<int, 3 * kNumLegs * kMpcHorizon> kept_{};
  int kept_count_ = 0;
  Eigen::MatrixXd b_kept_;
  Eigen::MatrixXd weighted_b_;
};

}  // namespace cerebellum
