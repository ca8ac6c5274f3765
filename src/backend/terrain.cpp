#include "backend/terrain.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <stdexcept>

#include "core/number_text.hpp"
#include "core/text_file.hpp"

namespace cerebellum {
namespace {

constexpr double kPi = 3.14159265358979323846;

// the accepted ranges: what the robot's legs could meet at all, not what it can climb today
constexpr double kMaxSlopeDeg = 35.0;
constexpr double kMaxStepHeight_m = 0.3;
constexpr double kMaxStairRise_m = 0.25;
constexpr double kMinStairRun_m = 0.15;
constexpr double kMaxStairRun_m = 1.0;
constexpr double kMaxRoughAmplitude_m = 0.1;
// the features' lengths along x
constexpr double kRampLength_m = 3.0;    // each ramp, horizontally
constexpr double kPlateauLength_m = 1.5;  // between the ramps and the stairs' flights
constexpr double kStepDepth_m = 1.0;
constexpr double kStairLanding_m = 1.0;
// rough ground: 24 m of it ahead (20 m of walking and room), 5 cm cells, bumps about 0.25 m apart
constexpr double kRoughFrom_m = -1.0;
constexpr double kRoughTo_m = 23.0;
constexpr double kRoughCell_m = 0.05;
constexpr double kRoughLattice_m = 0.25;
// a rough patch's lowest point stays this far above the floor plane: drawn at the same height
// the two surfaces flicker through each other (the depth buffer cannot tell them apart)
constexpr double kRoughLift_m = 0.005;
// a rough patch from a spec rises over 1 m, so the robot starts on flat ground
constexpr double kRoughRampFrom_m = 0.5;
constexpr double kRoughRampTo_m = 1.5;
// a terrain file's limits
constexpr std::size_t kMaxTerrainFileBytes = 1 << 20;
constexpr std::size_t kMaxBoxes = 1000;
constexpr std::size_t kMaxFields = 16;
constexpr double kMaxExtent_m = 100.0;
constexpr double kMaxBoxPitchDeg = 45.0;
constexpr std::size_t kMaxFieldCells = 2'000'000;

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = text.find(separator, start);
    parts.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) return parts;
    start = end + 1;
  }
}

[[noreturn]] void bad_spec(const std::string& spec, const std::string& why) {
  throw std::invalid_argument("terrain '" + spec + "': " + why + " (accepted: " + terrain_spec_forms() + ")");
}

double spec_number(const std::string& spec, const std::string& what, const std::string& text, double lower,
                   double upper) {
  const std::optional<double> number = finite_number(text);
  if (!number) bad_spec(spec, what + " must be a number, got '" + text + "'");
  const double value = *number;
  if (!(value > lower && value <= upper)) {
    char range[96];
    std::snprintf(range, sizeof range, " must be in (%g, %g], got %g", lower, upper, value);
    bad_spec(spec, what + range);
  }
  return value;
}

// a box whose top face runs from (x0, z0) to (x1, z1) along x, kThickness thick, across the width
TerrainBox ramp_box(double x0, double z0, double x1, double z1) {
  constexpr double kThickness_m = 0.1;
  const double pitch = std::atan2(z1 - z0, x1 - x0);
  const double half_length = 0.5 * std::hypot(x1 - x0, z1 - z0);
  // the top face's centre, then half the thickness down along the face's normal (-sin, cos)
  const double top_x = 0.5 * (x0 + x1);
  const double top_z = 0.5 * (z0 + z1);
  const double h = 0.5 * kThickness_m;
  return {{top_x + h * std::sin(pitch), 0.0, top_z - h * std::cos(pitch)}, {half_length, kTerrainHalfWidth_m, h}, pitch};
}

// a block from the floor up to height across the width, from x0 to x1
TerrainBox block(double x0, double x1, double height) {
  return {{0.5 * (x0 + x1), 0.0, 0.5 * height}, {0.5 * (x1 - x0), kTerrainHalfWidth_m, 0.5 * height}, 0.0};
}

TerrainGeometry slope_geometry(double slope_deg) {
  const double rise = kRampLength_m * std::tan(slope_deg * kPi / 180.0);
  const double up_end = kTerrainStartX_m + kRampLength_m;
  const double down_start = up_end + kPlateauLength_m;
  TerrainGeometry g;
  g.boxes.push_back(ramp_box(kTerrainStartX_m, 0.0, up_end, rise));
  g.boxes.push_back(block(up_end, down_start, rise));
  g.boxes.push_back(ramp_box(down_start, rise, down_start + kRampLength_m, 0.0));
  return g;
}

TerrainGeometry stairs_geometry(double rise, double run) {
  TerrainGeometry g;
  double x = kTerrainStartX_m;
  for (int i = 1; i <= kStairSteps; ++i, x += run) g.boxes.push_back(block(x, x + run, i * rise));
  g.boxes.push_back(block(x, x + kStairLanding_m, kStairSteps * rise));
  x += kStairLanding_m;
  for (int i = kStairSteps; i >= 1; --i, x += run) g.boxes.push_back(block(x, x + run, i * rise));
  return g;
}

// 32 bits of the generator as a number in [-1, 1]: the same on every platform (the standard's
// distributions are not)
double unit_value(std::mt19937& generator) { return static_cast<double>(generator()) / 4294967295.0 * 2.0 - 1.0; }

double smoothstep(double t) { return t * t * (3.0 - 2.0 * t); }

// seeded smooth noise in [-1, 1] over the field's cells: random values on a coarser lattice,
// interpolated with a smoothstep (no steps between cells: the ground is bumpy, not broken)
TerrainHeightField rough_field(double center_x, double center_y, double half_x, double half_y, double amplitude_m,
                               std::uint32_t seed, bool ramp_in) {
  TerrainHeightField field;
  field.center_x_m = center_x;
  field.center_y_m = center_y;
  field.half_x_m = half_x;
  field.half_y_m = half_y;
  field.cols = static_cast<int>(std::lround(2.0 * half_x / kRoughCell_m)) + 1;
  field.rows = static_cast<int>(std::lround(2.0 * half_y / kRoughCell_m)) + 1;
  const int lattice_cols = static_cast<int>(std::ceil(2.0 * half_x / kRoughLattice_m)) + 2;
  const int lattice_rows = static_cast<int>(std::ceil(2.0 * half_y / kRoughLattice_m)) + 2;
  std::mt19937 generator(seed);
  std::vector<double> lattice(static_cast<std::size_t>(lattice_rows) * lattice_cols);
  for (double& value : lattice) value = unit_value(generator);
  const auto at = [&](int r, int c) { return lattice[static_cast<std::size_t>(r) * lattice_cols + c]; };
  field.heights_m.resize(static_cast<std::size_t>(field.rows) * field.cols);
  for (int r = 0; r < field.rows; ++r) {
    for (int c = 0; c < field.cols; ++c) {
      const double x_local = c * (2.0 * half_x) / (field.cols - 1);
      const double y_local = r * (2.0 * half_y) / (field.rows - 1);
      const double u = x_local / kRoughLattice_m;
      const double v = y_local / kRoughLattice_m;
      const int c0 = static_cast<int>(u);
      const int r0 = static_cast<int>(v);
      const double su = smoothstep(u - c0);
      const double sv = smoothstep(v - r0);
      const double noise = (1 - sv) * ((1 - su) * at(r0, c0) + su * at(r0, c0 + 1)) +
                           sv * ((1 - su) * at(r0 + 1, c0) + su * at(r0 + 1, c0 + 1));
      double weight = 1.0;
      if (ramp_in) {
        const double x = center_x - half_x + x_local;
        weight = smoothstep(std::clamp((x - kRoughRampFrom_m) / (kRoughRampTo_m - kRoughRampFrom_m), 0.0, 1.0));
      }
      // above the floor: the mean is the amplitude (plus the lift), the deviation from it at most
      // the amplitude
      field.heights_m[static_cast<std::size_t>(r) * field.cols + c] =
          kRoughLift_m + weight * amplitude_m * (1.0 + noise);
    }
  }
  return field;
}

// --- the terrain file -------------------------------------------------------------------------

[[noreturn]] void bad_file(const std::string& path, const YAML::Node& node, const std::string& why) {
  const YAML::Mark mark = node.Mark();
  throw std::invalid_argument("terrain file " + path + (mark.line >= 0 ? ":" + std::to_string(mark.line + 1) : "") +
                              ": " + why + " (the format: docs/terrain.md)");
}

void only_keys(const std::string& path, const YAML::Node& node, const std::set<std::string>& keys,
               const std::string& where) {
  if (!node.IsMap()) bad_file(path, node, where + " must be a map of " + std::to_string(keys.size()) + " keys");
  for (const auto& entry : node) {
    const std::string key = entry.first.as<std::string>();
    if (!keys.count(key)) {
      std::string accepted;
      for (const std::string& k : keys) accepted += (accepted.empty() ? "" : ", ") + k;
      bad_file(path, entry.first, "unknown key '" + key + "' in " + where + " (accepted: " + accepted + ")");
    }
  }
}

double file_number(const std::string& path, const YAML::Node& node, const std::string& what, double lower,
                   double upper) {
  double value = 0.0;
  try {
    value = node.as<double>();
  } catch (const YAML::Exception&) {
    bad_file(path, node, what + " must be a number");
  }
  if (!std::isfinite(value) || value < lower || value > upper) {
    char range[96];
    std::snprintf(range, sizeof range, " must be in [%g, %g], got %g", lower, upper, value);
    bad_file(path, node, what + range);
  }
  return value;
}

template <std::size_t N>
std::array<double, N> file_vector(const std::string& path, const YAML::Node& node, const std::string& what,
                                  double lower, double upper) {
  if (!node.IsSequence() || node.size() != N) bad_file(path, node, what + " must be a list of " + std::to_string(N) + " numbers");
  std::array<double, N> out{};
  for (std::size_t i = 0; i < N; ++i) out[i] = file_number(path, node[i], what + "[" + std::to_string(i) + "]", lower, upper);
  return out;
}

const YAML::Node& required(const std::string& path, const YAML::Node& parent, const YAML::Node& node,
                           const std::string& key) {
  if (!node) bad_file(path, parent, "missing key '" + key + "'");
  return node;
}

TerrainGeometry file_geometry(const std::string& path) {
  std::string error;
  const std::optional<std::string> text = read_text_file(path, kMaxTerrainFileBytes, error);
  if (!text) throw std::invalid_argument("terrain file " + path + ": " + error);
  YAML::Node root;
  try {
    root = YAML::Load(*text);
  } catch (const YAML::Exception& e) {
    throw std::invalid_argument("terrain file " + path + ":" + std::to_string(e.mark.line + 1) + ": not YAML: " + e.msg);
  }
  if (!root || root.IsNull()) throw std::invalid_argument("terrain file " + path + ": empty (the format: docs/terrain.md)");
  only_keys(path, root, {"boxes", "rough"}, "the file");
  TerrainGeometry g;
  if (const YAML::Node boxes = root["boxes"]) {
    if (!boxes.IsSequence()) bad_file(path, boxes, "'boxes' must be a list");
    if (boxes.size() > kMaxBoxes) bad_file(path, boxes, "at most " + std::to_string(kMaxBoxes) + " boxes");
    for (const YAML::Node& box : boxes) {
      only_keys(path, box, {"center_m", "half_size_m", "pitch_deg"}, "a box");
      TerrainBox b;
      b.center_m = file_vector<3>(path, required(path, box, box["center_m"], "center_m"), "center_m", -kMaxExtent_m, kMaxExtent_m);
      b.half_size_m = file_vector<3>(path, required(path, box, box["half_size_m"], "half_size_m"), "half_size_m", 1e-3, kMaxExtent_m);
      if (box["pitch_deg"]) {
        b.pitch_rad = file_number(path, box["pitch_deg"], "pitch_deg", -kMaxBoxPitchDeg, kMaxBoxPitchDeg) * kPi / 180.0;
      }
      g.boxes.push_back(b);
    }
  }
  if (const YAML::Node patches = root["rough"]) {
    if (!patches.IsSequence()) bad_file(path, patches, "'rough' must be a list");
    if (patches.size() > kMaxFields) bad_file(path, patches, "at most " + std::to_string(kMaxFields) + " rough patches");
    for (const YAML::Node& patch : patches) {
      only_keys(path, patch, {"center_m", "half_size_m", "amplitude_m", "seed"}, "a rough patch");
      const auto center = file_vector<2>(path, required(path, patch, patch["center_m"], "center_m"), "center_m", -kMaxExtent_m, kMaxExtent_m);
      const auto half = file_vector<2>(path, required(path, patch, patch["half_size_m"], "half_size_m"), "half_size_m", 0.1, kMaxExtent_m);
      const double amplitude = file_number(path, required(path, patch, patch["amplitude_m"], "amplitude_m"), "amplitude_m",
                                           1e-3, kMaxRoughAmplitude_m);
      const double seed = patch["seed"] ? file_number(path, patch["seed"], "seed", 0, 4294967295.0) : 1.0;
      const double cells = (2.0 * half[0] / kRoughCell_m + 1.0) * (2.0 * half[1] / kRoughCell_m + 1.0);
      if (cells > kMaxFieldCells) bad_file(path, patch, "a rough patch of at most " + std::to_string(kMaxFieldCells) + " 5 cm cells");
      g.fields.push_back(rough_field(center[0], center[1], half[0], half[1], amplitude, static_cast<std::uint32_t>(seed), false));
    }
  }
  return g;
}

// the highest point of a box's x-z cross-section (a rotated rectangle) on the vertical line at x
std::optional<double> box_top_at(const TerrainBox& box, double x, double y) {
  if (std::abs(y - box.center_m[1]) > box.half_size_m[1]) return std::nullopt;
  const double c = std::cos(box.pitch_rad);
  const double s = std::sin(box.pitch_rad);
  std::array<std::array<double, 2>, 4> corners{};
  const double hx = box.half_size_m[0];
  const double hz = box.half_size_m[2];
  const std::array<std::array<double, 2>, 4> local{{{-hx, -hz}, {hx, -hz}, {hx, hz}, {-hx, hz}}};
  for (std::size_t i = 0; i < 4; ++i) {
    corners[i] = {box.center_m[0] + c * local[i][0] - s * local[i][1], box.center_m[2] + s * local[i][0] + c * local[i][1]};
  }
  std::optional<double> top;
  for (std::size_t i = 0; i < 4; ++i) {
    const auto& a = corners[i];
    const auto& b = corners[(i + 1) % 4];
    const double lo = std::min(a[0], b[0]);
    const double hi = std::max(a[0], b[0]);
    if (x < lo || x > hi) continue;
    const double z = hi - lo < 1e-12 ? std::max(a[1], b[1]) : a[1] + (b[1] - a[1]) * (x - a[0]) / (b[0] - a[0]);
    top = top ? std::max(*top, z) : z;
  }
  return top;
}

// the field's surface at (x, y) as MuJoCo's collision and rays see it: each cell split into two
// triangles along its diagonal from (col, row) to (col + 1, row + 1)
std::optional<double> field_top_at(const TerrainHeightField& field, double x, double y) {
  const double u = (x - (field.center_x_m - field.half_x_m)) / (2.0 * field.half_x_m) * (field.cols - 1);
  const double v = (y - (field.center_y_m - field.half_y_m)) / (2.0 * field.half_y_m) * (field.rows - 1);
  if (u < 0.0 || v < 0.0 || u > field.cols - 1 || v > field.rows - 1) return std::nullopt;
  const int c = std::min(static_cast<int>(u), field.cols - 2);
  const int r = std::min(static_cast<int>(v), field.rows - 2);
  const double fu = u - c;
  const double fv = v - r;
  const auto h = [&](int rr, int cc) { return field.heights_m[static_cast<std::size_t>(rr) * field.cols + cc]; };
  if (fu >= fv) {  // the triangle (c, r), (c + 1, r), (c + 1, r + 1)
    return h(r, c) + fu * (h(r, c + 1) - h(r, c)) + fv * (h(r + 1, c + 1) - h(r, c + 1));
  }
  // the triangle (c, r), (c, r + 1), (c + 1, r + 1)
  return h(r, c) + fv * (h(r + 1, c) - h(r, c)) + fu * (h(r + 1, c + 1) - h(r + 1, c));
}

}  // namespace

double TerrainHeightField::top_m() const {
  return heights_m.empty() ? 0.0 : *std::max_element(heights_m.begin(), heights_m.end());
}

const char* terrain_spec_forms() {
  return "flat, slope:DEG, step:HEIGHT_M, stairs:RISE_M:RUN_M, rough:AMPLITUDE_M[:SEED], file:PATH";
}

TerrainSpec parse_terrain_spec(const std::string& text) {
  TerrainSpec spec;
  spec.text = text;
  const std::size_t colon = text.find(':');
  const std::string kind = text.substr(0, colon);
  const std::string rest = colon == std::string::npos ? "" : text.substr(colon + 1);
  const std::vector<std::string> values = split(rest, ':');
  const auto need = [&](std::size_t lower, std::size_t upper) {
    if (colon == std::string::npos || values.size() < lower || values.size() > upper) {
      bad_spec(text, "'" + kind + "' takes " + std::to_string(lower) + (upper > lower ? " or " + std::to_string(upper) : "") +
                         " value" + (upper > 1 ? "s" : "") + " after ':'");
    }
  };
  if (kind == "flat") {
    if (colon != std::string::npos) bad_spec(text, "'flat' takes no value");
    return spec;
  }
  if (kind == "slope") {
    need(1, 1);
    spec.kind = TerrainKind::Slope;
    spec.slope_deg = spec_number(text, "the slope in degrees", values[0], 0.0, kMaxSlopeDeg);
  } else if (kind == "step") {
    need(1, 1);
    spec.kind = TerrainKind::Step;
    spec.step_height_m = spec_number(text, "the step's height in m", values[0], 0.0, kMaxStepHeight_m);
  } else if (kind == "stairs") {
    need(2, 2);
    spec.kind = TerrainKind::Stairs;
    spec.stair_rise_m = spec_number(text, "the rise in m", values[0], 0.0, kMaxStairRise_m);
    spec.stair_run_m = spec_number(text, "the run in m", values[1], kMinStairRun_m - 1e-9, kMaxStairRun_m);
  } else if (kind == "rough") {
    need(1, 2);
    spec.kind = TerrainKind::Rough;
    spec.rough_amplitude_m = spec_number(text, "the amplitude in m", values[0], 0.0, kMaxRoughAmplitude_m);
    if (values.size() == 2) {
      const double seed = spec_number(text, "the seed", values[1], -1.0, 4294967295.0);
      if (seed != std::floor(seed)) bad_spec(text, "the seed must be a whole number, got '" + values[1] + "'");
      spec.rough_seed = static_cast<std::uint32_t>(seed);
    }
  } else if (kind == "file") {
    if (colon == std::string::npos || rest.empty()) bad_spec(text, "'file' takes a path after ':'");
    spec.kind = TerrainKind::File;
    spec.file = rest;
  } else {
    bad_spec(text, "unknown terrain '" + kind + "'");
  }
  return spec;
}

TerrainGeometry terrain_geometry(const TerrainSpec& spec) {
  switch (spec.kind) {
    case TerrainKind::Flat: return {};
    case TerrainKind::Slope: return slope_geometry(spec.slope_deg);
    case TerrainKind::Step: {
      TerrainGeometry g;
      g.boxes.push_back(block(kTerrainStartX_m, kTerrainStartX_m + kStepDepth_m, spec.step_height_m));
      return g;
    }
    case TerrainKind::Stairs: return stairs_geometry(spec.stair_rise_m, spec.stair_run_m);
    case TerrainKind::Rough: {
      TerrainGeometry g;
      g.fields.push_back(rough_field(0.5 * (kRoughFrom_m + kRoughTo_m), 0.0, 0.5 * (kRoughTo_m - kRoughFrom_m),
                                     kTerrainHalfWidth_m, spec.rough_amplitude_m, spec.rough_seed, true));
      return g;
    }
    case TerrainKind::File: return file_geometry(spec.file);
  }
  return {};
}

double ground_height_m(const TerrainGeometry& geometry, double x_m, double y_m) {
  double top = 0.0;  // the floor
  for (const TerrainBox& box : geometry.boxes) {
    if (const std::optional<double> z = box_top_at(box, x_m, y_m)) top = std::max(top, *z);
  }
  for (const TerrainHeightField& field : geometry.fields) {
    if (const std::optional<double> z = field_top_at(field, x_m, y_m)) top = std::max(top, *z);
  }
  return top;
}

}  // namespace cerebellum
