// The robot's MuJoCo model with a terrain's geoms added (MuJoCo 2.2.2 cannot edit a compiled
// model, so the terrain goes in through the XML: a small model file that includes the robot's
// and adds the ground's boxes and height fields, then the heights are written into the compiled
// model). Written to a private temporary folder and removed once loaded.
#pragma once

#include <string>

#include "backend/terrain.hpp"

struct mjModel_;

namespace cerebellum {

// the terrain's MJCF: the boxes and height fields as geoms (heights not included: they are
// written after compiling); include_file: the robot model to include, relative to where the
// returned XML is saved (empty: the terrain alone, for tests)
std::string terrain_mjcf(const TerrainGeometry& terrain, const std::string& include_file);

// loads robot_model_path with the terrain added (a flat terrain loads the file as it is); throws
// std::runtime_error naming the file and MuJoCo's reason
mjModel_* load_model_with_terrain(const std::string& robot_model_path, const TerrainGeometry& terrain);

// writes the height fields' heights into a model compiled from terrain_mjcf(terrain, ...)
void fill_terrain_heights(mjModel_* model, const TerrainGeometry& terrain);

}  // namespace cerebellum
