// The LAZ chunk table: where each chunk of a chunked LAZ file starts, how
// many bytes and (for variable chunks, COPC) how many points it holds. The
// file stores its offset in the 8 bytes before the first chunk (or, when
// the writer could not seek back, in the file's last 8 bytes); the table is
// itself arithmetic-coded, each entry predicted from the one before.
#pragma once

#include <cstdint>
#include <vector>

#include "cloud/byte_source.hpp"
#include "cloud/laz/laszip_vlr.hpp"

namespace spinhash::host::laz {

struct ChunkEntry {
  uint64_t offset = 0;  // of the chunk's first byte in the file
  uint64_t bytes = 0;
  uint64_t points = 0;
};

// Reads and checks the table of a chunked file whose point data starts at
// points_offset; the chunks' points sum to at least point_count (the
// header's). Throws CloudError ("LAZ: ...").
std::vector<ChunkEntry> read_chunk_table(ByteSource& src, uint64_t points_offset, const LaszipVlr& vlr,
                                         uint64_t point_count);

}  // namespace spinhash::host::laz
