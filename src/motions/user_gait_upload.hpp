// One uploaded user-gait file, whatever transport carried it: parsed, checked for what would make
// the gait unsafe, stored; once a definition and parameters are both stored, the program is built
// and handed to the loop through the UserGaitSlot. A transport only decodes its packet and answers
// with the result (a second transport uploads gaits by calling the same receive()).
#pragma once

#include <string>

#include "modes/user_gait.hpp"
#include "motions/user_gait_store.hpp"

namespace cerebellum {

struct UserGaitUploadResult {
  bool accepted = false;
  // refused: why ("the previous gait is kept" where it is); stored: what the file held and whether
  // the gait is ready to run or waits for its other half
  std::string detail;
};

class UserGaitUpload {
 public:
  explicit UserGaitUpload(UserGaitSlot& slot) : slot_(slot) {}

  // the transport's thread (one thread): the text of one received file
  UserGaitUploadResult receive(const std::string& text);
  // any thread: what is stored so far
  const UserGaitStore& store() const { return store_; }

 private:
  UserGaitSlot& slot_;
  UserGaitStore store_;
};

}  // namespace cerebellum
