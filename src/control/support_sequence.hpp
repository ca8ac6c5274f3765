// Taking one leg off the ground and putting it back, in the order a standing robot must do it:
// shift the centre of mass over the other three feet, unload the leg, lift it; and backwards.
// One scalar phase s runs 0..3 for the leg in question: [0, 1] shift, [1, 2] unload, [2, 3] lift.
// Asking for another leg puts the current one down first.
#pragma once

namespace cerebellum {

struct SupportSequenceConfig {
  double shift_duration_s = 0.8;
  double unload_duration_s = 0.3;
  double lift_duration_s = 0.5;
};

class SupportSequence {
 public:
  static constexpr int kNoLeg = -1;

  explicit SupportSequence(const SupportSequenceConfig& config = {});
  // four feet on the ground, nothing moving
  void reset();
  // the leg that should be in the air (kNoLeg: all four down)
  void request(int leg);
  void advance(double dt_s);

  // the leg being shifted away from, unloaded, lifted or held up; kNoLeg when all stand
  int leg() const { return leg_; }
  // 0..1 fractions (smoothed) of the current leg's phases
  double shift() const;
  double load() const;  // 1: carries its share, 0: carries nothing
  double lift() const;
  // the leg has left (or reached) the ground: its foot is driven by position, not force
  bool in_air() const { return leg_ != kNoLeg && phase_ > 2.0; }
  // the request has been reached
  bool settled() const;
  // 0..1 of the way to the request (1 once settled)
  double progress() const;

 private:
  SupportSequenceConfig config_;
  int leg_ = kNoLeg;
  int requested_ = kNoLeg;
  double phase_ = 0.0;
};

}  // namespace cerebellum
