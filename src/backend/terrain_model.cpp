#include "backend/terrain_model.hpp"

#include <mujoco/mujoco.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace cerebellum {
namespace {

namespace fs = std::filesystem;

// the depth of a height field's base below its lowest point (MuJoCo needs a solid under it)
constexpr double kFieldBase_m = 0.05;

std::string field_name(std::size_t i) { return "terrain_field_" + std::to_string(i); }

// a temporary folder of our own, removed when done (mkdtemp: no other process gets the same)
class TemporaryFolder {
 public:
  TemporaryFolder() {
    std::string pattern = (fs::temp_directory_path() / "cerebellum-terrain-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("terrain: cannot make a temporary folder in " + fs::temp_directory_path().string());
    path_ = pattern;
  }
  ~TemporaryFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

}  // namespace

std::string terrain_mjcf(const TerrainGeometry& terrain, const std::string& include_file) {
  std::ostringstream xml;
  xml.precision(9);
  xml << "<mujoco model=\"terrain\">\n";
  if (!include_file.empty()) xml << "  <include file=\"" << include_file << "\"/>\n";
  // a greener checker than the floor's, uniform on every face, so steps and ramps read at a glance
  xml << "  <asset>\n"
         "    <texture name=\"terrain_grid\" type=\"2d\" builtin=\"checker\" rgb1=\"0.40 0.47 0.42\" "
         "rgb2=\"0.50 0.57 0.52\" width=\"512\" height=\"512\"/>\n"
         "    <material name=\"terrain\" texture=\"terrain_grid\" texrepeat=\"4 4\" texuniform=\"true\"/>\n";
  for (std::size_t i = 0; i < terrain.fields.size(); ++i) {
    const TerrainHeightField& f = terrain.fields[i];
    xml << "    <hfield name=\"" << field_name(i) << "\" nrow=\"" << f.rows << "\" ncol=\"" << f.cols << "\" size=\""
        << f.half_x_m << " " << f.half_y_m << " " << std::max(f.top_m(), 1e-6) << " " << kFieldBase_m << "\"/>\n";
  }
  xml << "  </asset>\n  <worldbody>\n";
  // every terrain geom meets the robot's (contype 1 against the robot's conaffinity 1), as the floor
  const char* contact = "contype=\"1\" conaffinity=\"1\" condim=\"3\" friction=\"0.8 0.02 0.01\" material=\"terrain\"";
  for (std::size_t i = 0; i < terrain.boxes.size(); ++i) {
    const TerrainBox& b = terrain.boxes[i];
    // a rotation about y by a positive angle turns +x down: a ramp up turns by -pitch. As a
    // quaternion, not euler angles, whose unit depends on the including model's compiler
    const double half_turn = -0.5 * b.pitch_rad;
    xml << "    <geom name=\"terrain_box_" << i << "\" type=\"box\" pos=\"" << b.center_m[0] << " " << b.center_m[1] << " "
        << b.center_m[2] << "\" size=\"" << b.half_size_m[0] << " " << b.half_size_m[1] << " " << b.half_size_m[2]
        << "\" quat=\"" << std::cos(half_turn) << " 0 " << std::sin(half_turn) << " 0\" " << contact << "/>\n";
  }
  for (std::size_t i = 0; i < terrain.fields.size(); ++i) {
    const TerrainHeightField& f = terrain.fields[i];
    xml << "    <geom name=\"terrain_field_" << i << "\" type=\"hfield\" hfield=\"" << field_name(i) << "\" pos=\""
        << f.center_x_m << " " << f.center_y_m << " 0\" " << contact << "/>\n";
  }
  xml << "  </worldbody>\n</mujoco>\n";
  return xml.str();
}

void fill_terrain_heights(mjModel* model, const TerrainGeometry& terrain) {
  for (std::size_t i = 0; i < terrain.fields.size(); ++i) {
    const TerrainHeightField& f = terrain.fields[i];
    const int id = mj_name2id(model, mjOBJ_HFIELD, field_name(i).c_str());
    if (id < 0 || model->hfield_nrow[id] != f.rows || model->hfield_ncol[id] != f.cols) {
      throw std::runtime_error("terrain: the model has no height field " + field_name(i) + " of the terrain's size");
    }
    // MuJoCo scales the stored values (0..1) by the field's elevation, size[2]
    const double top = model->hfield_size[4 * id + 2];
    float* data = model->hfield_data + model->hfield_adr[id];
    for (std::size_t k = 0; k < f.heights_m.size(); ++k) data[k] = static_cast<float>(f.heights_m[k] / top);
  }
}

mjModel* load_model_with_terrain(const std::string& robot_model_path, const TerrainGeometry& terrain) {
  char error[1024] = {0};
  if (terrain.flat()) {
    mjModel* model = mj_loadXML(robot_model_path.c_str(), nullptr, error, sizeof error);
    if (model == nullptr) throw std::runtime_error("model " + robot_model_path + " failed to load: " + error);
    return model;
  }
  TemporaryFolder folder;
  // MuJoCo 2.2.2 resolves an include against the including file's folder and takes no absolute path
  const std::string include = fs::relative(fs::absolute(robot_model_path), folder.path()).string();
  const fs::path xml_path = folder.path() / "terrain.xml";
  {
    std::ofstream out(xml_path);
    out << terrain_mjcf(terrain, include);
    if (!out) throw std::runtime_error("terrain: cannot write " + xml_path.string());
  }
  mjModel* model = mj_loadXML(xml_path.c_str(), nullptr, error, sizeof error);
  if (model == nullptr) {
    throw std::runtime_error("model " + robot_model_path + " with the terrain failed to load: " + error);
  }
  fill_terrain_heights(model, terrain);
  return model;
}

}  // namespace cerebellum
