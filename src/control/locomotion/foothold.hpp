// Where a swing foot lands (Raibert heuristic with velocity feedback and a centrifugal term).
#pragma once

#include <Eigen/Core>

namespace cerebellum {

struct FootholdConfig {
  double velocity_gain = 0.1;  // k in k (v - v_des)
  // clamp of the offset from the hip in the heading frame: what a leg reaches at standing height
  // (thigh 0.12 + shank 0.174 at 0.25 m height reach 0.15 m forward; the abad range ~0.08 m sideways)
  double max_offset_forward_m = 0.15;
  double max_offset_lateral_m = 0.08;
  // a push (velocity error above this) is caught with steps as far as the leg stretches
  double push_velocity_error_m_s = 0.5;
  double max_offset_push_m = 0.3;
  // k sideways while gait 1's trot catches a push on the spot (catching_push): with the walking k
  // (0.1) the feet landing far out under a body moving sideways at 1-1.9 m/s tripped it over the
  // diagonal (25 N s from the left fell at 3 of 15 moments of the push sweep, from the front it
  // ended in the footpos watch at all 15); 0.05 and 0.08 fell more than 0.07 (docs/benchmarks.md)
  double catch_lateral_velocity_gain = 0.07;
};

// hip_world: the hip's position under the body at touchdown (world, on the ground plane);
// velocities in the world frame; heading (yaw) of the body; stance duration in seconds; body
// height for the centrifugal term. velocity_desired_before: the desired velocity of about a second
// earlier (low-passed). The footholds reach as for a push only when the body is that far from both:
// a push moves the body away from a steady command, a command change moves the command away from
// the body (a slow trot taking over a body still backing at 0.7 m/s, commanded forward, placed its
// front foot under the trunk's centre and rolled over, soak seed 1380). catching_push: the trot is
// gait 1's catch of a push, which corrects a push's sideways error with catch_lateral_velocity_gain
Eigen::Vector3d raibert_foothold(const Eigen::Vector3d& hip_world, const Eigen::Vector3d& velocity,
                                 const Eigen::Vector3d& velocity_desired,
                                 const Eigen::Vector3d& velocity_desired_before, double yaw_rate_desired, double yaw,
                                 double stance_duration_s, double body_height_m, const FootholdConfig& config,
                                 bool catching_push = false);

}  // namespace cerebellum
