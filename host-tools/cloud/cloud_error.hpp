// The one error of the point-cloud readers: malformed or unreadable input,
// with a message naming the file and what is wrong. Everything a reader
// already handed out stays valid. In its own header so that the byte
// sources, the format readers and the point sources all throw it without
// including one another.
#pragma once

#include <stdexcept>

namespace spinhash::host {

class CloudError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace spinhash::host
