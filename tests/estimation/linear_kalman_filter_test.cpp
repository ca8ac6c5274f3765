// The linear Kalman filter against synthetic motion with known truth and against the closed-form
// covariance of integrated white acceleration.
#include "estimation/linear_kalman_filter.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

constexpr double kDt = 0.002;

std::array<Eigen::Vector3d, kNumLegs> planted_feet() {
  return {Eigen::Vector3d(0.16, -0.13, 0.0), Eigen::Vector3d(0.16, 0.13, 0.0), Eigen::Vector3d(-0.16, -0.13, 0.0),
          Eigen::Vector3d(-0.16, 0.13, 0.0)};
}

// what the legs would measure for a trunk at p moving at v over feet that stand still
LegObservations observe(const Eigen::Vector3d& p, const Eigen::Vector3d& v,
                        const std::array<Eigen::Vector3d, kNumLegs>& feet, const LinearKalmanFilter::Trust& trust) {
  LegObservations legs;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    legs[leg].foot_relative_world = feet[leg] - p;
    legs[leg].body_velocity_world = v;
    legs[leg].trust = trust[leg];
  }
  return legs;
}

Eigen::Vector3d gaussian(std::mt19937& rng, double sigma) {
  std::normal_distribution<double> normal(0.0, sigma);
  return {normal(rng), normal(rng), normal(rng)};
}

constexpr LinearKalmanFilter::Trust kAllPlanted{1.0, 1.0, 1.0, 1.0};

// constant velocity over planted feet; returns the velocity error after 2 s
double constant_velocity_error(const LinearKalmanFilterConfig& config, Eigen::Vector3d* position_error) {
  const Eigen::Vector3d p0(0.0, 0.0, 0.25);
  const Eigen::Vector3d v_true(0.4, -0.25, 0.05);
  const auto feet = planted_feet();
  LinearKalmanFilter filter(config);
  filter.initialize(p0, Eigen::Vector3d::Zero(), feet);
  std::mt19937 rng(7);
  for (int k = 1; k <= 1000; ++k) {
    const Eigen::Vector3d p = p0 + v_true * (k * kDt);
    EXPECT_TRUE(filter.predict(gaussian(rng, 0.05), kDt, kAllPlanted));
    LegObservations legs = observe(p, v_true, feet, kAllPlanted);
    for (LegObservation& leg : legs) {
      leg.foot_relative_world += gaussian(rng, 1e-3);
      leg.body_velocity_world += gaussian(rng, 0.02);
    }
    EXPECT_TRUE(filter.correct(legs));
  }
  *position_error = filter.position() - (p0 + v_true * (1000 * kDt));
  return (filter.velocity() - v_true).norm();
}

TEST(LinearKalmanFilter, ConvergesToTheTrueVelocityWithAllFeetPlanted) {
  Eigen::Vector3d position_error;
  EXPECT_LT(constant_velocity_error({}, &position_error), 0.01);
  EXPECT_LT(position_error.norm(), 0.005);
}

TEST(LinearKalmanFilter, FindsTheVelocityFromFootPositionsAlone) {
  // velocity measurements made worthless: the velocity must come from the moving foot offsets
  LinearKalmanFilterConfig config;
  config.foot_velocity_sigma_m_s = 1e3;
  Eigen::Vector3d position_error;
  EXPECT_LT(constant_velocity_error(config, &position_error), 0.02);
  EXPECT_LT(position_error.norm(), 0.005);
}

// the trunk at rest by the IMU while every planted leg says it moves at 0.3 m/s (feet pushing in
// the air while the plan says stance: positions and velocities agree, within the innovation
// gate) for 20 ms; the estimated speed
double speed_after_legs_disagree_with_the_imu(const LinearKalmanFilterConfig& config,
                                              std::uint64_t* limited_corrections = nullptr) {
  const Eigen::Vector3d p(0.0, 0.0, 0.25);
  const auto feet = planted_feet();
  LinearKalmanFilter filter(config);
  filter.initialize(p, Eigen::Vector3d::Zero(), feet);
  for (int k = 0; k < 10; ++k) {
    EXPECT_TRUE(filter.predict(Eigen::Vector3d::Zero(), kDt, kAllPlanted));
    const Eigen::Vector3d v_legs(0.3, 0.0, 0.0);
    EXPECT_TRUE(filter.correct(observe(p + v_legs * ((k + 1) * kDt), v_legs, feet, kAllPlanted)));
  }
  if (limited_corrections != nullptr) *limited_corrections = filter.limited_velocity_corrections();
  return filter.velocity().norm();
}

TEST(LinearKalmanFilter, TheLegsMoveTheVelocityNoFasterThanTheConfiguredRate) {
  // unsure of its velocity (as after a flight): the plain update would follow the legs at once
  LinearKalmanFilterConfig config;
  config.initial_velocity_sigma_m_s = 1.0;
  const double limit_m_s = config.max_leg_velocity_correction_m_s2 * 10 * kDt;
  std::uint64_t limited = 0;
  const double speed_m_s = speed_after_legs_disagree_with_the_imu(config, &limited);
  EXPECT_GT(limited, 0u);
  EXPECT_LE(speed_m_s, limit_m_s + 1e-12);
  EXPECT_GT(speed_m_s, 0.99 * limit_m_s);  // the legs still pull, at the limit
  // the plain Kalman update follows the legs much further: the limit above can fail
  LinearKalmanFilterConfig plain = config;
  plain.max_leg_velocity_correction_m_s2 = std::numeric_limits<double>::infinity();
  EXPECT_GT(speed_after_legs_disagree_with_the_imu(plain), 2.0 * limit_m_s);
}

TEST(LinearKalmanFilter, TheLegsStillRemoveAConstantImuBias) {
  // the IMU reads 0.4 m/s^2 forward for a trunk at rest over planted feet for 2 s: integrated
  // alone, 0.8 m/s of error
  const Eigen::Vector3d p(0.0, 0.0, 0.25);
  const auto feet = planted_feet();
  LinearKalmanFilter filter;
  filter.initialize(p, Eigen::Vector3d::Zero(), feet);
  std::mt19937 rng(5);
  for (int k = 0; k < 1000; ++k) {
    ASSERT_TRUE(filter.predict(Eigen::Vector3d(0.4, 0.0, 0.0), kDt, kAllPlanted));
    LegObservations legs = observe(p, Eigen::Vector3d::Zero(), feet, kAllPlanted);
    for (LegObservation& leg : legs) leg.body_velocity_world += gaussian(rng, 0.02);
    ASSERT_TRUE(filter.correct(legs));
  }
  EXPECT_LT(filter.velocity().norm(), 0.02);
}

TEST(LinearKalmanFilter, PredictionMatchesClosedFormIntegration) {
  LinearKalmanFilterConfig config;
  config.accel_noise_density = 0.7;
  config.initial_position_sigma_m = 0.03;
  config.initial_velocity_sigma_m_s = 0.2;
  config.initial_foot_sigma_m = 0.01;
  const Eigen::Vector3d p0(0.1, -0.2, 0.3), v0(0.5, 0.0, -0.1), a(0.3, -0.6, 1.2);
  const LinearKalmanFilter::Trust trust{1.0, 0.0, 0.5, 0.25};
  LinearKalmanFilter filter(config);
  filter.initialize(p0, v0, planted_feet());
  // uneven steps: exact discretisation makes the result depend on the total time only
  double t = 0.0;
  for (int k = 0; k < 900; ++k) {
    const double dt = (k % 3 == 0) ? 0.001 : 0.0025;
    ASSERT_TRUE(filter.predict(a, dt, trust));
    t += dt;
  }
  // state: p0 + v0 t + a t^2 / 2, feet unmoved
  EXPECT_TRUE(filter.position().isApprox(p0 + v0 * t + 0.5 * a * t * t, 1e-12));
  EXPECT_TRUE(filter.velocity().isApprox(v0 + a * t, 1e-12));
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) EXPECT_EQ(filter.foot_position(leg), planted_feet()[leg]);

  // covariance of x(t) = x0 + v0 t + double integral of white noise, per axis
  const double q = 0.7 * 0.7, sp2 = 0.03 * 0.03, sv2 = 0.2 * 0.2;
  LinearKalmanFilter::Covariance expected = LinearKalmanFilter::Covariance::Zero();
  for (int k = 0; k < 3; ++k) {
    expected(k, k) = sp2 + t * t * sv2 + q * t * t * t / 3.0;
    expected(k, k + 3) = expected(k + 3, k) = t * sv2 + q * t * t / 2.0;
    expected(k + 3, k + 3) = sv2 + q * t;
  }
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const double rate = trust[leg] * config.stance_foot_drift * config.stance_foot_drift +
                        (1.0 - trust[leg]) * config.swing_foot_drift * config.swing_foot_drift;
    for (int k = 0; k < 3; ++k) expected(6 + 3 * leg + k, 6 + 3 * leg + k) = 0.01 * 0.01 + rate * t;
  }
  const LinearKalmanFilter::Covariance& p = filter.covariance();
  for (int i = 0; i < LinearKalmanFilter::kStateSize; ++i) {
    for (int j = 0; j < LinearKalmanFilter::kStateSize; ++j) {
      EXPECT_NEAR(p(i, j), expected(i, j), 1e-12 + 1e-10 * std::abs(expected(i, j))) << "P(" << i << ", " << j << ")";
    }
  }
}

TEST(LinearKalmanFilter, CorrectionEqualsTheTextbookBatchUpdate) {
  // a correlated prior from some prediction, then one correction with all legs at mixed trust,
  // against x + K (z - H x), P - K H P with K = P H^T (H P H^T + R)^-1 written out densely
  const LinearKalmanFilterConfig config;
  LinearKalmanFilter filter(config);
  filter.initialize(Eigen::Vector3d(0.01, -0.02, 0.26), Eigen::Vector3d(0.1, 0.0, 0.0), planted_feet());
  const LinearKalmanFilter::Trust trust{1.0, 0.3, 0.0, 0.8};
  for (int k = 0; k < 50; ++k) filter.predict(Eigen::Vector3d(0.2, -0.1, 0.05), kDt, trust);
  std::mt19937 rng(3);
  const Eigen::Vector3d p_true(0.0, 0.0, 0.25), v_true(0.05, 0.02, 0.0);
  LegObservations legs = observe(p_true, v_true, planted_feet(), trust);
  for (LegObservation& leg : legs) {
    leg.foot_relative_world += gaussian(rng, 0.01);
    leg.body_velocity_world += gaussian(rng, 0.05);
    leg.ground_height_m = gaussian(rng, 0.03).z();  // a ground that is not flat at z = 0
  }
  const Eigen::VectorXd x0 = filter.state();
  const Eigen::MatrixXd p0 = filter.covariance();

  const int n = LinearKalmanFilter::kStateSize, m = 7 * static_cast<int>(kNumLegs);
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(m, n);
  Eigen::VectorXd z = Eigen::VectorXd::Zero(m);
  Eigen::VectorXd r = Eigen::VectorXd::Zero(m);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const int row = 7 * static_cast<int>(leg), foot = 6 + 3 * static_cast<int>(leg);
    const double scale = 1.0 / std::max(trust[leg], config.min_trust);
    for (int k = 0; k < 3; ++k) {
      h(row + k, k) = -1.0;
      h(row + k, foot + k) = 1.0;
      z(row + k) = legs[leg].foot_relative_world[k];
      r(row + k) = std::pow(config.foot_relative_sigma_m, 2) * scale;
      h(row + 3 + k, 3 + k) = 1.0;
      z(row + 3 + k) = legs[leg].body_velocity_world[k];
      r(row + 3 + k) = std::pow(config.foot_velocity_sigma_m_s, 2) * scale;
    }
    h(row + 6, foot + 2) = 1.0;
    z(row + 6) = legs[leg].ground_height_m;
    r(row + 6) = std::pow(config.foot_height_sigma_m, 2) * scale;
  }
  const Eigen::MatrixXd s_inverse = (h * p0 * h.transpose() + Eigen::MatrixXd(r.asDiagonal())).inverse();
  const Eigen::MatrixXd gain = p0 * h.transpose() * s_inverse;
  const Eigen::VectorXd x_expected = x0 + gain * (z - h * x0);
  const Eigen::MatrixXd p_expected = p0 - gain * h * p0;

  ASSERT_TRUE(filter.correct(legs));
  EXPECT_LT((Eigen::VectorXd(filter.state()) - x_expected).cwiseAbs().maxCoeff(), 1e-10);
  const double p_scale = p0.cwiseAbs().maxCoeff();
  EXPECT_LT((Eigen::MatrixXd(filter.covariance()) - p_expected).cwiseAbs().maxCoeff(), 1e-10 * p_scale);
  // the correction did something: the check above can fail
  EXPECT_GT((x_expected - x0).norm(), 1e-3);
}

TEST(LinearKalmanFilter, CovarianceStaysSymmetricPositiveDefiniteOver10000Steps) {
  LinearKalmanFilter filter;
  const auto feet = planted_feet();
  filter.initialize(Eigen::Vector3d(0, 0, 0.25), Eigen::Vector3d::Zero(), feet);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst_asymmetry = 0.0;
  double smallest_eigenvalue = 1.0;
  for (int k = 0; k < 10000; ++k) {
    // a trot with trust ramps, a flight phase now and then, and random partial trust
    LinearKalmanFilter::Trust trust;
    const double phase = std::fmod(k * kDt, 0.36) / 0.36;
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      const bool diagonal_a = leg == 0 || leg == 3;
      const double leg_phase = std::fmod(phase + (diagonal_a ? 0.0 : 0.5), 1.0);
      trust[leg] = leg_phase < 0.5 ? std::clamp(std::min(leg_phase, 0.5 - leg_phase) / 0.05, 0.0, 1.0) : 0.0;
      if (k % 997 < 40) trust[leg] = 0.0;
      if (k % 1499 < 60) trust[leg] = unit(rng);
    }
    ASSERT_TRUE(filter.predict(gaussian(rng, 2.0), kDt, trust));
    LegObservations legs = observe(Eigen::Vector3d(0, 0, 0.25), Eigen::Vector3d::Zero(), feet, trust);
    for (LegObservation& leg : legs) {
      leg.foot_relative_world += gaussian(rng, 0.01);
      leg.body_velocity_world += gaussian(rng, 0.1);
    }
    ASSERT_TRUE(filter.correct(legs));
    const LinearKalmanFilter::Covariance& p = filter.covariance();
    worst_asymmetry = std::max(worst_asymmetry, (p - p.transpose()).cwiseAbs().maxCoeff());
    if (k % 10 == 0) {
      Eigen::SelfAdjointEigenSolver<LinearKalmanFilter::Covariance> eigen(p, Eigen::EigenvaluesOnly);
      smallest_eigenvalue = std::min(smallest_eigenvalue, eigen.eigenvalues().minCoeff());
    }
    ASSERT_EQ(Eigen::LLT<LinearKalmanFilter::Covariance>(p).info(), Eigen::Success) << "step " << k;
  }
  EXPECT_EQ(worst_asymmetry, 0.0);
  EXPECT_GT(smallest_eigenvalue, 0.0);
  EXPECT_TRUE(filter.state().allFinite());
}

TEST(LinearKalmanFilter, SwingFootFloatsWithoutMovingTheTrunk) {
  // the trunk stands still; leg 0's foot swings 0.1 m forward over 0.2 s
  const Eigen::Vector3d p(0.0, 0.0, 0.25);
  auto run = [&](double swing_trust, Eigen::Vector3d* foot_estimate) {
    auto feet = planted_feet();
    const LinearKalmanFilter::Trust trust{swing_trust, 1.0, 1.0, 1.0};
    LinearKalmanFilter filter;
    filter.initialize(p, Eigen::Vector3d::Zero(), feet);
    for (int k = 1; k <= 100; ++k) {
      feet[0] = planted_feet()[0] + Eigen::Vector3d(0.1 * k / 100.0, 0.0, 0.03 * std::sin(robot::kPi * k / 100.0));
      filter.predict(Eigen::Vector3d::Zero(), kDt, trust);
      filter.correct(observe(p, Eigen::Vector3d::Zero(), feet, trust));
    }
    *foot_estimate = filter.foot_position(0) - feet[0];
    return (filter.position() - p).norm();
  };
  Eigen::Vector3d foot_error;
  EXPECT_LT(run(0.0, &foot_error), 1e-3);
  EXPECT_LT(foot_error.norm(), 0.02);  // a floating foot trails its kinematics a little
  // the same foot fully trusted drags the trunk along: the check above can fail
  EXPECT_GT(run(1.0, &foot_error), 5e-3);
}

TEST(LinearKalmanFilter, NonFiniteInputIsSkippedAndTheFilterStaysFinite) {
  LinearKalmanFilter filter;
  EXPECT_FALSE(filter.valid());
  EXPECT_FALSE(filter.predict(Eigen::Vector3d::Zero(), kDt, kAllPlanted));  // not initialised
  const auto feet = planted_feet();
  const Eigen::Vector3d p(0.0, 0.0, 0.25);
  filter.initialize(p, Eigen::Vector3d::Zero(), feet);
  ASSERT_TRUE(filter.predict(Eigen::Vector3d::Zero(), kDt, kAllPlanted));
  ASSERT_TRUE(filter.correct(observe(p, Eigen::Vector3d::Zero(), feet, kAllPlanted)));
  const LinearKalmanFilter::StateVector x_before = filter.state();
  const LinearKalmanFilter::Covariance p_before = filter.covariance();

  const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
  LegObservations bad = observe(p, Eigen::Vector3d::Zero(), feet, kAllPlanted);
  bad[2].foot_relative_world.y() = nan;
  EXPECT_FALSE(filter.correct(bad));
  EXPECT_FALSE(filter.valid());
  bad = observe(p, Eigen::Vector3d::Zero(), feet, kAllPlanted);
  bad[1].body_velocity_world.x() = inf;
  EXPECT_FALSE(filter.correct(bad));
  bad = observe(p, Eigen::Vector3d::Zero(), feet, kAllPlanted);
  bad[3].trust = nan;
  EXPECT_FALSE(filter.correct(bad));
  EXPECT_FALSE(filter.predict(Eigen::Vector3d(0, nan, 0), kDt, kAllPlanted));
  EXPECT_FALSE(filter.predict(Eigen::Vector3d::Zero(), inf, kAllPlanted));
  EXPECT_FALSE(filter.predict(Eigen::Vector3d::Zero(), -kDt, kAllPlanted));
  EXPECT_FALSE(filter.predict(Eigen::Vector3d::Zero(), kDt, {1.0, nan, 1.0, 1.0}));
  // nothing changed
  EXPECT_EQ(filter.state(), x_before);
  EXPECT_EQ(filter.covariance(), p_before);

  // the next good step is taken and valid again
  EXPECT_TRUE(filter.predict(Eigen::Vector3d::Zero(), kDt, kAllPlanted));
  EXPECT_TRUE(filter.correct(observe(p, Eigen::Vector3d::Zero(), feet, kAllPlanted)));
  EXPECT_TRUE(filter.valid());
  EXPECT_TRUE(filter.state().allFinite());

  filter.reset();
  EXPECT_FALSE(filter.initialized());
  EXPECT_FALSE(filter.correct(observe(p, Eigen::Vector3d::Zero(), feet, kAllPlanted)));
}

}  // namespace
}  // namespace cerebellum

namespace cerebellum {
namespace {

// trunk at rest on planted feet while one leg reports a velocity 1.5 m/s off (a slipping foot)
Eigen::Vector3d velocity_with_one_slipping_leg(const LinearKalmanFilterConfig& config, std::uint64_t* gated) {
  const Eigen::Vector3d p(0.0, 0.0, 0.25);
  const auto feet = planted_feet();
  LinearKalmanFilter filter(config);
  filter.initialize(p, Eigen::Vector3d::Zero(), feet);
  for (int k = 0; k < 100; ++k) {
    filter.predict(Eigen::Vector3d::Zero(), kDt, kAllPlanted);
    LegObservations legs = observe(p, Eigen::Vector3d::Zero(), feet, kAllPlanted);
    legs[2].body_velocity_world = Eigen::Vector3d(1.5, 0.0, 0.0);
    filter.correct(legs);
  }
  *gated = filter.gated_velocity_measurements();
  return filter.velocity();
}

TEST(LinearKalmanFilter, InnovationGateSetsAsideASlippingLegsVelocity) {
  std::uint64_t gated = 0;
  const Eigen::Vector3d gated_velocity = velocity_with_one_slipping_leg(LinearKalmanFilterConfig{}, &gated);
  EXPECT_GE(gated, 90u);
  EXPECT_LT(gated_velocity.norm(), 0.05);
  // without the gate the same leg drags the estimate along
  LinearKalmanFilterConfig ungated;
  ungated.velocity_gate_chi2 = std::numeric_limits<double>::infinity();
  const Eigen::Vector3d ungated_velocity = velocity_with_one_slipping_leg(ungated, &gated);
  EXPECT_EQ(gated, 0u);
  EXPECT_GT(ungated_velocity.x(), 0.2);
}

}  // namespace
}  // namespace cerebellum
