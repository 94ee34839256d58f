// Reads the committed golden vectors (tests/golden/) on any target.
#pragma once
#include <vector>

#include "blob/aligned_bytes.hpp"

namespace spinhash {
namespace test {

// The golden blob in this target's byte order, or in the other one.
host::AlignedBytes golden_blob(bool own_byte_order);
// Every golden query, decoded (xyz floats; GoldenQuery::first_point indexes triples).
std::vector<float> golden_query_points();
// The stream's golden strip (golden_stream.i16), georeferenced xyz doubles in scan order.
std::vector<double> golden_stream_points();

}  // namespace test
}  // namespace spinhash
