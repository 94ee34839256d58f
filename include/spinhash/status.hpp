// Status codes returned by every fallible core call. Values are part of the
// C ABI (spinhash.h): only ever append, never renumber.
#pragma once
#include <cstdint>

namespace spinhash {

enum class Status : int32_t {
  kOk = 0,
  kInvalidArgument = 1,    // null pointer, zero size, config out of range
  kWorkspaceTooSmall = 2,  // caller's buffer < required_workspace_bytes(config)
  kMisalignedBuffer = 3,   // blob or workspace not aligned to kBufferAlignment
  // Database::open
  kBlobTruncated = 10,  // shorter than its header, table or declared size
  kBlobBadMagic = 11,
  kBlobUnsupportedVersion = 12,
  kBlobWrongByteOrder = 13,  // written for the other byte order
  kBlobHeaderChecksum = 14,
  kBlobSectionChecksum = 15,
  kBlobSectionOutOfBounds = 16,
  kBlobSectionOverlap = 17,
  kBlobSectionMisaligned = 18,
  kBlobMissingSection = 19,
  kBlobDuplicateSection = 20,
  kBlobCountOverflow = 21,   // counts whose products overflow or exceed limits
  kBlobSizeMismatch = 22,    // section size disagrees with its counts
  kBlobBadParameter = 23,    // parameter out of range or not finite
  kBlobBadModelTable = 24,   // model ranges, names or grids inconsistent
  kBlobBadFeature = 25,      // non-finite position, bad normal, model id out of range
  kBlobBadIndex = 26,        // LSH or grid entry outside the table it indexes
  kDatabaseTooLarge = 27,    // more models than config.max_models
  kBlobUnknownSection = 28,  // section id not defined by the format version
  kBlobNotZeroed = 29,       // padding, a reserved field or a name's tail not zero
  // recognize
  kEmptyCloud = 40,         // no finite points
  kTooManyPoints = 41,      // more points than config.max_points (refused)
  kNotEnoughFeatures = 42,  // too few usable oriented points / basis points
  kNotOpen = 43,            // recognizer used without a valid database/workspace
  // SceneRecognizer
  kTileTooLarge = 44,    // tile's footprint needs more grid cells than the config holds (refused)
  kTooManyObjects = 45,  // more objects than config.max_objects (objects past the cap not recognised)
  // SceneStream (and the tile API over it)
  kWindowOverflow = 46,  // a window or the stream buffer held more points than its capacity (counted)
  kStreamFlushed = 47,   // points pushed after flush(): refused (counted); reset() starts a new line
};

// Short English name of a status; "unknown" for values not listed.
const char* status_name(Status s) noexcept;

}  // namespace spinhash
