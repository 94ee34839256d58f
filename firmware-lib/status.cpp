#include "spinhash/status.hpp"

namespace spinhash {

const char* status_name(Status s) noexcept {
  switch (s) {
    case Status::kOk: return "ok";
    case Status::kInvalidArgument: return "invalid argument";
    case Status::kWorkspaceTooSmall: return "workspace too small";
    case Status::kMisalignedBuffer: return "buffer not aligned to 64 bytes";
    case Status::kBlobTruncated: return "blob truncated";
    case Status::kBlobBadMagic: return "not a spinhash blob (bad magic)";
    case Status::kBlobUnsupportedVersion: return "unsupported blob version";
    case Status::kBlobWrongByteOrder: return "blob written for the other byte order";
    case Status::kBlobHeaderChecksum: return "blob header checksum mismatch";
    case Status::kBlobSectionChecksum: return "blob section checksum mismatch";
    case Status::kBlobSectionOutOfBounds: return "blob section beyond the end";
    case Status::kBlobSectionOverlap: return "blob sections overlap";
    case Status::kBlobSectionMisaligned: return "blob section misaligned";
    case Status::kBlobMissingSection: return "blob section missing";
    case Status::kBlobDuplicateSection: return "blob section duplicated";
    case Status::kBlobCountOverflow: return "blob counts overflow or exceed limits";
    case Status::kBlobSizeMismatch: return "blob section size disagrees with its counts";
    case Status::kBlobBadParameter: return "blob parameter out of range";
    case Status::kBlobBadModelTable: return "blob model table inconsistent";
    case Status::kBlobBadFeature: return "blob feature invalid";
    case Status::kBlobBadIndex: return "blob index out of range";
    case Status::kDatabaseTooLarge: return "database has more models than the workspace supports";
    case Status::kBlobUnknownSection: return "blob section id unknown";
    case Status::kBlobNotZeroed: return "blob padding or reserved bytes not zero";
    case Status::kEmptyCloud: return "empty cloud";
    case Status::kTooManyPoints: return "cloud larger than the workspace";
    case Status::kNotEnoughFeatures: return "not enough features";
    case Status::kNotOpen: return "not initialised";
    case Status::kTileTooLarge: return "tile footprint larger than the scene grid";
    case Status::kTooManyObjects: return "more objects than the scene workspace holds";
    case Status::kWindowOverflow: return "a scene window held more points than its capacity";
    case Status::kStreamFlushed: return "points pushed after the stream was flushed";
  }
  return "unknown";
}

}  // namespace spinhash
