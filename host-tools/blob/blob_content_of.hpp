// The content of an open database as host vectors: what serialize_blob
// would write back byte for byte (native order). Lets host tools derive
// databases from a blob file as the build does from its content (the
// leave-one-model-out databases of `spinhash verify`).
#pragma once

#include "blob/blob_content.hpp"
#include "spinhash/database.hpp"

namespace spinhash {
namespace host {

BlobContent content_of(const Database& db);

}  // namespace host
}  // namespace spinhash
