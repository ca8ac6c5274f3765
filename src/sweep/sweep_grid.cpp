#include "sweep/sweep_grid.hpp"

#include <stdexcept>
#include <string>

#include "core/high_level_command.hpp"

namespace cerebellum {

std::uint64_t grid_size(const SweepSpec& spec) {
  std::uint64_t size = 1;
  for (const Axis& axis : spec.axes) {
    const std::uint64_t n = axis.values.size();
    // saturate rather than overflow: a hostile file may multiply to more than 2^64
    size = n != 0 && size > kGridSizeCap / n ? kGridSizeCap : size * n;
  }
  return size;
}

std::vector<double> cell_values(const SweepSpec& spec, std::uint64_t index) {
  if (index >= grid_size(spec))
    throw std::out_of_range("cell " + std::to_string(index) + " is outside the grid of " +
                            std::to_string(grid_size(spec)) + " cells");
  std::vector<double> values(spec.axes.size());
  // mixed radix, last axis fastest
  for (std::size_t i = spec.axes.size(); i-- > 0;) {
    const std::uint64_t n = spec.axes[i].values.size();
    values[i] = spec.axes[i].values[index % n];
    index /= n;
  }
  return values;
}

Scenario cell_scenario(const SweepSpec& spec, std::uint64_t index) {
  Scenario s = spec.base;
  const std::vector<double> values = cell_values(spec, index);
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double v = values[i];
    switch (spec.axes[i].kind) {
      case AxisKind::Seed: s.seed = static_cast<unsigned>(v); break;
      case AxisKind::Gait:
        for (ScriptedCommand& c : s.commands)
          if (c.mode == static_cast<int>(ModeId::Locomotion)) c.gait = static_cast<int>(v);
        break;
      case AxisKind::PushImpulse:
        for (ScenarioPush& p : s.pushes) p.impulse_n_s = v;
        break;
      case AxisKind::PushDirection:
        for (ScenarioPush& p : s.pushes) p.direction_deg = v;
        break;
      case AxisKind::PushAt:
        for (ScenarioPush& p : s.pushes) p.at_s = v;
        break;
      case AxisKind::Terrain: s.terrain = spec.axes[i].terrains.at(static_cast<std::size_t>(v)); break;
      case AxisKind::JumpOrMotionId:
        for (ScriptedCommand& c : s.commands)
          if (c.mode == static_cast<int>(ModeId::Jump3d) || c.mode == static_cast<int>(ModeId::Motion))
            c.gait = static_cast<int>(v);
        break;
    }
  }
  return s;
}

}  // namespace cerebellum
