// InputError: the input is wrong in a way the user can fix. The message names the
// point, curve or face at fault. The CLI turns it into exit status 2, the Python
// module into ValueError.
#pragma once

#include <stdexcept>
#include <string>

namespace tquad {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace tquad
