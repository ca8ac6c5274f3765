// The ground the simulated robot walks on, built at start from a short spec (`cerebellum sim
// --terrain SPEC`, `robot: terrain:` in the configuration) or a terrain file: flat, a slope up and
// down, one step, a flight of stairs up and down, rough ground (a seeded height field), or any
// boxes and rough patches a file lists. Pure geometry here (no MuJoCo): the model builder
// (terrain_model) turns it into geoms, and ground_height_m() answers the height under a point for
// sim_truth, tests and benchmarks from the same numbers.
//
// The robot starts at the origin facing +x: every feature lies ahead of it along +x, 1 m away.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace cerebellum {

enum class TerrainKind { Flat, Slope, Step, Stairs, Rough, File };

struct TerrainSpec {
  TerrainKind kind = TerrainKind::Flat;
  double slope_deg = 0.0;      // slope: the ramps' angle, up then down
  double step_height_m = 0.0;  // step: one step up, 1 m deep, then down
  double stair_rise_m = 0.0;   // stairs: kStairSteps steps up, a landing, the same down
  double stair_run_m = 0.0;
  double rough_amplitude_m = 0.0;  // rough: the ground's deviation from its mean height, at most
  std::uint32_t rough_seed = 1;
  std::string file;  // file: a terrain file (docs/terrain.md)
  std::string text;  // the spec as written, for messages
};

// a box of the ground: rotated by pitch_rad about the world's y axis, positive raising its top
// towards +x (a ramp up)
struct TerrainBox {
  std::array<double, 3> center_m{};
  std::array<double, 3> half_size_m{};
  double pitch_rad = 0.0;
};

// a height field over a rectangle: heights_m[row * cols + col], rows along y (from -half_y),
// cols along x (from -half_x); every height >= 0 (the floor plane lies under it)
struct TerrainHeightField {
  double center_x_m = 0.0;
  double center_y_m = 0.0;
  double half_x_m = 0.0;
  double half_y_m = 0.0;
  int rows = 0;
  int cols = 0;
  std::vector<double> heights_m;
  double top_m() const;  // the highest height (the field's elevation scale)
};

struct TerrainGeometry {
  std::vector<TerrainBox> boxes;
  std::vector<TerrainHeightField> fields;
  bool flat() const { return boxes.empty() && fields.empty(); }
};

inline constexpr int kStairSteps = 4;
// where the features start ahead of the robot, and how wide they are (the robot may drift)
inline constexpr double kTerrainStartX_m = 1.0;
inline constexpr double kTerrainHalfWidth_m = 2.0;

// throws std::invalid_argument naming the spec, the part that is wrong and what is accepted
TerrainSpec parse_terrain_spec(const std::string& text);
// the accepted forms, for help texts and errors
const char* terrain_spec_forms();

// the spec's geometry; a file's is read from disk (throws std::invalid_argument naming the file,
// the line and the key when it is malformed)
TerrainGeometry terrain_geometry(const TerrainSpec& spec);

// the height of the ground's top surface under the world point (x, y): the floor (0), the boxes'
// and the height fields' tops
double ground_height_m(const TerrainGeometry& geometry, double x_m, double y_m);

}  // namespace cerebellum
