#include "modes/motion.hpp"

#include <algorithm>

namespace cerebellum {

bool MotionLibrary::add(Motion motion) {
  if (find(motion.id) != nullptr) return false;
  const auto after = std::find_if(motions_.begin(), motions_.end(), [&](const Motion& m) { return m.id > motion.id; });
  motions_.insert(after, std::move(motion));
  return true;
}

const Motion* MotionLibrary::find(int id) const {
  for (const Motion& motion : motions_) {
    if (motion.id == id) return &motion;
  }
  return nullptr;
}

std::string MotionLibrary::id_list() const {
  std::string text;
  for (const Motion& motion : motions_) {
    if (!text.empty()) text += ' ';
    text += std::to_string(motion.id);
  }
  return text.empty() ? "none" : text;
}

}  // namespace cerebellum
