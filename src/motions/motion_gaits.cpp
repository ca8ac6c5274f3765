#include "motions/motion_gaits.hpp"

#include <optional>
#include <stdexcept>
#include <utility>

#include "core/text_file.hpp"
#include "motions/user_gait_convert.hpp"
#include "motions/user_gait_file.hpp"
#include "motions/user_gait_program.hpp"

namespace cerebellum {
namespace {

std::string read_text(const std::string& path) {
  std::string error;
  std::optional<std::string> text = read_text_file(path, kMaxUserGaitFileBytes, error);
  if (!text) throw std::invalid_argument(path + ": " + error);
  return std::move(*text);
}

UserGaitFile parse_checked(const std::string& path, const std::string& text, UserGaitFile::Kind kind) {
  const UserGaitParse parsed = parse_user_gait_file(text);
  if (!parsed.file) throw std::invalid_argument(path + ": " + parsed.error);
  if (parsed.file->kind != kind) {
    throw std::invalid_argument(
        path + (kind == UserGaitFile::Kind::Definition ? ": is not a gait definition" : ": is not gait parameters"));
  }
  const std::string problem = user_gait_file_problem(*parsed.file);
  if (!problem.empty()) throw std::invalid_argument(path + ": " + problem);
  return *parsed.file;
}

}  // namespace

std::shared_ptr<const UserGaitProgram> load_user_gait_files(const std::string& definition_path,
                                                            const std::string& parameters_path) {
  const UserGaitFile definition =
      parse_checked(definition_path, read_text(definition_path), UserGaitFile::Kind::Definition);
  std::string parameters_text = read_text(parameters_path);
  if (!is_converted_gait_parameters(parameters_text)) {
    UserGaitConversion converted = convert_gait_parameters(parameters_text);
    if (!converted.error.empty()) throw std::invalid_argument(parameters_path + ": " + converted.error);
    parameters_text = std::move(converted.text);
  }
  const UserGaitFile parameters = parse_checked(parameters_path, parameters_text, UserGaitFile::Kind::Parameters);
  return build_user_gait_program(definition.definition, parameters.parameters);
}

void attach_user_gaits(MotionLibrary& library) {
  for (Motion& motion : library.motions()) {
    if (motion.user_gait_definition.empty()) continue;
    try {
      motion.user_gait = load_user_gait_files(motion.user_gait_definition, motion.user_gait_parameters);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(motion.origin + ": user_gait: " + e.what());
    }
  }
}

}  // namespace cerebellum
