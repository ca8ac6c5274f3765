#include "motions/motion_file.hpp"

#include "motions/command_step_toml.hpp"

namespace cerebellum {

MotionFileParse parse_motion_file(std::string_view text) {
  MotionFileParse result;
  if (text.size() > kMaxMotionFileBytes) {
    result.error =
        "is " + std::to_string(text.size()) + " bytes, more than the limit of " + std::to_string(kMaxMotionFileBytes);
    return result;
  }
  const std::optional<toml::table> parsed = parse_toml_document(text, result.error);
  if (!parsed) return result;
  const toml::table& document = *parsed;
  TomlProblem problem;
  Motion motion;
  const std::optional<long long> id = toml_integer_in(document.get("id"), kFirstBuiltInMotionId, kLastUserMotionId);
  if (!id) {
    problem.set("id must be an integer in [" + std::to_string(kFirstBuiltInMotionId) + ", " +
                std::to_string(kLastUserMotionId) + "] (" + std::to_string(kFirstUserMotionId) + ".." +
                std::to_string(kLastUserMotionId) + " for users' motions)");
  }
  motion.id = static_cast<int>(id.value_or(0));
  const std::optional<std::string_view> name = document["name"].value<std::string_view>();
  if (!name || name->empty() || name->size() > kMaxMotionNameLength) {
    problem.set("name must be a text of 1 to " + std::to_string(kMaxMotionNameLength) + " characters");
  } else {
    motion.name = std::string(*name);
  }
  if (const toml::node* gait = document.get("user_gait")) {
    const toml::table* files = gait->as_table();
    const std::optional<std::string_view> definition =
        files != nullptr ? (*files)["definition"].value<std::string_view>() : std::nullopt;
    const std::optional<std::string_view> parameters =
        files != nullptr ? (*files)["parameters"].value<std::string_view>() : std::nullopt;
    if (files == nullptr || files->size() != 2 || !definition || !parameters || definition->empty() ||
        parameters->empty()) {
      problem.set("user_gait must be { definition = \"FILE\", parameters = \"FILE\" }");
    } else {
      motion.user_gait_definition = std::string(*definition);
      motion.user_gait_parameters = std::string(*parameters);
    }
  }
  const toml::array* steps = toml_entries(document, "step", kMaxMotionSteps, {"id", "name", "user_gait"}, problem);
  if (steps != nullptr) {
    for (std::size_t i = 0; i < steps->size(); ++i) {
      HighLevelCommand step = read_command_step(*steps->get(i)->as_table(), i, problem);
      if (step.duration < 1 || step.duration > kMaxMotionStepMs) {
        problem.set(toml_where("step", i, "duration") + " must be in [1, " + std::to_string(kMaxMotionStepMs) +
                    "] ms, found " + std::to_string(step.duration));
      }
      step.life_count = 0;
      motion.steps.push_back(step);
    }
  }
  if (problem.found()) {
    result.error = problem.text();
    return result;
  }
  result.motion = std::move(motion);
  return result;
}

}  // namespace cerebellum
