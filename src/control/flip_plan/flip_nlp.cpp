// Direct collocation of the planar model (trapezoidal) for IPOPT. Each knot carries the state,
// its acceleration, the motor torques and the ground forces; each knot obeys the inverse dynamics
// (so no mass matrix is inverted), the stance feet stay where they stood, the forces stay in their
// friction cones and the torques under the motors' torque-speed curve. Consecutive knots are tied
// by the trapezoid rule on q and qd. Jacobians are exact (forward-mode automatic differentiation
// of each knot's and each interval's constraints); the Hessian is IPOPT's limited-memory one.
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <IpIpoptApplication.hpp>
#include <IpIpoptCalculatedQuantities.hpp>
#include <IpTNLP.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "control/flip_plan/flip_problem.hpp"
#include "control/flip_plan/planar_model.hpp"

namespace cerebellum::flip {
namespace {

using Ipopt::Index;
using Ipopt::Number;
using AD = Eigen::AutoDiffScalar<Eigen::VectorXd>;

// a knot's variables
constexpr int kQ = 0;
constexpr int kQd = kQ + kDof;
constexpr int kQdd = kQd + kDof;
constexpr int kTau = kQdd + kDof;
constexpr int kMotors = 4;
constexpr int kForce = kTau + kMotors;
constexpr int kKnotVars = kForce + 2 * kPairs;
// a knot's constraints: dynamics, feet (x, z per pair), friction (two per pair), torque-speed
// (two per motor)
constexpr int kFeetRow = kDof;
constexpr int kFrictionRow = kFeetRow + 2 * kPairs;
constexpr int kSpeedRow = kFrictionRow + 2 * kPairs;
constexpr int kKnotRows = kSpeedRow + 2 * kMotors;
// an interval's constraints: trapezoid on q and qd; its variables: q, qd, qdd of both knots and h
constexpr int kIntervalRows = 2 * kDof;
constexpr int kIntervalKnotVars = 3 * kDof;
constexpr int kIntervalVars = 2 * kIntervalKnotVars + 1;
constexpr double kInfinity = 1e19;
constexpr double kFeasibleViolation = 1e-6;
// the landing: feet at most this far above the ground at the end of the flight, trunk between
constexpr double kTouchdownClearanceM = 0.03;
constexpr double kLandingTrunkMinM = 0.18;
constexpr double kLandingTrunkMaxM = 0.36;

// both pairs push, then the last pair alone (the rear for a back flip, the front for a front flip)
bool in_stance(int pair, int phase, int last_pair) {
  if (phase == kBothPairsPush) return true;
  return phase != kFlight && pair == last_pair;
}

// the knot's constraints, for a double or an automatic-differentiation scalar
template <typename T>
void knot_constraints(const std::vector<PlanarBody>& bodies, const FlipLimits& limits, const T* z, T* g) {
  dynamics_residual(bodies, z + kQ, z + kQd, z + kQdd, z + kTau, z + kForce, g);
  for (int pair = 0; pair < kPairs; ++pair) {
    const Point2<T> foot = foot_position(z + kQ, pair);
    // the foot is a ball: rolling without slipping, its centre moves by the radius times the
    // shank's turn, so a stance foot keeps x - r * (shank angle), not x
    g[kFeetRow + 2 * pair] = foot.x - robot::kFootRadius * segment_angle(z + kQ, 2, pair);
    g[kFeetRow + 2 * pair + 1] = foot.z;
    const T fx = z[kForce + 2 * pair];
    const T fz = z[kForce + 2 * pair + 1];
    g[kFrictionRow + 2 * pair] = fx - limits.friction_mu * fz;
    g[kFrictionRow + 2 * pair + 1] = -fx - limits.friction_mu * fz;
  }
  // the torque-speed curve as two lines per motor: tau <= slope (no_load - qd) bounds a motoring
  // torque past the full-torque speed, and is looser than the 12 Nm bound when braking
  const double slope = limits.torque_max_nm / (limits.no_load_speed_rad_s - limits.full_torque_speed_rad_s);
  const int joints[kMotors] = {kFrontHip, kFrontKnee, kRearHip, kRearKnee};
  for (int m = 0; m < kMotors; ++m) {
    const T tau = z[kTau + m];
    const T qd = z[kQd + joints[m]];
    g[kSpeedRow + 2 * m] = tau - slope * (limits.no_load_speed_rad_s - qd);
    g[kSpeedRow + 2 * m + 1] = -tau - slope * (limits.no_load_speed_rad_s + qd);
  }
}

// the trapezoid rule between knot a and knot b (each q, qd, qdd), h the interval's length
template <typename T>
void interval_constraints(const T* a, const T* b, const T& h, T* g) {
  for (int j = 0; j < kDof; ++j) {
    g[j] = b[j] - a[j] - 0.5 * h * (a[kDof + j] + b[kDof + j]);
    g[kDof + j] = b[kDof + j] - a[kDof + j] - 0.5 * h * (a[2 * kDof + j] + b[2 * kDof + j]);
  }
}

class FlipNlp : public Ipopt::TNLP {
 public:
  FlipNlp(const FlipRequest& request, FlipPlan& plan) : request_(request), plan_(plan), bodies_(planar_bodies()) {
    int knot = 0;
    for (int p = 0; p < kFlipPhases; ++p)
      for (int i = 0; i < request_.intervals[p]; ++i) interval_phase_.push_back(p), (void)knot++;
    knots_ = static_cast<int>(interval_phase_.size()) + 1;
    // the start: the default stand, feet on the ground, at rest
    start_q_[kX] = 0.0;
    start_q_[kPitch] = 0.0;
    for (int pair = 0; pair < kPairs; ++pair) {
      start_q_[hip_coordinate(pair)] = robot::kStandPose[1];
      start_q_[knee_coordinate(pair)] = robot::kStandPose[2];
    }
    start_q_[kZ] = 0.0;
    const Point2<double> foot = foot_position(start_q_.data(), kFrontPair);
    start_q_[kZ] = robot::kFootRadius - foot.z;
    for (int pair = 0; pair < kPairs; ++pair)
      stance_x_m_[pair] = foot_position(start_q_.data(), pair).x - robot::kFootRadius * segment_angle(start_q_.data(), 2, pair);
  }

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac_g, Index& nnz_h_lag, IndexStyleEnum& index_style) override {
    n = knots_ * kKnotVars + kFlipPhases;
    m = knots_ * kKnotRows + (knots_ - 1) * kIntervalRows;
    nnz_jac_g = knots_ * kKnotRows * kKnotVars + (knots_ - 1) * kIntervalRows * kIntervalVars;
    nnz_h_lag = 0;
    index_style = C_STYLE;
    return true;
  }

  int knot_phase(int k) const { return k < knots_ - 1 ? interval_phase_[k] : kFlight; }
  Index h_index(int phase) const { return knots_ * kKnotVars + phase; }

  bool get_bounds_info(Index n, Number* x_l, Number* x_u, Index m, Number* g_l, Number* g_u) override {
    const FlipLimits& lim = request_.limits;
    for (Index i = 0; i < n; ++i) x_l[i] = -kInfinity, x_u[i] = kInfinity;
    for (int k = 0; k < knots_; ++k) {
      Number* lo = x_l + k * kKnotVars;
      Number* hi = x_u + k * kKnotVars;
      const int phase = knot_phase(k);
      lo[kQ + kZ] = lim.trunk_height_min_m;
      for (int pair = 0; pair < kPairs; ++pair) {
        const std::size_t leg = pair == kFrontPair ? 0 : 2;
        const robot::JointRange hip = robot::joint_range(leg * kJointsPerLeg + 1);
        const robot::JointRange knee = robot::joint_range(leg * kJointsPerLeg + 2);
        lo[kQ + hip_coordinate(pair)] = hip.lower, hi[kQ + hip_coordinate(pair)] = hip.upper;
        lo[kQ + knee_coordinate(pair)] = knee.lower, hi[kQ + knee_coordinate(pair)] = knee.upper;
        // the ground pushes, never pulls; a foot in the air carries nothing
        if (in_stance(pair, phase, request_.last_pushing_pair)) {
          lo[kForce + 2 * pair + 1] = lim.stance_force_min_n;
        } else {
          lo[kForce + 2 * pair] = hi[kForce + 2 * pair] = 0.0;
          lo[kForce + 2 * pair + 1] = hi[kForce + 2 * pair + 1] = 0.0;
        }
      }
      for (int mtr = 0; mtr < kMotors; ++mtr) lo[kTau + mtr] = -lim.torque_max_nm, hi[kTau + mtr] = lim.torque_max_nm;
      // no joint faster than the motor turns unloaded
      for (int j = kFrontHip; j < kDof; ++j) lo[kQd + j] = -lim.no_load_speed_rad_s, hi[kQd + j] = lim.no_load_speed_rad_s;
    }
    // the start: at rest in the stand
    for (int j = 0; j < kDof; ++j) {
      x_l[kQ + j] = x_u[kQ + j] = start_q_[j];
      x_l[kQd + j] = x_u[kQd + j] = 0.0;
    }
    // the end: turned, near the take-off, trunk at a landing height
    Number* lo_end = x_l + (knots_ - 1) * kKnotVars;
    Number* hi_end = x_u + (knots_ - 1) * kKnotVars;
    lo_end[kQ + kX] = -lim.landing_distance_max_m, hi_end[kQ + kX] = lim.landing_distance_max_m;
    lo_end[kQ + kZ] = kLandingTrunkMinM, hi_end[kQ + kZ] = kLandingTrunkMaxM;
    lo_end[kQd + kPitch] = -lim.landing_pitch_rate_max_rad_s, hi_end[kQd + kPitch] = lim.landing_pitch_rate_max_rad_s;
    for (int j = kFrontHip; j < kDof; ++j) {
      lo_end[kQ + j] = std::max(lo_end[kQ + j], start_q_[j] - lim.landing_pose_tolerance_rad);
      hi_end[kQ + j] = std::min(hi_end[kQ + j], start_q_[j] + lim.landing_pose_tolerance_rad);
      lo_end[kQd + j] = -lim.landing_joint_rate_max_rad_s, hi_end[kQd + j] = lim.landing_joint_rate_max_rad_s;
    }
    if (request_.pitch_turn_rad != 0.0) lo_end[kQ + kPitch] = hi_end[kQ + kPitch] = request_.pitch_turn_rad;
    for (int p = 0; p < kFlipPhases; ++p) {
      x_l[h_index(p)] = request_.duration_min_s[p] / request_.intervals[p];
      x_u[h_index(p)] = request_.duration_max_s[p] / request_.intervals[p];
    }
    // constraints
    for (Index r = 0; r < m; ++r) g_l[r] = g_u[r] = 0.0;
    for (int k = 0; k < knots_; ++k) {
      Number* lo = g_l + k * kKnotRows;
      Number* hi = g_u + k * kKnotRows;
      const int phase = knot_phase(k);
      for (int pair = 0; pair < kPairs; ++pair) {
        if (in_stance(pair, phase, request_.last_pushing_pair)) {
          lo[kFeetRow + 2 * pair] = hi[kFeetRow + 2 * pair] = stance_x_m_[pair];
          lo[kFeetRow + 2 * pair + 1] = hi[kFeetRow + 2 * pair + 1] = robot::kFootRadius;
        } else {
          lo[kFeetRow + 2 * pair] = -kInfinity, hi[kFeetRow + 2 * pair] = kInfinity;
          lo[kFeetRow + 2 * pair + 1] = robot::kFootRadius;
          hi[kFeetRow + 2 * pair + 1] = k == knots_ - 1 ? robot::kFootRadius + kTouchdownClearanceM : kInfinity;
        }
      }
      for (int r = kFrictionRow; r < kKnotRows; ++r) lo[r] = -kInfinity, hi[r] = 0.0;
    }
    return true;
  }

  bool get_starting_point(Index n, bool init_x, Number* x, bool, Number*, Number*, Index, bool, Number*) override {
    if (!init_x) return false;
    std::fill(x, x + n, 0.0);
    const double turn = request_.pitch_turn_rad != 0.0 ? request_.pitch_turn_rad : -2.0 * robot::kPi;
    const int flight_start = request_.intervals[0] + request_.intervals[1];
    for (int k = 0; k < knots_; ++k) {
      Number* z = x + k * kKnotVars;
      for (int j = 0; j < kDof; ++j) z[kQ + j] = start_q_[j];
      if (k > flight_start) {
        const double s = double(k - flight_start) / double(knots_ - 1 - flight_start);
        z[kQ + kPitch] = turn * s;
        z[kQ + kZ] = start_q_[kZ] + 0.3 * std::sin(robot::kPi * s);
      }
      z[kForce + 1] = z[kForce + 3] = robot::kTotalMassKg * robot::kGravityMPerS2 / 4.0;
    }
    for (int p = 0; p < kFlipPhases; ++p)
      x[h_index(p)] = 0.5 * (request_.duration_min_s[p] + request_.duration_max_s[p]) / request_.intervals[p];
    return true;
  }

  // the effort: sum over knots of h * sum tau^2, plus the turn when the largest is asked
  double knot_weight(const Number* x, int k) const { return x[h_index(knot_phase(k))]; }
  bool eval_f(Index, const Number* x, bool, Number& f) override {
    f = 0.0;
    for (int k = 0; k < knots_; ++k) {
      const Number* z = x + k * kKnotVars;
      double sum = 0.0;
      for (int mtr = 0; mtr < kMotors; ++mtr) sum += z[kTau + mtr] * z[kTau + mtr];
      f += kEffortWeight * knot_weight(x, k) * sum;
    }
    for (int k = 0; k + 1 < knots_; ++k)
      for (int v = kTau; v < kKnotVars; ++v) {
        const double step = x[(k + 1) * kKnotVars + v] - x[k * kKnotVars + v];
        f += smoothing_weight(v) * step * step;
      }
    if (request_.pitch_turn_rad == 0.0) f += x[(knots_ - 1) * kKnotVars + kQ + kPitch];
    return true;
  }
  bool eval_grad_f(Index n, const Number* x, bool, Number* grad) override {
    std::fill(grad, grad + n, 0.0);
    for (int k = 0; k < knots_; ++k) {
      const Number* z = x + k * kKnotVars;
      double sum = 0.0;
      for (int mtr = 0; mtr < kMotors; ++mtr) {
        sum += z[kTau + mtr] * z[kTau + mtr];
        grad[k * kKnotVars + kTau + mtr] = kEffortWeight * 2.0 * knot_weight(x, k) * z[kTau + mtr];
      }
      grad[h_index(knot_phase(k))] += kEffortWeight * sum;
    }
    for (int k = 0; k + 1 < knots_; ++k)
      for (int v = kTau; v < kKnotVars; ++v) {
        const double step = x[(k + 1) * kKnotVars + v] - x[k * kKnotVars + v];
        grad[(k + 1) * kKnotVars + v] += 2.0 * smoothing_weight(v) * step;
        grad[k * kKnotVars + v] -= 2.0 * smoothing_weight(v) * step;
      }
    if (request_.pitch_turn_rad == 0.0) grad[(knots_ - 1) * kKnotVars + kQ + kPitch] = 1.0;
    return true;
  }

  bool eval_g(Index, const Number* x, bool, Index, Number* g) override {
    for (int k = 0; k < knots_; ++k) knot_constraints(bodies_, request_.limits, x + k * kKnotVars, g + k * kKnotRows);
    Number* gi = g + knots_ * kKnotRows;
    for (int k = 0; k + 1 < knots_; ++k)
      interval_constraints(x + k * kKnotVars, x + (k + 1) * kKnotVars, x[h_index(interval_phase_[k])], gi + k * kIntervalRows);
    return true;
  }

  bool eval_jac_g(Index, const Number* x, bool, Index, Index, Index* rows, Index* cols, Number* values) override {
    if (values == nullptr) {
      Index e = 0;
      for (int k = 0; k < knots_; ++k)
        for (int r = 0; r < kKnotRows; ++r)
          for (int v = 0; v < kKnotVars; ++v) rows[e] = k * kKnotRows + r, cols[e] = k * kKnotVars + v, ++e;
      for (int k = 0; k + 1 < knots_; ++k)
        for (int r = 0; r < kIntervalRows; ++r)
          for (int v = 0; v < kIntervalVars; ++v) {
            rows[e] = knots_ * kKnotRows + k * kIntervalRows + r;
            cols[e] = interval_variable(k, v);
            ++e;
          }
      return true;
    }
    Index e = 0;
    AD zk[kKnotVars];
    AD gk[kKnotRows];
    for (int k = 0; k < knots_; ++k) {
      for (int v = 0; v < kKnotVars; ++v) zk[v] = AD(x[k * kKnotVars + v], kKnotVars, v);
      knot_constraints(bodies_, request_.limits, zk, gk);
      for (int r = 0; r < kKnotRows; ++r)
        for (int v = 0; v < kKnotVars; ++v) values[e++] = derivative(gk[r], v, kKnotVars);
    }
    AD a[kIntervalKnotVars], b[kIntervalKnotVars], gi[kIntervalRows];
    for (int k = 0; k + 1 < knots_; ++k) {
      for (int v = 0; v < kIntervalKnotVars; ++v) {
        a[v] = AD(x[interval_variable(k, v)], kIntervalVars, v);
        b[v] = AD(x[interval_variable(k, kIntervalKnotVars + v)], kIntervalVars, kIntervalKnotVars + v);
      }
      const AD h(x[h_index(interval_phase_[k])], kIntervalVars, kIntervalVars - 1);
      interval_constraints(a, b, h, gi);
      for (int r = 0; r < kIntervalRows; ++r)
        for (int v = 0; v < kIntervalVars; ++v) values[e++] = derivative(gi[r], v, kIntervalVars);
    }
    return true;
  }

  void finalize_solution(Ipopt::SolverReturn status, Index, const Number* x, const Number*, const Number*, Index,
                         const Number* g, const Number*, Number, const Ipopt::IpoptData*,
                         Ipopt::IpoptCalculatedQuantities* quantities) override {
    plan_.solved = status == Ipopt::SUCCESS || status == Ipopt::STOP_AT_ACCEPTABLE_POINT;
    plan_.max_constraint_violation =
        quantities != nullptr ? quantities->unscaled_curr_nlp_constraint_violation(Ipopt::NORM_MAX) : kInfinity;
    plan_.feasible = plan_.max_constraint_violation <= kFeasibleViolation;
    plan_.knots.clear();
    double time_s = 0.0;
    for (int k = 0; k < knots_; ++k) {
      const Number* z = x + k * kKnotVars;
      FlipKnot knot{};
      knot.time_s = time_s;
      knot.phase = knot_phase(k);
      knot.trunk = {z[kQ + kX], z[kQ + kZ], z[kQ + kPitch]};
      for (int mtr = 0; mtr < kMotors; ++mtr) {
        knot.q_rad[mtr] = z[kQ + kFrontHip + mtr];
        knot.qd_rad_s[mtr] = z[kQd + kFrontHip + mtr];
        knot.tau_nm[mtr] = z[kTau + mtr];
        knot.foot_force_n[mtr] = z[kForce + mtr];
        plan_.peak_torque_nm[mtr] = std::max(plan_.peak_torque_nm[mtr], std::abs(z[kTau + mtr]));
      }
      plan_.knots.push_back(knot);
      if (k + 1 < knots_) time_s += x[h_index(interval_phase_[k])];
    }
    for (int p = 0; p < kFlipPhases; ++p) plan_.duration_s[p] = x[h_index(p)] * request_.intervals[p];
    plan_.pitch_turned_rad = plan_.knots.back().trunk[2] - plan_.knots.front().trunk[2];
    // the dynamics' rows and the trapezoid's: how far the returned motion is from the model
    double residual = 0.0;
    for (int k = 0; k < knots_; ++k)
      for (int r = 0; r < kDof; ++r) residual = std::max(residual, std::abs(g[k * kKnotRows + r]));
    for (int r = knots_ * kKnotRows; r < knots_ * kKnotRows + (knots_ - 1) * kIntervalRows; ++r)
      residual = std::max(residual, std::abs(g[r]));
    plan_.max_dynamics_residual = residual;
  }

 private:
  // small: the effort only breaks ties between motions that meet every constraint
  static constexpr double kEffortWeight = 1e-3;
  // knot-wise dynamics let torques and forces alternate from knot to knot with the same average
  // motion (the trapezoid sees only sums of neighbours); a penalty on their steps keeps them
  // smooth enough to play back
  static double smoothing_weight(int v) { return v < kForce ? 1e-3 : 1e-5; }

  static double derivative(const AD& value, int v, int size) {
    return value.derivatives().size() == size ? value.derivatives()[v] : 0.0;
  }
  // the interval's v-th variable: q, qd, qdd of knot k (0..20), of knot k+1 (21..41), then h
  Index interval_variable(int k, int v) const {
    if (v < kIntervalKnotVars) return k * kKnotVars + v;
    if (v < 2 * kIntervalKnotVars) return (k + 1) * kKnotVars + (v - kIntervalKnotVars);
    return h_index(interval_phase_[k]);
  }

  const FlipRequest& request_;
  FlipPlan& plan_;
  std::vector<PlanarBody> bodies_;
  std::vector<int> interval_phase_;
  int knots_ = 0;
  std::array<double, kDof> start_q_{};
  std::array<double, kPairs> stance_x_m_{};
};

}  // namespace

const char* flip_phase_name(int phase) {
  switch (phase) {
    case kBothPairsPush: return "both_pairs_push";
    case kRearPairPushes: return "rear_pair_pushes";
    case kFlight: return "flight";
    default: return "unknown";
  }
}

FlipPlan plan_flip(const FlipRequest& request) {
  FlipPlan plan;
  Ipopt::SmartPtr<Ipopt::TNLP> nlp = new FlipNlp(request, plan);
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  app->Options()->SetStringValue("hessian_approximation", "limited-memory");
  app->Options()->SetIntegerValue("max_iter", request.max_iterations);
  app->Options()->SetNumericValue("tol", 1e-6);
  app->Options()->SetNumericValue("constr_viol_tol", 1e-6);
  // the effort and smoothing terms are tie-breakers: a feasible point whose optimality has stalled
  // is a plan
  app->Options()->SetNumericValue("acceptable_tol", 1e-3);
  app->Options()->SetNumericValue("acceptable_constr_viol_tol", 1e-6);
  app->Options()->SetIntegerValue("acceptable_iter", 10);
  app->Options()->SetIntegerValue("print_level", request.print ? 5 : 0);
  app->Options()->SetStringValue("sb", "yes");
  if (app->Initialize() != Ipopt::Solve_Succeeded) {
    plan.status = "IPOPT did not initialise";
    return plan;
  }
  const Ipopt::ApplicationReturnStatus status = app->OptimizeTNLP(nlp);
  switch (status) {
    case Ipopt::Solve_Succeeded: plan.status = "solved"; break;
    case Ipopt::Solved_To_Acceptable_Level: plan.status = "solved to the acceptable level"; break;
    case Ipopt::Infeasible_Problem_Detected: plan.status = "infeasible (IPOPT converged to a point of least violation)"; break;
    case Ipopt::Maximum_Iterations_Exceeded: plan.status = "iteration limit"; break;
    case Ipopt::Restoration_Failed: plan.status = "restoration failed"; break;
    default: plan.status = "IPOPT status " + std::to_string(static_cast<int>(status)); break;
  }
  return plan;
}

}  // namespace cerebellum::flip
