#include "motions/user_gait_upload.hpp"

#include <cstdio>

#include "motions/user_gait_file.hpp"
#include "motions/user_gait_program.hpp"

namespace cerebellum {
namespace {

std::string describe_gait_file(const UserGaitFile& file) {
  if (file.kind == UserGaitFile::Kind::Definition) {
    int units = 0;
    for (const GaitSection& section : file.definition.sections) units += section.duration_units;
    char text[96];
    std::snprintf(text, sizeof text, "gait definition: %zu sections, %.2f s", file.definition.sections.size(),
                  units * kGaitSectionUnitS);
    return text;
  }
  long duration_ms = 0;
  for (const HighLevelCommand& step : file.parameters.steps) duration_ms += step.duration;
  // the fields the firmware gives a meaning this MC cannot: said where the upload is logged
  return "gait parameters: " + std::to_string(file.parameters.steps.size()) + " steps, " + std::to_string(duration_ms) +
         " ms (" + std::string(kUnusedGaitParameters) + ")";
}

}  // namespace

UserGaitUploadResult UserGaitUpload::receive(const std::string& text) {
  const UserGaitParse parsed = parse_user_gait_file(text);
  if (!parsed.file) return {false, parsed.error};
  if (const std::string unsafe = user_gait_file_problem(*parsed.file); !unsafe.empty()) {
    return {false, unsafe + "; the previous gait is kept"};
  }
  store_.store(*parsed.file);
  std::string detail = describe_gait_file(*parsed.file);
  const std::optional<UserGaitDefinition> definition = store_.definition();
  const std::optional<UserGaitParameters> parameters = store_.parameters();
  if (definition && parameters) {
    const std::shared_ptr<const UserGaitProgram> program = build_user_gait_program(*definition, *parameters);
    slot_.publish(program);
    char ready[128];
    std::snprintf(ready, sizeof(ready), "; ready to run (11/110, 62/110): %zu sections, %zu steps, %.2f s",
                  definition->sections.size(), parameters->steps.size(), program->duration_s());
    detail += ready;
  } else {
    detail += definition ? "; waiting for the parameters" : "; waiting for the definition";
  }
  return {true, detail};
}

}  // namespace cerebellum
