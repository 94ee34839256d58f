// What a layered LAZ chunk (point formats 6-10) decodes: every field of the
// record, or only the layers of the fields the pipeline takes (x y z, the
// return numbers, the class and its flags). LAS 1.4 compresses each group of
// fields into its own layer so that a reader can skip the rest unread, as
// LASzip's selective decompression does; a skipped field then holds its
// chunk's first point's value, and a skipped layer's bytes are not checked.
// Pointwise chunks (formats 0-5) interleave every field in one stream and
// always decode whole.
#pragma once

namespace spinhash::host::laz {

enum class LayerChoice { kAll, kPipeline };

}  // namespace spinhash::host::laz
