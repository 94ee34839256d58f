// Where each section of a blob goes, computed from its content. The layout is
// fixed: header, section table (one entry per id, in id order), then the
// sections in id order, each at the next multiple of 64; no trailing padding.
#pragma once
#include <cstdint>
#include <string>

#include "blob/blob_content.hpp"

namespace spinhash {
namespace host {

struct SectionPlacement {
  uint32_t id;
  uint64_t offset;
  uint64_t size;
};

struct BlobLayout {
  SectionPlacement sections[blob::kSectionIdCount];  // [i].id == i + 1
  uint64_t total_size;
};

// Checks that every vector has the length the params' counts call for and
// fills *layout. False with a message naming the first disagreement.
bool plan_blob_layout(const BlobContent& c, BlobLayout* layout, std::string* error);

}  // namespace host
}  // namespace spinhash
