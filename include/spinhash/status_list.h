/* The one list of spinhash's statuses.
 *
 * Everything that names a status is produced from it: spinhash::Status
 * (status.hpp), spinhash_status of the C header (spinhash.h), status_name()
 * and spinhash_status_name() (the message), the snake_case word of the JSON
 * output and of Python (host-tools/pipeline/status_word.hpp), and Python's
 * spinhash.STATUSES. tests/host/test_field_mirrors.cpp checks the table of
 * docs/api.md against it.
 *
 * Entries: X(cxx, value, c, word, message)
 *   cxx      the enumerator of spinhash::Status
 *   value    its number: part of the C ABI, only ever appended, never
 *            renumbered
 *   c        the C enumerator without its SPINHASH_ prefix
 *   word     the stable word of the JSON output ("status") and of Python
 *   message  short English text (status_name)
 *
 * Compiles as C99: no comment inside the list may use the // form (it would
 * swallow the line continuation). */
#ifndef SPINHASH_STATUS_LIST_H
#define SPINHASH_STATUS_LIST_H

#define SPINHASH_STATUS_LIST(X)                                                                             \
  X(kOk, 0, OK, "ok", "ok")                                                                                 \
  /* null pointer, zero size, config out of range */                                                        \
  X(kInvalidArgument, 1, INVALID_ARGUMENT, "invalid_argument", "invalid argument")                          \
  /* the caller's buffer is smaller than the required workspace */                                          \
  X(kWorkspaceTooSmall, 2, WORKSPACE_TOO_SMALL, "workspace_too_small", "workspace too small")               \
  /* blob or workspace not aligned to kBufferAlignment */                                                   \
  X(kMisalignedBuffer, 3, MISALIGNED_BUFFER, "misaligned_buffer", "buffer not aligned to 64 bytes")         \
  /* Database::open: shorter than its header, table or declared size */                                     \
  X(kBlobTruncated, 10, BLOB_TRUNCATED, "blob_truncated", "blob truncated")                                 \
  X(kBlobBadMagic, 11, BLOB_BAD_MAGIC, "blob_bad_magic", "not a spinhash blob (bad magic)")                 \
  X(kBlobUnsupportedVersion, 12, BLOB_UNSUPPORTED_VERSION, "blob_unsupported_version",                      \
    "unsupported blob version")                                                                             \
  X(kBlobWrongByteOrder, 13, BLOB_WRONG_BYTE_ORDER, "blob_wrong_byte_order",                                \
    "blob written for the other byte order")                                                                \
  X(kBlobHeaderChecksum, 14, BLOB_HEADER_CHECKSUM, "blob_header_checksum", "blob header checksum mismatch") \
  X(kBlobSectionChecksum, 15, BLOB_SECTION_CHECKSUM, "blob_section_checksum",                               \
    "blob section checksum mismatch")                                                                       \
  X(kBlobSectionOutOfBounds, 16, BLOB_SECTION_OUT_OF_BOUNDS, "blob_section_out_of_bounds",                  \
    "blob section beyond the end")                                                                          \
  X(kBlobSectionOverlap, 17, BLOB_SECTION_OVERLAP, "blob_section_overlap", "blob sections overlap")         \
  X(kBlobSectionMisaligned, 18, BLOB_SECTION_MISALIGNED, "blob_section_misaligned",                         \
    "blob section misaligned")                                                                              \
  X(kBlobMissingSection, 19, BLOB_MISSING_SECTION, "blob_missing_section", "blob section missing")          \
  X(kBlobDuplicateSection, 20, BLOB_DUPLICATE_SECTION, "blob_duplicate_section", "blob section duplicated") \
  /* counts whose products overflow or exceed limits */                                                     \
  X(kBlobCountOverflow, 21, BLOB_COUNT_OVERFLOW, "blob_count_overflow",                                     \
    "blob counts overflow or exceed limits")                                                                \
  /* a section's size disagrees with its counts */                                                          \
  X(kBlobSizeMismatch, 22, BLOB_SIZE_MISMATCH, "blob_size_mismatch",                                        \
    "blob section size disagrees with its counts")                                                          \
  /* a parameter out of range or not finite */                                                              \
  X(kBlobBadParameter, 23, BLOB_BAD_PARAMETER, "blob_bad_parameter", "blob parameter out of range")         \
  /* model ranges, names or grids inconsistent */                                                           \
  X(kBlobBadModelTable, 24, BLOB_BAD_MODEL_TABLE, "blob_bad_model_table", "blob model table inconsistent")  \
  /* a non-finite position, a bad normal, a model id out of range */                                        \
  X(kBlobBadFeature, 25, BLOB_BAD_FEATURE, "blob_bad_feature", "blob feature invalid")                      \
  /* an LSH or grid entry outside the table it indexes */                                                   \
  X(kBlobBadIndex, 26, BLOB_BAD_INDEX, "blob_bad_index", "blob index out of range")                         \
  /* more models than config.max_models */                                                                  \
  X(kDatabaseTooLarge, 27, DATABASE_TOO_LARGE, "database_too_large",                                        \
    "database has more models than the workspace supports")                                                 \
  /* a section id the format version does not define */                                                     \
  X(kBlobUnknownSection, 28, BLOB_UNKNOWN_SECTION, "blob_unknown_section", "blob section id unknown")       \
  /* padding, a reserved field or a name's tail not zero */                                                 \
  X(kBlobNotZeroed, 29, BLOB_NOT_ZEROED, "blob_not_zeroed", "blob padding or reserved bytes not zero")      \
  /* the Calibration section's counts, bands, passes or cells inconsistent */                               \
  X(kBlobBadCalibration, 30, BLOB_BAD_CALIBRATION, "blob_bad_calibration", "blob calibration inconsistent") \
  /* recognize: no finite points */                                                                         \
  X(kEmptyCloud, 40, EMPTY_CLOUD, "empty_cloud", "empty cloud")                                             \
  /* more points than config.max_points (refused) */                                                        \
  X(kTooManyPoints, 41, TOO_MANY_POINTS, "too_many_points", "cloud larger than the workspace")              \
  /* too few usable oriented points or basis points */                                                      \
  X(kNotEnoughFeatures, 42, NOT_ENOUGH_FEATURES, "not_enough_features", "not enough features")              \
  /* used without a valid database or workspace */                                                          \
  X(kNotOpen, 43, NOT_OPEN, "not_open", "not initialised")                                                  \
  /* SceneRecognizer: a footprint needs more grid cells than the config holds (refused) */                  \
  X(kTileTooLarge, 44, TILE_TOO_LARGE, "tile_too_large", "tile footprint larger than the scene grid")       \
  /* more objects than config.max_objects (objects past the cap not recognised) */                          \
  X(kTooManyObjects, 45, TOO_MANY_OBJECTS, "too_many_objects",                                              \
    "more objects than the scene workspace holds")                                                          \
  /* SceneStream and the tile API over it: a window or the stream buffer held more points than its capacity \
     (counted) */                                                                                           \
  X(kWindowOverflow, 46, WINDOW_OVERFLOW, "window_overflow",                                                \
    "a scene window held more points than its capacity")                                                    \
  /* points pushed after flush(): refused (counted); reset() starts a new line */                           \
  X(kStreamFlushed, 47, STREAM_FLUSHED, "stream_flushed", "points pushed after the stream was flushed")     \
  /* SceneStream: points more than max_lag behind the furthest pushed came after their windows (dropped,    \
     counted in points_late): order them along track first */                                               \
  X(kPointsLate, 48, POINTS_LATE, "points_late", "points came after their windows ran (out of order)")      \
  /* recognize: the query spent config.max_work; the answer is the best found so far (ranked, never         \
     confident) */                                                                                          \
  X(kWorkCapReached, 49, WORK_CAP_REACHED, "work_cap_reached", "work cap reached: best answer so far")

#endif /* SPINHASH_STATUS_LIST_H */
