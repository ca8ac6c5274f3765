#include "control/upright/upright_balance_design.hpp"

#include <mujoco/mujoco.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "control/upright/upright_state.hpp"
#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

using Matrix = Eigen::MatrixXd;
using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};

constexpr int kFreeJointVelocities = 6;
constexpr int kJointCount = static_cast<int>(kNumJoints);

// hip and knee (abad 0) that put the foot centre at (x, z) from the hip joint, body axes
std::array<double, 2> sagittal_leg_ik(double x, double z) {
  const SagittalIkResult ik = sagittal_inverse_kinematics(x, z);
  return {ik.hip, ik.knee};
}

// the trunk pitched nose up by `elevation` (MuJoCo quaternion w x y z)
Eigen::Quaterniond elevated(double elevation_rad) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(-elevation_rad, Eigen::Vector3d::UnitY()));
}

class Designer {
 public:
  Designer(const std::string& model_path, double control_period_s) {
    char error[1000] = "";
    model_.reset(mj_loadXML(model_path.c_str(), nullptr, error, sizeof(error)));
    if (!model_) throw std::runtime_error("two-leg stand: robot model " + model_path + " failed to load: " + error);
    if (model_->nq != kUprightPositionSize || model_->nv != kUprightVelocitySize || model_->nu != kNumJoints) {
      throw std::runtime_error("two-leg stand: robot model " + model_path +
                               " is not a floating body with 12 motor joints");
    }
    // the gain acts once per control tick, the torque held in between
    model_->opt.timestep = control_period_s;
    data_.reset(mj_makeData(model_.get()));
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      const std::string site = std::string(kLegNames[leg]) + "_foot";
      foot_site_[leg] = mj_name2id(model_.get(), mjOBJ_SITE, site.c_str());
      if (foot_site_[leg] < 0) throw std::runtime_error("two-leg stand: robot model has no site " + site);
    }
  }

  // the pose and the torques that hold it (no gain yet)
  UprightSample equilibrium(double elevation_rad, double hip_height_m, std::array<double, 2> front_hip_knee) {
    UprightPosition q = UprightPosition::Zero();
    const Eigen::Quaterniond orientation = elevated(elevation_rad);
    q.segment<4>(3) << orientation.w(), orientation.x(), orientation.y(), orientation.z();
    const Eigen::Matrix3d r = orientation.toRotationMatrix();
    const Eigen::Vector3d hind_hip_body(-robot::kHipX, 0.0, 0.0);
    // base height: the hind hips at hip_height_m
    q[2] = hip_height_m - (r * hind_hip_body).z();
    std::array<double, 2> hind{1.5, -1.5};
    // the legs' mass moves the centre of mass: iterate the hind feet under it
    for (int iteration = 0; iteration < 100; ++iteration) {
      for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
        const std::array<double, 2>& hip_knee = is_front_leg(leg) ? front_hip_knee : hind;
        q[7 + 3 * leg] = 0.0;
        q[7 + 3 * leg + 1] = hip_knee[0];
        q[7 + 3 * leg + 2] = hip_knee[1];
      }
      load(q);
      mj_kinematics(model_.get(), data_.get());
      mj_comPos(model_.get(), data_.get());
      const double com_x = data_->subtree_com[3 * 1 + 0];
      const Eigen::Vector3d hip_world = q.head<3>() + r * hind_hip_body;
      const Eigen::Vector3d foot_from_hip(com_x - hip_world.x(), 0.0, robot::kFootRadius - hip_world.z());
      const Eigen::Vector3d in_body = r.transpose() * foot_from_hip;
      const std::array<double, 2> next = sagittal_leg_ik(in_body.x(), in_body.z());
      const bool converged = std::abs(next[0] - hind[0]) + std::abs(next[1] - hind[1]) < 1e-12;
      hind = next;
      if (converged) break;
    }
    for (std::size_t leg = 2; leg < kNumLegs; ++leg) {
      q[7 + 3 * leg + 1] = hind[0];
      q[7 + 3 * leg + 2] = hind[1];
    }
    // the height at which the soft contacts carry the weight: the root's vertical residual of the
    // inverse dynamics at rest changes sign between the feet in the air and pressed in
    double low = -0.005, high = 0.003;
    const double base_z = q[2];
    const auto vertical_residual = [&](double dz) {
      q[2] = base_z + dz;
      inverse(q);
      return data_->qfrc_inverse[2];
    };
    if (vertical_residual(low) > 0.0 || vertical_residual(high) < 0.0) {
      throw std::runtime_error("two-leg stand: no height carries the weight at elevation " +
                               std::to_string(elevation_rad) + " rad");
    }
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (low + high);
      (vertical_residual(mid) > 0.0 ? high : low) = mid;
    }
    vertical_residual(0.5 * (low + high));
    for (int i = 0; i < kFreeJointVelocities; ++i) {
      if (std::abs(data_->qfrc_inverse[i]) > 0.05) {
        throw std::runtime_error("two-leg stand: the pose at elevation " + std::to_string(elevation_rad) +
                                 " rad is not balanced (residual " + std::to_string(data_->qfrc_inverse[i]) +
                                 " on the trunk's coordinate " + std::to_string(i) + ")");
      }
    }
    if (data_->ncon != 2) {
      throw std::runtime_error("two-leg stand: the pose at elevation " + std::to_string(elevation_rad) +
                               " rad touches the ground with " + std::to_string(data_->ncon) +
                               " contacts, not the hind feet");
    }
    UprightSample sample;
    sample.elevation_rad = elevation_rad;
    for (std::size_t j = 0; j < kNumJoints; ++j) sample.torque_nm[j] = data_->qfrc_inverse[kFreeJointVelocities + j];
    // origin under the hind feet (the design places them by rolling, below)
    const Eigen::Vector3d mid = 0.5 * (site(2) + site(3));
    q[0] -= mid.x();
    q[1] -= mid.y();
    sample.position = q;
    sample.hind_feet_mid_m = Eigen::Vector3d(0.0, 0.0, mid.z());
    return sample;
  }

  UprightSample sample(double elevation_rad, double hip_height_m, std::array<double, 2> front_hip_knee,
                       const UprightDesignConfig& config) {
    UprightSample sample = equilibrium(elevation_rad, hip_height_m, front_hip_knee);
    sample.gain = gain(sample, config);
    return sample;
  }

  // front hip and knee that put the front feet at (ahead_m, height_m) from the hind feet midpoint
  std::array<double, 2> front_reach(double elevation_rad, double hip_height_m, std::array<double, 2> guess,
                                    double ahead_m, double height_m) {
    std::array<double, 2> front = guess;
    for (int iteration = 0; iteration < 50; ++iteration) {
      const UprightPosition q = equilibrium(elevation_rad, hip_height_m, front).position;
      load(q);
      mj_kinematics(model_.get(), data_.get());
      const Eigen::Vector3d hind_mid = 0.5 * (site(2) + site(3));
      const Eigen::Matrix3d r = elevated(elevation_rad).toRotationMatrix();
      const Eigen::Vector3d front_hip = q.head<3>() + r * Eigen::Vector3d(robot::kHipX, 0.0, 0.0);
      const Eigen::Vector3d target(hind_mid.x() + ahead_m, 0.0, hind_mid.z() + height_m);
      const Eigen::Vector3d in_body = r.transpose() * (target - front_hip);
      const std::array<double, 2> next = sagittal_leg_ik(in_body.x(), in_body.z());
      const bool converged = std::abs(next[0] - front[0]) + std::abs(next[1] - front[1]) < 1e-10;
      front = next;
      if (converged) break;
    }
    return front;
  }

 private:
  void load(const UprightPosition& q) {
    std::copy(q.data(), q.data() + kUprightPositionSize, data_->qpos);
    mju_zero(data_->qvel, model_->nv);
  }

  void inverse(const UprightPosition& q) {
    load(q);
    mju_zero(data_->qacc, model_->nv);
    mj_inverse(model_.get(), data_.get());
  }

  Eigen::Vector3d site(std::size_t leg) const {
    const mjtNum* p = data_->site_xpos + 3 * foot_site_[leg];
    return {p[0], p[1], p[2]};
  }

  UprightGain gain(const UprightSample& sample, const UprightDesignConfig& config) {
    load(sample.position);
    for (std::size_t j = 0; j < kNumJoints; ++j) data_->ctrl[j] = sample.torque_nm[j];
    mj_forward(model_.get(), data_.get());
    const int nx = kUprightStateSize, nu = kNumJoints;
    RowMatrix a(nx, nx), b(nx, nu);
    mjd_transitionFD(model_.get(), data_.get(), 1e-6, 1, a.data(), b.data(), nullptr, nullptr);
    Matrix q = Matrix::Zero(nx, nx);
    // tilt: the rotation error's components about the world's horizontal axes
    const Eigen::Matrix3d r = elevated(sample.elevation_rad).toRotationMatrix();
    const Eigen::Matrix3d horizontal = Eigen::Vector3d(1.0, 1.0, 0.0).asDiagonal();
    q.block<3, 3>(3, 3) = config.tilt_weight * r.transpose() * horizontal * r;
    for (int j = 0; j < kJointCount; ++j) q(kFreeJointVelocities + j, kFreeJointVelocities + j) = config.joint_weight;
    for (int i = 0; i < kFreeJointVelocities; ++i) q(nx / 2 + i, nx / 2 + i) = config.trunk_velocity_weight;
    for (int j = 0; j < kJointCount; ++j) {
      q(nx / 2 + kFreeJointVelocities + j, nx / 2 + kFreeJointVelocities + j) = config.joint_velocity_weight;
    }
    const Matrix r_torque = config.torque_weight * Matrix::Identity(nu, nu);
    const Matrix p = solve_riccati(a, b, q, r_torque);
    const Matrix btp = b.transpose() * p;
    return (r_torque + btp * b).ldlt().solve(btp * a);
  }

  // the discrete algebraic Riccati equation by the structure-preserving doubling algorithm
  // (quadratic convergence: ~40 steps where the plain iteration takes ~10^4)
  static Matrix solve_riccati(const Matrix& a, const Matrix& b, const Matrix& q, const Matrix& r) {
    const int n = static_cast<int>(a.rows());
    const Matrix identity = Matrix::Identity(n, n);
    Matrix ak = a;
    Matrix gk = b * r.ldlt().solve(b.transpose());
    Matrix hk = q;
    for (int step = 0; step < 100; ++step) {
      const Eigen::PartialPivLU<Matrix> w(identity + gk * hk);
      const Matrix wa = w.solve(ak);
      const Matrix wg = w.solve(gk);
      const Matrix h_next = hk + ak.transpose() * hk * wa;
      const Matrix g_next = gk + ak * wg * ak.transpose();
      const double change = (h_next - hk).cwiseAbs().maxCoeff() / h_next.cwiseAbs().maxCoeff();
      ak = ak * wa;
      gk = 0.5 * (g_next + g_next.transpose());
      hk = 0.5 * (h_next + h_next.transpose());
      if (!hk.allFinite()) break;
      if (change < 1e-12) return hk;
    }
    throw std::runtime_error("two-leg stand: the balance gain's Riccati equation did not converge");
  }

  std::unique_ptr<mjModel, ModelDeleter> model_;
  std::unique_ptr<mjData, DataDeleter> data_;
  std::array<int, kNumLegs> foot_site_{};
};

}  // namespace

std::vector<UprightSample> design_upright_balance(const std::string& model_path, const UprightDesignConfig& config,
                                                  double control_period_s) {
  if (config.samples < 2) throw std::runtime_error("two-leg stand: the design needs at least 2 samples");
  Designer designer(model_path, control_period_s);
  // s = 0: the front feet just above their stand spots, ahead of the hind feet
  const std::array<double, 2> crouch_front =
      designer.front_reach(config.start_elevation_rad, config.start_hip_height_m, {0.0, -1.2},
                           config.front_foot_ahead_m, config.front_lift_m);
  const std::array<double, 2> folded{config.folded_front_hip_rad, config.folded_front_knee_rad};
  std::vector<UprightSample> samples;
  samples.reserve(static_cast<std::size_t>(config.samples));
  for (int i = 0; i < config.samples; ++i) {
    const double s = static_cast<double>(i) / (config.samples - 1);
    const auto between = [s](double from, double to) { return from + (to - from) * s; };
    samples.push_back(designer.sample(between(config.start_elevation_rad, config.end_elevation_rad),
                                      between(config.start_hip_height_m, config.end_hip_height_m),
                                      {between(crouch_front[0], folded[0]), between(crouch_front[1], folded[1])},
                                      config));
  }
  // the feet roll without slipping from s = 0 on: each pose stands where its rolled feet are
  const auto roll_angle = [](const UprightSample& sample) {
    JointArray<double> q{};
    for (std::size_t j = 0; j < kNumJoints; ++j) q[j] = sample.position[7 + static_cast<Eigen::Index>(j)];
    return hind_shank_roll_angle(upright_orientation(sample.position).toRotationMatrix(), q);
  };
  const double origin_rad = roll_angle(samples.front());
  for (UprightSample& sample : samples) {
    const double shift_m = robot::kFootRadius * (roll_angle(sample) - origin_rad);
    sample.position[0] += shift_m;
    sample.hind_feet_mid_m.x() += shift_m;
    sample.rolling_origin_rad = origin_rad;
  }
  return samples;
}

}  // namespace cerebellum
