#include "sweep/scenario_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "loop/lockstep_client.hpp"
#include "loop/simulated_robot.hpp"
#include "modes/motion_mode.hpp"
#include "sweep/random_soak.hpp"
#include "sweep/run_watch.hpp"

namespace cerebellum {

namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;
// a fault "until cleared" explains falls until the end of the run
constexpr double kForever = 1e18;

// Drives one run tick by tick: the current command kept alive as LockstepClient does (a new
// life_count, then the same command every heartbeat), the pushes applied when due, every tick
// watched. One driver for the script and the soak, so a command is never re-sent as a new one
// when a push or the script's next event falls inside it.
class RunDriver {
 public:
  RunDriver(Mc& mc, std::vector<ScenarioPush> pushes, RunWatch& watch, RunResult& result)
      : mc_(mc), pushes_(std::move(pushes)), watch_(watch), result_(result) {
    std::stable_sort(pushes_.begin(), pushes_.end(),
                     [](const ScenarioPush& a, const ScenarioPush& b) { return a.at_s < b.at_s; });
  }

  double now_s() const { return mc_.backend().time_s(); }

  void command(HighLevelCommand c) {
    c.life_count = ++life_count_ % 128;
    current_ = c;
    has_command_ = true;
    next_send_s_ = now_s();
    ++result_.commands;
  }

  // heartbeat false: the client is silent this tick (the soak's wait after a fall)
  void tick(bool heartbeat = true) {
    if (heartbeat && has_command_ && now_s() >= next_send_s_ - 1e-9) {
      mc_.machine().submit(current_, now_s());
      next_send_s_ += LockstepClient::kHeartbeatPeriodS;
    }
    while (next_push_ < pushes_.size() && now_s() >= pushes_[next_push_].at_s - 1e-9) {
      const ScenarioPush& p = pushes_[next_push_++];
      const double force_n = p.impulse_n_s / p.length_s;
      const double heading_rad = p.direction_deg * kDegToRad;
      mc_.simulation().request_force_pulse(
          {{force_n * std::cos(heading_rad), force_n * std::sin(heading_rad), 0.0}, p.length_s});
      ++result_.pushes;
    }
    const CycleRecord& record = mc_.loop().tick();
    watch_.observe(record, mc_.simulation().ground_truth(), now_s());
  }

  void run_until(double end_s) {
    while (now_s() < end_s - 1e-9) tick();
  }

 private:
  Mc& mc_;
  std::vector<ScenarioPush> pushes_;
  std::size_t next_push_ = 0;
  RunWatch& watch_;
  RunResult& result_;
  HighLevelCommand current_;
  bool has_command_ = false;
  int life_count_ = 0;
  double next_send_s_ = 0.0;
};

HighLevelCommand scripted(const ScriptedCommand& c) {
  return high_level_command(static_cast<ModeId>(c.mode), c.gait, c.vx_m_s, c.vy_m_s, c.yaw_rate_rad_s);
}

double run_end_s(const Scenario& s) {
  if (s.end_after_last_push_s <= 0.0) return s.duration_s;
  double last_s = 0.0;
  for (const ScenarioPush& p : s.pushes) last_s = std::max(last_s, p.at_s + p.length_s);
  return last_s + s.end_after_last_push_s;
}

// the soak of bench/fault_soak_bench.cpp, with the same draws in the same order
void run_soak(const SoakSpec& soak, unsigned seed, double end_s, Mc& mc, RunDriver& driver, RunWatch& watch,
              RunResult& result) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> hold(soak.hold_min_s, soak.hold_max_s);
  std::uniform_real_distribution<double> fault_length(soak.fault_min_s, soak.fault_max_s), chance(0.0, 1.0);
  std::string previous = "the stand";
  while (driver.now_s() < end_s) {
    if (chance(rng) < soak.fault_chance) {
      const std::string fault = random_fault(rng);
      const double length_s = fault_length(rng);
      const FaultParse parsed = parse_fault(fault + " for " + std::to_string(length_s));
      // the soak's own grammar cannot be refused; if it ever is, the run must not go on as if faulted
      if (!parsed.request || !mc.faults()->request(*parsed.request).empty())
        throw std::logic_error("the soak's own fault was refused: " + fault + ": " + parsed.error);
      ++result.faults;
      watch.fault_until(driver.now_s() + length_s);
    }
    const WalkCommand walk = random_walk_command(rng, soak.gaits);
    driver.command(high_level_command(ModeId::Locomotion, walk.gait, walk.velocity.x(), walk.velocity.y(),
                                      walk.velocity.z()));
    const int falls_before = result.falls;
    const double sent_s = driver.now_s();
    char described[96];
    std::snprintf(described, sizeof described, "gait %d (%.2f m/s, %.2f m/s, %.2f rad/s)", walk.gait,
                  walk.velocity.x(), walk.velocity.y(), walk.velocity.z());
    driver.run_until(driver.now_s() + hold(rng));
    if (result.falls > falls_before) {
      char note[320];
      std::snprintf(note, sizeof note, "fall at %.2f s, %.2f s into %s, which followed %s",
                    watch.fall_s(falls_before), watch.fall_s(falls_before) - sent_s, described, previous.c_str());
      result.fall_notes.emplace_back(note);
    }
    previous = described;
    const HighLevelStatus& status = mc.machine().status();
    const bool walking = status.mode == static_cast<int>(ModeId::Locomotion) && status.gait_id == walk.gait;
    if (result.falls == falls_before && walking) continue;
    if (result.falls > falls_before) {
      // as bench/fault_soak_bench.cpp waits, so a seed runs the same there and here: silent
      // ticks until the motors are damped or off or the robot is up, at most 3 s after the fall
      const double deadline_s = watch.fall_s(falls_before) + kSafeAfterFallS;
      bool safe = false;
      while (driver.now_s() < deadline_s && !safe) {
        driver.tick(false);
        safe = damped_or_off(mc.loop().last_cycle().command) || upright(mc.simulation().ground_truth());
      }
    }
    // stand up again once the faults are over (the protection ignores commands until it has
    // ended, 0.5 s after its last cause)
    mc.faults()->request(parse_fault("clear").request.value());
    driver.command(high_level_command(ModeId::PureDamper, 0));
    driver.run_until(driver.now_s() + 0.6);
    driver.command(high_level_command(ModeId::RecoveryStand, 0));
    driver.run_until(driver.now_s() + 8.0);
    previous = "the stand";
  }
}

// in the script's last mode, or, after a named motion (62), in the stand a finished motion leaves
bool ended_in_last_commanded_mode(const Scenario& s, const RunResult& r) {
  const int last = s.commands.back().mode;
  return r.end_mode == last ||
         (last == static_cast<int>(ModeId::Motion) && r.end_mode == static_cast<int>(MotionMode::kEndMode));
}

void judge_run(const Scenario& s, RunResult& r) {
  const bool scripted_only = !s.soak.has_value();
  if (r.non_finite_commands > 0 || r.falls_not_safe > 0 || (!scripted_only && r.falls_no_fault_near > 0)) {
    r.outcome = "unsafe";
  } else if (scripted_only && r.falls > 0) {
    r.outcome = "fell";
  } else if (scripted_only && !ended_in_last_commanded_mode(s, r)) {
    r.outcome = "stopped";  // a protective stop took the robot out of the commanded mode
  } else if (s.settle_speed_m_s > 0 && r.end_speed_m_s > s.settle_speed_m_s) {
    r.outcome = "moving";
  } else {
    r.outcome = "ok";
  }
}

}  // namespace

McConfig scenario_config(const Scenario& s) {
  McConfig config = s.config_path.empty() ? default_config() : load_config(s.config_path);
  if (s.terrain) config.robot.terrain = *s.terrain;
  if (s.sensor_noise) {
    config.robot.noise.enabled = true;
    config.robot.noise.seed = s.seed;
  }
  if (s.model_error) {
    config.robot.model_error = draw_model_error(*s.model_error, s.seed);
    config.robot.noise.scale(s.model_error->sensor_noise_scale);
  }
  return config;
}

RunResult run_scenario(const Scenario& s, const RunAttachments& attachments) {
  Mc mc = make_simulated_mc(scenario_config(s), s.faults);
  if (attachments.started) attachments.started(mc);
  RunResult result;
  RunWatch watch(result);
  for (const TimedFault& f : s.faults) {
    ++result.faults;
    watch.fault_until(f.request.duration_s > 0 ? f.at_s + f.request.duration_s : kForever);
  }
  RunDriver driver(mc, s.pushes, watch, result);
  const GroundTruth start = mc.simulation().ground_truth();
  const double end_s = run_end_s(s);
  const double script_end_s = s.soak ? std::min(s.soak->start_s, end_s) : end_s;
  for (std::size_t i = 0; i < s.commands.size() && s.commands[i].at_s < script_end_s; ++i) {
    driver.run_until(s.commands[i].at_s);
    driver.command(scripted(s.commands[i]));
  }
  driver.run_until(script_end_s);
  if (s.soak) run_soak(*s.soak, s.seed, end_s, mc, driver, watch, result);
  while (watch.awaiting_safety()) driver.tick();
  watch.finish();
  const GroundTruth end = mc.simulation().ground_truth();
  result.robot_time_s = driver.now_s();
  result.end_speed_m_s = std::hypot(end.velocity_world[0], end.velocity_world[1]);
  result.distance_m = std::hypot(end.position[0] - start.position[0], end.position[1] - start.position[1]);
  result.end_mode = mc.machine().status().mode;
  judge_run(s, result);
  if (attachments.ending) attachments.ending(mc);
  return result;
}

}  // namespace cerebellum
