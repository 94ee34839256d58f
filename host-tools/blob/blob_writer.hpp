// Serialises a BlobContent into the .shdb format (docs/blob-format.md) for a
// chosen byte order. The content is checked first: vector lengths against the
// params' counts, then the native-order image through Database::open, so a
// blob this returns always opens (on a machine of the order it was written for).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "blob/blob_content.hpp"
#include "blob/byte_order.hpp"
#include "spinhash/database.hpp"

namespace spinhash {
namespace host {

// On success *out holds the blob and *error is cleared; on failure *out is
// emptied and *error says why.
bool serialize_blob(const BlobContent& c, ByteOrder order, std::vector<uint8_t>* out, std::string* error);

// Serialises `content` (native order) into *bytes and opens it as *db (which
// points into *bytes); false with *error on failure.
bool open_content(const BlobContent& content, AlignedBytes* bytes, Database* db, std::string* error);

}  // namespace host
}  // namespace spinhash
