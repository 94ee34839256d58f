// spinhash.Database: a database blob read from a file or bytes, opened
// (validated) by the core. Recognizers keep it alive through a shared_ptr.
#pragma once
#include <memory>
#include <string>

#include "pipeline/database_file.hpp"

namespace spinhash::python {

struct PyDatabase {
  pipeline::DatabaseFile file;  // the bytes and the core's view of them (never moved)
  std::string source;           // the path, or "<bytes>", for messages
};

using DatabasePtr = std::shared_ptr<PyDatabase>;  // never changed after opening

}  // namespace spinhash::python
