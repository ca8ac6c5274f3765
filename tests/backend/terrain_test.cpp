// The terrains (backend/terrain, backend/terrain_model): the specs and their precise errors, the
// geometry against heights worked out by hand, ground_height_m() against MuJoCo's own ray cast on
// the compiled terrain (an independent check of every kind, the height field's triangles included),
// and the robot's model loading with a terrain.
#include "backend/terrain.hpp"

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "backend/mujoco_backend.hpp"
#include "backend/terrain_model.hpp"

namespace cerebellum {
namespace {

namespace fs = std::filesystem;

std::string error_of(const std::string& spec) {
  try {
    parse_terrain_spec(spec);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

fs::path write_file(const std::string& name, const std::string& text) {
  const fs::path path = fs::temp_directory_path() / ("cerebellum_terrain_test_" + std::to_string(::getpid()) + "_" + name);
  std::ofstream(path) << text;
  return path;
}

TEST(TerrainSpec, EachFormReadsItsValues) {
  EXPECT_EQ(parse_terrain_spec("flat").kind, TerrainKind::Flat);
  EXPECT_DOUBLE_EQ(parse_terrain_spec("slope:20").slope_deg, 20.0);
  EXPECT_DOUBLE_EQ(parse_terrain_spec("step:0.08").step_height_m, 0.08);
  const TerrainSpec stairs = parse_terrain_spec("stairs:0.1:0.28");
  EXPECT_DOUBLE_EQ(stairs.stair_rise_m, 0.1);
  EXPECT_DOUBLE_EQ(stairs.stair_run_m, 0.28);
  const TerrainSpec rough = parse_terrain_spec("rough:0.03:7");
  EXPECT_DOUBLE_EQ(rough.rough_amplitude_m, 0.03);
  EXPECT_EQ(rough.rough_seed, 7u);
  EXPECT_EQ(parse_terrain_spec("rough:0.03").rough_seed, 1u);
  EXPECT_EQ(parse_terrain_spec("file:my ground.yaml").file, "my ground.yaml");
}

TEST(TerrainSpec, AWrongSpecIsRefusedNamingWhatIsWrongAndTheAcceptedForms) {
  EXPECT_NE(error_of("hills:3").find("unknown terrain 'hills'"), std::string::npos);
  EXPECT_NE(error_of("hills:3").find("accepted: flat, slope:DEG"), std::string::npos);
  EXPECT_NE(error_of("slope").find("'slope' takes 1 value"), std::string::npos);
  EXPECT_NE(error_of("slope:40").find("the slope in degrees must be in (0, 35], got 40"), std::string::npos);
  EXPECT_NE(error_of("slope:-5").find("must be in (0, 35]"), std::string::npos);
  EXPECT_NE(error_of("step:high").find("the step's height in m must be a number, got 'high'"), std::string::npos);
  EXPECT_NE(error_of("step:nan").find("must be a number"), std::string::npos);
  EXPECT_NE(error_of("stairs:0.1").find("'stairs' takes 2 values"), std::string::npos);
  EXPECT_NE(error_of("stairs:0.1:0.05").find("the run in m must be in"), std::string::npos);
  EXPECT_NE(error_of("rough:0.5").find("the amplitude in m must be in (0, 0.1], got 0.5"), std::string::npos);
  EXPECT_NE(error_of("rough:0.03:1.5").find("the seed must be a whole number"), std::string::npos);
  EXPECT_NE(error_of("flat:1").find("'flat' takes no value"), std::string::npos);
  EXPECT_NE(error_of("file:").find("'file' takes a path"), std::string::npos);
}

TEST(TerrainGeometry, TheSlopeRisesAtItsAngleHoldsItsPlateauAndComesDownAgain) {
  const TerrainGeometry g = terrain_geometry(parse_terrain_spec("slope:20"));
  const double t = std::tan(20.0 * M_PI / 180.0);
  EXPECT_DOUBLE_EQ(ground_height_m(g, 0.0, 0.0), 0.0);
  EXPECT_NEAR(ground_height_m(g, 1.0 + 1.5, 0.3), 1.5 * t, 1e-9);
  EXPECT_NEAR(ground_height_m(g, 4.5, -1.0), 3.0 * t, 1e-9);    // the plateau (4 .. 5.5 m)
  EXPECT_NEAR(ground_height_m(g, 5.5 + 1.0, 0.0), 2.0 * t, 1e-9);  // 1 m down the far ramp
  EXPECT_DOUBLE_EQ(ground_height_m(g, 9.0, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(ground_height_m(g, 2.5, 2.5), 0.0) << "beyond its 4 m width the floor";
}

TEST(TerrainGeometry, TheStepAndTheStairsStandWhereTheirSpecsPutThem) {
  const TerrainGeometry step = terrain_geometry(parse_terrain_spec("step:0.08"));
  EXPECT_DOUBLE_EQ(ground_height_m(step, 0.99, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(ground_height_m(step, 1.5, 0.0), 0.08);
  EXPECT_DOUBLE_EQ(ground_height_m(step, 2.01, 0.0), 0.0);
  const TerrainGeometry stairs = terrain_geometry(parse_terrain_spec("stairs:0.1:0.28"));
  EXPECT_NEAR(ground_height_m(stairs, 1.0 + 0.28 * 2.5, 0.0), 0.3, 1e-12);  // the third step
  EXPECT_NEAR(ground_height_m(stairs, 1.0 + 0.28 * 4 + 0.5, 0.0), 0.4, 1e-12);  // the landing
  EXPECT_NEAR(ground_height_m(stairs, 1.0 + 0.28 * 4 + 1.0 + 0.28 * 0.5, 0.0), 0.4, 1e-12);  // first step down
  EXPECT_NEAR(ground_height_m(stairs, 1.0 + 0.28 * 8 + 1.0 - 0.1, 0.0), 0.1, 1e-12);
  EXPECT_DOUBLE_EQ(ground_height_m(stairs, 1.0 + 0.28 * 8 + 1.0 + 0.1, 0.0), 0.0);
}

TEST(TerrainGeometry, RoughGroundIsSeededStartsFlatAndStaysWithinItsAmplitudeOfItsMean) {
  const TerrainGeometry a = terrain_geometry(parse_terrain_spec("rough:0.03:7"));
  const TerrainGeometry b = terrain_geometry(parse_terrain_spec("rough:0.03:7"));
  const TerrainGeometry c = terrain_geometry(parse_terrain_spec("rough:0.03:8"));
  ASSERT_EQ(a.fields.size(), 1u);
  EXPECT_EQ(a.fields[0].heights_m, b.fields[0].heights_m);
  EXPECT_NE(a.fields[0].heights_m, c.fields[0].heights_m);
  EXPECT_NEAR(ground_height_m(a, 0.0, 0.0), 0.005, 1e-12) << "the robot starts on flat ground, 5 mm above the floor";
  EXPECT_NEAR(ground_height_m(a, 0.3, 1.0), 0.005, 1e-12);
  double lowest = 1.0;
  double highest = 0.0;
  for (double x = 2.0; x < 22.0; x += 0.013) {
    for (double y = -1.9; y < 1.9; y += 0.1) {
      const double h = ground_height_m(a, x, y);
      lowest = std::min(lowest, h);
      highest = std::max(highest, h);
    }
  }
  EXPECT_GE(lowest, 0.005);
  EXPECT_LE(highest, 0.005 + 0.06 + 1e-12);
  EXPECT_GT(highest - lowest, 0.03) << "rough, not flat";
}

// the terrain alone compiled by MuJoCo: its ray cast from above is the ground's height
class CompiledTerrain {
 public:
  explicit CompiledTerrain(const TerrainGeometry& terrain) {
    const fs::path path = write_file("alone.xml", terrain_mjcf(terrain, ""));
    char error[1000] = "";
    model_ = mj_loadXML(path.c_str(), nullptr, error, sizeof error);
    fs::remove(path);
    if (model_ == nullptr) throw std::runtime_error(error);
    fill_terrain_heights(model_, terrain);
    data_ = mj_makeData(model_);
    mj_forward(model_, data_);
  }
  ~CompiledTerrain() {
    mj_deleteData(data_);
    mj_deleteModel(model_);
  }
  double ray_height(double x, double y) const {
    constexpr double kFrom_m = 5.0;
    const mjtNum from[3] = {x, y, kFrom_m};
    const mjtNum down[3] = {0, 0, -1};
    int geom = -1;
    const mjtNum distance = mj_ray(model_, data_, from, down, nullptr, 1, -1, &geom);
    return distance < 0 ? 0.0 : std::max(0.0, kFrom_m - distance);  // nothing hit: the floor
  }

 private:
  mjModel* model_ = nullptr;
  mjData* data_ = nullptr;
};

void expect_ground_matches_mujoco(const std::string& spec_text) {
  const TerrainGeometry terrain = terrain_geometry(parse_terrain_spec(spec_text));
  const CompiledTerrain compiled(terrain);
  std::mt19937 generator(3);
  std::uniform_real_distribution<double> along(-0.5, 23.0);
  std::uniform_real_distribution<double> across(-2.5, 2.5);
  double worst = 0.0;
  for (int i = 0; i < 3000; ++i) {
    const double x = along(generator);
    const double y = across(generator);
    worst = std::max(worst, std::abs(ground_height_m(terrain, x, y) - compiled.ray_height(x, y)));
  }
  EXPECT_LT(worst, 1e-5) << spec_text << ": ground_height_m against MuJoCo's ray cast";
}

TEST(TerrainModel, TheGroundHeightIsWhereMujocosRayMeetsTheCompiledTerrainForEveryKind) {
  expect_ground_matches_mujoco("slope:20");
  expect_ground_matches_mujoco("step:0.08");
  expect_ground_matches_mujoco("stairs:0.1:0.28");
  expect_ground_matches_mujoco("rough:0.03:7");
}

TEST(TerrainFile, BoxesAndRoughPatchesFromAFileMatchMujocoToo) {
  const fs::path file = write_file("ground.yaml",
                                   "# a kerb and a tilted board beside a rough patch\n"
                                   "boxes:\n"
                                   "  - {center_m: [1.5, 0.0, 0.03], half_size_m: [0.2, 1.0, 0.03]}\n"
                                   "  - {center_m: [3.0, 0.5, 0.05], half_size_m: [0.6, 0.4, 0.02], pitch_deg: 12}\n"
                                   "rough:\n"
                                   "  - {center_m: [6.0, 0.0], half_size_m: [1.5, 1.0], amplitude_m: 0.02, seed: 5}\n");
  const TerrainSpec spec = parse_terrain_spec("file:" + file.string());
  const TerrainGeometry terrain = terrain_geometry(spec);
  EXPECT_EQ(terrain.boxes.size(), 2u);
  EXPECT_EQ(terrain.fields.size(), 1u);
  EXPECT_DOUBLE_EQ(ground_height_m(terrain, 1.5, 0.0), 0.06);
  const CompiledTerrain compiled(terrain);
  for (double x = 0.0; x < 8.0; x += 0.0137) {
    for (double y = -1.2; y < 1.2; y += 0.107) {  // off the patches' exact edges
      ASSERT_NEAR(ground_height_m(terrain, x, y), compiled.ray_height(x, y), 1e-5) << x << ", " << y;
    }
  }
  fs::remove(file);
}

std::string file_error(const std::string& text) {
  const fs::path file = write_file("bad.yaml", text);
  std::string error;
  try {
    terrain_geometry(parse_terrain_spec("file:" + file.string()));
  } catch (const std::invalid_argument& e) {
    error = e.what();
  }
  fs::remove(file);
  return error;
}

TEST(TerrainFile, AMalformedFileIsRefusedWithItsLineAndTheKey) {
  EXPECT_NE(file_error("boxes:\n  - {center_m: [1, 0, 0], half_size_m: [1, 1, 1], colour: red}\n")
                .find(":2: unknown key 'colour' in a box (accepted: center_m, half_size_m, pitch_deg)"),
            std::string::npos);
  EXPECT_NE(file_error("boxes:\n  - {center_m: [1, 0], half_size_m: [1, 1, 1]}\n")
                .find("center_m must be a list of 3 numbers"),
            std::string::npos);
  EXPECT_NE(file_error("boxes:\n  - {half_size_m: [1, 1, 1]}\n").find("missing key 'center_m'"), std::string::npos);
  EXPECT_NE(file_error("rough:\n  - {center_m: [1, 0], half_size_m: [1, 1], amplitude_m: 0.5}\n")
                .find("amplitude_m must be in [0.001, 0.1], got 0.5"),
            std::string::npos);
  EXPECT_NE(file_error("hills: 3\n").find("unknown key 'hills' in the file"), std::string::npos);
  EXPECT_NE(file_error("boxes: [\n").find("not YAML"), std::string::npos);
  EXPECT_NE(file_error("").find("empty"), std::string::npos);
  EXPECT_NE(file_error("boxes:\n  - {center_m: [.nan, 0, 0], half_size_m: [1, 1, 1]}\n").find("center_m[0] must be in"),
            std::string::npos);
}

TEST(TerrainModel, TheRobotsModelLoadsWithATerrainAndTheTruthReportsTheGroundUnderTheTrunk) {
  MujocoBackendConfig config;
  config.model_path = std::string(CEREBELLUM_MODEL_DIR) + "/cyberdog2.xml";
  config.terrain = parse_terrain_spec("step:0.08");
  MujocoBackend backend(config);
  EXPECT_DOUBLE_EQ(backend.ground_truth().ground_height_m, 0.0);
  backend.set_base_pose({1.5, 0.0, 0.4}, {1, 0, 0, 0});
  EXPECT_DOUBLE_EQ(backend.ground_truth().ground_height_m, 0.08);
  EXPECT_GE(mj_name2id(backend.model(), mjOBJ_GEOM, "terrain_box_0"), 0);
}

}  // namespace
}  // namespace cerebellum
