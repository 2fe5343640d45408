// The one exception type for bad input: the driver turns it into exit status 2.
// Its message must name the file, parameter or mesh group that is wrong and what is allowed.
#pragma once

#include <stdexcept>
#include <string>

namespace flowform {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace flowform
