// The stream's part of record_golden: a short flight-line strip and the
// objects SceneStream reports on it (golden_stream_format.hpp).
#pragma once
#include <string>

#include "spinhash/database.hpp"

namespace spinhash {
namespace golden {

// Writes dir/golden_stream.i16 and dir/golden_stream_expected.hpp from a run
// on `db` (the golden blob, opened); false after printing why.
bool record_stream(const std::string& dir, const Database& db);

}  // namespace golden
}  // namespace spinhash
